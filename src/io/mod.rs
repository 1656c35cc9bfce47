//! Images in and out: the 8-bit sRGB conversion, PNG and PPM files written
//! atomically, and the difference between two images.

pub mod image_diff;
pub mod image_file;
