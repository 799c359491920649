//! `hscene.geom`: hgeom's exact geometry in Python. Points are given in
//! ball coordinates (or on the hyperboloid as `(x, y, z, t)`, time last,
//! hgeom's order); isometries are hgeom's, with their Lorentz matrices.
//! Every constructor is hgeom's checked one: what it refuses is a
//! `ValueError` with its words.

use hgeom::glam::{DMat3, DVec3};
use hgeom::{GeomError, HLine, HPlane, Isometry as HIsometry, Point as HPoint, Schlafli};
use numpy::ndarray::{Array1, Array2};
use numpy::{IntoPyArray, PyArray1, PyArray2};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use rayon::prelude::*;

use crate::arrays;

/// hgeom's refusal as a `ValueError`.
pub fn geom_error(e: GeomError) -> PyErr {
    PyValueError::new_err(e.to_string())
}

/// A point of hyperbolic space, strictly inside the unit ball.
#[pyclass(module = "hscene.geom", frozen)]
#[derive(Clone, Copy)]
pub struct Point(HPoint);

impl Point {
    pub fn inner(&self) -> HPoint {
        self.0
    }

    pub fn from_inner(p: HPoint) -> Point {
        Point(p)
    }
}

/// Ball coordinates from a `Point` or three numbers.
fn point_arg(value: &Bound<'_, PyAny>, what: &str) -> PyResult<HPoint> {
    if let Ok(p) = value.cast::<Point>() {
        return Ok(p.get().0);
    }
    HPoint::from_coords(arrays::vec3(value, what)?).map_err(geom_error)
}

#[pymethods]
impl Point {
    /// The point with ball coordinates (x, y, z), |(x, y, z)| < 1.
    #[new]
    fn new(x: f64, y: f64, z: f64) -> PyResult<Point> {
        HPoint::new(x, y, z).map(Point).map_err(geom_error)
    }

    /// The point with these ball coordinates (three numbers or an array).
    #[staticmethod]
    fn from_ball(coords: &Bound<'_, PyAny>) -> PyResult<Point> {
        point_arg(coords, "ball coordinates").map(Point)
    }

    /// The point on the hyperboloid `t² - x² - y² - z² = 1`, `t > 0`,
    /// given as (x, y, z, t) (`time="last"`) or (t, x, y, z) (`"first"`).
    #[staticmethod]
    #[pyo3(signature = (coords, *, time="last"))]
    fn from_hyperboloid(coords: &Bound<'_, PyAny>, time: &str) -> PyResult<Point> {
        let v = arrays::vec4(coords, "hyperboloid coordinates")?;
        let v = if arrays::time_first(time)? {
            hgeom::glam::DVec4::new(v.y, v.z, v.w, v.x)
        } else {
            v
        };
        HPoint::from_hyperboloid(v).map(Point).ok_or_else(|| {
            PyValueError::new_err(
                "not a point of the hyperboloid: the vector must be finite and future timelike",
            )
        })
    }

    /// The origin.
    #[staticmethod]
    fn origin() -> Point {
        Point(HPoint::ORIGIN)
    }

    /// The point at hyperbolic distance `distance` from the origin in the
    /// direction `direction` (three numbers, not zero).
    #[staticmethod]
    fn at_distance(direction: &Bound<'_, PyAny>, distance: f64) -> PyResult<Point> {
        let dir = arrays::vec3(direction, "direction")?;
        HPoint::at_distance_from_origin(dir, distance)
            .map(Point)
            .map_err(geom_error)
    }

