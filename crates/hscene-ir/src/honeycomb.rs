//! A regular honeycomb as a scene object: the surface hgeom walks
//! ([`RegularHoneycomb`], which holds its symbol, style and placement) and
//! the materials of its parts.
//!
//! One object, several materials: the honeycomb's hits say what they met in
//! [`hgeom::Hit::part`] (an edge, a face or a vertex, and the class of the
//! cell it belongs to), and [`PartMaterials::material`] turns that into a
//! material. The renderer asks only that method, so it names no kind of
//! shape.

use hgeom::{HoneycombPart, RegularHoneycomb, decode_honeycomb_part};

use crate::material::MaterialId;

/// A regular honeycomb of hyperbolic space (`Honeycomb {p,q,r}, #M;`).
#[derive(Clone, Debug)]
pub struct Honeycomb {
    /// The walking surface, placed.
    pub surface: RegularHoneycomb,
    /// The materials of its parts.
    pub materials: PartMaterials,
}

/// Two honeycombs are equal when they have the same symbol, style,
/// placement, colouring and materials: the walk's tables follow from these.
impl PartialEq for Honeycomb {
    fn eq(&self, other: &Honeycomb) -> bool {
        self.surface.symbol() == other.surface.symbol()
            && self.surface.style() == other.surface.style()
            && self.surface.placement() == other.surface.placement()
            && self.surface.colouring() == other.surface.colouring()
            && self.materials == other.materials
    }
}

/// Which material each part of a honeycomb is drawn in, given the object's
/// own material `#M` (the edges and vertices).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PartMaterials {
    /// `faces = #F`: every face in `#F`.
    pub faces: Option<MaterialId>,
    /// `colors = (#A, #B, ...)`: the edges and vertices of cell class `k`
    /// are drawn in `palette[k % len]` (never the faces: those are drawn
    /// only when `faces` or `face_colors` asks). Empty without `colors`.
    pub palette: Vec<MaterialId>,
    /// `face_colors = (#A, #B, ...)`: the faces of cell class `k` are drawn
    /// in `face_palette[k % len]`, whatever else is given. Empty without it.
    pub face_palette: Vec<MaterialId>,
}

impl PartMaterials {
    /// Every material its parts may be drawn in besides the object's own:
    /// the faces' and the palette's.
    pub fn ids(&self) -> impl Iterator<Item = MaterialId> + '_ {
        self.faces
            .iter()
            .chain(&self.palette)
            .chain(&self.face_palette)
            .copied()
    }

    /// The index (into the scene's materials) of the material of the part
    /// a hit met (`hit.part`), for an object whose own material has index
    /// `own`.
    pub fn material(&self, part: u32, own: usize) -> usize {
        let (kind, class) = decode_honeycomb_part(part);
        let coloured = match self.palette.len() {
            0 => None,
            // A u32 class always fits in usize on the targets we build for.
            n => self.palette.get(class as usize % n).map(|m| m.index()),
        };
        let face_coloured = match self.face_palette.len() {
            0 => None,
            n => self.face_palette.get(class as usize % n).map(|m| m.index()),
        };
        let faces = self.faces.map(MaterialId::index);
        match kind {
            HoneycombPart::Face => face_coloured.or(faces).unwrap_or(own),
            HoneycombPart::Edge | HoneycombPart::Vertex => coloured.unwrap_or(own),
            // Beyond the walk's horizon: no part, so no material of its
            // own; the renderer draws it in the honeycomb's average
            // appearance.
            HoneycombPart::Horizon => own,
        }
    }
}

/// How many cell classes two palettes of `a` and `b` materials count round
/// together: the least common multiple of their lengths (an empty palette
/// counts as one).
pub fn palette_period(a: usize, b: usize) -> usize {
    let (a, b) = (a.max(1), b.max(1));
    let (mut x, mut y) = (a, b);
    while y != 0 {
        (x, y) = (y, x % y);
    }
    a / x * b
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The faces' material first, then the palette in order; none
    /// without either.
    #[test]
    fn ids_are_the_faces_then_the_palette() {
        let id = MaterialId::declared;
        let both = PartMaterials {
            faces: Some(id(2)),
            palette: vec![id(0), id(1)],
            face_palette: vec![id(3)],
        };
        assert_eq!(both.ids().collect::<Vec<_>>(), [id(2), id(0), id(1), id(3)]);
        let bare = PartMaterials {
            faces: None,
            palette: Vec::new(),
            face_palette: Vec::new(),
        };
        assert_eq!(bare.ids().count(), 0);
    }
}
