//! The tiles of the universal cover near the domain: which images of an
//! object a ray in the domain can meet, which images of a light are near,
//! and which element of the group brings a point into the domain.
//!
//! The tiles are the images `γ D` of the domain; the neighbour of tile
//! `γ D` across its face `i` is `γ g_i⁻¹ D`. The searches here walk the
//! elements `B = γ⁻¹` instead (the map that brings a tile back onto the
//! domain), whose neighbours are `g_i B`, breadth first, and tell two
//! elements apart by where they send a point inside the domain that no
//! element but the identity fixes (the group acts freely on the interior
//! of a manifold's domain and of a mirrored cell).

use std::collections::{HashSet, VecDeque};

use glam::DVec4;

use crate::error::GeomError;
use crate::isometry::Isometry;
use crate::lorentz;
use crate::plane::HPlane;
use crate::point::Point;
use crate::ray::Ray;

use super::QuotientSpace;

/// The most images of one object or light kept (`docs/manifolds.md`).
pub const MAX_COPIES: usize = 512;

/// The most tiles a search visits.
const MAX_TILES: usize = 20_000;

/// The most face crossings folding a point into the domain may take.
const MAX_FOLD_CROSSINGS: usize = 100_000;

impl QuotientSpace {
    /// The elements `B` of the group (the identity first) such that `B`
    /// of the h-ball about `centre` (a hyperboloid point) of `radius` may
    /// meet the domain: a ray in the domain meets the object's images
    /// only there. A tile is kept when the ball reaches the inner side of
    /// each of its faces, a test that can only keep too many.
    ///
    /// Errors: [`GeomError::TooManyCopies`] past [`MAX_COPIES`].
    pub fn copies_meeting(&self, centre: DVec4, radius: f64) -> Result<Vec<Isometry>, GeomError> {
        let reach = radius.sinh();
        let faces = &self.faces;
        self.search(|b: &Isometry| {
            let c = b.to_lorentz() * centre;
            faces.iter().all(|n| lorentz::dot(c, *n) > -reach)
        })
    }

    /// The images of `p` (a hyperboloid point) within `reach` of the
    /// domain's centre, nearest first, at most `limit`. They lie in the
    /// tiles that meet the ball of radius `reach` about the centre, which
    /// are face-connected (the ball is convex): the search walks the
    /// elements `A` whose image of that ball meets the domain (tile
    /// `A⁻¹ D` meets the ball) by the same test as
    /// [`QuotientSpace::copies_meeting`], and keeps `A⁻¹ p`. At most
    /// 20,000 tiles are visited; a cusped domain's tiles near the ball's
    /// rim can pass the test in numbers, so for a large reach the farthest
    /// images may be missed (`docs/manifolds.md`).
    pub fn images_within(&self, p: DVec4, reach: f64, limit: usize) -> Vec<DVec4> {
        let centre = self.centre();
        let sinh_reach = reach.sinh();
        let faces = &self.faces;
        let found = self.search_unbounded(
            |a: &Isometry| {
                let c = a.to_lorentz() * centre;
                faces.iter().all(|n| lorentz::dot(c, *n) > -sinh_reach)
            },
            MAX_TILES,
        );
        let mut images: Vec<(f64, DVec4)> = found
            .iter()
            .map(|a| a.inverse().to_lorentz() * p)
            .map(|x| (lorentz::distance(x, centre), x))
            .filter(|(d, _)| *d <= reach)
            .collect();
        images.sort_by(|a, b| a.0.total_cmp(&b.0));
        images.truncate(limit);
        images.into_iter().map(|(_, x)| x).collect()
    }

    /// An element `B` with `B(p)` in the domain: the one met by carrying
    /// the geodesic from the domain's centre to `p` across the faces.
    ///
    /// Errors: [`GeomError::TooManyCopies`] (with the crossing limit) for
    /// a point so far or so deep in a cusp that more than 100,000 faces lie
    /// between.
    pub fn fold(&self, p: &Point) -> Result<Isometry, GeomError> {
        let centre = self.centre();
        let x = p.to_hyperboloid();
        if self.contains(x, 0.0) {
            return Ok(Isometry::IDENTITY);
        }
        let Some((dir, length)) = lorentz::direction_towards(centre, x) else {
            return Ok(Isometry::IDENTITY);
        };
        let mut ray = Ray {
            origin: centre,
            dir,
        };
        let mut left = length;
        let mut b = Isometry::IDENTITY;
        for _ in 0..MAX_FOLD_CROSSINGS {
            match self.exit(&ray) {
                Some(c) if c.t < left => {
                    ray = self.carry(&ray, c);
                    left -= c.t;
                    b = self.pairing_at(&c)?.compose(&b);
                }
                _ => return Ok(b),
            }
        }
        Err(GeomError::TooManyCopies {
            limit: MAX_FOLD_CROSSINGS,
        })
    }

