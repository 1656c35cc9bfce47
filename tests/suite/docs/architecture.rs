//! The shape of the house, checked from the source (see `../shared/DESIGN.md`):
//! folders by role, dependencies pointing one way, views that never run the
//! tracer, a scene model that knows nothing of the command line.
//!
//! Each library file's `crate::…` paths (outside comments and its unit tests)
//! are read and checked against the layers below, lowest first. A file may use
//! its own folder and any folder in a lower layer; `methods.rs` (the catalogue
//! of method choices), `io/` (images and files) and `figure/` (the drawing
//! toolkit) sit outside the layers: anyone may use them, and they use nothing
//! else of the crate. Unit tests are left out because a test may build its
//! input any way it likes (a view's test records the pixel it draws); what
//! ships is the code above them. The files' imports form no circle, in the
//! library or in the binary (`src/bin/raytree/`, a crate of its own rooted in
//! `main.rs`, whose `crate::…` paths are its own modules and `raytree::…` the
//! library's). No file is over 800 lines, and no two files in one folder
//! share a name prefix (`lesson_spec.rs`, `lesson_frame.rs`): those make a
//! folder.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// The folders in layer order: each may use the ones before it.
const LAYERS: &[&str] = &[
    "math",
    "geometry",
    "shading",
    "scene",
    "trace",
    "tree",
    "views",
    "course",
    "inspector",
];

/// Used by anyone, using nothing of the crate.
const FREE: &[&str] = &["methods", "io", "figure"];

/// What runs the tracer: views read the recorded tree instead.
const TRACING: &[&str] = &[
    "crate::tree::record",
    "crate::trace::tracer",
    "crate::trace::accelerator",
    "crate::trace::render",
    "crate::trace::pixel",
    "crate::geometry::structures",
];

/// Crates that own a terminal: progress bars, raw mode, a TUI. The library
/// reports progress through a closure instead.
const TERMINAL: &[&str] = &["indicatif", "crossterm", "ratatui"];

/// The deliberate exceptions, each with its reason.
const EXCEPTIONS: &[(&str, &str, &str)] = &[
    (
        "src/inspector/",
        "crate::trace::",
        "the inspector traces the pixel you pick, and the preview, on demand",
    ),
    (
        "src/inspector/",
        "crate::tree::record",
        "the inspector records the pixel you pick",
    ),
    (
        "src/course/",
        "crate::tree::record",
        "a lesson records the pixel its step-through narrates",
    ),
    (
        "src/scene/overrides.rs",
        "clap",
        "one struct for the scene file's render block and the command-line flags",
    ),
];

fn src() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
}

/// Every source file of the package, library and binary, relative to the
/// package's folder (`src/…`), sorted.
fn source_files() -> Vec<String> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        for entry in std::fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                walk(&path, out);
            } else if path.extension().is_some_and(|e| e == "rs") {
                out.push(path);
            }
        }
    }
    let mut files = Vec::new();
    walk(&src(), &mut files);
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut names: Vec<String> = files
        .iter()
        .map(|p| p.strip_prefix(root).unwrap().display().to_string())
        .collect();
    names.sort();
    names
}

/// Every library source file, relative to the package's folder (`src/…`).
fn library_files() -> Vec<String> {
    (source_files().into_iter())
        .filter(|p| !p.starts_with("src/bin/"))
        .collect()
}

/// Every source file of the `raytree` binary (`src/bin/raytree/…`).
fn binary_files() -> Vec<String> {
    (source_files().into_iter())
        .filter(|p| p.starts_with("src/bin/raytree/"))
        .collect()
}

/// The file's code lines (comments and unit tests dropped), numbered from 1.
fn code_lines(file: &str) -> Vec<(usize, String)> {
    let text = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join(file)).unwrap();
    shipped_lines(&text)
}

/// The lines of `text` before its `#[cfg(test)]` module, comments dropped.
fn shipped_lines(text: &str) -> Vec<(usize, String)> {
    text.lines()
        .enumerate()
        .take_while(|(_, l)| l.trim() != "#[cfg(test)]")
        .filter(|(_, l)| !l.trim_start().starts_with("//"))
        .map(|(i, l)| (i + 1, l.to_owned()))
        .collect()
}

