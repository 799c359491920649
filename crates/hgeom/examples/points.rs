//! Moving and measuring points: distances next to the absolute, a
//! translation along a segment, and what the naive formula gets wrong.
//!
//! ```text
//! cargo run -p hgeom --example points
//! ```

use hgeom::{GeomError, Isometry, Point, Segment};

fn main() -> Result<(), GeomError> {
    println!("distance from the centre of the ball to (r, 0, 0), and the error of two formulas:");
    println!(
        "{:>10}  {:>20}  {:>10}  {:>10}",
        "1 - r", "distance", "hgeom", "naive"
    );
    for k in [1, 4, 8, 12, 15] {
        let p = Point::new(1.0 - 10f64.powi(-k), 0.0, 0.0)?;
        let r = p.coords().x;
        // 1 - r is exact here (Sterbenz), so ln((1 + r) / (1 - r)) is the
        // true distance of the stored point to a few ulps.
        let exact = ((2.0 - (1.0 - r)) / (1.0 - r)).ln();
        // The textbook acosh(1 + 2|x|^2 / (1 - |x|^2)) with 1 - |x|^2 formed
        // as written: the subtraction cancels the digits it needs.
        let naive = (1.0 + 2.0 * r * r / (1.0 - r * r)).acosh();
        let ours = Point::ORIGIN.distance(p);
        println!(
            "{:>10.1e}  {:>20.15}  {:>10.1e}  {:>10.1e}",
            1.0 - r,
            exact,
            (ours - exact).abs(),
            (naive - exact).abs()
        );
    }

    // A translation along a segment moves its start onto its end and keeps
    // every distance.
    let a = Point::new(0.2, 0.1, -0.3)?;
    let b = Point::new(-0.6, 0.5, 0.4)?;
    let slide = Isometry::translation(&Segment::new(a, b)?)?;
    let c = Point::new(0.0, -0.7, 0.1)?;
    println!();
    println!("translation along a -> b (length {:.15}):", a.distance(b));
    println!("  d(T a, b)            = {:.3e}", (slide * a).distance(b));
    println!("  d(a, c)              = {:.15}", a.distance(c));
    println!(
        "  d(T a, T c)          = {:.15}",
        (slide * a).distance(slide * c)
    );

    // Walking far away and back: 200 steps of length ~1.6 out along a
    // segment, then back again with the inverse.
    let step = Isometry::translation(&Segment::new(Point::ORIGIN, Point::new(0.0, 0.0, 0.7)?)?)?;
    let mut there = Isometry::IDENTITY;
    for _ in 0..20 {
        there = step * there;
    }
    let far = there * Point::ORIGIN;
    println!();
    println!(
        "20 steps out: distance {:.6} from the origin, 1 - |x| = {:.3e}",
        Point::ORIGIN.distance(far),
        far.gap() / 2.0
    );
    let back = there.inverse() * far;
    println!(
        "and back:    {:.3e} from where it started",
        back.distance(Point::ORIGIN)
    );
    Ok(())
}
