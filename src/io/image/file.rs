//! Image files: PNG or PPM, chosen by the file's extension, written from an
//! [`Image`] through the one sRGB conversion, and read back as 8-bit RGB.

use std::io::{BufWriter, Write};
use std::path::Path;

use anyhow::{Context, Result, bail};
use image::ImageEncoder;

use crate::io::image::{Image, to_rgb8};
use crate::io::input::{MAX_INPUT_BYTES, read_bytes};

/// The formats raytree writes, chosen by the output file's extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// `.png`
    Png,
    /// `.ppm` (binary P6)
    Ppm,
}

/// The format for `path`, from its extension.
pub fn format_of(path: &Path) -> Result<Format> {
    match path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase)
        .as_deref()
    {
        Some("png") => Ok(Format::Png),
        Some("ppm") => Ok(Format::Ppm),
        _ => bail!(
            "cannot write {}: the output must end in .png or .ppm",
            path.display()
        ),
    }
}

/// The encoded file contents of `image` in `format`.
pub fn encode(image: &Image, format: Format) -> Result<Vec<u8>> {
    let rgb = to_rgb8(image);
    let mut out = Vec::with_capacity(rgb.len() + 64);
    match format {
        Format::Png => {
            let encoder = image::codecs::png::PngEncoder::new(BufWriter::new(&mut out));
            encoder
                .write_image(
                    &rgb,
                    image.width,
                    image.height,
                    image::ExtendedColorType::Rgb8,
                )
                .context("cannot encode PNG")?;
        }
        Format::Ppm => {
            write!(out, "P6\n{} {}\n255\n", image.width, image.height)?;
            out.extend_from_slice(&rgb);
        }
    }
    Ok(out)
}

/// Reads a PNG or PPM (a regular file of at most [`MAX_INPUT_BYTES`]) as
/// 8-bit RGB.
pub fn read_rgb8(path: &Path) -> Result<image::RgbImage> {
    let bytes = read_bytes(path, MAX_INPUT_BYTES)
        .map_err(|reason| anyhow::anyhow!("cannot read {}: {reason}", path.display()))?;
    let reader = image::ImageReader::new(std::io::Cursor::new(bytes))
        .with_guessed_format()
        .with_context(|| format!("cannot read {}", path.display()))?;
    let img = reader.decode().map_err(|e| match e {
        // The library's "The image format could not be determined" says less
        // than this: it is some other kind of file.
        image::ImageError::Unsupported(_) => {
            anyhow::anyhow!(
                "{}: not a PNG or PPM image, the kinds raytree reads",
                path.display()
            )
        }
        e => anyhow::anyhow!(
            "{}: not an image raytree can read (a PNG or PPM): {e}",
            path.display()
        ),
    })?;
    Ok(img.to_rgb8())
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    #[test]
    fn ppm_has_header_and_top_row_first() {
        let image = Image {
            width: 2,
            height: 2,
            pixels: vec![DVec3::X, DVec3::ZERO, DVec3::ZERO, DVec3::ONE],
        };
        let bytes = encode(&image, Format::Ppm).unwrap();
        assert_eq!(&bytes[..11], b"P6\n2 2\n255\n");
        assert_eq!(&bytes[11..14], &[255, 0, 0]);
        assert_eq!(&bytes[20..23], &[255, 255, 255]);
    }

    #[test]
    fn ppm_and_png_read_back() {
        let image = Image {
            width: 3,
            height: 2,
            pixels: vec![
                DVec3::X,
                DVec3::Y,
                DVec3::Z,
                DVec3::ZERO,
                DVec3::ONE,
                DVec3::X,
            ],
        };
        let dir = tempfile::tempdir().unwrap();
        for (name, format) in [("a.ppm", Format::Ppm), ("a.png", Format::Png)] {
            let path = dir.path().join(name);
            std::fs::write(&path, encode(&image, format).unwrap()).unwrap();
            let back = read_rgb8(&path).unwrap();
            assert_eq!(back.as_raw(), &to_rgb8(&image), "{name}");
        }
    }
}