    /// Ball coordinates, a float64 array of 3.
    #[getter]
    fn ball<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        Array1::from_vec(self.0.coords().to_array().to_vec()).into_pyarray(py)
    }

    /// Hyperboloid coordinates (x, y, z, t), time last.
    #[getter]
    fn hyperboloid<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        Array1::from_vec(self.0.to_hyperboloid().to_array().to_vec()).into_pyarray(py)
    }

    /// `1 - |x|²`, computed accurately (the point's distance from the
    /// absolute, in the ball).
    #[getter]
    fn gap(&self) -> f64 {
        self.0.gap()
    }

    /// Hyperbolic distance to `other`.
    fn distance(&self, other: &Point) -> f64 {
        self.0.distance(other.0)
    }

    fn __repr__(&self) -> String {
        let c = self.0.coords();
        format!("Point({:?}, {:?}, {:?})", c.x, c.y, c.z)
    }

    fn __getnewargs__(&self) -> (f64, f64, f64) {
        let c = self.0.coords();
        (c.x, c.y, c.z)
    }
}

/// An orientation-preserving or -reversing isometry of H³.
#[pyclass(module = "hscene.geom", frozen)]
#[derive(Clone)]
pub struct Isometry(HIsometry);

#[pymethods]
impl Isometry {
    /// The identity.
    #[new]
    fn new() -> Isometry {
        Isometry(HIsometry::IDENTITY)
    }

    /// The isometry with this 4 × 4 Lorentz matrix (by rows; time
    /// coordinate `time`, "last" as hgeom or "first" as SnapPy), acting on
    /// hyperboloid column vectors.
    #[staticmethod]
    #[pyo3(signature = (matrix, *, time="last"))]
    fn from_matrix(matrix: &Bound<'_, PyAny>, time: &str) -> PyResult<Isometry> {
        let m = arrays::mat4(matrix, "the matrix", arrays::time_first(time)?)?;
        HIsometry::from_lorentz(m).map(Isometry).map_err(geom_error)
    }

