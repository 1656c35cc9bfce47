//! The fuzzer's mutations, chosen from random bytes through `arbitrary`: a
//! JSON value swapped for an edge case, a key dropped, duplicated or
//! unknown, an object written as an array, text damaged where JSON cannot
//! say it; and for the line formats (OBJ, NFF, CSV) lines dropped, repeated,
//! swapped or cut, words swapped for each format's edge cases.

use arbitrary::Unstructured;
use serde_json::{Value, json};

/// The line-level edge cases for the structures CSV: fields and lines that
/// are almost right.
const CSV_EDITS: LineEdits = LineEdits {
    empty: "# x",
    words: &[
        "", "nan", "-1", "1e999", "grid", "auto", "0", "161", "\"", "a,b",
    ],
    lines: &[
        "",
        "# comment",
        "a.json,grid,auto,1x1x1,1,1,0,0,0,0,0,0,0",
        "a.json,bvh,,,1,0,0,0,0,0,0,0,0",
        "\"unclosed,bvh",
    ],
    tail: ",",
};

/// Values that test the edges of every range.
fn edge_value(u: &mut Unstructured, doc: &Value) -> arbitrary::Result<Value> {
    Ok(match u.int_in_range(0..=13)? {
        0 => Value::Null,
        1 => json!(u.arbitrary::<bool>()?),
        2 => json!(*u.choose(&[
            0.0, -0.0, -1.0, 0.5, 1.0, 2.0, 3.0, 9.0, 1024.0, 1025.0, 1000.0, 1001.0, 32768.0
        ])?),
        3 => json!(*u.choose(&[
            1e308, -1e308, 5e-324, 1e-300, 1e9, 2e9, -1e9, 1e-9, 1e-10, 1e6, 1e7, 1e12, 1e13
        ])?),
        4 => json!(*u.choose(&[u64::MAX, u64::from(u32::MAX), 4_294_967_296, 1 << 53])?),
        5 => json!(*u.choose(&[i64::MIN, -1, -2_147_483_649])?),
        6 => json!(
            u.arbitrary::<f64>()
                .ok()
                .filter(|x| x.is_finite())
                .unwrap_or(0.0)
        ),
        7 => json!([
            u.arbitrary::<i8>()?,
            u.arbitrary::<i8>()?,
            u.arbitrary::<i8>()?
        ]),
        8 => json!([]),
        9 => json!({}),
        10 => json!(*u.choose(&[
            "",
            "sphere",
            "glass",
            "default",
            "fresnel",
            "epsilon=-1",
            "adaptive=nan",
            "x\u{1b}[2J",
            "a\nb",
            "\u{7f}",
            "é",
            "m.obj",
            "n.obj",
            "/dev/zero",
            "..",
            "none.obj"
        ])?),
        11 => json!(u.arbitrary::<String>()?),
        12 => any_node(u, doc)?.clone(),
        _ => json!(u.int_in_range(0..=20)?),
    })
}

/// A node of `doc` at random (the root included).
fn any_node<'v>(u: &mut Unstructured, doc: &'v Value) -> arbitrary::Result<&'v Value> {
    let mut at = doc;
    while u.ratio(3, 4)? {
        at = match at {
            Value::Array(a) if !a.is_empty() => u.choose(a)?,
            Value::Object(m) if !m.is_empty() => {
                let keys: Vec<&String> = m.keys().collect();
                &m[*u.choose(&keys)?]
            }
            _ => break,
        };
    }
    Ok(at)
}

