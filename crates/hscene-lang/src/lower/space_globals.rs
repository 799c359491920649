//! The `Globals` keys of quotient spaces: `space = NAME` or
//! `space = {p,q,r}`, `domain = w, #M` and `light_reach = d`, and the
//! checks of a scene in a space (what cannot be placed there, what lies
//! outside the domain and is folded in). What a space is and how rays,
//! objects and lights behave in it: `docs/manifolds.md`.

use std::path::PathBuf;
use std::sync::Arc;

use hgeom::glam::DMat4;
use hgeom::{HOROSPHERE_CELL_REACH, MAX_COPIES, QuotientSpace, SPACE_NAMES, SpaceKind};

use super::Lowerer;
use super::text::quote;
use crate::diagnostic::{Code, Diagnostic, Span};
use crate::ir::{
    DEFAULT_LIGHT_REACH, DomainEdges, MAX_LIGHT_REACH, MAX_SPACE_LIGHTS, MaterialId, Space,
};
use crate::space_file::{self, SpaceFileError, VOLUME_TOLERANCE};
use crate::syntax::Value;

/// The space keys as given, settled once every object and light is known.
#[derive(Default)]
pub(super) struct SpaceParts {
    kind: Option<(SpaceKind, Span)>,
    /// The pairings of a domain read from a file (`space = "file.json"`).
    pairings: Option<Arc<[DMat4]>>,
    domain: Option<(f64, MaterialId, Span)>,
    light_reach: Option<(f64, Span)>,
    /// `space` was given but refused (a space file that glues no
    /// manifold, an unknown name): `domain` and `light_reach` are then not
    /// "without space", and no HSC1007 says they are.
    refused: bool,
    /// The space came from the caller (`Options::space`), not the text.
    given: bool,
}

impl SpaceParts {
    /// The caller's space ([`crate::Options::space`]): a domain of
    /// pairings, placed at the start of the file for the few messages
    /// that point at the space.
    pub(super) fn give(&mut self, pairings: Arc<[DMat4]>) {
        self.pairings = Some(pairings);
        self.kind = Some((SpaceKind::Pairings, Span::new(0, 0)));
        self.given = true;
    }
}

/// The space keys.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum SpaceKey {
    /// `space`.
    Space,
    /// `domain`.
    Domain,
    /// `light_reach`.
    LightReach,
}

fn spaces_help() -> String {
    format!(
        "spaces are {}, `{{p,q,r}}` (one of the 15 regular honeycombs) for its cell with \
         mirror walls, or a file name in quotes (\"m004.json\") for a manifold given by the \
         face pairings of a Dirichlet domain (docs/manifolds.md)",
        SPACE_NAMES.join(", ")
    )
}