    /// Its 4 × 4 Lorentz matrix (float64, by rows).
    #[pyo3(signature = (*, time="last"))]
    fn to_matrix<'py>(&self, py: Python<'py>, time: &str) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let rows = arrays::mat4_rows(&self.0.to_lorentz(), arrays::time_first(time)?);
        let data: Vec<f64> = rows.iter().flatten().copied().collect();
        Array2::from_shape_vec((4, 4), data)
            .map(|a| a.into_pyarray(py))
            .map_err(|e| PyValueError::new_err(e.to_string()))
    }

    /// The translation that takes `start` to `end` along their geodesic.
    #[staticmethod]
    fn translation(start: &Bound<'_, PyAny>, end: &Bound<'_, PyAny>) -> PyResult<Isometry> {
        let (a, b) = (point_arg(start, "start")?, point_arg(end, "end")?);
        let segment = hgeom::Segment::new(a, b).map_err(geom_error)?;
        HIsometry::translation(&segment)
            .map(Isometry)
            .map_err(geom_error)
    }

    /// The translation along `line` by `distance` (towards its second end).
    #[staticmethod]
    fn translation_along(line: &Line, distance: f64) -> PyResult<Isometry> {
        if !distance.is_finite() {
            return Err(PyValueError::new_err(format!(
                "the distance must be finite, not {distance}"
            )));
        }
        // The canonical line is the z axis: translate along it, and carry
        // that onto the line.
        let to_line = line.0.to_line();
        let along = HPoint::at_distance_from_origin(DVec3::Z, distance.abs())
            .map(|p| {
                if distance < 0.0 {
                    HPoint::from_coords(-p.coords())
                } else {
                    Ok(p)
                }
            })
            .and_then(|p| p)
            .map_err(geom_error)?;
        let t = HIsometry::transvection_from_origin(along);
        Ok(Isometry(to_line.compose(&t).compose(&to_line.inverse())))
    }

    /// The rotation by `angle` radians about `line` (right-handed about
    /// its direction).
    #[staticmethod]
    fn rotation(line: &Line, angle: f64) -> PyResult<Isometry> {
        HIsometry::rotation(&line.0, angle)
            .map(Isometry)
            .map_err(geom_error)
    }

    /// The rotation by `angle` radians about the axis through the origin
    /// with direction `axis`.
    #[staticmethod]
    fn rotation_about_origin(axis: &Bound<'_, PyAny>, angle: f64) -> PyResult<Isometry> {
        let axis = arrays::vec3(axis, "axis")?;
        if axis.length_squared() == 0.0 || !angle.is_finite() {
            return Err(PyValueError::new_err(
                "the axis must be a non-zero direction and the angle finite",
            ));
        }
        HIsometry::orthogonal(DMat3::from_axis_angle(axis.normalize(), angle))
            .map(Isometry)
            .map_err(geom_error)
    }

    /// The reflection in `plane`.
    #[staticmethod]
    fn reflection(plane: &Plane) -> Isometry {
        Isometry(HIsometry::reflection(&plane.0))
    }

    /// The inverse.
    fn inverse(&self) -> Isometry {
        Isometry(self.0.inverse())
    }

    /// Whether it preserves orientation.
    #[getter]
    fn preserves_orientation(&self) -> bool {
        self.0.preserves_orientation()
    }

    /// The image of a point; or of N points, an N × 3 array of ball
    /// coordinates, as an N × 3 array.
    fn apply<'py>(
        &self,
        py: Python<'py>,
        points: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        if let Ok(p) = points.cast::<Point>() {
            let image = self.0.checked_apply(&p.get().0).map_err(geom_error)?;
            return Ok(Bound::new(py, Point(image))?.into_any());
        }
        let (n, data) = ball_rows(points, "points")?;
        let iso = self.0;
        let out = py.detach(|| {
            data.par_chunks_exact(3)
                .map(|c| {
                    let p = HPoint::from_coords(DVec3::new(c[0], c[1], c[2]))?;
                    iso.checked_apply(&p).map(|q| q.coords().to_array())
                })
                .collect::<Result<Vec<_>, GeomError>>()
        });
        let out = out.map_err(geom_error)?;
        let flat: Vec<f64> = out.into_iter().flatten().collect();
        Array2::from_shape_vec((n, 3), flat)
            .map(|a| a.into_pyarray(py).into_any())
            .map_err(|e| PyValueError::new_err(e.to_string()))
    }

    /// `f @ g` is `f` after `g`; `f @ p` is `f` applied to the point `p`.
    fn __matmul__<'py>(
        &self,
        py: Python<'py>,
        other: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        if let Ok(g) = other.cast::<Isometry>() {
            return Ok(Bound::new(py, Isometry(self.0.compose(&g.get().0)))?.into_any());
        }
        self.apply(py, other)
    }

    /// As `@`.
    fn __mul__<'py>(
        &self,
        py: Python<'py>,
        other: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        self.__matmul__(py, other)
    }

    fn __call__<'py>(
        &self,
        py: Python<'py>,
        points: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        self.apply(py, points)
    }

    fn __repr__(&self) -> String {
        let a = self.0.translation_part().coords();
        format!(
            "<hscene.geom.Isometry moving the origin to ({:.6}, {:.6}, {:.6})>",
            a.x, a.y, a.z
        )
    }
}

/// A complete geodesic.
#[pyclass(module = "hscene.geom", frozen)]
pub struct Line(HLine);

#[pymethods]
impl Line {
    /// The line through the points `a` and `b`.
    #[new]
    fn new(a: &Bound<'_, PyAny>, b: &Bound<'_, PyAny>) -> PyResult<Line> {
        let (a, b) = (point_arg(a, "a")?, point_arg(b, "b")?);
        HLine::through(&a.into(), &b.into())
            .map(Line)
            .map_err(geom_error)
    }

    /// The line through `point` with the ball direction `direction` there.
    #[staticmethod]
    fn from_point_direction(
        point: &Bound<'_, PyAny>,
        direction: &Bound<'_, PyAny>,
    ) -> PyResult<Line> {
        let p = point_arg(point, "point")?;
        let d = arrays::vec3(direction, "direction")?;
        HLine::from_point_direction(&p, d)
            .map(Line)
            .map_err(geom_error)
    }

    /// The point at signed arc length `s` from its base point.
    fn point_at(&self, s: f64) -> PyResult<Point> {
        self.0.point_at(s).map(Point).map_err(geom_error)
    }

    /// The point of the line nearest the origin.
    #[getter]
    fn base(&self) -> Point {
        Point(self.0.base())
    }

