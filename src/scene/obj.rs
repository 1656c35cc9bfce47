//! Wavefront OBJ meshes, read by `tobj`. Only geometry is used: positions,
//! optional vertex normals, and faces (polygons are split into triangles);
//! materials come from the scene file, so `mtllib` and `usemtl` are ignored.
//!
//! Errors are one line naming the file and, where there is one, the line.

use std::io::{BufRead, Read};
use std::path::Path;

use glam::DVec3;

use crate::geometry::mesh::Mesh;
use crate::io::headroom;
use crate::io::input::{self, MAX_INPUT_BYTES};
use crate::scene::limits::MAX_COORDINATE;

/// Why an OBJ file could not be used.
#[derive(Debug, thiserror::Error)]
#[error("{file}{}: {message}", line.map(|l| format!(":{l}")).unwrap_or_default())]
pub struct ObjError {
    /// The file.
    pub file: String,
    /// 1-based line, when the problem is on one.
    pub line: Option<usize>,
    /// What is wrong.
    pub message: String,
}

/// Reads the OBJ file at `path` (a regular file of at most
/// [`MAX_INPUT_BYTES`], checked before reading, and text: a binary file is
/// refused from its first bytes); `smooth` keeps its vertex normals, if any.
pub fn load(path: &Path, smooth: bool) -> Result<Mesh, ObjError> {
    let file = path.display().to_string();
    let error = |message| ObjError {
        file: file.clone(),
        line: None,
        message,
    };
    let text = input::read_text(path, MAX_INPUT_BYTES).map_err(error)?;
    headroom::check(headroom::obj_need(text.as_bytes()), headroom::available()).map_err(error)?;
    parse(text.as_bytes(), &file, smooth)
}

/// Parses OBJ text; `file` names it in errors.
pub fn parse(bytes: &[u8], file: &str, smooth: bool) -> Result<Mesh, ObjError> {
    let error = |line: Option<usize>, message: String| ObjError {
        file: file.to_owned(),
        line,
        message,
    };
    if let Some(not_text) = input::not_text(bytes) {
        return Err(error(None, not_text.to_string()));
    }
    // tobj stops at the first line it cannot parse, but takes faces it drops
    // or cannot use and finds a bad index only where a group ends: the faces
    // are checked here, and the first problem in the file is the one named.
    let face = first_bad_face(bytes);
    let models = match read_models(bytes) {
        Err((line, _)) if face.as_ref().is_some_and(|f| f.0 <= line) => None,
        Err((line, message)) => return Err(error(Some(line), message)),
        Ok(models) => Some(models),
    };
    let coordinate = first_out_of_range(bytes).map(|line| {
        let message = format!("a coordinate is not a finite number within ±{MAX_COORDINATE:e}");
        (line, message)
    });
    let first = [face, coordinate].into_iter().flatten().min_by_key(|p| p.0);
    if let Some((line, message)) = first {
        return Err(error(Some(line), message));
    }
    let mesh = join_models(&models.unwrap_or_default(), smooth);
    if mesh.faces.is_empty() {
        return Err(error(None, "has no faces (no `f` lines)".to_owned()));
    }
    Ok(mesh)
}

fn lines_in(bytes: &[u8]) -> usize {
    bytes.iter().filter(|&&b| b == b'\n').count()
}

/// tobj's models (polygons split into triangles, points and lines dropped), or
/// the line tobj stopped at and what it said.
fn read_models(bytes: &[u8]) -> Result<Vec<tobj::Model>, (usize, String)> {
    let options = tobj::LoadOptions {
        triangulate: true,
        ignore_points: true,
        ignore_lines: true,
        ..tobj::LoadOptions::default()
    };
    let mut reader = Lines { bytes, pos: 0 };
    let loaded = tobj::load_obj_buf(&mut reader, &options, |_| {
        Ok((Vec::new(), Default::default()))
    });
    loaded
        .map(|(models, _)| models)
        .map_err(|e| (lines_in(&bytes[..reader.pos]).max(1), e.to_string()))
}

/// All models as one mesh; with `smooth`, its vertex normals (unit length) when
/// every face has them.
fn join_models(models: &[tobj::Model], smooth: bool) -> Mesh {
    let mut positions = Vec::new();
    let mut normals = Vec::new();
    let mut faces = Vec::new();
    let mut face_normals = Vec::new();
    let with_normals = smooth
        && models.iter().all(|m| {
            !m.mesh.normals.is_empty() && m.mesh.normal_indices.len() == m.mesh.indices.len()
        });
    let vec3 = |p: &[f64]| DVec3::new(p[0], p[1], p[2]);
    for model in models {
        let m = &model.mesh;
        let base = positions.len() as u32;
        let nbase = normals.len() as u32;
        positions.extend(m.positions.chunks_exact(3).map(vec3));
        faces.extend(
            m.indices
                .chunks_exact(3)
                .map(|f| [base + f[0], base + f[1], base + f[2]]),
        );
        if with_normals {
            normals.extend(
                m.normals
                    .chunks_exact(3)
                    .map(|n| vec3(n).try_normalize().unwrap_or(DVec3::ZERO)),
            );
            face_normals.extend(
                m.normal_indices
                    .chunks_exact(3)
                    .map(|f| [nbase + f[0], nbase + f[1], nbase + f[2]]),
            );
        }
    }
    Mesh::new(positions, normals, faces, face_normals)
}

/// The text as a reader that knows how far tobj has read.
struct Lines<'a> {
    bytes: &'a [u8],
    pos: usize,
}

impl Read for Lines<'_> {
    fn read(&mut self, out: &mut [u8]) -> std::io::Result<usize> {
        let n = out.len().min(self.bytes.len() - self.pos);
        out[..n].copy_from_slice(&self.bytes[self.pos..self.pos + n]);
        self.pos += n;
        Ok(n)
    }
}

