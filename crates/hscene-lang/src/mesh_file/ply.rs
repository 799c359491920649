//! Reading PLY files (ASCII or binary) one element at a time.
//!
//! The header is parsed by ply-rs-bw; the payload is then read element by
//! element into a small row that keeps only what a mesh uses, and each row
//! goes straight into the [`MeshData`] arrays. Neither the file's bytes nor
//! a per-element map of named properties is ever held whole: a mesh of a
//! million triangles costs its positions and index triples while it is
//! read, not the several hundred bytes a triangle that a map per element
//! would.

use std::io::BufRead;

use hgeom::glam::DVec3;
use ply_rs_bw::parser::{Parser, Reader};
use ply_rs_bw::ply::{Encoding, Property, PropertyAccess, PropertyAccessResult};

use super::data::{MeshData, MeshFileError, fan};

/// What a mesh uses of one PLY element: a vertex's coordinates and normal,
/// a face's index list. Other properties are ignored.
#[derive(Default)]
struct Row {
    xyz: [Option<f64>; 3],
    normal: [Option<f64>; 3],
    /// `vertex_indices`, and `vertex_index` (used only without the first).
    indices: Option<Property>,
    index: Option<Property>,
}

impl PropertyAccess for Row {
    fn new() -> Row {
        Row::default()
    }

    fn set_property(&mut self, name: &str, property: Property) -> PropertyAccessResult {
        let slot = match name {
            "x" => &mut self.xyz[0],
            "y" => &mut self.xyz[1],
            "z" => &mut self.xyz[2],
            "nx" => &mut self.normal[0],
            "ny" => &mut self.normal[1],
            "nz" => &mut self.normal[2],
            "vertex_indices" => {
                self.indices = Some(property);
                return PropertyAccessResult::Set;
            }
            "vertex_index" => {
                self.index = Some(property);
                return PropertyAccessResult::Set;
            }
            _ => return PropertyAccessResult::Ignored,
        };
        *slot = scalar(&property);
        PropertyAccessResult::Set
    }
}

/// A numeric scalar property as `f64`.
fn scalar(p: &Property) -> Option<f64> {
    Some(match *p {
        Property::Char(x) => f64::from(x),
        Property::UChar(x) => f64::from(x),
        Property::Short(x) => f64::from(x),
        Property::UShort(x) => f64::from(x),
        Property::Int(x) => f64::from(x),
        Property::UInt(x) => f64::from(x),
        Property::Float(x) => f64::from(x),
        Property::Double(x) => x,
        _ => return None,
    })
}

/// An integer list property as indices; a negative index becomes
/// `u32::MAX`, which the range check rejects.
fn list(p: &Property) -> Option<Vec<u32>> {
    fn convert<T: Copy + Into<i64>>(v: &[T]) -> Vec<u32> {
        v.iter()
            .map(|&x| u32::try_from(x.into()).unwrap_or(u32::MAX))
            .collect()
    }
    Some(match p {
        Property::ListChar(v) => convert(v),
        Property::ListUChar(v) => convert(v),
        Property::ListShort(v) => convert(v),
        Property::ListUShort(v) => convert(v),
        Property::ListInt(v) => convert(v),
        Property::ListUInt(v) => convert(v),
        _ => return None,
    })
}

/// The parser's error as a position and a kind of problem (its own
/// messages quote the offending line, which is not passed on).
fn invalid(kind: std::io::ErrorKind, line: Option<usize>) -> MeshFileError {
    let problem = match kind {
        std::io::ErrorKind::UnexpectedEof => "not a valid PLY file: it ends early",
        _ => "not a valid PLY file: malformed header or data",
    };
    match line {
        Some(line) => MeshFileError::invalid_at(line, problem),
        None => MeshFileError::Invalid(problem.to_string()),
    }
}

/// Reads a PLY file of at most `len` bytes from `source`; `len` only bounds
/// what is reserved up front for the element counts the header claims.
pub(super) fn parse<R: BufRead>(source: R, len: u64) -> Result<MeshData, MeshFileError> {
    let parser = Parser::<Row>::new();
    let mut reader = Reader::new(source);
    let header = parser
        .read_header(&mut reader)
        .map_err(|e| invalid(e.kind(), e.line()))?;
    if !header.elements.contains_key("vertex") {
        return Err(MeshFileError::Invalid(
            "the PLY file has no `vertex` element".into(),
        ));
    }
    if !header.elements.contains_key("face") {
        return Err(MeshFileError::Invalid(
            "the PLY file has no `face` element".into(),
        ));
    }
    // Every vertex takes at least 6 bytes (`0 0 0\n`, three binary chars
    // and more), every triangle at least 4: a header cannot make us reserve
    // more than the file could fill.
    let len = usize::try_from(len).unwrap_or(usize::MAX);
    let mut positions = Vec::new();
    let mut normals = Vec::new();
    let mut triangles = Vec::new();
    // Elements are numbered from the line after the header (where the
    // reader stands now), as the parser numbers them: one per line in
    // ASCII, one per element in binary.
    let mut line = reader.line();
    let mut text = String::new();
    for (name, def) in &header.elements {
        match name.as_str() {
            "vertex" => positions.reserve_exact(def.count.min(len / 6)),
            "face" => triangles.reserve_exact(def.count.min(len / 4)),
            _ => {}
        }
        for i in 0..def.count {
            let read = match header.encoding {
                Encoding::Ascii => {
                    text.clear();
                    match reader.get_mut().read_line(&mut text) {
                        Ok(0) => {
                            return Err(invalid(std::io::ErrorKind::UnexpectedEof, Some(line)));
                        }
                        Ok(_) => parser.read_ascii_element(&text, def),
                        Err(e) => return Err(invalid(e.kind(), Some(line))),
                    }
                }
                Encoding::BinaryLittleEndian => {
                    parser.read_little_endian_element(reader.get_mut(), def)
                }
                Encoding::BinaryBigEndian => parser.read_big_endian_element(reader.get_mut(), def),
            };
            let row = read.map_err(|e| invalid(e.kind(), Some(line)))?;
            match name.as_str() {
                "vertex" => {
                    let [Some(x), Some(y), Some(z)] = row.xyz else {
                        return Err(MeshFileError::Invalid(format!(
                            "PLY vertex {} lacks a numeric x, y or z",
                            i + 1
                        )));
                    };
                    positions.push(DVec3::new(x, y, z));
                    if let [Some(x), Some(y), Some(z)] = row.normal {
                        let n = DVec3::new(x, y, z);
                        if !n.is_finite() {
                            return Err(MeshFileError::Invalid(format!(
                                "PLY vertex {} has a normal that is not a finite number",
                                i + 1
                            )));
                        }
                        normals.push(n);
                    }
                }
                "face" => {
                    let face = row.indices.or(row.index).as_ref().and_then(list);
                    let Some(face) = face else {
                        return Err(MeshFileError::Invalid(format!(
                            "PLY face {} has no `vertex_indices` list of integers",
                            i + 1
                        )));
                    };
                    fan(&face, &mut triangles)?;
                }
                _ => {}
            }
            line += 1;
        }
    }
    // A PLY element's properties are the same for every vertex: either all
    // have a normal or none has.
    let has_normals = !positions.is_empty() && normals.len() == positions.len();
    if !has_normals {
        normals = Vec::new();
    }
    let corner_normals = if has_normals {
        triangles.clone()
    } else {
        Vec::new()
    };
    Ok(MeshData {
        positions,
        triangles,
        normals,
        corner_normals,
    })
}
