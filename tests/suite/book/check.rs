//! Comparing the made book with the committed one, naming what went stale;
//! and writing it (bless).

use std::collections::BTreeSet;
use std::path::Path;

use super::make::{Content, File, OWNED};
use super::page;
use super::run::root;

/// Figures are drawn the same way everywhere, but another SIMD path in the
/// rasterizer may round an edge pixel's coverage differently (the golden
/// diagrams allow the same 8 of 255); a moved line or label changes far more.
const FIGURE_TOLERANCE: u8 = 8;

/// Every difference between `files` and the repository, one line each.
pub fn stale(files: &[File]) -> Vec<String> {
    let mut out = Vec::new();
    for f in files {
        match &f.content {
            Content::Text(fresh) => out.extend(stale_text(f, fresh)),
            Content::Png(fresh) => out.extend(stale_figure(f, fresh)),
        }
    }
    for orphan in orphans(files) {
        out.push(format!("{orphan}: made by no lesson or page any more"));
    }
    out
}

fn stale_text(f: &File, fresh: &str) -> Vec<String> {
    let Ok(committed) = std::fs::read_to_string(root().join(&f.path)) else {
        return vec![format!("{}: missing (made from {})", f.path, f.origin)];
    };
    if committed == fresh {
        return Vec::new();
    }
    let was = page::quoted(&committed);
    let mut out: Vec<String> = f
        .numbers
        .iter()
        .filter(|n| was.get(&n.name) != Some(&n.value))
        .map(|n| {
            let before = was.get(&n.name).map_or("nothing".to_owned(), |v| v.clone());
            format!(
                "{}: number {} is stale: {before} in the book, {} now (from {})",
                f.path, n.name, n.value, n.from
            )
        })
        .collect();
    out.extend(
        f.blocks
            .iter()
            .filter(|(_, block)| !committed.contains(block.as_str()))
            .map(|(what, _)| format!("{}: {what} is stale (made from {})", f.path, f.origin)),
    );
    if out.is_empty() {
        let line = committed
            .lines()
            .zip(fresh.lines())
            .position(|(a, b)| a != b);
        let line = line.unwrap_or(committed.lines().count().min(fresh.lines().count())) + 1;
        out.push(format!(
            "{}: differs from what {} make now, from line {line}",
            f.path, f.origin
        ));
    }
    out
}

fn stale_figure(f: &File, fresh: &[u8]) -> Option<String> {
    let path = root().join(&f.path);
    let Ok(committed) = image::open(&path) else {
        return Some(format!("{}: missing (made by {})", f.path, f.origin));
    };
    let committed = committed.to_rgb8();
    let fresh = image::load_from_memory(fresh)
        .expect("raytree writes PNGs")
        .to_rgb8();
    if committed.dimensions() != fresh.dimensions() {
        return Some(format!(
            "{}: figure is stale: {:?} in the book, {:?} now (made by {})",
            f.path,
            committed.dimensions(),
            fresh.dimensions(),
            f.origin
        ));
    }
    let worst = committed
        .as_raw()
        .iter()
        .zip(fresh.as_raw())
        .map(|(a, b)| a.abs_diff(*b))
        .max()
        .unwrap_or(0);
    (worst > FIGURE_TOLERANCE).then(|| {
        format!(
            "{}: figure is stale: a pixel differs by {worst} of 255 (made by {})",
            f.path, f.origin
        )
    })
}

/// Files in the folders the book owns that nothing made.
fn orphans(files: &[File]) -> Vec<String> {
    let made: BTreeSet<&str> = files.iter().map(|f| f.path.as_str()).collect();
    let mut out = Vec::new();
    for dir in OWNED {
        walk(&root().join(dir), &mut |p| {
            let rel = p.strip_prefix(root()).unwrap().display().to_string();
            if !made.contains(rel.as_str()) {
                out.push(rel);
            }
        });
    }
    out.sort();
    out
}

fn walk(dir: &Path, f: &mut dyn FnMut(&Path)) {
    let Ok(read) = std::fs::read_dir(dir) else {
        return;
    };
    for entry in read.flatten() {
        let p = entry.path();
        if p.is_dir() {
            walk(&p, f);
        } else {
            f(&p);
        }
    }
}

/// Writes every stale file and removes the orphans.
pub fn bless(files: &[File]) {
    for f in files {
        let path = root().join(&f.path);
        let write = match &f.content {
            Content::Text(t) => std::fs::read_to_string(&path).ok().as_deref() != Some(t.as_str()),
            Content::Png(png) => stale_figure(f, png).is_some(),
        };
        if write {
            std::fs::create_dir_all(path.parent().unwrap()).unwrap();
            let bytes = match &f.content {
                Content::Text(t) => t.as_bytes(),
                Content::Png(p) => p.as_slice(),
            };
            std::fs::write(&path, bytes).unwrap();
            println!("wrote {}", f.path);
        }
    }
    for orphan in orphans(files) {
        std::fs::remove_file(root().join(&orphan)).unwrap();
        println!("removed {orphan}");
    }
}
