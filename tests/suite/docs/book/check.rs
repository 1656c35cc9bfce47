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
            Content::Unmade => {}
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
    let around = around_holes(&committed, fresh);
    if around.is_ok() {
        return Vec::new();
    }
    let was = page::quoted(&committed);
    let mut out: Vec<String> = f
        .numbers
        .iter()
        .filter(|n| n.value != page::HOLE && was.get(&n.name) != Some(&n.value))
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
    if let (true, Err((part, rest))) = (out.is_empty(), around)
        && fresh.contains(page::HOLE)
    {
        // The first line of the part that is not where it should be.
        let mut lines = part.lines().filter(|l| !l.trim().is_empty());
        let line = lines
            .clone()
            .find(|l| !rest.contains(l))
            .or(lines.next())
            .unwrap_or("");
        out.push(format!(
            "{}: differs from what {} make now, at {line:?} (the parts not made here aside)",
            f.path, f.origin
        ));
    }
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

/// Whether `committed` is `fresh` with something in place of each
/// [`page::HOLE`] (what this machine could not make); else the first part of
/// `fresh` it does not have where it should, and the rest of `committed`
/// from where that part should be.
fn around_holes<'a, 'b>(committed: &'b str, fresh: &'a str) -> Result<(), (&'a str, &'b str)> {
    let parts: Vec<&str> = fresh.split(page::HOLE).collect();
    let (first, last) = (parts[0], parts[parts.len() - 1]);
    if parts.len() == 1 {
        return if committed == fresh {
            Ok(())
        } else {
            Err((fresh, committed))
        };
    }
    if !committed.starts_with(first) {
        return Err((first, committed));
    }
    let mut at = first.len();
    for part in &parts[1..parts.len() - 1] {
        match committed[at..].find(part) {
            Some(i) => at += i + part.len(),
            None => return Err((part, &committed[at..])),
        }
    }
    if committed.len() - at >= last.len() && committed.ends_with(last) {
        Ok(())
    } else {
        Err((last, &committed[at..]))
    }
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
        // What this machine could not make stays as committed.
        let bytes = match &f.content {
            Content::Text(t) if !t.contains(page::HOLE) => t.as_bytes(),
            Content::Png(p) => p.as_slice(),
            Content::Text(_) | Content::Unmade => continue,
        };
        let write = match &f.content {
            Content::Png(png) => stale_figure(f, png).is_some(),
            _ => std::fs::read(&path).ok().as_deref() != Some(bytes),
        };
        if write {
            std::fs::create_dir_all(path.parent().unwrap()).unwrap();
            std::fs::write(&path, bytes).unwrap();
            println!("wrote {}", f.path);
        }
    }
    for orphan in orphans(files) {
        std::fs::remove_file(root().join(&orphan)).unwrap();
        println!("removed {orphan}");
    }
}
