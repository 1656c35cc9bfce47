//! Argument groups several commands share (the scene with its overrides, the
//! pixel or ray to trace), the parsers of their values, the pool of worker
//! threads `--threads` asks for, and [`Usage`], the error of a command line
//! that parses but asks for what cannot be.

use std::path::PathBuf;

use anyhow::{Context, Result};
use glam::DVec3;
use raytree::math::ray::Ray;
use raytree::methods::{Accel, Antialiasing, Weights};
use raytree::scene::Scene;
use raytree::scene::limits;
use raytree::scene::overrides::{Overrides, Protocol};
use raytree::scene::settings::RenderSettings;
use raytree::scene::source::{self, SceneSource};
use raytree::tree::document::TraceDocument;
use raytree::tree::record::{self, TraceError};

/// A refusal of the command line itself, found after it parsed: a flag's
/// value out of its range (one the scene sets, as a pixel outside the image),
/// two flags that do not go together, an output name of the wrong kind.
/// `main` reports it as it reports clap's own usage errors: one line ending
/// with the `--help` to read, exit status 2. Everything else (a file's
/// content, reading or writing) stays exit status 1.
#[derive(Debug)]
pub struct Usage(pub String);

impl std::fmt::Display for Usage {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for Usage {}

/// `message` as a [`Usage`] error.
pub fn usage(message: impl std::fmt::Display) -> anyhow::Error {
    Usage(message.to_string()).into()
}

/// Whether `e` is, or was caused by, a [`Usage`] error.
pub fn is_usage(e: &anyhow::Error) -> bool {
    e.chain().any(|cause| cause.is::<Usage>())
}

/// A scene and the settings that override its `render` block.
#[derive(clap::Args)]
pub struct SceneArgs {
    /// Scene file (JSON, see scenes/README.md, or NFF, by the extension .nff); the built-in Whitted scene if omitted.
    pub scene: Option<PathBuf>,
    /// Render as a benchmark prescribes: spd, the Standard Procedural Databases' protocol (512×512, rays through the 513×513 pixel corners averaged four to a pixel, max depth 5, no cutoff, and its rule that every transmitting hit spawns a reflected and a refracted ray, which raytree meets by Fresnel weights; the shading the SPD leaves to the renderer); the flags below, given beside it, win, but --weights constant, which breaks that rule, is refused.
    #[arg(long, value_enum)]
    pub protocol: Option<Protocol>,
    #[command(flatten)]
    pub overrides: Overrides,
}

impl SceneArgs {
    /// The scene with the command line's settings applied and checked, and
    /// what names it in a trace.
    pub fn load(&self) -> Result<(Scene, SceneSource)> {
        let (mut scene, source) = source::load(self.scene.as_deref())?;
        scene.settings = self.settings(&scene.settings)?;
        Ok((scene, source))
    }

    /// [`SceneArgs::load`] for a command that builds every structure itself
    /// (`structures`), where --grid-res and --tree-depth shape the grid and
    /// the trees it builds whatever the scene's own `accel`.
    pub fn load_for_every_structure(&self) -> Result<(Scene, SceneSource)> {
        let (mut scene, source) = source::load(self.scene.as_deref())?;
        scene.settings = self.checked(&scene.settings)?;
        Ok((scene, source))
    }

    /// `own` (a scene's settings, already checked when it was read) with the
    /// flags given put in place, checked: settings the flags make impossible
    /// are a [`Usage`] error naming the flag.
    pub fn settings(&self, own: &RenderSettings) -> Result<RenderSettings> {
        let settings = self.checked(own)?;
        // A structure's own flag under another structure would be ignored;
        // auto builds a hierarchy or nothing, never a grid or a tree.
        let grid = settings.accel == Accel::Grid;
        let tree = matches!(settings.accel, Accel::Octree | Accel::Bsp);
        let unused = if self.overrides.grid_res.is_some() && !grid {
            Some(("--grid-res", "the grid's cells", "grid"))
        } else if self.overrides.tree_depth.is_some() && !tree {
            Some((
                "--tree-depth",
                "the octree's or the k-d tree's depth",
                "octree or --accel bsp",
            ))
        } else {
            None
        };
        if let Some((flag, what, needs)) = unused {
            let now = match settings.accel {
                Accel::Auto => "auto (a bounding volume hierarchy or none, never a grid or a tree)",
                other => other.name(),
            };
            return Err(usage(format_args!(
                "{flag}: sets {what}, and the scene is traced with --accel {now}; give --accel {needs} beside it"
            )));
        }
        Ok(settings)
    }

