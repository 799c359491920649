//! A Wavefront OBJ reader for what a mesh needs: `v`, `vn` and `f` lines.
//!
//! Everything else (texture coordinates, groups, materials, lines, points)
//! is skipped. Errors name the line and the kind of problem and
//! never quote the file, whose content may be anything.

use hgeom::glam::DVec3;

use super::data::{MAX_MESH_TRIANGLES, MeshData, MeshFileError, fan};

/// Parses OBJ text (any line-end convention) into positions and triangles.
/// Face indices are 1-based, or negative to count back from the last vertex
/// read so far; `i`, `i/t`, `i//n` and `i/t/n` are all accepted.
pub(super) fn parse(bytes: &[u8]) -> Result<MeshData, MeshFileError> {
    let mut positions = Vec::new();
    let mut triangles = Vec::new();
    let mut normals = Vec::new();
    let mut corner_normals = Vec::new();
    let mut face = Vec::new();
    let mut face_normals = Vec::new();
    for (index, line) in lines(bytes).enumerate() {
        let number = index + 1;
        let invalid = |problem: &str| MeshFileError::invalid_at(number, problem);
        let mut words = line
            .split(|b| b.is_ascii_whitespace())
            .filter(|w| !w.is_empty());
        match words.next() {
            Some(b"v") => positions.push(coordinates(&mut words, &VERTEX).map_err(invalid)?),
            Some(b"vn") => normals.push(coordinates(&mut words, &NORMAL).map_err(invalid)?),
            Some(b"f") => {
                face.clear();
                face_normals.clear();
                for word in words {
                    // A face of millions of vertices makes as many
                    // triangles: refused as it is read, not once built.
                    if triangles.len() + face.len() > MAX_MESH_TRIANGLES {
                        return Err(MeshFileError::TooManyTriangles);
                    }
                    face.push(vertex_index(word, positions.len()).ok_or_else(|| {
                        invalid("a face refers to a vertex that is not defined before it")
                    })?);
                    face_normals.push(normal_index(word, normals.len()).ok_or_else(|| {
                        invalid("a face refers to a normal that is not defined before it")
                    })?);
                }
                if face.len() < 3 {
                    return Err(invalid("a face needs at least three vertices"));
                }
                let before = triangles.len();
                fan(&face, &mut triangles)?;
                // Corner normals only once the file has normals: one row per
                // triangle, those before the first normal without.
                if !normals.is_empty() {
                    corner_normals.resize(before, [u32::MAX; 3]);
                    fan(&face_normals, &mut corner_normals)?;
                }
            }
            _ => {}
        }
    }
    if normals.is_empty() || corner_normals.iter().flatten().all(|&n| n == u32::MAX) {
        corner_normals.clear();
    }
    Ok(MeshData {
        positions,
        triangles,
        normals,
        corner_normals,
    })
}

/// What can be wrong with the coordinates of a `v` or `vn` line, in words.
struct CoordinateProblems {
    missing: &'static str,
    not_a_number: &'static str,
    not_finite: &'static str,
}

const VERTEX: CoordinateProblems = CoordinateProblems {
    missing: "a vertex needs three coordinates",
    not_a_number: "a vertex coordinate is not a number",
    not_finite: "a vertex coordinate is not a finite number",
};

const NORMAL: CoordinateProblems = CoordinateProblems {
    missing: "a vertex normal needs three coordinates",
    not_a_number: "a vertex normal coordinate is not a number",
    not_finite: "a vertex normal is not finite",
};

/// The three finite coordinates that start `words`.
fn coordinates<'w>(
    words: &mut impl Iterator<Item = &'w [u8]>,
    problems: &CoordinateProblems,
) -> Result<DVec3, &'static str> {
    let mut xyz = [0.0; 3];
    for c in &mut xyz {
        let word = words.next().ok_or(problems.missing)?;
        *c = number_of(word).ok_or(problems.not_a_number)?;
    }
    let v = DVec3::from_array(xyz);
    if !v.is_finite() {
        return Err(problems.not_finite);
    }
    Ok(v)
}

/// The lines of `bytes`, each ended by LF, CRLF or a lone CR.
fn lines(mut bytes: &[u8]) -> impl Iterator<Item = &[u8]> {
    std::iter::from_fn(move || {
        if bytes.is_empty() {
            return None;
        }
        let end = bytes
            .iter()
            .position(|&b| b == b'\n' || b == b'\r')
            .unwrap_or(bytes.len());
        let line = &bytes[..end];
        let skip = match bytes.get(end..end + 2) {
            Some(b"\r\n") => 2,
            Some(_) | None if end < bytes.len() => 1,
            _ => 0,
        };
        bytes = &bytes[end + skip..];
        Some(line)
    })
}

fn number_of(word: &[u8]) -> Option<f64> {
    std::str::from_utf8(word).ok()?.parse().ok()
}

/// The 0-based vertex of a face entry `i[/t[/n]]`, given `count` vertices
/// read so far; `None` if it is malformed or outside `1..=count` (or
/// `-count..=-1`).
fn vertex_index(word: &[u8], count: usize) -> Option<u32> {
    index_in(word.split(|&b| b == b'/').next()?, count)
}

/// The 0-based normal of a face entry `i/t/n` or `i//n` given `count`
/// normals read so far, `u32::MAX` for an entry without one; `None` if the
/// normal index is malformed or out of range.
fn normal_index(word: &[u8], count: usize) -> Option<u32> {
    match word.split(|&b| b == b'/').nth(2) {
        None | Some(b"") => Some(u32::MAX),
        Some(n) => index_in(n, count),
    }
}

/// A 1-based (or negative, counting back) OBJ index among `count` items.
fn index_in(word: &[u8], count: usize) -> Option<u32> {
    let i: i64 = std::str::from_utf8(word).ok()?.parse().ok()?;
    let count = i64::try_from(count).ok()?;
    let zero_based = match i {
        i if i > 0 && i <= count => i - 1,
        i if i < 0 && -i <= count => count + i,
        _ => return None,
    };
    u32::try_from(zero_based).ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_vertices_and_faces_in_every_index_form() {
        let data =
            parse(b"# c\r\nv 0 0 0\rv 1 0 0\nv 0 1 0 1\nvn 0 0 1\nf 1/1/1 2//1 -1\ng x\nf 1 2 3\n")
                .unwrap();
        assert_eq!(data.positions.len(), 3);
        assert_eq!(data.triangles, vec![[0, 1, 2], [0, 1, 2]]);
        assert_eq!(data.normals, vec![DVec3::Z]);
        let none = u32::MAX;
        assert_eq!(data.corner_normals, vec![[0, 0, none], [none; 3]]);
    }

    #[test]
    fn errors_give_the_line_and_never_the_content() {
        for (text, line) in [
            (&b"v 0 0 0\nv root:x:0:0:root:/root:/bin/bash 1 2\n"[..], 2),
            (b"v 0 0 0\nv 1 0 0\nv 0 1 0\n\n\nf 1 2 4\n", 6),
            (b"v 0 0\n", 1),
            (b"v 0 0 0\r\rf 1 1\n", 3),
            (b"v 1e999 0 0\n", 1),
            (b"v 0 0 0\nf 0 1 1\n", 2),
            (b"v 0 0 0\nvn 0 0 1\nf 1//1 1//2 1//1\n", 3),
            (b"vn 0 x 1\n", 1),
        ] {
            let e = parse(text).unwrap_err().to_string();
            assert!(e.starts_with(&format!("line {line}: ")), "{e}");
            assert!(!e.contains("root") && !e.contains('\n'), "{e}");
        }
    }
}
