//! The honeycomb's settings and accessors: what it reports (horizon hits,
//! the colouring of its parts), how far it is walked, where it is placed,
//! and how it is moved. The walk itself is in `walk.rs`.

#[cfg(test)]
use std::sync::Arc;

use glam::{DVec3, DVec4};

use crate::error::GeomError;
use crate::isometry::Isometry;
use crate::lorentz;
use crate::point::Point;

#[cfg(test)]
use super::super::domain::WalkDomain;
use super::super::kernels::lorentz_inverse;
use super::super::schlafli::Schlafli;
use super::super::style::{CellColouring, HoneycombStyle};
use super::super::uniform::Rings;
use super::super::view_horizon::ViewHorizon;
use super::{RANK_CLASSES, RegularHoneycomb};

impl RegularHoneycomb {
    /// The ringed nodes of its Coxeter diagram ([`Rings::REGULAR`] for a
    /// regular honeycomb).
    pub fn rings(&self) -> Rings {
        self.rings
    }

    /// With `on`, a ray that the horizon stops (not `t_max`, not a
    /// depth's last cell) reports a hit there, at the distance where the
    /// walk gave up, on the part
    /// [`HoneycombPart::Horizon`](super::HoneycombPart::Horizon) with the
    /// normal facing the ray: a renderer can draw what lies beyond (the
    /// honeycomb's average appearance) instead of the background. A shadow
    /// test ([`RegularHoneycomb::blocks`]) never reports one. Off by
    /// default: the walk then says only what it met.
    pub fn with_horizon_hits(mut self, on: bool) -> RegularHoneycomb {
        self.horizon_hits = on;
        self
    }

    /// The same honeycomb with its parts classed by `colouring` (by rank
    /// unless asked).
    ///
    /// Errors: [`GeomError::OddEdgeCycle`] for
    /// [`CellColouring::Parity`](CellColouring::Parity) when `r` is
    /// odd; [`GeomError::UniformWithCells`] for it on a uniform honeycomb.
    pub fn with_colouring(
        mut self,
        colouring: CellColouring,
    ) -> Result<RegularHoneycomb, GeomError> {
        if colouring == CellColouring::Parity {
            if !self.rings.is_regular() {
                return Err(GeomError::UniformWithCells);
            }
            if !self.symbol.r().is_multiple_of(2) {
                return Err(GeomError::OddEdgeCycle { r: self.symbol.r() });
            }
        }
        self.colouring = colouring;
        Ok(self)
    }

    /// The same honeycomb with as many cell classes as there can be ranks
    /// ([`RANK_CLASSES`]), so that a hit's class is its cell's rank itself
    /// (the layer or shell about the base cell, `cells.rs`): for inspecting
    /// a picture (which word length a pixel shows). The class modulo `k`
    /// is what `k` classes would give. Unchanged for a uniform honeycomb
    /// or one coloured by parity, whose classes are not ranks.
    pub fn with_rank_classes(mut self) -> RegularHoneycomb {
        if self.rings.is_regular() && self.colouring == CellColouring::Rank {
            self.style.cell_classes = RANK_CLASSES;
        }
        self
    }

    /// How its parts get their class.
    pub fn colouring(&self) -> CellColouring {
        self.colouring
    }

    /// True if rays the horizon stops report a hit there
    /// ([`RegularHoneycomb::with_horizon_hits`]).
    pub fn horizon_hits(&self) -> bool {
        self.horizon_hits
    }

    /// The same honeycomb walked only out to `distance` from the origin of
    /// its frame (module docs).
    ///
    /// Errors: [`GeomError::BadRadius`] unless `0 < distance <= 36`
    /// (beyond, f64 holds no ball point).
    pub fn with_horizon(mut self, distance: f64) -> Result<RegularHoneycomb, GeomError> {
        if !(distance > 0.0 && distance <= 36.0) {
            return Err(GeomError::BadRadius(distance));
        }
        self.horizon = distance;
        self.cosh_horizon = distance.cosh();
        Ok(self)
    }

    /// The distance from the origin of the frame where the walk stops.
    pub fn horizon(&self) -> f64 {
        self.horizon
    }

