//! The camera: the `from` (or `eye`), `to` and `up` globals, settled into
//! an [`ir::Camera`](crate::ir::Camera) once `Globals` is read.

use hgeom::glam::DVec3;
use hgeom::{HPlane, Point, Segment};

use super::Lowerer;
use crate::diagnostic::{Code, Diagnostic, Span};
use crate::ir::Camera;
use crate::syntax::Value;

/// The default view target: the thesis's `to = (0,0,0.1)`.
const DEFAULT_TARGET: DVec3 = DVec3::new(0.0, 0.0, 0.1);

/// The camera's points as given.
#[derive(Default)]
pub(super) struct CameraParts {
    eye: Option<(Point, Span)>,
    target: Option<(Point, Span)>,
    up: Option<(Point, Span)>,
    /// A camera key was given but did not resolve (already reported), so
    /// camera checks would only cascade.
    failed: bool,
}

/// Which point of the camera a global sets.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum CameraKey {
    /// `from` (or `eye`).
    Eye,
    /// `to`.
    Target,
    /// `up`.
    Up,
}

impl Lowerer<'_> {
    /// One of the camera's globals.
    pub(super) fn camera_global(&mut self, key: CameraKey, value: &Value) {
        let role = match key {
            CameraKey::Target => "the view target",
            CameraKey::Up => "the up point",
            CameraKey::Eye => "the eye",
        };
        let point = self.point_arg(value, role).map(|p| (p, value.span()));
        self.camera_parts.failed |= point.is_none();
        match key {
            CameraKey::Target => self.camera_parts.target = point,
            CameraKey::Up => self.camera_parts.up = point,
            CameraKey::Eye => self.camera_parts.eye = point,
        }
    }

    /// The camera, with its defaults; `None` if a part failed or the parts
    /// do not fix a view.
    /// Where `up` was given, if it was.
    pub(super) fn up_span(&self) -> Option<Span> {
        self.camera_parts.up.map(|(_, span)| span)
    }

    /// Where `to` was given, if it was.
    pub(super) fn target_span(&self) -> Option<Span> {
        self.camera_parts.target.map(|(_, span)| span)
    }

    pub(super) fn camera(&mut self) -> Option<Camera> {
        if self.camera_parts.failed {
            return None;
        }
        let (eye, eye_span) = self
            .camera_parts
            .eye
            .unwrap_or((Point::ORIGIN, Span::default()));
        let (target, target_span) = match self.camera_parts.target {
            Some(t) => t,
            // The default target can only meet an explicit eye.
            None => (Point::from_coords(DEFAULT_TARGET).ok()?, eye_span),
        };
        if Segment::new(eye, target).is_err() {
            self.report(
                Diagnostic::new(
                    Code::DegenerateCamera,
                    target_span,
                    "the view target coincides with the eye",
                )
                .with_help("`to` must differ from `from` (the eye defaults to the origin)"),
            );
            return None;
        }
        let up = self.camera_parts.up.map(|(p, _)| p);
        if let Some((u, span)) = self.camera_parts.up {
            let collinear = HPlane::through(&eye.into(), &target.into(), &u.into()).is_err();
            if collinear {
                self.report(Diagnostic::new(Code::DegenerateCamera, span, "the up point lies on the line of sight, so it does not fix an up direction").with_help("choose an up point off the h-line through the eye and the target"));
                return None;
            }
        }
        Some(Camera { eye, target, up })
    }
}
