//! `raytree generate`: scene files made by program, for scaling runs.

use std::path::PathBuf;

use anyhow::{Context, Result};
use raytree::scene::generate;

use crate::output;

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
    let (path, text) = match &args.what {
        Generated::Spheres {
            count,
            seed,
            output,
        } => (output, generate::random_spheres(*count as usize, *seed)),
        Generated::Grid { size, seed, output } => (output, generate::sphere_grid(*size, *seed)),
        Generated::Icosphere { triangles, output } => {
            let levels = generate::icosphere_levels(*triangles);
            let obj = output.with_extension("obj");
            let name = obj
                .file_name()
                .context("the output needs a file name")?
                .to_string_lossy()
                .into_owned();
            let mesh = generate::icosphere_obj(levels);
            output::create(&obj)?.commit(mesh.as_bytes())?;
            eprintln!(
                "wrote {} ({} triangles)",
                obj.display(),
                20u64 << (2 * levels)
            );
            (output, generate::icosphere_scene(&name, 20 << (2 * levels)))
        }
    };
    output::create(path)?.commit(text.as_bytes())?;
    eprintln!("wrote {}", path.display());
    Ok(())
}
