//! How the scene is seen: the observer, the pixel net, the image's size and
//! the window on the view plane.

use std::num::NonZeroU32;

use hgeom::glam::DVec3;
use hgeom::{HLine, Isometry, Point};

/// The pixel net (docs/rendering.md, "The five pixel nets"), numbered as
/// in the thesis.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Net {
    /// Net 0: the Euclidean grid on the plane `z = f` (a pinhole camera).
    Euclidean,
    /// Net 1: intersections of two pencils of hyperparallel h-lines.
    HyperparallelLines,
    /// Net 2: a Euclidean grid on the great disk, moved onto the view plane.
    GreatDisk,
    /// Net 3: nodes of two families of h-equidistant curves, one per pixel.
    Equidistant,
    /// Net 4: net 3 nodes, shown on the great disk by interpolation.
    EquidistantInterpolated,
}

impl Net {
    /// All nets, by index.
    pub const ALL: [Net; 5] = [
        Net::Euclidean,
        Net::HyperparallelLines,
        Net::GreatDisk,
        Net::Equidistant,
        Net::EquidistantInterpolated,
    ];

    /// The thesis's index `0..=4`.
    pub fn index(self) -> u8 {
        match self {
            Net::Euclidean => 0,
            Net::HyperparallelLines => 1,
            Net::GreatDisk => 2,
            Net::Equidistant => 3,
            Net::EquidistantInterpolated => 4,
        }
    }

    /// The net with the thesis's index.
    pub fn from_index(i: u64) -> Option<Net> {
        Net::ALL.get(usize::try_from(i).ok()?).copied()
    }
}

/// Image size in pixels, both sides at least 1.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Resolution {
    width: NonZeroU32,
    height: NonZeroU32,
}

impl Resolution {
    /// `width` columns by `height` rows; `None` if either is 0.
    pub const fn new(width: u32, height: u32) -> Option<Resolution> {
        match (NonZeroU32::new(width), NonZeroU32::new(height)) {
            (Some(width), Some(height)) => Some(Resolution { width, height }),
            _ => None,
        }
    }

    /// Columns.
    pub const fn width(self) -> u32 {
        self.width.get()
    }

    /// Rows.
    pub const fn height(self) -> u32 {
        self.height.get()
    }
}

/// Size of the sampled window on the view plane (Euclidean units for nets 0,
/// 2 and 4, hyperbolic lengths for nets 1 and 3). Invariant: both positive.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Window {
    /// Horizontal extent.
    pub width: f64,
    /// Vertical extent.
    pub height: f64,
}

/// The observer.
///
/// Invariants: `target != eye`, and `up` (when given) does not lie on the
/// h-line through `eye` and `target`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    /// The eye point.
    pub eye: Point,
    /// The view target: the view h-plane passes through it, orthogonal to the
    /// view direction.
    pub target: Point,
    /// A point towards which "up" points; `None` means the ball's `+y`
    /// direction at the eye.
    pub up: Option<Point>,
}

/// Moves the eye, the target and the up point. A camera with the default
/// up direction (`+y` at the eye) first gets an explicit up point on the
/// geodesic leaving the eye in that direction, so that the direction turns
/// with the camera. `None` if a point leaves what f64 can represent.
pub fn move_camera(cam: &mut Camera, iso: &Isometry) -> Option<()> {
    if cam.up.is_none() {
        cam.up = default_up_point(&cam.eye);
    }
    let eye = iso.checked_apply(&cam.eye).ok()?;
    let target = iso.checked_apply(&cam.target).ok()?;
    let up = match &cam.up {
        Some(u) => Some(iso.checked_apply(u).ok()?),
        None => None,
    };
    *cam = Camera { eye, target, up };
    Some(())
}

/// A point towards which the default up direction (`+y` at the eye) points.
fn default_up_point(eye: &Point) -> Option<Point> {
    let line = HLine::from_point_direction(eye, DVec3::Y).ok()?;
    // Any point on the geodesic gives the same direction; a short step stays
    // representable even for an eye far out.
    [1.0, 0.1, 1e-3]
        .into_iter()
        .find_map(|s| line.point_at(s).ok())
}