impl BufRead for Lines<'_> {
    fn fill_buf(&mut self) -> std::io::Result<&[u8]> {
        Ok(&self.bytes[self.pos..])
    }

    fn consume(&mut self, amt: usize) {
        self.pos += amt;
    }
}

/// The keyword and fields of each line, numbered from 1.
fn statements(bytes: &[u8]) -> impl Iterator<Item = (usize, &str, Vec<&str>)> {
    let text = std::str::from_utf8(bytes).unwrap_or_default();
    text.lines().enumerate().filter_map(|(i, line)| {
        let mut words = line.split_whitespace();
        words.next().map(|key| (i + 1, key, words.collect()))
    })
}

/// The first `v` or `vn` line with a coordinate that is NaN, infinite or
/// beyond the scene's coordinate limit.
fn first_out_of_range(bytes: &[u8]) -> Option<usize> {
    statements(bytes).find_map(|(line, key, fields)| {
        let bad = matches!(key, "v" | "vn")
            && fields.iter().any(|f| {
                f.parse::<f64>()
                    .is_ok_and(|x| x.is_nan() || x.abs() > MAX_COORDINATE)
            });
        bad.then_some(line)
    })
}

/// The first face raytree cannot use, and why: one of fewer than 3
/// vertices (tobj would drop it, or stop at the end of the file), or one that
/// names a vertex, texture coordinate or normal the file does not define
/// (tobj checks a texture coordinate or a normal only if the file has some).
/// A negative index counts back from the line before the face.
fn first_bad_face(bytes: &[u8]) -> Option<(usize, String)> {
    let count = |k: &str| statements(bytes).filter(|(_, key, _)| *key == k).count() as i64;
    let total = [count("v"), count("vt"), count("vn")];
    let mut before = [0i64; 3];
    const KINDS: [(&str, &str); 3] = [("vertex", "v"), ("texcoord", "vt"), ("normal", "vn")];
    for (line, key, fields) in statements(bytes) {
        if let Some(k) = KINDS.iter().position(|(_, kw)| *kw == key) {
            before[k] += 1;
        }
        if key != "f" {
            continue;
        }
        if fields.len() < 3 {
            let message = format!("a face needs at least 3 vertices, got {}", fields.len());
            return Some((line, message));
        }
        for field in &fields {
            for (k, part) in field.split('/').take(3).enumerate() {
                // An unparsable index is tobj's to name; a missing texture
                // coordinate or normal (`1//2`, `1`) is allowed.
                let Ok(i) = part.parse::<i64>() else { continue };
                if (1..=total[k]).contains(&i) || (-before[k]..=-1).contains(&i) {
                    continue;
                }
                let (what, kw) = KINDS[k];
                let (n, place) = match i < 0 {
                    true => (before[k], "before this face"),
                    false => (total[k], "in the file"),
                };
                let lines = match n {
                    0 => format!("no `{kw}` lines"),
                    1 => format!("1 `{kw}` line"),
                    n => format!("{n} `{kw}` lines"),
                };
                let message = format!("face {what} index out of bounds: {i} ({lines} {place})");
                return Some((line, message));
            }
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    const QUAD: &str =
        "# a unit square\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1 4//1\n";

    #[test]
    fn a_quad_becomes_two_triangles_with_normals() {
        let m = parse(QUAD.as_bytes(), "quad.obj", true).unwrap();
        assert_eq!(m.positions.len(), 4);
        assert_eq!(m.faces.len(), 2);
        assert_eq!(m.face_normals.len(), 2);
        assert_eq!(m.normals, vec![DVec3::Z]);
        let flat = parse(QUAD.as_bytes(), "quad.obj", false).unwrap();
        assert!(flat.face_normals.is_empty());
    }

    #[test]
    fn vertex_normals_are_unit_before_they_are_mixed() {
        // Two vertex normals, one five times longer: made unit length first, their
        // mix at the midpoint of the edge between them is halfway (45°); mixed as
        // written, it would lean toward the long one (atan 5 ≈ 78.7°).
        let obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nvn 5 0 0\nf 1//1 2//2 3//1\n";
        let m = parse(obj.as_bytes(), "long.obj", true).unwrap();
        assert_eq!(m.normals, vec![DVec3::Z, DVec3::X]);
        let ray = crate::math::ray::Ray::new(DVec3::new(0.5, 0.0, 1.0), DVec3::NEG_Z);
        let s = m.surface(&ray, 1.0, 0, crate::methods::TriangleMethod::Watertight);
        let halfway = DVec3::new(1.0, 0.0, 1.0).normalize();
        // Two unit vectors mixed half and half and normalized: a few ulps apart.
        assert!(
            (s.shading_normal - halfway).length() < 1e-15,
            "{:?}",
            s.shading_normal
        );
    }

    #[test]
    fn errors_name_the_file_and_line() {
        let cases = [
            (
                "v 0 0 0\nv 1 x 0\nv 0 1 0\nf 1 2 3\n",
                "bad.obj:2: position parse error",
            ),
            (
                "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n",
                "bad.obj:4: face vertex index out of bounds: 9 (3 `v` lines in the file)",
            ),
            (
                "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 a\n",
                "bad.obj:4: face parse error",
            ),
            (
                "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n",
                "bad.obj:2: a coordinate is not a finite number within ±1e9",
            ),
            ("v 0 0 0\n", "bad.obj: has no faces (no `f` lines)"),
        ];
        for (text, expected) in cases {
            let e = parse(text.as_bytes(), "bad.obj", true).unwrap_err();
            assert_eq!(e.to_string(), expected, "{text:?}");
        }
    }
}