impl Lowerer<'_> {
    /// `space = NAME`, `space = {p,q,r}` or `light_reach = d`; `domain`
    /// comes through [`Lowerer::domain_global`].
    pub(super) fn space_global(&mut self, key: SpaceKey, value: &Value) {
        match key {
            SpaceKey::Space => self.space_name(value),
            SpaceKey::LightReach => {
                let Some(x) = self.number(value) else {
                    return;
                };
                if !(x > 0.0 && x <= MAX_LIGHT_REACH) {
                    self.report(
                        Diagnostic::new(
                            Code::InvalidValue,
                            value.span(),
                            format!(
                                "`light_reach` must be above 0 and at most {MAX_LIGHT_REACH}, got {}",
                                hgeom::Compact(x)
                            ),
                        )
                        .with_help("each image of a light lights the points within this distance of it; 2.5 is the default"),
                    );
                    return;
                }
                self.space.light_reach = Some((x, value.span()));
            }
            SpaceKey::Domain => {
                // `domain` needs its material: the section loop passes it
                // with the clause after it.
                self.domain_global(value, None, value.span());
            }
        }
    }

    /// `domain = w, #M`: the domain's edges as rods of radius `w` in `#M`;
    /// `material` is the clause after the assignment, if any.
    pub(super) fn domain_global(&mut self, width: &Value, material: Option<&Value>, span: Span) {
        let usage = "write `domain = 0.03, #gold;`: the rods' radius, then their material";
        let Some(material) = material else {
            self.report(
                Diagnostic::new(
                    Code::WrongArity,
                    span,
                    "`domain` needs a radius and a material",
                )
                .with_help(usage),
            );
            return;
        };
        let w = self.number(width);
        let m = self.material_arg(material);
        let (Some(w), Some(m)) = (w, m) else {
            return;
        };
        if !(w > 0.0 && w <= 1.0) {
            self.report(
                Diagnostic::new(
                    Code::InvalidValue,
                    width.span(),
                    format!(
                        "the domain's rods need a radius above 0 and at most 1, got {}",
                        hgeom::Compact(w)
                    ),
                )
                .with_help(usage),
            );
            return;
        }
        self.space.domain = Some((w, m, span));
    }

    fn space_name(&mut self, value: &Value) {
        if self.space.given {
            self.report(
                Diagnostic::new(
                    Code::InvalidValue,
                    value.span(),
                    "this scene's space is given by its caller, and so cannot be named here too",
                )
                .with_help("remove `space = ...`, or give no space to Scene.from_str"),
            );
            return;
        }
        // Cleared below once the space is known.
        self.space.refused = true;
        let kind = match value {
            Value::Ident(name) => match SpaceKind::from_name(&name.text) {
                Some(kind) => kind,
                None => {
                    self.report(
                        Diagnostic::new(
                            Code::InvalidValue,
                            value.span(),
                            format!("unknown space `{}`", name.text),
                        )
                        .with_help(spaces_help()),
                    );
                    return;
                }
            },
            Value::Symbol { .. } => {
                let Some(symbol) = self.schlafli(value, &spaces_help()) else {
                    return;
                };
                SpaceKind::Mirrors(symbol)
            }
            Value::Str { text, span } => {
                if let Some(pairings) = self.space_file(text, *span) {
                    self.space.pairings = Some(pairings);
                    self.space.kind = Some((SpaceKind::Pairings, *span));
                    self.space.refused = false;
                }
                return;
            }
            other => {
                self.report(
                    Diagnostic::new(
                        Code::WrongType,
                        other.span(),
                        format!("expected a space's name, found {}", other.describe()),
                    )
                    .with_help(spaces_help()),
                );
                return;
            }
        };
        if let Err(e) = QuotientSpace::new(kind) {
            self.report(
                Diagnostic::new(
                    Code::InvalidValue,
                    value.span(),
                    format!("{kind} cannot be a space here: {e}"),
                )
                .with_help(spaces_help()),
            );
            return;
        }
        self.space.kind = Some((kind, value.span()));
        self.space.refused = false;
    }

    /// The space, once every object and light is known: what cannot be
    /// placed in a space is refused where it is written, and what lies
    /// outside the domain is folded in with a warning (the renderer folds
    /// it: the scene is the same either way).
    pub(super) fn settle_space(&mut self) {
        let Some((kind, kind_span)) = self.space.kind else {
            if self.space.refused {
                return;
            }
            for span in [
                self.space.domain.map(|d| d.2),
                self.space.light_reach.map(|r| r.1),
            ]
            .into_iter()
            .flatten()
            {
                self.report(Diagnostic::new(
                    Code::IneffectiveOption,
                    span,
                    "this has no effect without `space = NAME`: the scene is in H³",
                ));
            }
            return;
        };
        let built = match &self.space.pairings {
            Some(pairings) => QuotientSpace::from_pairings(pairings),
            None => QuotientSpace::new(kind),
        };
        let Ok(space) = built else {
            return;
        };
        let mut found = Vec::new();
        for (k, (o, span)) in self.objects.iter().enumerate() {
            let surfaces = o.shape.to_surfaces();
            let balls: Option<Vec<_>> = surfaces.iter().map(|s| s.bound()).collect();
            let Some(ball) = balls.and_then(|b| b.first().copied()) else {
                found.push(Diagnostic::new(
                    Code::NotInSpace,
                    *span,
                    format!(
                        "a {} is unbounded and cannot be placed in a space: its images would fill it",
                        o.shape.kind_name()
                    ),
                ).with_help("use bounded objects (spheres, polygons, polyhedra, meshes, rods); `domain = w, #M` draws the domain's edges"));
                continue;
            };
            let centre = ball.center();
            if !space.contains(centre, 1e-12) {
                found.push(outside(*span, &format!("object {}", k + 1)));
            }
            let reach = surfaces
                .iter()
                .filter_map(|s| s.bound())
                .map(|b| hgeom::lorentz::distance(centre, b.center()) + b.radius())
                .fold(0.0, f64::max);
            let placed = hgeom::Point::from_hyperboloid(centre)
                .and_then(|p| space.fold(&p).ok())
                .map(|home| home.to_lorentz() * centre);
            // A horosphere-inscribed cell lists its faces only near its
            // base point: what lies deeper in the cell's cusp would miss
            // the images in the faces beyond.
            let too_deep = space.domain().is_none()
                && placed.is_some_and(|home| {
                    hgeom::lorentz::distance(home, hgeom::glam::DVec4::W) + reach
                        > HOROSPHERE_CELL_REACH
                });
            if too_deep {
                found.push(Diagnostic::new(
                    Code::NotInSpace,
                    *span,
                    format!("this object reaches farther than {HOROSPHERE_CELL_REACH} from the origin, too deep in the cell's cusp to be mirrored in all the faces near it"),
                ).with_help("place it nearer the origin (the centre of the cell's face there)"));
            } else if let Some(home) = placed
                && space.copies_meeting(home, reach).is_err()
            {
                found.push(Diagnostic::new(
                    Code::NotInSpace,
                    *span,
                    format!("this object is too large for the domain: more than {MAX_COPIES} of its images would meet it"),
                ).with_help("make it smaller than the domain, or place it away from the cusps"));
            }
        }
        for (k, (l, span)) in self.lights.iter().enumerate() {
            if k == MAX_SPACE_LIGHTS {
                found.push(
                    Diagnostic::new(
                        Code::NotInSpace,
                        *span,
                        format!("a scene in a space may have at most {MAX_SPACE_LIGHTS} lights; this is one more"),
                    )
                    .with_help("each light in a space shines through hundreds of its images; merge lights, or light the scene with `emission`"),
                );
            }
            if l.radius > 0.0 {
                found.push(
                    Diagnostic::new(
                        Code::NotInSpace,
                        *span,
                        "an area light (`radius`) cannot be placed in a space",
                    )
                    .with_help(
                        "use a point light, or a sphere with `emission` for a lamp that is seen",
                    ),
                );
            } else if !l.on_camera && !space.contains(l.position.to_hyperboloid(), 1e-12) {
                found.push(outside(*span, &format!("light {}", k + 1)));
            }
        }
        if self.settings.sky.is_some() {
            found.push(Diagnostic::new(
                Code::IneffectiveOption,
                kind_span,
                "`sky` has no effect in a space: no ray leaves it for the sphere at infinity",
            ));
        }
        for d in found {
            self.report(d);
        }
        self.settings.space = Some(Space {
            kind,
            pairings: self.space.pairings.clone(),
            domain: self
                .space
                .domain
                .map(|(width, material, _)| DomainEdges { width, material }),
            light_reach: self.space.light_reach.map_or(DEFAULT_LIGHT_REACH, |r| r.0),
        });
    }
}