    fn checked(&self, own: &RenderSettings) -> Result<RenderSettings> {
        let own = self.protocol.map_or(*own, |p| p.overrides().apply(own));
        let settings = self.overrides.apply(&own);
        // Flags that would be ignored, or would break the protocol asked for,
        // are refused: the counts printed must be what the user asked for.
        if self.overrides.spp.is_some() && settings.aa != Antialiasing::Grid {
            let why = match settings.aa {
                Antialiasing::Corners if self.overrides.aa.is_none() => {
                    "--protocol spd traces one ray through each pixel corner; give --aa grid beside it to sample a grid"
                }
                Antialiasing::Corners => "--aa corners traces one ray through each pixel corner",
                _ => "--aa adaptive takes as many samples as each pixel needs",
            };
            return Err(usage(format_args!(
                "--spp: samples the --aa grid only, and {why}"
            )));
        }
        if self.protocol == Some(Protocol::Spd) && settings.weights == Weights::Constant {
            return Err(usage(
                "--weights constant: --protocol spd spawns a reflected and a refracted ray at every transmitting hit, which raytree meets by Fresnel (or Schlick) weights; constant weights reflect only where the material's own reflection is above 0, so the counts would not be the protocol's",
            ));
        }
        if let Err((field, message)) = settings.validate() {
            return Err(usage(format_args!(
                "--{}: {message}",
                field.replace('_', "-")
            )));
        }
        Ok(settings)
    }

    /// The files the scene was read from (the scene file and its OBJ files):
    /// no output may replace one of them.
    pub fn inputs(&self, scene: &Scene) -> Vec<PathBuf> {
        self.scene
            .iter()
            .cloned()
            .chain(scene.mesh_files.iter().cloned())
            .collect()
    }

