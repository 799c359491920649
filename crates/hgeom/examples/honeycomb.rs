//! The {4,3,5} honeycomb by hand: build the cube whose dihedral angles are
//! 72 degrees, reflect it across its six faces, and check that five cubes
//! meet around every edge and that the neighbours fit face to face.
//!
//! ```text
//! cargo run -p hgeom --example honeycomb
//! ```

use hgeom::{GeomError, Isometry, Point, Polyhedron, Vertex, cube_435, cube_435_circumradius};

fn main() -> Result<(), GeomError> {
    let cube = cube_435()?;
    let centre = cube.center();
    println!(
        "{{4,3,5}} cube: circumradius {:.15} (cosh R = phi^2 / sqrt 2), {} faces",
        cube_435_circumradius(),
        cube.faces().len()
    );

    // One layer of neighbours: the reflection in each face.
    let mirrors: Vec<Isometry> = cube
        .faces()
        .iter()
        .map(|f| Isometry::reflection(&f.plane()))
        .collect();
    let neighbours: Vec<Polyhedron> = mirrors.iter().map(|m| cube.transformed(m)).collect();
    for (i, n) in neighbours.iter().enumerate() {
        // Face to face: the reflected cell shares face i with the cube.
        let shared = &cube.faces()[i];
        let misfit = shared
            .vertices()
            .iter()
            .map(|v| nearest_vertex(v, n))
            .fold(0.0, f64::max);
        println!(
            "neighbour {i}: centre {:.12} away, shared face off by {misfit:.1e}",
            centre.distance(n.center()),
        );
    }

    // Around an edge: alternate the reflections in the two faces meeting
    // there; five steps of each (ten reflections) return to the start,
    // because 5 x 72 degrees = 360 degrees.
    let (f, g) = adjacent_faces(&cube);
    let mut placement = Isometry::IDENTITY;
    let mut centres = vec![centre];
    for k in 0..10 {
        let m = if k % 2 == 0 { &mirrors[f] } else { &mirrors[g] };
        placement = *m * placement;
        centres.push(placement * centre);
    }
    let distinct = count_distinct(&centres[..10]);
    println!(
        "around the edge of faces {f} and {g}: {distinct} cells (images of the centre), \
         back to the start to {:.1e}",
        centres[10].distance(centre)
    );
    Ok(())
}

fn nearest_vertex(v: &Vertex, cell: &Polyhedron) -> f64 {
    let p = interior(v);
    cell.faces()
        .iter()
        .flat_map(|face| face.vertices().iter())
        .map(|w| p.distance(interior(w)))
        .fold(f64::INFINITY, f64::min)
}

fn interior(v: &Vertex) -> Point {
    match v {
        Vertex::Interior(p) => *p,
        Vertex::Ideal(_) => unreachable!("the {{4,3,5}} cube has no ideal vertices"),
    }
}

/// Two faces sharing an edge: two vertices in common.
fn adjacent_faces(cell: &Polyhedron) -> (usize, usize) {
    let faces = cell.faces();
    for i in 0..faces.len() {
        for j in (i + 1)..faces.len() {
            let common = faces[i]
                .vertices()
                .iter()
                .filter(|v| {
                    faces[j]
                        .vertices()
                        .iter()
                        .any(|w| interior(v).distance(interior(w)) < 1e-12)
                })
                .count();
            if common == 2 {
                return (i, j);
            }
        }
    }
    unreachable!("a cube has adjacent faces")
}

fn count_distinct(points: &[Point]) -> usize {
    let mut distinct: Vec<Point> = Vec::new();
    for p in points {
        if distinct.iter().all(|q| q.distance(*p) > 1e-9) {
            distinct.push(*p);
        }
    }
    distinct.len()
}