/// One structural mutation somewhere in `doc`.
fn mutate_json(u: &mut Unstructured, doc: &mut Value) -> arbitrary::Result<()> {
    let replacement = edge_value(u, doc)?;
    // Walk down to a node, noting its JSON pointer, then take it mutably.
    let mut pointer = String::new();
    let mut here: &Value = doc;
    while u.ratio(4, 5)? {
        here = match here {
            Value::Array(a) if !a.is_empty() => {
                let i = u.choose_index(a.len())?;
                pointer.push_str(&format!("/{i}"));
                &a[i]
            }
            Value::Object(m) if !m.is_empty() => {
                let keys: Vec<&String> = m.keys().collect();
                let k = *u.choose(&keys)?;
                pointer.push_str(&format!("/{}", k.replace('~', "~0").replace('/', "~1")));
                &m[k]
            }
            _ => break,
        };
    }
    let Some(at) = doc.pointer_mut(&pointer) else {
        return Ok(());
    };
    match (u.int_in_range(0..=7)?, &mut *at) {
        (0, Value::Object(m)) if !m.is_empty() => {
            let keys: Vec<String> = m.keys().cloned().collect();
            m.remove(u.choose(&keys)?);
        }
        (1, Value::Object(m)) => {
            let key = u.choose(&[
                "name",
                "radius",
                "unknown",
                "sphere",
                "plane",
                "mesh",
                "transform",
                "ior",
            ])?;
            m.insert((*key).to_owned(), replacement);
        }
        (2, Value::Object(m)) => *at = Value::Array(m.values().cloned().collect()),
        (3, Value::Array(a)) if !a.is_empty() => {
            let i = u.choose_index(a.len())?;
            if u.arbitrary()? {
                a.remove(i);
            } else {
                let copy = a[i].clone();
                a.push(copy);
            }
        }
        (4, Value::Number(n)) => {
            let x = n.as_f64().unwrap_or(0.0);
            let f = *u.choose(&[-1.0, 0.0, 2.0, 1e10, 1e-10, 1.000_000_1])?;
            *at = json!(if f == 0.0 { x + 1.0 } else { x * f });
        }
        (5, Value::Number(n)) => {
            let x = n.as_u64().unwrap_or(0);
            *at = json!(x + u.int_in_range(1..=3)?);
        }
        _ => *at = replacement,
    }
    Ok(())
}

/// Text-level damage JSON values cannot express: a key written twice, a cut,
/// a stray byte.
fn damage_text(u: &mut Unstructured, text: &mut String) -> arbitrary::Result<()> {
    match u.int_in_range(0..=9)? {
        0 => {
            if let Some(i) = text.find('{') {
                let key =
                    u.choose(&["\"name\": \"x\", ", "\"radius\": 1, ", "\"objects\": [], "])?;
                if text[i + 1..].trim_start().starts_with('"') {
                    text.insert_str(i + 1, key);
                }
            }
        }
        1 => {
            let cut = u.choose_index(text.len().max(1))?;
            let cut = (0..=cut)
                .rev()
                .find(|&c| text.is_char_boundary(c))
                .unwrap_or(0);
            text.truncate(cut);
        }
        2 => {
            let at = u.choose_index(text.len().max(1))?;
            let at = (0..=at)
                .rev()
                .find(|&c| text.is_char_boundary(c))
                .unwrap_or(0);
            let c = *u.choose(&['{', '}', '[', ']', ',', ':', '"', '\\', '\u{1b}', '\0'])?;
            text.insert(at, c);
        }
        _ => {}
    }
    Ok(())
}

/// What a line-level mutator may put in: a line for an emptied file, words
/// to swap in, whole lines to swap in, and a word to append.
pub(super) struct LineEdits {
    empty: &'static str,
    words: &'static [&'static str],
    lines: &'static [&'static str],
    tail: &'static str,
}

pub(super) const OBJ_EDITS: LineEdits = LineEdits {
    empty: "f 1 2 3",
    words: &[
        "0",
        "-1",
        "-9",
        "99",
        "1e308",
        "nan",
        "inf",
        "-inf",
        "2e9",
        "1/",
        "//",
        "1//9",
        "x",
        "",
        "4294967296",
        "-2147483649",
    ],
    lines: &[
        "f 1",
        "f 1 2",
        "f 1 1 1",
        "v 1",
        "vn 0 0 0",
        "vt",
        "l 1 2",
        "p 1",
        "mtllib x.mtl",
        "usemtl red",
        "o",
        "g",
        "s off",
    ],
    tail: " 1e-300",
};

