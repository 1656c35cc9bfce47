//! Writing images: the one conversion from linear RGB to 8-bit sRGB, and PNG or
//! PPM files written atomically (a temporary file beside the target, renamed over
//! it once complete), so an interrupted run never leaves a broken image.

use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};
use glam::DVec3;
use image::ImageEncoder;
use tempfile::NamedTempFile;

use crate::trace::render::Image;

/// Linear RGB to 8-bit sRGB, for one channel: clamp to [0, 1] (NaN counts as 0),
/// apply the sRGB transfer function (IEC 61966-2-1: `12.92·v` below 0.0031308,
/// else `1.055·v^(1/2.4) - 0.055`), scale to 255 and round to nearest.
pub fn linear_to_srgb8(v: f64) -> u8 {
    let v = if v.is_nan() { 0.0 } else { v.clamp(0.0, 1.0) };
    let s = if v <= 0.003_130_8 {
        12.92 * v
    } else {
        1.055 * v.powf(1.0 / 2.4) - 0.055
    };
    (s * 255.0 + 0.5).floor() as u8
}

/// A color's 8-bit sRGB triple.
pub fn rgb8(c: DVec3) -> [u8; 3] {
    [
        linear_to_srgb8(c.x),
        linear_to_srgb8(c.y),
        linear_to_srgb8(c.z),
    ]
}

/// The image as 8-bit sRGB bytes, rows top first.
pub fn to_rgb8(image: &Image) -> Vec<u8> {
    image.pixels.iter().flat_map(|&c| rgb8(c)).collect()
}

/// The formats raytree writes, chosen by the output file's extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// `.png`
    Png,
    /// `.ppm` (binary P6)
    Ppm,
}

/// An output file, opened as a temporary file beside its target before the work
/// that fills it starts, so a bad path fails at once rather than after a render.
#[derive(Debug)]
pub struct PendingFile {
    target: PathBuf,
    temp: NamedTempFile,
}

impl PendingFile {
    /// Prepares to write `target`, failing with a one-line reason if its folder
    /// does not exist or cannot be written.
    pub fn create(target: &Path) -> Result<Self> {
        let dir = match target.parent() {
            Some(p) if !p.as_os_str().is_empty() => p,
            _ => Path::new("."),
        };
        if target.is_dir() {
            bail!("cannot write {}: it is a directory", target.display());
        }
        let temp = tempfile::Builder::new()
            .prefix(".raytree-")
            .suffix(".part")
            .tempfile_in(dir)
            .map_err(|e| anyhow::anyhow!("cannot write {}: {}", target.display(), io_reason(&e)))?;
        Ok(Self {
            target: target.to_owned(),
            temp,
        })
    }

    /// Where the temporary file is, until it is committed.
    pub fn temp_path(&self) -> &Path {
        self.temp.path()
    }

    /// Writes `bytes` and renames the file into place.
    pub fn commit(self, bytes: &[u8]) -> Result<()> {
        let Self { target, mut temp } = self;
        let fail = |e: std::io::Error| {
            anyhow::anyhow!("cannot write {}: {}", target.display(), io_reason(&e))
        };
        temp.write_all(bytes).map_err(fail)?;
        temp.as_file().sync_all().map_err(fail)?;
        #[cfg(unix)]
        {
            use std::os::unix::fs::PermissionsExt;
            temp.as_file()
                .set_permissions(std::fs::Permissions::from_mode(0o644))
                .map_err(fail)?;
        }
        temp.persist(&target).map_err(|e| fail(e.error))?;
        Ok(())
    }
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

/// The OS's reason without Rust's "(os error N)" suffix.
fn io_reason(e: &std::io::Error) -> String {
    let s = e.to_string();
    match s.find(" (os error") {
        Some(i) => s[..i].to_owned(),
        None => s,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn srgb_conversion_matches_the_standard() {
        assert_eq!(linear_to_srgb8(0.0), 0);
        assert_eq!(linear_to_srgb8(1.0), 255);
        assert_eq!(linear_to_srgb8(7.0), 255);
        assert_eq!(linear_to_srgb8(-1.0), 0);
        assert_eq!(linear_to_srgb8(f64::NAN), 0);
        // Linear 0.5 is sRGB 1.055·0.5^(1/2.4) - 0.055 = 0.7354 → 187.5 → 188.
        assert_eq!(linear_to_srgb8(0.5), 188);
        // Linear 0.214 is sRGB 1.055·0.214^(1/2.4) - 0.055 = 0.49996 → 127.49 → 127.
        assert_eq!(linear_to_srgb8(0.214), 127);
        // The linear segment: 0.001 → 12.92·0.001·255 = 3.29 → 3.
        assert_eq!(linear_to_srgb8(0.001), 3);
    }

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
}