    /// Its two ideal end points, unit vectors (ball coordinates on the
    /// sphere at infinity), as a 2 × 3 array.
    #[getter]
    fn ends<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let (a, b) = self.0.ends();
        let data = [a.coords().to_array(), b.coords().to_array()].concat();
        Array2::from_shape_vec((2, 3), data)
            .map(|a| a.into_pyarray(py))
            .map_err(|e| PyValueError::new_err(e.to_string()))
    }

    /// Hyperbolic distance from `point` to the line.
    fn distance_to(&self, point: &Bound<'_, PyAny>) -> PyResult<f64> {
        Ok(self.0.distance_to(&point_arg(point, "point")?))
    }

    /// Its image under `isometry`.
    fn transformed(&self, isometry: &Isometry) -> Line {
        Line(self.0.transformed(&isometry.0))
    }
}

/// A totally geodesic plane.
#[pyclass(module = "hscene.geom", frozen)]
pub struct Plane(HPlane);

#[pymethods]
impl Plane {
    /// The plane through three points.
    #[new]
    fn new(a: &Bound<'_, PyAny>, b: &Bound<'_, PyAny>, c: &Bound<'_, PyAny>) -> PyResult<Plane> {
        let (a, b, c) = (point_arg(a, "a")?, point_arg(b, "b")?, point_arg(c, "c")?);
        HPlane::through(&a.into(), &b.into(), &c.into())
            .map(Plane)
            .map_err(geom_error)
    }

    /// The perpendicular bisector of `a` and `b` (`a` on its positive side).
    #[staticmethod]
    fn bisector(a: &Bound<'_, PyAny>, b: &Bound<'_, PyAny>) -> PyResult<Plane> {
        HPlane::bisector(&point_arg(a, "a")?, &point_arg(b, "b")?)
            .map(Plane)
            .map_err(geom_error)
    }

    /// The plane through `start` orthogonal to the geodesic towards `towards`.
    #[staticmethod]
    fn orthogonal_at(start: &Bound<'_, PyAny>, towards: &Bound<'_, PyAny>) -> PyResult<Plane> {
        HPlane::orthogonal_at(&point_arg(start, "start")?, &point_arg(towards, "towards")?)
            .map(Plane)
            .map_err(geom_error)
    }

    /// The plane with this unit spacelike normal (x, y, z, t).
    #[staticmethod]
    fn from_normal(normal: &Bound<'_, PyAny>) -> PyResult<Plane> {
        HPlane::from_normal(arrays::vec4(normal, "normal")?)
            .map(Plane)
            .map_err(geom_error)
    }

    /// Its unit spacelike normal (x, y, z, t), time last.
    #[getter]
    fn normal<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        Array1::from_vec(self.0.normal().to_array().to_vec()).into_pyarray(py)
    }

    /// Signed hyperbolic distance from the plane to `point` (positive on
    /// the side the normal points to).
    fn signed_distance(&self, point: &Bound<'_, PyAny>) -> PyResult<f64> {
        Ok(self.0.signed_distance(&point_arg(point, "point")?))
    }

    /// The reflection in the plane.
    fn reflection(&self) -> Isometry {
        Isometry(HIsometry::reflection(&self.0))
    }

    /// Its image under `isometry`.
    fn transformed(&self, isometry: &Isometry) -> Plane {
        Plane(self.0.transformed(&isometry.0))
    }
}

/// An N × 3 array of ball coordinates, as N and its numbers by rows.
fn ball_rows(value: &Bound<'_, PyAny>, what: &str) -> PyResult<(usize, Vec<f64>)> {
    let (shape, data) = arrays::floats(value, what)?;
    match shape.as_slice() {
        [n, 3] => Ok((*n, data)),
        [3] => Ok((1, data)),
        _ => Err(PyValueError::new_err(format!(
            "{what} must be an N x 3 array of ball coordinates, not an array of shape {shape:?}"
        ))),
    }
}

