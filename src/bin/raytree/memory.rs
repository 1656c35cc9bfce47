//! How much memory this process may still take: the least of what the
//! machine has available, what its control group allows and its address-space
//! limit (`ulimit -v`). Read from Linux's `/proc` and `/sys`; elsewhere unknown.

/// Bytes this process may still allocate, if known.
pub fn available() -> Option<u64> {
    [meminfo(), cgroup(), address_space()]
        .into_iter()
        .flatten()
        .min()
}

/// `MemAvailable` in `/proc/meminfo` (in kB there).
fn meminfo() -> Option<u64> {
    let text = std::fs::read_to_string("/proc/meminfo").ok()?;
    let line = text.lines().find(|l| l.starts_with("MemAvailable:"))?;
    let kb: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kb * 1024)
}

/// A cgroup v2 limit less what the group already uses.
fn cgroup() -> Option<u64> {
    let read = |f: &str| std::fs::read_to_string(format!("/sys/fs/cgroup/{f}")).ok();
    let max: u64 = read("memory.max")?.trim().parse().ok()?;
    let current: u64 = read("memory.current")
        .and_then(|s| s.trim().parse().ok())
        .unwrap_or(0);
    Some(max.saturating_sub(current))
}

/// The soft address-space limit (`ulimit -v`), from `/proc/self/limits`.
fn address_space() -> Option<u64> {
    let text = std::fs::read_to_string("/proc/self/limits").ok()?;
    let line = text.lines().find(|l| l.starts_with("Max address space"))?;
    line.split_whitespace().nth(3)?.parse().ok()
}
