//! Sizes in the words people use, for messages about files and memory.

/// A size as people say it: `512 bytes`, `3.4 MB`, `1.1 GB` (powers of 1000),
/// or `1 GiB` for an exact power of 1024.
pub fn bytes_in_words(n: u64) -> String {
    const GIB: u64 = 1 << 30;
    if n >= GIB && n.is_multiple_of(GIB) {
        return format!("{} GiB", n / GIB);
    }
    let x = n as f64;
    match n {
        0..1_000 => format!("{n} bytes"),
        1_000..1_000_000 => format!("{:.1} kB", x / 1e3),
        1_000_000..1_000_000_000 => format!("{:.1} MB", x / 1e6),
        _ => format!("{:.1} GB", x / 1e9),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_in_words() {
        assert_eq!(bytes_in_words(999), "999 bytes");
        assert_eq!(bytes_in_words(3_400_000), "3.4 MB");
        assert_eq!(bytes_in_words(1 << 30), "1 GiB");
        assert_eq!(bytes_in_words(11_000_000_000), "11.0 GB");
    }
}
