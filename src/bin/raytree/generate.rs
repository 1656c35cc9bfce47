//! `raytree generate`: scene files made by program, for scaling runs.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};
use raytree::io::input::{MAX_INPUT_BYTES, bytes_in_words};
use raytree::scene::generate;

use crate::args::usage;
use crate::{memory, output};

#[derive(clap::Args)]
pub struct Args {
    #[command(subcommand)]
    what: Generated,
}

#[derive(clap::Subcommand)]
enum Generated {
    /// N random spheres over a floor, at a density that stays the same as N grows.
    Spheres {
        /// How many spheres.
        #[arg(long, value_name = "N", value_parser = clap::value_parser!(u64).range(1..=10_000_000))]
        count: u64,
        /// Seed of the random placement and materials.
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// Scene file to write.
        #[arg(short, long, value_name = "OUT.json")]
        output: PathBuf,
    },
    /// A grid of spheres with random materials (scenes/spheres.json is the default).
    Grid {
        /// Spheres across, up and deep.
        #[arg(long, value_name = "XxYxZ", default_value = "20x5x20", value_parser = parse_grid)]
        size: [u32; 3],
        /// Seed of the materials.
        #[arg(long, default_value_t = 2026)]
        seed: u64,
        /// Scene file to write.
        #[arg(short, long, value_name = "OUT.json")]
        output: PathBuf,
    },
    /// A subdivided icosahedron of about N triangles (20·4^k), as an OBJ file beside a scene that uses it.
    Icosphere {
        /// Triangles wanted; the nearest 20·4^k is made.
        #[arg(long, value_name = "N", value_parser = clap::value_parser!(u64).range(1..=100_000_000))]
        triangles: u64,
        /// Scene file to write; the mesh goes beside it, with .obj.
        #[arg(short, long, value_name = "OUT.json")]
        output: PathBuf,
    },
}

/// `XxYxZ`: spheres across, up and deep, at most 10 million in all.
fn parse_grid(s: &str) -> Result<[u32; 3], String> {
    let parts: Vec<Option<u32>> = s.split('x').map(|p| p.parse().ok()).collect();
    match parts[..] {
        [Some(x), Some(y), Some(z)]
            if x > 0
                && y > 0
                && z > 0
                && u64::from(x) * u64::from(y) * u64::from(z) <= 10_000_000 =>
        {
            Ok([x, y, z])
        }
        _ => Err(format!(
            "'{s}' is not a grid size like 20x5x20 (each at least 1, at most 10 million spheres)"
        )),
    }
}

pub fn run(args: &Args) -> Result<()> {
    let (path, need, what) = match &args.what {
        Generated::Spheres { count, output, .. } => (
            output,
            generate::memory_for_spheres(*count),
            format!("{count} spheres"),
        ),
        Generated::Grid { size, output, .. } => {
            let count = size.iter().map(|&n| u64::from(n)).product();
            (
                output,
                generate::memory_for_spheres(count),
                format!("{count} spheres"),
            )
        }
        Generated::Icosphere { triangles, output } => {
            let levels = generate::icosphere_levels(*triangles);
            (
                output,
                generate::memory_for_icosphere(levels),
                format!("{} triangles", 20u64 << (2 * levels)),
            )
        }
    };
    if !output::has_extension(path, "json") {
        return Err(usage(format_args!(
            "cannot write {}: a generated scene is a .json file{}",
            path.display(),
            if matches!(args.what, Generated::Icosphere { .. }) {
                " (its mesh goes beside it, as .obj)"
            } else {
                ""
            }
        )));
    }
    if let Generated::Icosphere { triangles, .. } = &args.what {
        let levels = generate::icosphere_levels(*triangles);
        let size = generate::icosphere_obj_bytes(levels);
        if size > MAX_INPUT_BYTES {
            let most = (0..levels)
                .rev()
                .find(|&l| generate::icosphere_obj_bytes(l) <= MAX_INPUT_BYTES)
                .unwrap_or(0);
            return Err(usage(format_args!(
                "an icosphere of {} triangles would be an OBJ file of about {}, more than the {} raytree reads; the most it makes is {} triangles (--triangles {} or fewer)",
                20u64 << (2 * levels),
                bytes_in_words(size),
                bytes_in_words(MAX_INPUT_BYTES),
                20u64 << (2 * most),
                // The nearest level is made: up to halfway to the next.
                ((20u64 << (2 * most)) + (20u64 << (2 * most + 2))) / 2
            )));
        }
    }
    if let Some(available) = memory::available().filter(|&a| need > a) {
        bail!(
            "making {what} needs about {} of memory, more than the {} this machine has available",
            bytes_in_words(need),
            bytes_in_words(available)
        );
    }
    match &args.what {
        Generated::Spheres { count, seed, .. } => {
            let text = generate::random_spheres(*count as usize, *seed);
            readable(path, &text)?;
            output::create(path, &[])?.commit(text.as_bytes())?;
        }
        Generated::Grid { size, seed, .. } => {
            let text = generate::sphere_grid(*size, *seed);
            readable(path, &text)?;
            output::create(path, &[])?.commit(text.as_bytes())?;
        }
        Generated::Icosphere { triangles, .. } => icosphere(*triangles, path)?,
    }
    output::note(&format!("wrote {}", path.display()))?;
    Ok(())
}

/// The icosphere's OBJ file beside its scene, both opened before either is
/// written, and never one file for both.
fn icosphere(triangles: u64, path: &Path) -> Result<()> {
    let levels = generate::icosphere_levels(triangles);
    let obj = path.with_extension("obj");
    if raytree::io::output::same_file(&obj, path) {
        bail!(
            "cannot write {}: the mesh goes beside the scene with .obj, so the scene needs another name (e.g. .json)",
            path.display()
        );
    }
    let name = obj
        .file_name()
        .context("the output needs a file name")?
        .to_string_lossy()
        .into_owned();
    let mesh_file = output::create(&obj, &[])?;
    let scene_file = output::create(path, std::slice::from_ref(&obj))?;
    let mesh = generate::icosphere_obj(levels);
    readable(&obj, &mesh)?;
    let text = generate::icosphere_scene(&name, 20 << (2 * levels));
    output::commit_all(vec![
        (mesh_file, mesh.as_bytes()),
        (scene_file, text.as_bytes()),
    ])?;
    output::note(&format!(
        "wrote {} ({} triangles)",
        obj.display(),
        20u64 << (2 * levels)
    ))?;
    Ok(())
}

/// Refuses to write `text` to `path` when raytree would not read it back.
/// The sizes allowed keep below the limit (10 million spheres take at most
/// 106 bytes each; an icosphere's OBJ is estimated before it is made), so
/// this only guards that reasoning.
fn readable(path: &Path, text: &str) -> Result<()> {
    let size = text.len() as u64;
    if size > MAX_INPUT_BYTES {
        bail!(
            "cannot write {}: it would be {}, more than the {} raytree reads",
            path.display(),
            bytes_in_words(size),
            bytes_in_words(MAX_INPUT_BYTES)
        );
    }
    Ok(())
}