/// Hyperbolic distance between two points; or, for two N × 3 arrays of
/// ball coordinates, the N distances row by row (in parallel, without the
/// GIL). A row that is not finite or not inside the ball is a ValueError
/// naming it.
#[pyfunction]
fn distance<'py>(
    py: Python<'py>,
    a: &Bound<'py, PyAny>,
    b: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyAny>> {
    if let (Ok(p), Ok(q)) = (a.cast::<Point>(), b.cast::<Point>()) {
        return Ok(p.get().0.distance(q.get().0).into_pyobject(py)?.into_any());
    }
    let (n, xs) = ball_rows(a, "a")?;
    let (m, ys) = ball_rows(b, "b")?;
    if n != m {
        return Err(PyValueError::new_err(format!(
            "a and b must have as many points: {n} and {m}"
        )));
    }
    let out = py.detach(|| {
        xs.par_chunks_exact(3)
            .zip(ys.par_chunks_exact(3))
            .enumerate()
            .map(|(k, (x, y))| {
                let p = HPoint::from_coords(DVec3::new(x[0], x[1], x[2]));
                let q = HPoint::from_coords(DVec3::new(y[0], y[1], y[2]));
                match (p, q) {
                    (Ok(p), Ok(q)) => Ok(p.distance(q)),
                    (Err(e), _) => Err(format!("a[{k}]: {e}")),
                    (_, Err(e)) => Err(format!("b[{k}]: {e}")),
                }
            })
            .collect::<Result<Vec<f64>, String>>()
    });
    let out = out.map_err(PyValueError::new_err)?;
    Ok(Array1::from_vec(out).into_pyarray(py).into_any())
}

/// The midpoint of the geodesic segment from `a` to `b`.
#[pyfunction]
fn midpoint(a: &Bound<'_, PyAny>, b: &Bound<'_, PyAny>) -> PyResult<Point> {
    let (a, b) = (point_arg(a, "a")?, point_arg(b, "b")?);
    if a.coords() == b.coords() {
        return Ok(Point(a));
    }
    // Translate `a` to the origin; there the midpoint of the segment to
    // `b'` is at half its distance along its direction; translate back.
    let to_origin = HIsometry::transvection_from_origin(a).inverse();
    let b0 = to_origin.apply(&b);
    let half = HPoint::at_distance_from_origin(b0.coords(), 0.5 * b0.distance_from_origin())
        .map_err(geom_error)?;
    Ok(Point(to_origin.inverse().apply(&half)))
}

/// A regular honeycomb `{p,q,r}` of H³ (one of the fifteen), placed as
/// `Honeycomb {p,q,r}` places it: its measures and its base cell.
#[pyclass(module = "hscene.geom", frozen)]
pub struct Honeycomb {
    symbol: Schlafli,
    simplex: hgeom::CoxeterSimplex,
}

impl Honeycomb {
    /// The distance between simplex vertices `i` and `j` (the module docs
    /// of hgeom's `simplex.rs`: 0 a vertex, 1 an edge's midpoint, 2 a
    /// face's centre, 3 the cell's centre); infinite when either is ideal.
    fn between(&self, i: usize, j: usize) -> f64 {
        let ideal = self.simplex.ideal();
        if ideal[i] || ideal[j] {
            return f64::INFINITY;
        }
        let v = self.simplex.vertices();
        hgeom::lorentz::distance(v[i], v[j])
    }
}

/// Most vertices a cell is searched for (the largest finite cell, the
/// icosahedron's dual's, has 20).
const MAX_CELL_VERTICES: usize = 64;

#[pymethods]
impl Honeycomb {
    /// The honeycomb `{p,q,r}`; a symbol that is not one of the fifteen
    /// hyperbolic ones is a ValueError saying what it is.
    #[new]
    fn new(p: u32, q: u32, r: u32) -> PyResult<Honeycomb> {
        let symbol = Schlafli::new(p, q, r).map_err(|e| PyValueError::new_err(e.to_string()))?;
        Ok(Honeycomb {
            symbol,
            simplex: hgeom::CoxeterSimplex::new(symbol),
        })
    }