/// NFF's: entities with wrong counts, degenerate shapes, huge vertex counts.
pub(super) const NFF_EDITS: LineEdits = LineEdits {
    empty: "s 0 0 0 1",
    words: &[
        "0",
        "-1",
        "1",
        "2",
        "3",
        "1e308",
        "nan",
        "NaN",
        "inf",
        "-inf",
        "2e9",
        "1e-300",
        "x",
        "",
        "4294967296",
        "99999999",
        "0.5",
        "-0",
    ],
    lines: &[
        "p 2",
        "p 3",
        "p 1000000000",
        "pp 3",
        "p 3\n0 0 0\n1 1 1\n2 2 2",
        "p 3\n0 0 0\n0 0 0\n1 0 0",
        "c\n0 0 0 0\n0 0 1 0",
        "c\n0 0 0 1\n0 0 0 1",
        "c\n0 0 0 -1\n0 0 1 1",
        "s 0 0 0 0",
        "s 0 0 0 -1",
        "f 1 1 1 1 0.6 10 0.6 1.5",
        "f 1 1 1 1 0 10 0.5 0",
        "v",
        "b 1 1",
        "l 1 2",
        "up 0 0 0",
        "angle 180",
        "resolution 0 4",
        "# comment",
        "q 1 2 3",
    ],
    tail: " 1",
};

/// A seed of a line-based format (OBJ, NFF) with a few line-level
/// mutations: lines dropped, repeated, swapped or cut short, words and lines
/// swapped for `edits`' edge cases, and now and then a byte that is not UTF-8.
pub(super) fn mutate_lines(
    u: &mut Unstructured,
    text: &str,
    edits: &LineEdits,
) -> arbitrary::Result<Vec<u8>> {
    let mut lines: Vec<String> = text.lines().map(str::to_owned).collect();
    for _ in 0..u.int_in_range(1..=4)? {
        if lines.is_empty() {
            lines.push(edits.empty.to_owned());
        }
        let i = u.choose_index(lines.len())?;
        match u.int_in_range(0..=7)? {
            0 => {
                lines.remove(i);
            }
            1 => lines.insert(i, lines[i].clone()),
            2 => {
                let mut words: Vec<String> = lines[i].split(' ').map(str::to_owned).collect();
                let w = u.choose_index(words.len())?;
                words[w] = (*u.choose(edits.words)?).to_owned();
                lines[i] = words.join(" ");
            }
            3 => lines[i] = (*u.choose(edits.lines)?).to_owned(),
            4 => {
                let j = u.choose_index(lines.len())?;
                lines.swap(i, j);
            }
            5 => lines[i] = u.arbitrary::<String>()?,
            6 => lines.truncate(i),
            _ => lines[i].push_str(edits.tail),
        }
    }
    let mut bytes = lines.join("\n").into_bytes();
    if u.ratio(1, 20)? {
        let at = u.choose_index(bytes.len().max(1))?.min(bytes.len());
        bytes.insert(at, 0xff);
    }
    Ok(bytes)
}

/// A structures CSV seed with line and word mutations, as text.
pub(super) fn mutated_csv(u: &mut Unstructured, seeds: &[String]) -> String {
    let seed = u.choose(seeds).map_or("", String::as_str);
    let bytes = mutate_lines(u, seed, &CSV_EDITS).unwrap_or_default();
    String::from_utf8_lossy(&bytes).into_owned()
}

/// A seed with 1 to 4 mutations, as text, maybe damaged.
pub(super) fn mutated(u: &mut Unstructured, seeds: &[Value]) -> String {
    let mut doc = u.choose(seeds).cloned().unwrap_or(Value::Null);
    let n = u.int_in_range(1..=4).unwrap_or(1);
    for _ in 0..n {
        let _ = mutate_json(u, &mut doc);
    }
    let mut text = serde_json::to_string_pretty(&doc).unwrap();
    let _ = damage_text(u, &mut text);
    text
}
