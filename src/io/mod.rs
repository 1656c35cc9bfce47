//! Images in and out: the linear-RGB image and its one conversion to 8-bit
//! sRGB, image files, output files written atomically, and the difference
//! between two images.

pub mod image;
pub mod image_diff;
pub mod image_file;
pub mod output;
