//! The built book has no broken internal link and no missing image: every
//! relative `href` and `src` in `book/book/*.html` names a file that exists,
//! and every `#anchor` an `id` in it. Needs the built book, so it is ignored
//! by default; CI runs it after `mdbook build book`:
//! `cargo test --release book::links -- --ignored`.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use super::run::root;

fn files_with(dir: &Path, extension: &str, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap().flatten() {
        let p = entry.path();
        if p.is_dir() {
            files_with(&p, extension, out);
        } else if p.extension().is_some_and(|e| e == extension) {
            out.push(p);
        }
    }
}

/// The values of `attr="…"` in `html`.
fn attributes<'a>(html: &'a str, attr: &str) -> Vec<&'a str> {
    let key = format!(" {attr}=\"");
    let mut out = Vec::new();
    let mut rest = html;
    while let Some(i) = rest.find(&key) {
        let tail = &rest[i + key.len()..];
        let end = tail.find('"').unwrap_or(tail.len());
        out.push(&tail[..end]);
        rest = &tail[end..];
    }
    out
}

fn external(link: &str) -> bool {
    link.contains("://")
        || link.starts_with("mailto:")
        || link.starts_with("//")
        || link.starts_with("javascript:")
}

/// Every broken link of the built book, as `page: link (why)`.
fn broken(book: &Path) -> Vec<String> {
    let mut pages = Vec::new();
    files_with(book, "html", &mut pages);
    let texts: BTreeMap<PathBuf, String> = pages
        .iter()
        .map(|p| (p.clone(), std::fs::read_to_string(p).unwrap()))
        .collect();
    let mut out = Vec::new();
    let mut shown = std::collections::BTreeSet::new();
    for (page, html) in &texts {
        let links = attributes(html, "src")
            .into_iter()
            .chain(attributes(html, "href"));
        for src in links.filter(|l| !external(l)) {
            if let Ok(p) = page.parent().unwrap().join(src).canonicalize() {
                shown.insert(p);
            }
        }
    }
    // A figure swallowed by a badly closed code block is no broken link, but
    // it is shown nowhere.
    let mut pngs = Vec::new();
    files_with(book, "png", &mut pngs);
    for png in pngs {
        if !shown.contains(&png.canonicalize().unwrap()) {
            out.push(format!(
                "{}: shown on no page",
                png.strip_prefix(book).unwrap().display()
            ));
        }
    }
    for (page, html) in &texts {
        // The 404 page is served from the site's root, whatever the address.
        if page.file_name().is_some_and(|n| n == "404.html") {
            continue;
        }
        let links = attributes(html, "href")
            .into_iter()
            .chain(attributes(html, "src"));
        for link in links.filter(|l| !l.is_empty() && !external(l)) {
            let (file, anchor) = link.split_once('#').unwrap_or((link, ""));
            let file = file.split('?').next().unwrap_or("");
            let target = if file.is_empty() {
                page.clone()
            } else {
                page.parent().unwrap().join(file)
            };
            let target = if target.is_dir() {
                target.join("index.html")
            } else {
                target
            };
            let name = page.strip_prefix(book).unwrap().display();
            if !target.is_file() {
                out.push(format!("{name}: {link} (no such file)"));
                continue;
            }
            if anchor.is_empty() {
                continue;
            }
            let canonical = target.canonicalize().unwrap();
            let text = texts
                .iter()
                .find(|(p, _)| p.canonicalize().unwrap() == canonical)
                .map(|(_, t)| t);
            if text.is_some_and(|t| !t.contains(&format!("id=\"{anchor}\""))) {
                out.push(format!("{name}: {link} (no id {anchor})"));
            }
        }
    }
    out
}

#[test]
#[ignore = "needs the built book: mdbook build book (CI runs it)"]
fn links_in_the_built_book_resolve() {
    let book = root().join("book/book");
    assert!(
        book.join("index.html").is_file(),
        "build the book first: mdbook build book"
    );
    let broken = broken(&book);
    assert!(
        broken.is_empty(),
        "broken links in the built book:\n{}",
        broken.join("\n")
    );
}

#[test]
fn the_link_check_finds_a_missing_image_and_anchor() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::create_dir(dir.path().join("a")).unwrap();
    std::fs::write(dir.path().join("a/x.png"), "").unwrap();
    std::fs::write(dir.path().join("a/lost.png"), "").unwrap();
    std::fs::write(
        dir.path().join("a/page.html"),
        "<h2 id=\"here\"></h2><img src=\"x.png\"><img src=\"y.png\"><a href=\"#here\"></a>\
         <a href=\"../index.html#gone\"></a><a href=\"https://example.org/\"></a>",
    )
    .unwrap();
    std::fs::write(dir.path().join("index.html"), "<p id=\"top\"></p>").unwrap();
    let found = broken(dir.path());
    assert_eq!(
        found,
        [
            "a/lost.png: shown on no page",
            "a/page.html: ../index.html#gone (no id gone)",
            "a/page.html: y.png (no such file)"
        ]
    );
}