    /// The symbol (p, q, r).
    #[getter]
    fn symbol(&self) -> (u32, u32, u32) {
        (self.symbol.p(), self.symbol.q(), self.symbol.r())
    }

    /// Edge length (infinite with ideal vertices).
    #[getter]
    fn edge_length(&self) -> f64 {
        2.0 * self.between(0, 1)
    }

    /// Distance from a cell's centre to its faces (infinite for cells
    /// inscribed in horospheres).
    #[getter]
    fn inradius(&self) -> f64 {
        self.between(3, 2)
    }

    /// Distance from a cell's centre to its edges' midpoints.
    #[getter]
    fn midradius(&self) -> f64 {
        self.between(3, 1)
    }

    /// Distance from a cell's centre to its vertices.
    #[getter]
    fn circumradius(&self) -> f64 {
        self.between(3, 0)
    }

    /// Dihedral angle of a cell at an edge, 2π/r radians.
    #[getter]
    fn dihedral_angle(&self) -> f64 {
        2.0 * std::f64::consts::PI / f64::from(self.symbol.r())
    }

    /// Whether every cell and vertex is finite.
    #[getter]
    fn is_compact(&self) -> bool {
        self.symbol.is_compact()
    }

    /// Whether the vertices are ideal (on the sphere at infinity).
    #[getter]
    fn has_ideal_vertices(&self) -> bool {
        self.symbol.has_ideal_vertices()
    }

    /// Whether the cells are inscribed in horospheres (infinitely many faces).
    #[getter]
    fn has_ideal_cells(&self) -> bool {
        self.symbol.has_ideal_cells()
    }

    /// The base cell's vertices in ball coordinates, V × 3 (ideal
    /// vertices are unit vectors). The cell's symmetry group is
    /// generated by the reflections in the simplex's walls through its
    /// centre (0, 1, 2); the vertices are the orbit of the simplex's
    /// vertex 0.
    fn cell_vertices<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        if self.symbol.has_ideal_cells() {
            return Err(PyValueError::new_err(format!(
                "the cells of {} are inscribed in horospheres and have infinitely many vertices",
                self.symbol
            )));
        }
        let v0 = self.simplex.vertices()[0];
        let walls: Vec<_> = (0..3).map(|i| self.simplex.reflection(i)).collect();
        // The ball point of a hyperboloid point, or the direction of a
        // null vector (an ideal vertex, time 1).
        let ideal = self.simplex.ideal()[0];
        let to_ball = |x: hgeom::glam::DVec4| {
            if ideal {
                x.truncate() / x.w
            } else {
                x.truncate() / (1.0 + x.w)
            }
        };
        let mut found = vec![v0];
        let mut k = 0;
        while k < found.len() {
            let x = found[k];
            for w in &walls {
                let y = *w * x;
                if !found
                    .iter()
                    .any(|z| (to_ball(*z) - to_ball(y)).length() < 1e-9)
                {
                    if found.len() == MAX_CELL_VERTICES {
                        return Err(PyValueError::new_err(
                            "too many vertices: not a finite cell",
                        ));
                    }
                    found.push(y);
                }
            }
            k += 1;
        }
        let data: Vec<f64> = found.iter().flat_map(|x| to_ball(*x).to_array()).collect();
        Array2::from_shape_vec((found.len(), 3), data)
            .map(|a| a.into_pyarray(py))
            .map_err(|e| PyValueError::new_err(e.to_string()))
    }

    fn __repr__(&self) -> String {
        format!(
            "Honeycomb({}, {}, {})",
            self.symbol.p(),
            self.symbol.q(),
            self.symbol.r()
        )
    }
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<Point>()?;
    m.add_class::<Isometry>()?;
    m.add_class::<Line>()?;
    m.add_class::<Plane>()?;
    m.add_class::<Honeycomb>()?;
    m.add_function(wrap_pyfunction!(distance, m)?)?;
    m.add_function(wrap_pyfunction!(midpoint, m)?)?;
    Ok(())
}
