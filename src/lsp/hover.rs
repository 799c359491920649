//! `textDocument/hover` on a reference or a declared name: where a point or
//! light ends up (ball coordinates after every transformation of frame 0)
//! and its hyperbolic distance from the eye, a material's fields, an
//! object's shapes; lines and planes show their declaration.

use std::fmt::Write as _;

use hgeom::{Point, Vertex};
use hscene_ir::{Rgb, Scene};
use hscene_lang::symbols::{Definition, SymbolKind};
use lsp_types::{Hover, HoverContents, HoverParams, MarkupContent, MarkupKind};

use super::documents::{Document, Documents};
use super::position::range;
use super::request_error::RequestError;

pub fn hover(docs: &Documents, p: HoverParams) -> Result<Option<Hover>, RequestError> {
    let (doc, offset) = docs.at(&p.text_document_position_params)?;
    let symbols = &doc.symbols;
    let Some(hit) = symbols.at(offset) else {
        return Ok(None);
    };
    let hit_span = match hit {
        hscene_lang::symbols::Hit::Use(u) => symbols.uses[u].reference.span,
        hscene_lang::symbols::Hit::Declaration(d) => symbols.definitions[d]
            .name
            .as_ref()
            .map_or(symbols.definitions[d].span, |n| n.span),
    };
    let text = match symbols.definition_of(hit) {
        Some(d) => describe(doc, &symbols.definitions[d]),
        None => match hit {
            hscene_lang::symbols::Hit::Use(u) if is_camera(&symbols.uses[u].reference) => {
                camera(doc.compiled.scene.as_ref())
            }
            _ => return Ok(None),
        },
    };
    Ok(Some(Hover {
        contents: HoverContents::Markup(MarkupContent {
            kind: MarkupKind::Markdown,
            value: text,
        }),
        range: Some(range(&doc.lines, hit_span)),
    }))
}

fn is_camera(r: &hscene_lang::syntax::Reference) -> bool {
    r.sigil == hscene_lang::syntax::RefSigil::At
        && r.target == hscene_lang::syntax::RefTarget::Name("camera".into())
}

/// `@camera`: where the eye looks from and to (after its transformations).
fn camera(scene: Option<&Scene>) -> String {
    let mut out = String::from("**the camera** `@camera`\n\n");
    match scene {
        Some(s) => {
            let _ = writeln!(out, "Eye: `{}`  ", coords(s.camera.eye));
            let _ = writeln!(out, "Looking at: `{}`", coords(s.camera.target));
        }
        None => out.push_str("The scene has errors: final positions are not known.\n"),
    }
    out
}

fn describe(doc: &Document, def: &Definition) -> String {
    let mut out = format!("**{} {}**", def.kind.as_str(), def.label());
    if let (Some(k), Some(_)) = (def.number, &def.name) {
        let _ = write!(out, " (number {k})");
    }
    out.push_str("\n\n");
    let declaration = doc.text[def.span.start()..def.span.end()].trim();
    let _ = writeln!(out, "```hscene\n{declaration}\n```");
    let Some(scene) = &doc.compiled.scene else {
        out.push_str("\nThe scene has errors: final positions are not known.\n");
        return out;
    };
    let eye = scene.camera.eye;
    let facts = match def.kind {
        SymbolKind::Point => def.number.and_then(|k| point(scene, k, eye)),
        SymbolKind::Material => def.number.and_then(|k| material(scene, k)),
        SymbolKind::Object => def.name.as_ref().map(|n| object(scene, &n.text, eye)),
        SymbolKind::Light => def.name.as_ref().and_then(|n| light(scene, &n.text, eye)),
        SymbolKind::Line | SymbolKind::Plane => None,
    };
    if let Some(facts) = facts {
        out.push('\n');
        out.push_str(&facts);
    }
    out
}

fn coords(p: Point) -> String {
    let c = p.coords();
    format!("({}, {}, {})", c.x, c.y, c.z)
}

fn at_distance(p: Point, eye: Point) -> String {
    format!(
        "Final position (ball coordinates, after all transformations): `{}`  \nHyperbolic distance from the eye: `{}`\n",
        coords(p),
        eye.distance(p)
    )
}

fn point(scene: &Scene, number: usize, eye: Point) -> Option<String> {
    let record = scene.points.iter().find(|r| r.number == number)?;
    Some(match record.position {
        Vertex::Interior(p) => at_distance(p, eye),
        Vertex::Ideal(i) => {
            let c = i.coords();
            format!(
                "Ideal point (on the absolute) at `({}, {}, {})`, infinitely far from the eye\n",
                c.x, c.y, c.z
            )
        }
    })
}

fn rgb(c: Rgb) -> String {
    format!("({}, {}, {})", c.r, c.g, c.b)
}

fn material(scene: &Scene, number: usize) -> Option<String> {
    let m = scene.materials.get(number.checked_sub(1)?)?;
    let mut out = String::from("| field | value |\n|---|---|\n");
    let _ = writeln!(out, "| ambient | `{}` |", rgb(m.ambient));
    let _ = writeln!(out, "| diffuse | `{}` |", rgb(m.diffuse));
    let _ = writeln!(out, "| specular | `{}` |", rgb(m.specular));
    let _ = writeln!(out, "| alpha (reflection) | `{}` |", m.reflection);
    let _ = writeln!(out, "| trans (transmission) | `{}` |", m.transmission);
    let _ = writeln!(out, "| shininess | `{}` |", m.shininess);
    let _ = writeln!(out, "| refraction | `{}` |", m.refraction);
    if let Some(t) = &m.texture {
        let _ = writeln!(
            out,
            "| checker | scale `{}`, diffuse `{}` |",
            t.scale,
            rgb(t.diffuse)
        );
    }
    Some(out)
}

fn object(scene: &Scene, name: &str, eye: Point) -> String {
    let mut out = String::new();
    for o in scene
        .objects
        .iter()
        .filter(|o| o.name.as_deref() == Some(name))
    {
        let material = o.material.index() + 1;
        if let Some(s) = o.shape.sphere() {
            let _ = writeln!(
                out,
                "Sphere of radius `{}`, material `#{material}`  ",
                s.radius()
            );
            out.push_str(&at_distance(s.center(), eye));
        } else {
            let _ = writeln!(out, "A {}, material `#{material}`  ", o.shape.kind_name());
        }
    }
    out
}

fn light(scene: &Scene, name: &str, eye: Point) -> Option<String> {
    let l = scene
        .lights
        .iter()
        .find(|l| l.name.as_deref() == Some(name))?;
    Some(format!(
        "{}Diffuse `{}`, specular `{}`\n",
        at_distance(l.position, eye),
        rgb(l.diffuse),
        rgb(l.specular)
    ))
}
