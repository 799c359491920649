//! The `BRDFs` section: Phong materials and their checker textures.

use super::Lowerer;
use super::table::{self, SeenKeys, unknown_word, words};
use crate::diagnostic::{Code, Diagnostic};
use crate::ir::{ImageTexture, Material, Pattern, Rgb, Texture};
use crate::syntax::{BrokenStatement, Clause, Section, Value};

/// A material field.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Field {
    Ambient,
    Diffuse,
    Specular,
    Alpha,
    Trans,
    Shininess,
    Refraction,
    Checker,
    CheckerDiffuse,
    CheckerAmbient,
    Emission,
    Absorption,
    Texture,
    TextureRotate,
}

/// Every material field, in the order the help lists them.
const FIELDS: &[(&str, Field)] = &[
    ("ambient", Field::Ambient),
    ("diffuse", Field::Diffuse),
    ("specular", Field::Specular),
    ("alpha", Field::Alpha),
    ("trans", Field::Trans),
    ("shininess", Field::Shininess),
    ("refraction", Field::Refraction),
    ("checker", Field::Checker),
    ("checker_diffuse", Field::CheckerDiffuse),
    ("checker_ambient", Field::CheckerAmbient),
    ("emission", Field::Emission),
    ("absorption", Field::Absorption),
    ("texture", Field::Texture),
    ("texture_rotate", Field::TextureRotate),
];

/// The names of the material fields, in the order of [`FIELDS`].
pub(crate) const MATERIAL_FIELDS: [&str; FIELDS.len()] = words!(FIELDS, 0);

fn fields_help() -> String {
    format!("material fields are {}", MATERIAL_FIELDS.join(", "))
}

/// The checker fields of one material statement, as given (and the image
/// texture's turn, settled once every field is read).
#[derive(Default)]
struct CheckerFields {
    scale: Option<f64>,
    diffuse: Option<Rgb>,
    ambient: Option<Rgb>,
    rotate: Option<(f64, crate::diagnostic::Span)>,
}

/// `c` with every channel multiplied by `k`.
fn scaled(c: Rgb, k: f64) -> Rgb {
    Rgb::new(c.r * k, c.g * k, c.b * k)
}

/// A material with every field at its default.
fn default_material(name: Option<String>) -> Material {
    Material {
        name,
        ..Material::default()
    }
}