    /// The scene's file stem, or "whitted" for the built-in scene: the start of
    /// default output names.
    pub fn stem(&self) -> &std::ffi::OsStr {
        self.scene
            .as_ref()
            .and_then(|p| p.file_stem())
            .unwrap_or("whitted".as_ref())
    }
}

/// What to trace: a pixel or a ray.
#[derive(clap::Args)]
#[command(group(clap::ArgGroup::new("target").required(true).args(["pixel", "ray"])))]
pub struct TargetArgs {
    /// The pixel to trace, in image coordinates: x to the right, y down from the top-left, as in the rendered image.
    #[arg(long, value_name = "X,Y", value_parser = parse_pixel, allow_hyphen_values = true)]
    pub pixel: Option<(u32, u32)>,
    /// Trace one ray instead of a pixel: its origin and direction in world coordinates, each number within ±1e9 as a scene's are. It starts in the media around its origin: from inside a glass ball, in glass.
    #[arg(long, value_name = "OX,OY,OZ:DX,DY,DZ", value_parser = parse_ray, allow_hyphen_values = true)]
    pub ray: Option<Ray>,
    /// With several samples per pixel, keep only sample K (1 is the first; row by row from the top-left).
    #[arg(long, value_name = "K", conflicts_with = "ray", value_parser = clap::value_parser!(u32).range(1..))]
    pub sample: Option<u32>,
}

impl TargetArgs {
    /// Records the pixel's or the ray's trees. A pixel outside the image, a
    /// sample the pixel does not have, or settings whose trees a trace cannot
    /// hold (lowering --spp or --max-depth is the remedy) is a [`Usage`]
    /// error; the ray was checked when parsed.
    pub fn record(&self, scene: &Scene, source: SceneSource) -> Result<TraceDocument> {
        let recorded = match (self.pixel, self.ray) {
            (Some((x, y)), _) => record::pixel(scene, source, x, y, self.sample.map(|k| k - 1)),
            (_, Some(ray)) => record::ray(scene, source, ray),
            _ => unreachable!("clap requires --pixel or --ray"),
        };
        recorded.map_err(|e| match e {
            TraceError::PixelOutside { .. }
            | TraceError::SampleOutside { .. }
            | TraceError::TooManyRays { .. } => usage(e),
            TraceError::BadRay => e.into(),
        })
    }
}

/// `WxH`, each side 64 to 8192 pixels.
pub fn parse_size(s: &str) -> Result<(u32, u32), String> {
    let (w, h) = s
        .split_once(['x', 'X'])
        .ok_or("expected WxH, e.g. 1200x800")?;
    let side = |v: &str| {
        v.trim()
            .parse::<u32>()
            .ok()
            .filter(|&n| (64..=8192).contains(&n))
            .ok_or_else(|| format!("'{v}' is not a size from 64 to 8192 pixels"))
    };
    Ok((side(w)?, side(h)?))
}

/// A count from 1 up (a level, a hit's number): any whole number is read, so
/// that 0 and -1 are refused with the range, not the integer type's limits.
pub fn parse_from_one(s: &str) -> Result<u32, String> {
    match s.trim().parse::<i128>() {
        Ok(n) if n < 1 => Err(format!("must be 1 or more, got {n}")),
        Ok(n) => u32::try_from(n).map_err(|_| format!("must be 1 to {}, got {n}", u32::MAX)),
        Err(_) => Err(format!("'{s}' is not a whole number")),
    }
}

/// `X,Y` in image coordinates. A negative coordinate is read (its flag
/// takes values starting with a hyphen) so that it is refused as a pixel
/// outside the image, not as an unknown flag `-1`.
pub fn parse_pixel(s: &str) -> Result<(u32, u32), String> {
    let (x, y) = s.split_once(',').ok_or("expected X,Y, e.g. 320,240")?;
    let coord = |name: &str, edge: &str, v: &str| {
        let v = v.trim();
        match v.parse::<i64>() {
            Ok(n) if n < 0 => Err(format!(
                "{name} {n} is outside the image: {name} counts from 0 at its {edge} edge"
            )),
            _ => v
                .parse::<u32>()
                .map_err(|_| format!("'{v}' is not a pixel coordinate (a whole number ≥ 0)")),
        }
    };
    Ok((coord("x", "left", x)?, coord("y", "top", y)?))
}

/// `OX,OY,OZ:DX,DY,DZ`: an origin and a direction that is not zero, every
/// coordinate within a scene's limits (±[`limits::MAX_COORDINATE`]), so that
/// every number of the trace stays finite, as it does for a scene's rays.
fn parse_ray(s: &str) -> Result<Ray, String> {
    let (o, d) = s
        .split_once(':')
        .ok_or("expected OX,OY,OZ:DX,DY,DZ, e.g. 0,1,5:0,0,-1")?;
    let origin = DVec3::from(parse_numbers::<3>(o)?);
    let dir = DVec3::from(parse_numbers::<3>(d)?);
    limits::point(origin).map_err(|e| format!("the origin: {e}"))?;
    limits::point(dir).map_err(|e| format!("the direction: {e}"))?;
    if dir == DVec3::ZERO {
        return Err("the direction must not be zero".to_owned());
    }
    // Checked, not normalized: t counts along the direction as given.
    if dir.try_normalize().is_none() {
        return Err("the direction is too short to normalize (its length underflows)".to_owned());
    }
    Ok(Ray::new(origin, dir))
}

fn parse_numbers<const N: usize>(s: &str) -> Result<[f64; N], String> {
    let parts: Vec<&str> = s.split(',').map(str::trim).collect();
    if parts.len() != N {
        return Err(format!(
            "expected {N} comma-separated numbers, got {}",
            parts.len()
        ));
    }
    let mut out = [0.0; N];
    for (o, p) in out.iter_mut().zip(parts) {
        *o = p
            .parse::<f64>()
            .ok()
            .filter(|v| v.is_finite())
            .ok_or_else(|| format!("'{p}' is not a finite number"))?;
    }
    Ok(out)
}

/// Most worker threads: more only costs time on any machine of today (each
/// thread's start-up and memory) and thousands stall it.
const MAX_THREADS: usize = 256;

/// "1 thread", "2 threads".
pub fn threads_word(threads: usize) -> String {
    if threads == 1 {
        "1 thread".to_owned()
    } else {
        format!("{threads} threads")
    }
}

/// `--threads N`: 1 to [`MAX_THREADS`].
pub fn parse_threads(s: &str) -> Result<usize, String> {
    s.trim()
        .parse::<usize>()
        .ok()
        .filter(|n| (1..=MAX_THREADS).contains(n))
        .ok_or_else(|| format!("must be a whole number from 1 to {MAX_THREADS}"))
}

/// A pool of `threads` workers ([`parse_threads`] checked the number; one
/// per core by default), and how many.
pub fn thread_pool(threads: Option<usize>) -> Result<(rayon::ThreadPool, usize)> {
    let threads =
        threads.unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()));
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .context("cannot start worker threads")?;
    Ok((pool, threads))
}