/// The top folder (or file stem) a path of the crate names: `crate::views::text` → `views`.
fn top(path: &str) -> &str {
    path.trim_start_matches("crate::")
        .split("::")
        .next()
        .unwrap_or("")
}

/// Where a library file sits: its folder, or its stem for a top-level file.
fn folder_of(file: &str) -> &str {
    let rest = file.trim_start_matches("src/");
    match rest.split_once('/') {
        Some((folder, _)) => folder,
        None => rest.trim_end_matches(".rs"),
    }
}

/// Every `crate::a::b…` path on a line.
fn crate_paths(line: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut rest = line;
    while let Some(i) = rest.find("crate::") {
        let tail = &rest[i..];
        let end = tail
            .find(|c: char| !(c.is_alphanumeric() || c == '_' || c == ':'))
            .unwrap_or(tail.len());
        out.push(tail[..end].trim_end_matches(':').to_owned());
        rest = &tail[end..];
    }
    out
}

fn excepted(file: &str, what: &str) -> bool {
    EXCEPTIONS
        .iter()
        .any(|(f, w, _)| file.starts_with(f) && what.starts_with(w))
}

/// Every breach of the rules, one line each.
fn breaches() -> Vec<String> {
    library_files()
        .iter()
        .flat_map(|file| breaches_in(file, &code_lines(file)))
        .collect()
}

/// The breaches of the rules on `lines` of library file `file`.
fn breaches_in(file: &str, lines: &[(usize, String)]) -> Vec<String> {
    let rank = |folder: &str| LAYERS.iter().position(|l| *l == folder);
    let above_tree = |folder: &str| rank(folder) > rank("tree");
    let here = folder_of(file);
    let mut out = Vec::new();
    for (n, line) in lines {
        if line.contains("crate::{") {
            out.push(format!(
                "{file}:{n}: write one path per `use` so this test can read it"
            ));
        }
        for path in crate_paths(line) {
            let there = top(&path);
            if there == here || excepted(file, &path) {
                continue;
            }
            if FREE.contains(&here) {
                out.push(format!(
                    "{file}:{n}: {here} uses nothing of the crate, but names {path}"
                ));
            } else if FREE.contains(&there) || there.is_empty() || there == "record" {
                // `crate::record!` is the recorder's hook macro, exported at the root.
            } else if above_tree(here) && TRACING.iter().any(|t| path.starts_with(t)) {
                out.push(format!(
                    "{file}:{n}: {here} runs the tracer ({path}); views read the recorded tree"
                ));
            } else if rank(there).is_none() || rank(there) > rank(here) {
                out.push(format!(
                    "{file}:{n}: {here} uses {path}, a layer above it ({})",
                    LAYERS.join(" < ")
                ));
            }
        }
        for tool in ["clap", "indicatif"] {
            if here == "scene" && names_crate(line, tool) && !excepted(file, tool) {
                out.push(format!(
                    "{file}:{n}: the scene model names {tool}; it knows nothing of the command line"
                ));
            }
        }
        for tool in TERMINAL {
            if here != "inspector" && names_crate(line, tool) {
                out.push(format!(
                    "{file}:{n}: {tool} below the binary; only the inspector and the binary own a terminal"
                ));
            }
        }
    }
    out
}

/// Whether `line` names the external crate `tool`.
fn names_crate(line: &str, tool: &str) -> bool {
    line.contains(&format!("{tool}::")) || line.contains(&format!("use {tool}"))
}

#[test]
fn dependencies_point_one_way() {
    let found = breaches();
    assert!(
        found.is_empty(),
        "the layers are broken:\n{}",
        found.join("\n")
    );
}

#[test]
fn the_checker_sees_a_breach() {
    // The rules themselves, on made-up lines, so a checker that reads nothing fails here.
    assert_eq!(
        crate_paths("use crate::trace::tracer::Tracer; let x = crate::views::text::format(a);"),
        ["crate::trace::tracer::Tracer", "crate::views::text::format"]
    );
    assert_eq!(folder_of("src/views/text.rs"), "views");
    assert_eq!(folder_of("src/methods.rs"), "methods");
    assert!(excepted(
        "src/inspector/state/preview.rs",
        "crate::trace::tracer::Tracer"
    ));
    assert!(!excepted(
        "src/views/text.rs",
        "crate::trace::tracer::Tracer"
    ));
    assert!(library_files().len() > 40, "{:?}", library_files());
    assert!(binary_files().len() > 10, "{:?}", binary_files());
}

