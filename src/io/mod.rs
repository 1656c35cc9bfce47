//! Files in and out: input files read within limits, the linear-RGB image and
//! its one conversion to 8-bit sRGB, image files, output files written
//! atomically, the difference between two images, and the lecture's
//! PostScript program.

pub mod input; // regular files only, size checked before reading, text that is text
pub mod headroom; // whether a file will fit in memory once loaded
pub mod sizes; // sizes in words: 3.4 MB, 1 GiB
pub mod image; // linear RGB, and the one conversion to 8-bit sRGB; PNG and PPM; differences
pub mod output; // files written atomically
pub mod postscript; // the lecture's PostScript ray tracer, its transcription slips repaired
