//! What the pictures must show because of the geometry: isometry invariance
//! (thesis Fig. 33), nets 2 and 4 agreeing up to interpolation (thesis
//! §8.4), and h-lines seen from the eye as straight lines (thesis §6.4.1).

use hgeom::glam::DVec3;
use hrender::Image;
use hscene_ir::{Net, Rgb};
use hscene_test_support::SplitMix64;
use hscene_test_support::scenes::*;

/// Fraction of pixels whose channels all agree within `tol`; `flip` compares
/// pixel `(x, y)` of `a` with `(W-1-x, y)` of `b`.
fn agreement(a: &Image, b: &Image, tol: f32, flip: bool) -> f64 {
    let (w, h) = (a.width(), a.height());
    let mut good = 0usize;
    for y in 0..h {
        for x in 0..w {
            let bx = if flip { w - 1 - x } else { x };
            let (p, q) = (a.get(x, y), b.get(bx, y));
            if (0..3).all(|c| (p[c] - q[c]).abs() <= tol) {
                good += 1;
            }
        }
    }
    good as f64 / f64::from(w * h)
}

/// Number of pixels that differ from the background: keeps the invariance
/// test from passing on an empty picture.
fn lit(img: &Image, bg: Rgb) -> usize {
    let bg = [bg.r as f32, bg.g as f32, bg.b as f32];
    img.pixels()
        .iter()
        .filter(|p| (0..3).any(|c| (p[c] - bg[c]).abs() > 0.02))
        .count()
}

/// Windows giving every net a similar field of view on the mixed scene
/// (Euclidean for nets 0 and 2, hyperbolic lengths for 1 and 3; net 4 is
/// windowed like net 2).
const WINDOWS: [f64; 5] = [0.12, 0.24, 0.12, 0.24, 0.12];

/// Thesis Fig. 33: moving the eye, the view target, the up point, every
/// object and every light by one isometry leaves the image unchanged. Five
/// random orientation-preserving isometries with translation parts of
/// hyperbolic length 2.5 to 5, every net; 96x96 pixels, at most 0.1 % of
/// them may differ by more than 1/255 (a silhouette pixel may flip on a
/// 1e-12 change of a grazing ray).
#[test]
fn isometries_leave_the_image_unchanged_in_every_net() {
    let mut rng = SplitMix64::new(2024);
    let isometries: Vec<_> = (0..5)
        .map(|_| random_isometry(&mut rng, 5.0, false))
        .collect();
    for (net, window) in Net::ALL.into_iter().zip(WINDOWS) {
        let base = mixed_scene(net, 96, window);
        let reference = draw(&base);
        assert!(
            lit(&reference, base.settings.background) > 96 * 96 / 10,
            "{net:?}"
        );
        for (case, iso) in isometries.iter().enumerate() {
            let moved_image = draw(&moved(&base, iso));
            let share = agreement(&reference, &moved_image, 1.0 / 255.0, false);
            assert!(share >= 0.999, "{net:?}, isometry {case}: {share}");
        }
    }
}

/// An orientation-reversing isometry maps the canonical frame to its mirror
/// image in the plane x = 0 (the camera's right is `up x view`, which a
/// reflection reverses): the picture is the same, flipped left to right.
#[test]
fn reflections_mirror_the_image() {
    let mut rng = SplitMix64::new(99);
    for net in [Net::Euclidean, Net::EquidistantInterpolated] {
        let base = mixed_scene(net, 64, WINDOWS[net.index() as usize]);
        let reference = draw(&base);
        let iso = random_isometry(&mut rng, 4.0, true);
        assert!(!iso.preserves_orientation());
        let mirrored = draw(&moved(&base, &iso));
        let share = agreement(&reference, &mirrored, 1.0 / 255.0, true);
        assert!(share >= 0.999, "{net:?}: {share}");
    }
}