#[test]
fn src_shows_the_architecture() {
    // `ls src`: the folders by role, the catalogue of methods, the crate root, the binary.
    let mut top: Vec<String> = std::fs::read_dir(src())
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    top.sort();
    let mut expected: Vec<String> = LAYERS
        .iter()
        .chain(FREE.iter().filter(|f| **f != "methods"))
        .map(|s| s.to_string())
        .chain(["bin", "lib.rs", "methods.rs"].map(String::from))
        .collect();
    expected.sort();
    assert_eq!(top, expected);
}

/// Files of one concept, with a backstop: none over 800 lines, the library's
/// or the binary's.
#[test]
fn no_source_file_is_over_800_lines() {
    for file in source_files() {
        let lines = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join(&file))
            .unwrap()
            .lines()
            .count();
        assert!(
            lines <= 800,
            "{file} has {lines} lines; find the concepts it holds and give each a file"
        );
    }
}

#[test]
fn the_rules_catch_a_view_that_records_and_a_toolkit_that_reaches_in() {
    let line = |text: &str| vec![(7, text.to_owned())];
    let view = breaches_in(
        "src/views/text.rs",
        &line("let trace = crate::tree::record::pixel(&scene, 1, 2);"),
    );
    assert_eq!(
        view,
        [
            "src/views/text.rs:7: views runs the tracer (crate::tree::record::pixel); views read the recorded tree"
        ]
    );
    let figure = breaches_in(
        "src/figure/canvas.rs",
        &line("use crate::views::numbers::num;"),
    );
    assert_eq!(
        figure,
        [
            "src/figure/canvas.rs:7: figure uses nothing of the crate, but names crate::views::numbers::num"
        ]
    );
    let course = breaches_in("src/course/lesson.rs", &line("use crate::tree::record;"));
    assert!(course.is_empty(), "{course:?}");
    let progress = breaches_in("src/trace/render.rs", &line("use indicatif::ProgressBar;"));
    assert_eq!(progress.len(), 1, "{progress:?}");
    // A unit test below `#[cfg(test)]` may record what it checks.
    let shipped =
        shipped_lines("use a;\n// b\n#[cfg(test)]\nmod tests {\n    use crate::tree::record;\n}\n");
    assert_eq!(shipped, [(1, "use a;".to_owned())]);
}

/// The folder a source file's crate is rooted in: `src/bin/NAME/` for the
/// binary NAME (its root `main.rs`), `src/` for the library (`lib.rs`).
fn crate_root(file: &str) -> &str {
    match file
        .strip_prefix("src/bin/")
        .and_then(|rest| rest.split_once('/'))
    {
        Some((name, _)) => &file[.."src/bin/".len() + name.len() + 1],
        None => "src/",
    }
}

/// The module a source file is, in its own crate: `src/a/b.rs` → `[a, b]`,
/// `src/a/mod.rs` → `[a]`, `src/lib.rs` → `[]`; `src/bin/raytree/aov.rs` →
/// `[aov]`, `src/bin/raytree/main.rs` → `[]`.
fn module_of(file: &str) -> Vec<String> {
    let rest = file
        .strip_prefix(crate_root(file))
        .unwrap_or(file)
        .trim_end_matches(".rs");
    let mut parts: Vec<String> = rest.split('/').map(str::to_owned).collect();
    let root = parts.len() == 1 && matches!(parts[0].as_str(), "lib" | "main");
    if root || parts.last().is_some_and(|p| p == "mod") {
        parts.pop();
    }
    parts
}

