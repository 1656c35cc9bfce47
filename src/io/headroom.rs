//! Whether a file about to be loaded will fit in memory. A file within the
//! size limit can still need more memory than the machine has: a million
//! spheres, 101 MB of scene JSON, peaked at 838 MB while parsed and built; 5
//! million triangles, a 588 MB OBJ file, at 2.47 GB. So a 1 GiB scene needs
//! 8 GiB or more. Running out halfway ends in the allocator's abort and a
//! backtrace; this refuses before parsing, with the figures, as `raytree
//! generate` does before it writes. The need is counted by what the file
//! holds (objects, faces), not its bytes, so a compact file is not let by.
//!
//! The memory to be had is the smaller of the system's available memory
//! (`MemAvailable` in `/proc/meminfo`) and what the address-space limit
//! (`ulimit -v`, in `/proc/self/limits`) leaves above what the process maps
//! already. Where neither can be read (not Linux), nothing is refused. What
//! the render's threads map later (stacks, allocator arenas) is not counted:
//! under a tight `ulimit -v` a render can still fail after the check.

use crate::io::sizes::bytes_in_words;

/// Memory a scene's JSON takes at the peak of loading and building, beyond
/// its text, per `{` in it: each object has two (itself and its shape), and
/// the million spheres took 369 bytes each beyond the text. Counting braces,
/// not bytes, keeps a compact file (a sphere in 40 bytes) from slipping by.
pub const JSON_PER_BRACE: u64 = 400;

/// Memory an OBJ mesh takes at the peak of loading and building its
/// hierarchy, beyond its text, per face line (360 bytes measured; the
/// vertices, about half as many, included).
pub const OBJ_PER_FACE: u64 = 400;

/// Memory a saved trace takes once read, per byte of its JSON: its numbers
/// are most of it, and a 78 MB trace of 100,000 object tests opened in the
/// inspector peaked at 232 MB with its scene (3 rounds that up).
pub const TRACE_PER_BYTE: u64 = 3;

/// The memory loading a scene's JSON `text` takes at its peak, in bytes.
pub fn json_scene_need(text: &[u8]) -> u64 {
    let braces = text.iter().filter(|&&b| b == b'{').count() as u64;
    (text.len() as u64).saturating_add(braces.saturating_mul(JSON_PER_BRACE))
}

/// The memory loading an OBJ file's `bytes` takes at its peak, in bytes.
pub fn obj_need(bytes: &[u8]) -> u64 {
    let faces = bytes
        .split(|&b| b == b'\n')
        .filter(|l| l.trim_ascii_start().starts_with(b"f "))
        .count() as u64;
    (bytes.len() as u64).saturating_add(faces.saturating_mul(OBJ_PER_FACE))
}

/// Refuses to load what takes `need` bytes at its peak when `available`
/// (bytes) is known and less. The error is the reason alone; the caller
/// names the file.
pub fn check(need: u64, available: Option<u64>) -> Result<(), String> {
    match available {
        Some(have) if need > have => Err(format!(
            "loading it takes about {} of memory, more than the {} this process can have",
            bytes_in_words(need),
            bytes_in_words(have)
        )),
        _ => Ok(()),
    }
}

/// The memory this process can still have, in bytes, if the system says.
pub fn available() -> Option<u64> {
    let read = |path: &str| std::fs::read_to_string(path).ok();
    let system = read("/proc/meminfo").and_then(|t| kib_field(&t, "MemAvailable:"));
    let limit = read("/proc/self/limits").and_then(|t| address_space_limit(&t));
    let mapped = read("/proc/self/status")
        .and_then(|t| kib_field(&t, "VmSize:"))
        .unwrap_or(0);
    match (system, limit.map(|l| l.saturating_sub(mapped))) {
        (Some(a), Some(b)) => Some(a.min(b)),
        (a, b) => a.or(b),
    }
}

/// A `Name:   N kB` line's value in bytes.
fn kib_field(text: &str, name: &str) -> Option<u64> {
    let line = text.lines().find(|l| l.starts_with(name))?;
    let kib: u64 = line[name.len()..].split_whitespace().next()?.parse().ok()?;
    Some(kib.saturating_mul(1024))
}

/// The soft limit of `Max address space` in `/proc/self/limits` (bytes), if
/// there is one.
fn address_space_limit(text: &str) -> Option<u64> {
    let line = text.lines().find(|l| l.starts_with("Max address space"))?;
    line["Max address space".len()..]
        .split_whitespace()
        .next()?
        .parse()
        .ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_file_is_refused_only_when_its_need_is_known_to_exceed_the_memory() {
        let gib = 1u64 << 30;
        assert!(check(10 * gib, Some(20 * gib)).is_ok());
        assert!(check(10 * gib, None).is_ok());
        let e = check(10 * gib, Some(6 * gib)).unwrap_err();
        assert_eq!(
            e,
            "loading it takes about 10 GiB of memory, more than the 6 GiB this process can have"
        );
    }

    #[test]
    fn the_need_counts_objects_and_faces_not_bytes() {
        let sphere = br#"{"sphere": {"center": [1, 2, 3], "radius": 1}},"#;
        let text: Vec<u8> = sphere.repeat(1000);
        assert_eq!(
            json_scene_need(&text),
            text.len() as u64 + 2000 * JSON_PER_BRACE
        );
        let obj = b"v 0 0 0\nv 1 0 0\nv 0 1 0\n  f 1 2 3\nf 1 2 3\nvn 0 0 1\n# f 9 9 9\n";
        assert_eq!(obj_need(obj), obj.len() as u64 + 2 * OBJ_PER_FACE);
    }

    #[test]
    fn the_systems_figures_are_read_from_its_text() {
        let meminfo =
            "MemTotal:       24589064 kB\nMemFree:         1000 kB\nMemAvailable:   20000000 kB\n";
        assert_eq!(kib_field(meminfo, "MemAvailable:"), Some(20_000_000 * 1024));
        assert_eq!(kib_field(meminfo, "VmSize:"), None);
        let limits = "Limit                     Soft Limit           Hard Limit           Units     \n\
                      Max stack size            8388608              unlimited            bytes     \n\
                      Max address space         10240000000          unlimited            bytes     \n";
        assert_eq!(address_space_limit(limits), Some(10_240_000_000));
        let unlimited = limits.replace("10240000000", "unlimited");
        assert_eq!(address_space_limit(&unlimited), None);
    }
}
