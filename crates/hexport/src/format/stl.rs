//! Binary STL: an 80-byte header, the triangle count, then per triangle
//! its normal and corners as little-endian f32 (millimetres) and a zero
//! attribute word.

use crate::model::Model;

/// The header text (padded with zeros to 80 bytes). It must not start
/// with `solid`, which readers take for ASCII STL.
const HEADER: &[u8] = b"hscene export: Poincare ball, millimetres, centre at the origin";

pub(super) fn encode(model: &Model) -> Vec<u8> {
    let count = model.triangle_count();
    let mut out = Vec::with_capacity(84 + 50 * count);
    let mut header = [0u8; 80];
    header[..HEADER.len()].copy_from_slice(HEADER);
    out.extend_from_slice(&header);
    // The budget keeps the count far below u32::MAX.
    out.extend_from_slice(&(count as u32).to_le_bytes());
    for shell in &model.shells {
        for t in &shell.triangles {
            let corners = shell.corners(t);
            let n = super::normal(corners);
            for v in std::iter::once(n).chain(corners) {
                for c in [v.x, v.y, v.z] {
                    out.extend_from_slice(&(c as f32).to_le_bytes());
                }
            }
            out.extend_from_slice(&[0, 0]);
        }
    }
    out
}