/// The files of its crate `file` imports from: every `crate::…`, `super::…`
/// and `self::…` path (and each item of a `{…}` list after one) resolved to
/// the longest prefix that is a file of the crate. A crate's root names its
/// modules without `crate::` (`main.rs` dispatches to every command's file):
/// [`add_root_edges`] adds its part.
fn imports(file: &str, lines: &[(usize, String)], modules: &[Vec<String>]) -> Vec<Vec<String>> {
    let me = module_of(file);
    let is_mod = me.is_empty() || file.ends_with("mod.rs");
    let parent: Vec<String> = if is_mod {
        me.clone()
    } else {
        me[..me.len() - 1].to_vec()
    };
    let mut found: Vec<Vec<String>> = Vec::new();
    for (_, line) in lines {
        for (k, _) in line
            .match_indices("crate::")
            .chain(line.match_indices("super::"))
        {
            if k > 0 && line[..k].ends_with(|c: char| c.is_alphanumeric() || c == '_' || c == ':') {
                continue;
            }
            let tail = &line[k..];
            let end = tail
                .find(|c: char| !(c.is_alphanumeric() || c == '_' || c == ':'))
                .unwrap_or(tail.len());
            let mut segments: Vec<&str> =
                tail[..end].split("::").filter(|s| !s.is_empty()).collect();
            let mut base = if segments[0] == "crate" {
                Vec::new()
            } else {
                parent.clone()
            };
            segments.remove(0);
            while segments.first() == Some(&"super") {
                base.pop();
                segments.remove(0);
            }
            let path: Vec<String> = base
                .into_iter()
                .chain(segments.iter().map(|s| s.to_string()))
                .collect();
            let mut candidates = vec![path.clone()];
            if tail[end..].starts_with('{') {
                let list = &tail[end + 1..tail.find('}').unwrap_or(tail.len())];
                for item in list
                    .split(',')
                    .map(|i| i.split(" as ").next().unwrap().trim())
                {
                    if !item.is_empty() && item != "self" {
                        candidates.push(
                            path.iter()
                                .cloned()
                                .chain(item.split("::").map(str::to_owned))
                                .collect(),
                        );
                    }
                }
            }
            for c in candidates {
                let longest = (1..=c.len())
                    .rev()
                    .map(|n| &c[..n])
                    .find(|p| modules.iter().any(|m| m == p));
                if let Some(m) = longest
                    && m != me.as_slice()
                    && !found.iter().any(|f| f == m)
                {
                    found.push(m.to_vec());
                }
            }
        }
    }
    found
}

/// The crate root's part in the graph: it uses every module it declares
/// (`mod x;`, then `x::run(…)` without `crate::`), and a file that names an
/// item the root itself defines (`crate::parse_words`, a `fn`, `struct`,
/// `enum`, `const` or `static` of the root's) uses the root: a circle, since
/// the root reaches that file.
fn add_root_edges(
    files: &[(String, Vec<(usize, String)>)],
    modules: &[Vec<String>],
    edges: &mut [Vec<usize>],
) {
    let Some(root) = modules.iter().position(Vec::is_empty) else {
        return;
    };
    let declared = |line: &str, keyword: &str| {
        let rest = line.trim_start().trim_start_matches("pub ").trim_start();
        let rest = rest.strip_prefix(keyword)?.strip_prefix(' ')?;
        let end = rest.find(|c: char| !(c.is_alphanumeric() || c == '_'))?;
        Some(rest[..end].to_owned())
    };
    let root_lines = &files[root].1;
    for (_, line) in root_lines {
        if let Some(name) = declared(line, "mod") {
            let declared_module = modules.iter().position(|m| *m == [name.clone()]);
            edges[root].extend(declared_module);
        }
    }
    let items: Vec<String> = (root_lines.iter())
        .flat_map(|(_, l)| ["fn", "struct", "enum", "const", "static"].map(|k| declared(l, k)))
        .flatten()
        .collect();
    for (i, (_, lines)) in files.iter().enumerate() {
        let names_root_item = |line: &String| {
            crate_paths(line).iter().any(|path| {
                let first = path.trim_start_matches("crate::").split("::").next();
                first.is_some_and(|f| items.iter().any(|item| item == f))
            })
        };
        if i != root && lines.iter().any(|(_, l)| names_root_item(l)) {
            edges[i].push(root);
        }
    }
}