    /// The pairing a crossing is carried by.
    fn pairing_at(&self, c: &super::Crossing) -> Result<Isometry, GeomError> {
        match self.pairings.get(c.face) {
            Some(g) => Ok(*g),
            None => Ok(Isometry::reflection(&HPlane::from_normal(c.normal)?)),
        }
    }

    /// The largest distance from the domain's centre to a finite vertex,
    /// or to a face: for a closed space, the radius of the ball about the
    /// centre that holds the domain; for a cusped one, of the ball that
    /// holds it but for its cusps; for a horosphere-inscribed cell, 1 (its
    /// faces' spacing near the base point).
    pub fn radius(&self) -> f64 {
        self.finite_radius()
    }

    fn finite_radius(&self) -> f64 {
        let Some(domain) = &self.domain else {
            return 1.0;
        };
        let centre = self.centre();
        let vertices = domain
            .vertices()
            .iter()
            .zip(domain.ideal())
            .filter(|(_, ideal)| !**ideal)
            .map(|(v, _)| lorentz::distance(*v, centre));
        let faces = domain
            .faces()
            .iter()
            .map(|n| lorentz::dot(centre, *n).asinh());
        vertices.chain(faces).fold(0.0, f64::max)
    }

    /// A point inside the domain: its centre, or for a horosphere-inscribed
    /// cell (whose base point is the centre of a face) the point 0.3 in
    /// from it.
    fn interior(&self) -> DVec4 {
        let inside = match (&self.horo, self.faces.first()) {
            (Some(_), Some(n)) => {
                // In the base placement the face through the origin.
                let base = self.placement.inverse().to_lorentz() * *n;
                Point::at_distance_from_origin(base.truncate(), 0.3)
                    .map_or(DVec4::W, |p| p.to_hyperboloid())
            }
            _ => DVec4::W,
        };
        self.placement.to_lorentz() * inside
    }

    /// Breadth-first over the elements `g_i B` from the identity, keeping
    /// those `keep` accepts (and going on only from them).
    fn search(&self, keep: impl Fn(&Isometry) -> bool) -> Result<Vec<Isometry>, GeomError> {
        let found = self.search_unbounded(keep, MAX_COPIES + 1);
        if found.len() > MAX_COPIES {
            return Err(GeomError::TooManyCopies { limit: MAX_COPIES });
        }
        Ok(found)
    }

    fn search_unbounded(&self, keep: impl Fn(&Isometry) -> bool, most: usize) -> Vec<Isometry> {
        let witness = self.witness();
        let key = |b: &Isometry| {
            let w = b.to_lorentz() * witness;
            let q = w.truncate() / (1.0 + w.w);
            (
                (q.x * 1e7).round() as i64,
                (q.y * 1e7).round() as i64,
                (q.z * 1e7).round() as i64,
            )
        };
        let mut seen = HashSet::new();
        let mut found = Vec::new();
        let mut queue = VecDeque::from([Isometry::IDENTITY]);
        seen.insert(key(&Isometry::IDENTITY));
        while let Some(b) = queue.pop_front() {
            found.push(b);
            if found.len() >= most || seen.len() > MAX_TILES {
                break;
            }
            for g in &self.pairings {
                let next = g.compose(&b);
                if seen.insert(key(&next)) && keep(&next) {
                    queue.push_back(next);
                }
            }
        }
        found
    }

    /// A point inside the domain that no element but the identity fixes:
    /// the centre nudged in a direction of no symmetry.
    fn witness(&self) -> DVec4 {
        let centre = self.interior();
        let inradius = self
            .faces
            .iter()
            .map(|n| lorentz::dot(centre, *n).asinh())
            .fold(f64::INFINITY, f64::min)
            .min(0.3);
        let nudge = Point::at_distance_from_origin(
            glam::DVec3::new(0.312_5, 0.577_215_664, 0.723_606_797),
            0.37 * inradius,
        )
        .map_or(glam::DVec4::W, |p| p.to_hyperboloid());
        // The nudge is made at the origin; carry it to the interior point.
        let to_inside = Point::from_hyperboloid(self.placement.inverse().to_lorentz() * centre)
            .map_or(Isometry::IDENTITY, Isometry::transvection_from_origin);
        self.placement.to_lorentz() * to_inside.to_lorentz() * nudge
    }
}
