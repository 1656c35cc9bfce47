//! Helpers shared by the integration tests.

use glam::DVec3;
use raytree::scene::Scene;
use raytree::trace::recorder::{HitEvent, RayKind, RayStart, Recorder, ShadowEvent};

/// Parses a scene written inline in a test.
pub fn scene(json: &str) -> Scene {
    raytree::scene::loader::parse(json, "test.json").unwrap_or_else(|e| panic!("{e}"))
}

/// The shipped scenes, by file name.
pub fn shipped() -> Vec<(&'static str, Scene)> {
    [
        "whitted.json",
        "nested.json",
        "ellipsoids.json",
        "cones.json",
    ]
    .into_iter()
    .map(|name| {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("scenes")
            .join(name);
        (
            name,
            raytree::scene::loader::load(&path).unwrap_or_else(|e| panic!("{e}")),
        )
    })
    .collect()
}

/// Keeps every event of interest, flat, in the order the tracer sent them.
#[derive(Default)]
pub struct Log {
    pub rays: Vec<RayStart>,
    pub hits: Vec<HitEvent>,
    pub shadows: Vec<ShadowEvent>,
    pub branches: Vec<raytree::trace::recorder::BranchEvent>,
    pub colors: Vec<raytree::trace::recorder::SumEvent>,
}

impl Recorder for Log {
    const ENABLED: bool = true;
    fn ray_started(&mut self, start: &RayStart) {
        self.rays.push(*start);
    }
    fn hit(&mut self, hit: &HitEvent) {
        self.hits.push(*hit);
    }
    fn shadow_ray(&mut self, shadow: &ShadowEvent) {
        self.shadows.push(*shadow);
    }
    fn branch(&mut self, branch: &raytree::trace::recorder::BranchEvent) {
        self.branches.push(*branch);
    }
    fn ray_finished(&mut self, sum: &raytree::trace::recorder::SumEvent) {
        self.colors.push(*sum);
    }
}

impl Log {
    /// The rays of one kind.
    pub fn of_kind(&self, kind: RayKind) -> Vec<RayStart> {
        self.rays
            .iter()
            .filter(|r| r.kind == kind)
            .copied()
            .collect()
    }
}

/// Whether two colors agree to `tol` in every channel.
pub fn close(a: DVec3, b: DVec3, tol: f64) -> bool {
    (a - b).abs().max_element() <= tol
}

/// Runs the `raytree` binary with `args` in a fresh folder holding `files`
/// (name, contents) and checks the failure contract: exit code `code` (1, or 2
/// for a malformed command line), one line on stderr starting `error: `, no
/// panic, no file added and every file as it was. Returns the line.
pub fn refused_with(code: i32, name: &str, files: &[(&str, &[u8])], args: &[&str]) -> String {
    // A folder of this call's own: two tests may name their cases alike
    // ("pixel-outside" is both a trace file's and a command line's), and the
    // harness runs them at once.
    static CALLS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let call = CALLS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let dir = std::env::temp_dir().join(format!(
        "raytree-refused-{name}-{}-{call}",
        std::process::id()
    ));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    for (file, bytes) in files {
        std::fs::write(dir.join(file), bytes).unwrap();
    }
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_raytree"))
        .args(args)
        .current_dir(&dir)
        .stdin(std::process::Stdio::null())
        .output()
        .expect("the binary runs");
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(
        out.status.code(),
        Some(code),
        "{name}: exit code; stderr: {stderr}"
    );
    assert!(!stderr.contains("panicked"), "{name}: panicked: {stderr}");
    let lines: Vec<&str> = stderr.lines().collect();
    assert_eq!(
        lines.len(),
        1,
        "{name}: stderr must be one line: {stderr:?}"
    );
    assert!(lines[0].starts_with("error: "), "{name}: {stderr}");
    assert!(
        !lines[0].contains('\u{1b}'),
        "{name}: a raw escape reached the terminal"
    );
    let mut left: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    left.sort();
    let mut given: Vec<String> = files.iter().map(|(f, _)| f.to_string()).collect();
    given.sort();
    given.dedup();
    assert_eq!(left, given, "{name}: files added or removed");
    for (file, bytes) in files {
        assert_eq!(
            &std::fs::read(dir.join(file)).unwrap(),
            bytes,
            "{name}: {file} changed"
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
    lines[0].to_owned()
}

/// Runs `raytree ARGS` in `dir` with its address space limited to `mib`
/// MiB: a reader that would fill the memory fails instead of passing.
#[cfg(target_os = "linux")]
pub fn within_memory(dir: &std::path::Path, mib: u64, args: &[&str]) -> (Option<i32>, String, f64) {
    let start = std::time::Instant::now();
    let out = std::process::Command::new("sh")
        .arg("-c")
        .arg(format!("ulimit -v {}; exec \"$0\" \"$@\"", mib << 10))
        .arg(env!("CARGO_BIN_EXE_raytree"))
        .args(args)
        .current_dir(dir)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr).into_owned();
    (out.status.code(), err, start.elapsed().as_secs_f64())
}

/// [`refused_with`] exit code 1: a bad input, not a malformed command line.
pub fn refused(name: &str, files: &[(&str, &[u8])], args: &[&str]) -> String {
    refused_with(1, name, files, args)
}

/// How far a drawn figure may stray from its committed PNG, in 8-bit levels
/// per channel: figures are drawn the same way on every machine, but another
/// SIMD path in the rasterizer may round an edge pixel's coverage (of a line or
/// a glyph) differently; a moved line or label, or a changed value, changes
/// pixels by far more.
pub const FIGURE_TOLERANCE: u8 = 8;

/// The largest difference between two images' channels, in 8-bit levels.
pub fn worst_difference(a: &[u8], b: &[u8]) -> u8 {
    assert_eq!(a.len(), b.len(), "images of different sizes");
    a.iter()
        .zip(b)
        .map(|(a, b)| a.abs_diff(*b))
        .max()
        .unwrap_or(0)
}

/// Checks `fig` against the PNG at `path` within [`FIGURE_TOLERANCE`]; with
/// `RAYTREE_BLESS` set, writes it there instead. `bless` names the test
/// filter that remakes it.
pub fn matches_golden(fig: &raytree::figure::canvas::Figure, path: &std::path::Path, bless: &str) {
    if std::env::var_os("RAYTREE_BLESS").is_some() {
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::write(path, fig.png()).unwrap();
        return;
    }
    let golden = image::open(path)
        .unwrap_or_else(|e| {
            panic!(
                "{}: {e} (make it with RAYTREE_BLESS=1 cargo test --release {bless})",
                path.display()
            )
        })
        .to_rgb8();
    assert_eq!(golden.dimensions(), fig.size(), "{}", path.display());
    let worst = worst_difference(golden.as_raw(), &fig.rgb());
    assert!(
        worst <= FIGURE_TOLERANCE,
        "{} is stale: a pixel differs by {worst} of 255 (RAYTREE_BLESS=1 cargo test --release {bless})",
        path.display()
    );
}

/// The commands `raytree --help` lists (`help` left out), in its order.
pub fn command_names(help: &str) -> Vec<&str> {
    help.lines()
        .skip_while(|l| !l.starts_with("Commands:"))
        .skip(1)
        .take_while(|l| !l.trim().is_empty())
        // A command's line is indented two spaces; a wrapped description, more.
        .filter(|l| l.starts_with("  ") && !l.starts_with("   "))
        .filter_map(|l| l.split_whitespace().next())
        .filter(|n| *n != "help")
        .collect()
}