/// The circles of one crate's import graph, `files` with their code lines:
/// each strongly connected set of files larger than one, as `a ↔ b ↔ …`.
fn circles_among(files: &[(String, Vec<(usize, String)>)]) -> Vec<String> {
    let modules: Vec<Vec<String>> = files.iter().map(|(f, _)| module_of(f)).collect();
    let mut edges: Vec<Vec<usize>> = files
        .iter()
        .map(|(f, lines)| {
            imports(f, lines, &modules)
                .iter()
                .filter_map(|m| modules.iter().position(|x| x == m))
                .collect()
        })
        .collect();
    add_root_edges(files, &modules, &mut edges);
    // Which files each file reaches (a few hundred files: a walk from each is plenty fast).
    let reach = |from: usize| {
        let mut seen = vec![false; files.len()];
        let mut stack = edges[from].clone();
        while let Some(v) = stack.pop() {
            if !std::mem::replace(&mut seen[v], true) {
                stack.extend(&edges[v]);
            }
        }
        seen
    };
    let reached: Vec<Vec<bool>> = (0..files.len()).map(reach).collect();
    let mut out = Vec::new();
    let mut done = vec![false; files.len()];
    for a in 0..files.len() {
        if done[a] || !reached[a][a] {
            continue;
        }
        let set: Vec<usize> = (0..files.len())
            .filter(|&b| reached[a][b] && reached[b][a])
            .collect();
        for &b in &set {
            done[b] = true;
        }
        out.push(
            set.iter()
                .map(|&b| files[b].0.as_str())
                .collect::<Vec<_>>()
                .join(" ↔ "),
        );
    }
    out
}

/// The circles of the library's imports, then of the binary's.
fn circles() -> Vec<String> {
    let read = |files: Vec<String>| -> Vec<(String, Vec<(usize, String)>)> {
        (files.into_iter())
            .map(|f| {
                let lines = code_lines(&f);
                (f, lines)
            })
            .collect()
    };
    let mut found = circles_among(&read(library_files()));
    found.extend(circles_among(&read(binary_files())));
    found
}

#[test]
fn no_file_imports_itself_through_others() {
    let found = circles();
    assert!(
        found.is_empty(),
        "these files import each other (cut the circle: move the shared part into a file both use):\n{}",
        found.join("\n")
    );
}

#[test]
fn the_circle_finder_resolves_paths() {
    let modules: Vec<Vec<String>> = [
        "views/diagram/layout",
        "views/diagram/style",
        "views/diagram",
        "figure/pen",
        "tree/steps",
    ]
    .iter()
    .map(|m| m.split('/').map(str::to_owned).collect())
    .collect();
    let lines = vec![
        (
            1,
            "use crate::views::diagram::style::{Scale, pale};".to_owned(),
        ),
        (2, "use super::layout::Layout;".to_owned()),
        (
            3,
            "use crate::figure::{pen::Pen, canvas::Figure};".to_owned(),
        ),
        (4, "let s = crate::tree::steps::steps(&t);".to_owned()),
    ];
    let found = imports("src/views/diagram/draw.rs", &lines, &modules);
    let names: Vec<String> = found.iter().map(|m| m.join("/")).collect();
    assert_eq!(
        names,
        [
            "views/diagram/style",
            "views/diagram/layout",
            "figure/pen",
            "tree/steps"
        ]
    );
}