impl Lowerer<'_> {
    /// A material statement that did not parse (already reported) still
    /// takes its number and name, like a broken point statement.
    fn broken_material(&mut self, b: &BrokenStatement) {
        let name = b
            .name
            .as_ref()
            .filter(|_| b.labelled)
            .map(|n| n.text.to_string());
        let index = self
            .materials
            .push(default_material(name.clone()), b.span, true);
        if let Some(n) = &name {
            self.materials.bind(n, index);
        }
    }

    pub(super) fn brdfs_section(&mut self, section: &Section) {
        self.materials
            .reserve(section.statements.len() + section.broken.len());
        let mut broken = section.broken.iter().peekable();
        for st in &section.statements {
            while let Some(b) = broken.next_if(|b| b.span.start() < st.span.start()) {
                self.broken_material(b);
            }
            let mut m = default_material(st.label.as_ref().map(|l| l.text.to_string()));
            let mut seen = SeenKeys::default();
            let mut checker = CheckerFields::default();
            for clause in &st.clauses {
                let Clause::Assign { key, value, .. } = clause else {
                    self.report(
                        Diagnostic::new(
                            Code::WrongType,
                            clause.span(),
                            "expected a `field = value` pair",
                        )
                        .with_help(fields_help()),
                    );
                    continue;
                };
                if let Some(twice) = seen.again(key) {
                    self.report(twice);
                }
                match table::find(FIELDS, &key.text) {
                    Some((_, field)) => self.material_field(*field, value, &mut m, &mut checker),
                    None => self.report(unknown_word(
                        Code::UnknownKey,
                        key,
                        "material field",
                        &MATERIAL_FIELDS,
                        &fields_help(),
                    )),
                }
            }
            match (&mut m.image, checker.rotate) {
                (Some(image), Some((turn, _))) => image.rotate = turn,
                (None, Some((_, span))) => self.report(
                    Diagnostic::new(
                        Code::IneffectiveOption,
                        span,
                        "`texture_rotate` has no effect without `texture = \"file\"`",
                    )
                    .with_help("add `texture = \"image.png\"` or remove `texture_rotate`"),
                ),
                _ => {}
            }
            m.texture = checker.scale.map(|scale| {
                Box::new(Texture {
                    pattern: Pattern::Checker,
                    scale,
                    diffuse: checker.diffuse.unwrap_or(scaled(m.diffuse, 0.25)),
                    ambient: checker.ambient.unwrap_or(scaled(m.ambient, 0.25)),
                })
            });
            if m.texture.is_none()
                && let Some(key) = FIELDS
                    .iter()
                    .filter(|(_, f)| matches!(f, Field::CheckerDiffuse | Field::CheckerAmbient))
                    .find_map(|(name, _)| seen.get(name))
            {
                self.report(
                    Diagnostic::new(
                        Code::IneffectiveOption,
                        key,
                        "the checker colours have no effect without `checker = size`",
                    )
                    .with_help("add `checker = 0.25` (the cell size, a hyperbolic length) or remove the checker colours"),
                );
            }
            let declared = self.materials.push_declared(m, st.span, st.label.as_ref());
            self.report_refused(declared);
        }
        for b in broken {
            self.broken_material(b);
        }
    }

    /// One `field = value` of a material.
    fn material_field(
        &mut self,
        field: Field,
        value: &Value,
        m: &mut Material,
        checker: &mut CheckerFields,
    ) {
        match field {
            Field::Ambient => m.ambient = self.rgb(value).unwrap_or(m.ambient),
            Field::Diffuse => m.diffuse = self.rgb(value).unwrap_or(m.diffuse),
            Field::Specular => m.specular = self.rgb(value).unwrap_or(m.specular),
            Field::Alpha => m.reflection = self.unit_interval(value, "alpha").unwrap_or(0.0),
            Field::Trans => m.transmission = self.unit_interval(value, "trans").unwrap_or(0.0),
            Field::Shininess => {
                if let Some(x) = self.number(value) {
                    if x >= 0.0 {
                        m.shininess = x;
                    } else {
                        self.error(
                            Code::InvalidValue,
                            value.span(),
                            format!("shininess must be non-negative, got {}", hgeom::Compact(x)),
                        );
                    }
                }
            }
            Field::Refraction => {
                if let Some(x) = self.number(value) {
                    if x > 0.0 {
                        m.refraction = x;
                    } else {
                        self.error(
                            Code::InvalidValue,
                            value.span(),
                            format!(
                                "the index of refraction must be positive, got {}",
                                hgeom::Compact(x)
                            ),
                        );
                    }
                }
            }
            Field::Checker => {
                if let Some(x) = self.positive(value, "the checker cell size") {
                    checker.scale = Some(x);
                }
            }
            Field::CheckerDiffuse => checker.diffuse = self.rgb(value),
            Field::CheckerAmbient => checker.ambient = self.rgb(value),
            Field::Emission => m.emission = self.rgb(value).unwrap_or(m.emission),
            Field::Absorption => m.absorption = self.rgb(value).unwrap_or(m.absorption),
            Field::Texture => {
                if let Some((path, image)) = self.image_file(value, "a texture") {
                    let rotate = m.image.as_ref().map_or(0.0, |t| t.rotate);
                    m.image = Some(Box::new(ImageTexture {
                        path,
                        image,
                        rotate,
                    }));
                }
            }
            Field::TextureRotate => {
                if let Some(x) = self.number(value) {
                    if x.is_finite() && x.abs() <= 360.0 {
                        checker.rotate = Some((x.to_radians(), value.span()));
                    } else {
                        self.error(
                            Code::InvalidValue,
                            value.span(),
                            format!(
                                "texture_rotate is an angle in degrees from -360 to 360, got {}",
                                hgeom::Compact(x)
                            ),
                        );
                    }
                }
            }
        }
    }
}