    /// The distance from an eye at the origin beyond which a cell's
    /// features subtend less than `pixel_angle` radians: a circle of radius
    /// `t` has circumference `2π sinh t`, so a feature of size `s` at
    /// distance `t` subtends `s / sinh t`, and `t = asinh(s / pixel_angle)`,
    /// with `s` twice the distance from an edge's midpoint to a face centre
    /// (the width of a face across its middle: 1.25 for `{4,3,5}`). Thin
    /// rods vanish sooner; this is where the cells themselves do. At most 36.
    pub fn horizon_for_pixel(&self, pixel_angle: f64) -> f64 {
        (self.feature_size() / pixel_angle)
            .asinh()
            .clamp(f64::MIN_POSITIVE, 36.0)
    }

    /// The same honeycomb with, for rays from the origin of its frame (the
    /// eye), the horizon of their own pixel on a flat image plane: a ray at
    /// `θ` from `axis` stops at [`RegularHoneycomb::horizon_for_pixel`] of
    /// `pixel_angle cos² θ`, a lower bound of the angle between its pixel's
    /// ray and its neighbours' when the pixels at the middle are
    /// `pixel_angle` apart (module `view_horizon`), and never beyond
    /// [`RegularHoneycomb::horizon`]. Other rays (shadows, reflections)
    /// keep that horizon.
    ///
    /// Errors: [`GeomError::BadDirection`] for an axis that is zero or not
    /// finite; [`GeomError::BadAngle`] for a pixel angle that is not
    /// positive and finite.
    pub fn with_view_horizon(
        mut self,
        axis: DVec3,
        pixel_angle: f64,
    ) -> Result<RegularHoneycomb, GeomError> {
        self.view = Some(ViewHorizon::new(axis, self.feature_size(), pixel_angle)?);
        Ok(self)
    }

    /// Twice the distance from an edge's midpoint to a face centre: the
    /// width of a face across its middle (1.25 for `{4,3,5}`).
    fn feature_size(&self) -> f64 {
        let v = self.simplex_vertices;
        2.0 * lorentz::distance(v[1], v[2])
    }

    /// The walls the walk reflects the ray in ([`WalkStep::wall`] indexes
    /// them), inward unit normals in the honeycomb's frame before placement:
    /// the faces of the base cell when the cells are finite, else (and for
    /// every uniform honeycomb other than the regular one) the four mirrors
    /// of the characteristic simplex
    /// ([`CoxeterSimplex::normals`](super::super::simplex::CoxeterSimplex::normals)).
    pub fn walls(&self) -> Vec<DVec4> {
        self.domain.walls().to_vec()
    }

    /// The same honeycomb walked through the characteristic simplex even
    /// when its cells are finite: the slower walk the cell walk is checked
    /// against.
    #[cfg(test)]
    pub(in crate::honeycomb) fn walked_by_simplex(mut self) -> RegularHoneycomb {
        let simplex = super::super::simplex::CoxeterSimplex::new(self.symbol);
        if let Ok(domain) = WalkDomain::simplex(&simplex, &self.style) {
            self.domain = Arc::new(domain);
        }
        self
    }

    /// `cosh` of the radius about the base point (in the honeycomb's own
    /// frame) that holds every part, when it is finite (a depth-limited
    /// honeycomb with finite cells and vertices).
    pub(in crate::honeycomb) fn reach(&self) -> Option<f64> {
        self.cosh_reach
    }

    /// The Schläfli symbol.
    pub fn symbol(&self) -> Schlafli {
        self.symbol
    }

    /// The style it was built with.
    pub fn style(&self) -> HoneycombStyle {
        self.style
    }

    /// The placement: the isometry from the base placement to this one.
    pub fn placement(&self) -> Isometry {
        self.placement
    }

    /// The base point after placement: the centre of the base cell, or the
    /// centre of one of its faces when the cells are horosphere-inscribed
    /// (their centres are ideal).
    pub fn base_cell_center(&self) -> Point {
        self.placement.translation_part()
    }

    /// The image under `iso` (composed with the placement).
    pub fn transformed(&self, iso: &Isometry) -> RegularHoneycomb {
        let placement = iso.compose(&self.placement);
        let to_world = placement.to_lorentz();
        RegularHoneycomb {
            placement,
            to_world,
            to_local: lorentz_inverse(to_world),
            ..self.clone()
        }
    }

    /// True if the placement and its matrices are finite and usable.
    pub fn is_representable(&self) -> bool {
        self.placement.translation_part().is_representable()
            && self.to_world.is_finite()
            && self.to_local.is_finite()
    }
}