impl Lowerer<'_> {
    /// The pairings of the space file `text` (relative to the scene's
    /// directory), checked as a file and as a gluing; reported at `span`
    /// and `None` if either fails.
    fn space_file(&mut self, text: &str, span: Span) -> Option<Arc<[DMat4]>> {
        let path = match self.base_dir {
            Some(dir) => dir.join(text),
            None => PathBuf::from(text),
        };
        self.inputs.push(path.clone());
        let data = match space_file::load_data(&path) {
            Ok(d) => d,
            Err(SpaceFileError::Io(e)) => {
                self.report(
                    Diagnostic::new(
                        Code::SpaceFileUnreadable,
                        span,
                        format!("cannot read the space file {}: {e}", quote(text)),
                    )
                    .with_help("a relative file name is taken from the scene file's directory"),
                );
                return None;
            }
            Err(e) => {
                self.report(
                    Diagnostic::new(
                        Code::SpaceFileInvalid,
                        span,
                        format!("the space file {} is not one: {e}", quote(text)),
                    )
                    .with_help(FILE_HELP),
                );
                return None;
            }
        };
        let space = match QuotientSpace::from_pairings(&data.pairings) {
            Ok(space) => space,
            Err(e) => {
                self.report(
                    Diagnostic::new(
                        Code::SpaceFileInvalid,
                        span,
                        format!("the pairings in {} glue no manifold: {e}", quote(text)),
                    )
                    .with_help(refusal_help(&e)),
                );
                return None;
            }
        };
        if let (Some(given), Some(own)) = (data.volume, space.volume()) {
            let error = (own - given).abs() / given.abs().max(f64::MIN_POSITIVE);
            if !(error <= VOLUME_TOLERANCE) {
                self.report(
                    Diagnostic::new(
                        Code::VolumeMismatch,
                        span,
                        format!(
                            "the file gives the volume {given}, but its domain's is {own} \
                             ({error:.1e} relative, more than {VOLUME_TOLERANCE:e})"
                        ),
                    )
                    .with_help(
                        "the pairings are not those of the manifold the volume is of, or not \
                         accurate enough: write them from snappy.ManifoldHP as docs/manifolds.md shows",
                    ),
                );
            }
        }
        Some(data.pairings.into())
    }
}

/// What to try after a refusal: where the error is one of precision
/// (a test missed by a measured error), more digits help; a gluing that is
/// wrong is not helped by them.
fn refusal_help(e: &hgeom::GeomError) -> String {
    match e {
        hgeom::GeomError::InexactPairing { .. } | hgeom::GeomError::EdgeCycle { .. } => format!(
            "{FILE_HELP}; if the file came from snappy.Manifold (double precision), write it \
             from snappy.ManifoldHP, whose pairings carry 60 digits (docs/manifolds.md)"
        ),
        _ => FILE_HELP.to_string(),
    }
}

/// What a space file holds.
const FILE_HELP: &str = "a space file is JSON: {\"pairings\": [4×4 Lorentz matrices by rows, time \
                         coordinate first]}, the face pairings of a Dirichlet domain about the \
                         origin, as SnapPy's dirichlet_domain().pairing_matrices() gives them";

/// The warning for something placed outside the domain.
fn outside(span: Span, what: &str) -> Diagnostic {
    Diagnostic::new(
        Code::OutsideDomain,
        span,
        format!("{what} lies outside the fundamental domain; it is folded in (moved by the gluing to its image inside)"),
    )
    .with_help("place it in the domain around the origin to see it where it is written")
}