/// Nets 2 and 4 show the same great disk; net 4 interpolates bilinearly
/// from net-3 nodes whose spacing is at most one pixel pitch (equal at the
/// disk's centre, finer elsewhere), so each net-4 pixel is a weighted mean
/// of samples taken within its 3x3 pixel neighbourhood. With `r(p)` the
/// range of the net-2 image over that neighbourhood (largest over the
/// channels):
///
/// * every net-4 pixel lies within `r(p)` (plus one quantum) of the net-2
///   pixel — for 99 % of the pixels (a feature thinner than a pixel can sit
///   between the samples and break the premise);
/// * where the picture is smooth (`r(p) <= 8/255`) that is a tight bound:
///   99 % of those pixels agree to `8/255 + 1/255`;
/// * the mean absolute difference is at most half the mean range: at an
///   edge the interpolated value is a blend, on average half-way.
#[test]
fn nets_two_and_four_agree_up_to_interpolation() {
    const TAU: f32 = 8.0 / 255.0;
    const Q: f32 = 1.0 / 255.0;
    // Odd, so that near the centre the pixel centres fall half-way between
    // net-3 nodes and the interpolation is really exercised.
    const SIZE: u32 = 127;
    let net2 = draw(&mixed_scene(Net::GreatDisk, SIZE, 0.16));
    let net4 = draw(&mixed_scene(Net::EquidistantInterpolated, SIZE, 0.16));
    let (mut pixels, mut within, mut smooth, mut smooth_ok) = (0usize, 0usize, 0usize, 0usize);
    let (mut sum_diff, mut sum_range) = (0.0f64, 0.0f64);
    for y in 1..SIZE - 1 {
        for x in 1..SIZE - 1 {
            let (p, q) = (net2.get(x, y), net4.get(x, y));
            let diff = (0..3)
                .map(|c| (p[c].clamp(0.0, 1.0) - q[c].clamp(0.0, 1.0)).abs())
                .fold(0.0f32, f32::max);
            let mut range = 0.0f32;
            for c in 0..3 {
                let (mut lo, mut hi) = (f32::MAX, f32::MIN);
                for dy in 0..3 {
                    for dx in 0..3 {
                        let v = net2.get(x + dx - 1, y + dy - 1)[c].clamp(0.0, 1.0);
                        lo = lo.min(v);
                        hi = hi.max(v);
                    }
                }
                range = range.max(hi - lo);
            }
            pixels += 1;
            sum_diff += f64::from(diff);
            sum_range += f64::from(range);
            within += usize::from(diff <= range + Q);
            if range <= TAU {
                smooth += 1;
                smooth_ok += usize::from(diff <= TAU + Q);
            }
        }
    }
    let n = pixels as f64;
    assert!(
        within as f64 >= 0.99 * n,
        "{within} of {pixels} within the local range"
    );
    assert!(
        smooth as f64 > 0.7 * n,
        "the picture is mostly smooth: {smooth}"
    );
    assert!(
        smooth_ok as f64 >= 0.99 * smooth as f64,
        "{smooth_ok} of {smooth} smooth pixels agree"
    );
    assert!(
        sum_diff <= 0.5 * sum_range,
        "mean difference {} vs mean range {}",
        sum_diff / n,
        sum_range / n
    );
    // Not vacuous: the picture has edges, and the nets do differ there.
    assert!(sum_diff > 0.0 && (n - smooth as f64) > 500.0);
}

/// Thesis §6.4.1: seen from the eye, every h-line looks straight, because
/// the h-line and the eye span an h-plane through the eye, which is a
/// Euclidean plane through the origin of the canonical frame, and the
/// pinhole net 0 maps such a plane to a line. A thin rod on an h-line that
/// misses the eye is drawn; per column, the centroid of its lit pixels must
/// lie within a pixel of the line through the projections of its end points
/// (and of the least-squares line).
#[test]
fn an_h_line_seen_from_the_eye_is_straight() {
    const SIZE: u32 = 160;
    let (f, window) = (0.1, 0.24);
    let a = p(-0.45, 0.25, 0.35);
    let b = p(0.5, -0.2, 0.55);
    // The rod's segment is a circular arc in the ball, visibly not a chord:
    // its midpoint (the normalised sum on the hyperboloid) is off the
    // Euclidean segment a-b.
    let m = a.to_hyperboloid() + b.to_hyperboloid();
    let m = hgeom::Point::from_hyperboloid(m / (-hgeom::lorentz::dot(m, m)).sqrt()).unwrap();
    let chord = (b.coords() - a.coords()).normalize();
    let off = (m.coords() - a.coords())
        .reject_from_normalized(chord)
        .length();
    assert!(off > 0.05, "the arc is curved: {off}");
    let mut s = scene(
        settings(Net::Euclidean, SIZE, window),
        default_camera(f),
        vec![flat(1.0, 1.0, 1.0)],
        vec![],
        vec![obj(rod(a, b, 0.004), 0)],
    );
    s.settings.background = Rgb::BLACK;
    s.settings.ambient = Rgb::new(1.0, 1.0, 1.0);
    let img = draw(&s);
    // Pixel coordinates (column, row, from the top-left) of a ball point.
    let project = |q: DVec3| {
        let (x, y) = (f * q.x / q.z, f * q.y / q.z);
        (
            (x / window + 0.5) * f64::from(SIZE) - 0.5,
            (0.5 - y / window) * f64::from(SIZE) - 0.5,
        )
    };
    let (pa, pb) = (project(a.coords()), project(b.coords()));
    let mut centres = Vec::new();
    for x in 0..SIZE {
        let (mut w, mut wy) = (0.0, 0.0);
        for y in 0..SIZE {
            let v = f64::from(img.get(x, y)[0]);
            w += v;
            wy += v * f64::from(y);
        }
        if w > 0.5 {
            centres.push((f64::from(x), wy / w));
        }
    }
    assert!(
        centres.len() > SIZE as usize / 2,
        "the streak crosses the view"
    );
    // Distance of each centroid from the predicted line, measured along the
    // column (the streak is far from vertical).
    let slope = (pb.1 - pa.1) / (pb.0 - pa.0);
    let worst = centres
        .iter()
        .map(|(x, y)| (y - (pa.1 + slope * (x - pa.0))).abs())
        .fold(0.0, f64::max);
    assert!(
        worst < 1.0,
        "centroids off the predicted line by {worst} px"
    );
    // And the least-squares line through the centroids fits them to a pixel.
    let n = centres.len() as f64;
    let (mx, my) = centres
        .iter()
        .fold((0.0, 0.0), |(sx, sy), (x, y)| (sx + x / n, sy + y / n));
    let sxy: f64 = centres.iter().map(|(x, y)| (x - mx) * (y - my)).sum();
    let sxx: f64 = centres.iter().map(|(x, _)| (x - mx) * (x - mx)).sum();
    let k = sxy / sxx;
    let fit = centres
        .iter()
        .map(|(x, y)| (y - (my + k * (x - mx))).abs())
        .fold(0.0, f64::max);
    assert!(fit < 1.0, "residual of the fitted line {fit} px");
}