/// Made-up files of the binary: `crate::` is the binary's own root, and
/// `raytree::` the library, which never leads back.
#[test]
fn the_circle_finder_reads_the_binary() {
    let file = |name: &str, lines: &[&str]| {
        let lines = (lines.iter().enumerate())
            .map(|(i, l)| (i + 1, (*l).to_owned()))
            .collect::<Vec<_>>();
        (format!("src/bin/raytree/{name}.rs"), lines)
    };
    assert_eq!(module_of("src/bin/raytree/aov.rs"), ["aov"]);
    assert!(module_of("src/bin/raytree/main.rs").is_empty());
    let main = file(
        "main",
        &["mod aov;", "mod render;", "let r = render::run(&a);"],
    );
    let args = file("args", &["use raytree::scene::Scene;"]);
    let render = file(
        "render",
        &[
            "use crate::args::thread_pool;",
            "return crate::aov::run(args, name);",
        ],
    );
    let aov = file(
        "aov",
        &[
            "use crate::render::{Args, thread_pool};",
            "use raytree::trace::aov::Aov;",
        ],
    );
    let circle = [main.clone(), args.clone(), render.clone(), aov.clone()];
    assert_eq!(
        circles_among(&circle),
        ["src/bin/raytree/render.rs ↔ src/bin/raytree/aov.rs"]
    );
    // Cut as the binary cuts it: the pool in args.rs, the dispatch in main.rs.
    let render = file("render", &["use crate::args::thread_pool;"]);
    let aov = file(
        "aov",
        &["use crate::args::thread_pool;", "use crate::render::Args;"],
    );
    assert!(circles_among(&[main.clone(), args, render, aov]).is_empty());
    // A command that calls back into an item of the root (which dispatches
    // to it) is a circle with the root; naming a module through `crate::`
    // is not.
    let main = file(
        "main",
        &[
            "mod lesson;",
            "fn parse_words(w: &[String]) {}",
            "lesson::run(&a);",
        ],
    );
    let lesson = file("lesson", &["crate::parse_words(&words);"]);
    assert_eq!(
        circles_among(&[main.clone(), lesson]),
        ["src/bin/raytree/main.rs ↔ src/bin/raytree/lesson.rs"]
    );
    let lesson = file(
        "lesson",
        &["(read.check)(&words); crate::output::print(t);"],
    );
    assert!(circles_among(&[main, lesson]).is_empty());
}

/// The groups of two or more files in one folder whose stems share a
/// `word_` prefix (the stem up to its first `_`: `lesson_spec.rs` and
/// `lesson_frame.rs` share `lesson_`), one line each. Only stems with a `_`
/// count: `polygon.rs` beside `polygon_plane.rs` shares nothing.
fn shared_prefixes(files: &[String]) -> Vec<String> {
    let mut groups: BTreeMap<(&str, &str), Vec<&str>> = BTreeMap::new();
    for file in files {
        let (folder, name) = file.rsplit_once('/').unwrap_or(("", file));
        let stem = name.strip_suffix(".rs").unwrap_or(name);
        if let Some((word, _)) = stem.split_once('_') {
            groups.entry((folder, word)).or_default().push(name);
        }
    }
    (groups.into_iter())
        .filter(|(_, names)| names.len() > 1)
        .map(|((folder, word), names)| {
            format!(
                "{folder}/: {} share the prefix `{word}_`: make a folder `{word}/`",
                names.join(", ")
            )
        })
        .collect()
}

#[test]
fn the_prefix_rule_catches_files_that_share_a_prefix() {
    let files = [
        "src/course/lesson.rs",
        "src/course/lesson_frame.rs",
        "src/course/lesson_spec.rs",
        "src/course/spec_file.rs",
        "src/geometry/polygon.rs",
        "src/geometry/polygon_plane.rs",
        "src/geometry/walk_tests.rs",
        "src/views/lesson_view.rs",
        "src/bin/raytree/image_out.rs",
        "src/bin/raytree/image_in.rs",
    ]
    .map(str::to_owned);
    assert_eq!(
        shared_prefixes(&files),
        [
            "src/bin/raytree/: image_out.rs, image_in.rs share the prefix `image_`: make a folder `image/`",
            "src/course/: lesson_frame.rs, lesson_spec.rs share the prefix `lesson_`: make a folder `lesson/`",
        ]
    );
}

#[test]
fn no_two_files_in_a_folder_share_a_prefix() {
    let found = shared_prefixes(&source_files());
    assert!(
        found.is_empty(),
        "files named as parts of one thing:\n{}",
        found.join("\n")
    );
}

#[test]
fn the_map_names_every_folder_of_src() {
    let map =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("ARCHITECTURE.md"))
            .expect("ARCHITECTURE.md, the map of the house");
    let mut folders: Vec<String> = source_files()
        .iter()
        .filter_map(|f| {
            f.strip_prefix("src/")?
                .rsplit_once('/')
                .map(|(d, _)| format!("{d}/"))
        })
        .collect();
    folders.sort();
    folders.dedup();
    assert!(folders.len() >= 12, "{folders:?}");
    let missing: Vec<&String> = folders
        .iter()
        .filter(|d| !map.contains(&format!("`{d}`")))
        .collect();
    assert!(
        missing.is_empty(),
        "ARCHITECTURE.md does not name {missing:?}"
    );
}
