//! The five pixel nets (docs/rendering.md, "The five pixel nets"): maps from a pixel's fractional position to the
//! primary ray (a diameter from the eye at the origin of the canonical frame).

use hgeom::glam::DVec3;
use hgeom::mobius::add_raw;
use hscene_ir::view::PixelFootprint;
use hscene_ir::{Net, Window};

/// Where a sample of the screen looks.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Sample {
    /// A primary ray from the origin in this (unit) direction.
    Ray(DVec3),
    /// The sample falls outside the part of the view plane the net covers:
    /// it shows the background.
    Outside,
}

/// A net bound to its window and the view-plane distance `f`.
#[derive(Clone, Copy, Debug)]
pub struct PixelNet {
    net: Net,
    window: Window,
    view_distance: f64,
}

impl PixelNet {
    /// Bind a net to its parameters.
    pub fn new(net: Net, window: Window, view_distance: f64) -> PixelNet {
        PixelNet {
            net,
            window,
            view_distance,
        }
    }

    /// Which net it is.
    pub fn net(&self) -> Net {
        self.net
    }

    /// The primary ray for screen position `(sx, sy)`, both in `[-1/2, 1/2]`
    /// with `sx` growing to the right and `sy` upwards.
    ///
    /// Net 4 samples the screen like net 2; the interpolation from net-3 nodes
    /// happens in the renderer, which calls [`PixelNet::equidistant_node`].
    pub fn sample(&self, sx: f64, sy: f64) -> Sample {
        let (w, h, f) = (self.window.width, self.window.height, self.view_distance);
        match self.net {
            Net::Euclidean => {
                let p = DVec3::new(w * sx, h * sy, f);
                if p.length_squared() >= 1.0 {
                    Sample::Outside
                } else {
                    Sample::Ray(p.normalize())
                }
            }
            Net::HyperparallelLines => {
                // The perpendiculars to the x- and y-axes at distances a and b
                // meet at the Klein point (tanh a, tanh b), if anywhere.
                let k = (w * sx).tanh();
                let l = (h * sy).tanh();
                let gap = (1.0 - k * k) - l * l;
                if gap <= 0.0 {
                    return Sample::Outside;
                }
                // Klein -> Poincaré: q = k / (1 + sqrt(1 - |k|^2)).
                let s = 1.0 / (1.0 + gap.sqrt());
                self.through_disk_point(k * s, l * s)
            }
            Net::GreatDisk | Net::EquidistantInterpolated => {
                let (u, v) = (w * sx, h * sy);
                if u * u + v * v >= 1.0 {
                    Sample::Outside
                } else {
                    self.through_disk_point(u, v)
                }
            }
            Net::Equidistant => self.equidistant_node(w * sx, h * sy),
        }
    }

    /// The net-3 node at signed distances `a` from the y-axis and `b` from the
    /// x-axis of the disk: on the disk's hyperboloid `x1 = sinh a`,
    /// `x2 = sinh b`, so the Poincaré point is `(x1, x2) / (1 + x0)`.
    pub fn equidistant_node(&self, a: f64, b: f64) -> Sample {
        let (x1, x2) = (a.sinh(), b.sinh());
        let x0 = (1.0 + x1 * x1 + x2 * x2).sqrt();
        if !x0.is_finite() {
            return Sample::Outside;
        }
        self.through_disk_point(x1 / (1.0 + x0), x2 / (1.0 + x0))
    }

    /// Move the disk point `(u, v, 0)` onto the view plane with the translation
    /// `T_f` along z (Möbius addition of `(0,0,f)`), and aim at it.
    fn through_disk_point(&self, u: f64, v: f64) -> Sample {
        let f = self.view_distance;
        let q = DVec3::new(u, v, 0.0);
        let gap_q = (1.0 - u * u) - v * v;
        let (p, _) = add_raw(DVec3::new(0.0, 0.0, f), 1.0 - f * f, q, gap_q);
        let len = p.length();
        if len > 0.0 && len.is_finite() {
            Sample::Ray(p / len)
        } else {
            Sample::Outside
        }
    }
}

/// How the picture's pixels sample the directions at the eye: the
/// smallest angle between the primary rays of two neighbouring pixels, over
/// the middle and the corners of the picture (nets other than 0 spread
/// their pixels unevenly), and for net 0 (a flat image plane on the +z
/// axis) a lower bound of that angle at the middle, from which each ray's
/// own follows (`hscene_ir::view::PixelFootprint`). `None` if no two
/// neighbours both see the scene. Honeycombs are walked to where their
/// cells shrink below a pixel (`ir::Shape::for_footprint`).
pub fn pixel_footprint(net: &PixelNet, width: u32, height: u32) -> Option<PixelFootprint> {
    let (dx, dy) = (1.0 / f64::from(width), 1.0 / f64::from(height));
    let angles_at = |x: f64, y: f64| {
        let here = net.sample(x, y);
        [(x + dx, y), (x, y + dy)].map(move |(u, v)| match (here, net.sample(u, v)) {
            (Sample::Ray(a), Sample::Ray(b)) => Some(a.angle_between(b)),
            _ => None,
        })
    };
    let usable = |a: &f64| *a > 0.0 && a.is_finite();
    let smallest = [
        (0.0, 0.0),
        (-0.5 + dx, -0.5 + dy),
        (0.5 - 2.0 * dx, 0.5 - 2.0 * dy),
    ]
    .iter()
    .flat_map(|&(x, y)| angles_at(x, y))
    .flatten()
    .filter(usable)
    .min_by(f64::total_cmp)?;
    // The bound `a cos² θ` holds for the angle's rate of change at the
    // ray's own direction; across one pixel it moves by about the pixel
    // angle times tan θ, a few thousandths: 1 % below is a lower bound.
    let plane = match net.net() {
        Net::Euclidean => angles_at(0.0, 0.0)
            .into_iter()
            .flatten()
            .filter(usable)
            .min_by(f64::total_cmp)
            .map(|middle| (DVec3::Z, 0.99 * middle)),
        _ => None,
    };
    Some(PixelFootprint { smallest, plane })
}

#[cfg(test)]
mod tests {
    use super::*;

    const W: Window = Window {
        width: 2.0,
        height: 2.0,
    };

    fn dir(s: Sample) -> DVec3 {
        match s {
            Sample::Ray(d) => d,
            Sample::Outside => panic!("expected a ray"),
        }
    }

    #[test]
    fn centre_pixel_looks_along_z_in_every_net() {
        for net in Net::ALL {
            let d = dir(PixelNet::new(net, W, 0.3).sample(0.0, 0.0));
            assert!((d - DVec3::Z).length() < 1e-15, "{net:?}");
        }
    }

    #[test]
    fn euclidean_net_is_a_pinhole() {
        let n = PixelNet::new(
            Net::Euclidean,
            Window {
                width: 0.2,
                height: 0.2,
            },
            0.1,
        );
        let d = dir(n.sample(0.5, 0.0));
        assert!((d - DVec3::new(0.1, 0.0, 0.1).normalize()).length() < 1e-15);
        assert_eq!(
            PixelNet::new(
                Net::Euclidean,
                Window {
                    width: 4.0,
                    height: 4.0
                },
                0.1
            )
            .sample(0.5, 0.5),
            Sample::Outside
        );
    }

    #[test]
    fn great_disk_and_equidistant_nets_agree_on_axes() {
        // On the x-axis of the disk the equidistant coordinate a is the
        // hyperbolic distance from the centre, so u = tanh(a/2).
        let a = 0.8f64;
        let f = 0.25;
        let eq = PixelNet::new(
            Net::Equidistant,
            Window {
                width: 2.0 * a,
                height: 1.0,
            },
            f,
        );
        let gd = PixelNet::new(
            Net::GreatDisk,
            Window {
                width: 2.0 * (a / 2.0).tanh(),
                height: 1.0,
            },
            f,
        );
        assert!((dir(eq.sample(0.5, 0.0)) - dir(gd.sample(0.5, 0.0))).length() < 1e-14);
    }

    #[test]
    fn hyperparallel_net_leaves_corners_uncovered() {
        let n = PixelNet::new(
            Net::HyperparallelLines,
            Window {
                width: 4.0,
                height: 4.0,
            },
            0.1,
        );
        assert_eq!(n.sample(0.5, 0.5), Sample::Outside);
        assert!(matches!(n.sample(0.1, 0.1), Sample::Ray(_)));
    }

    /// On net 0 the bound `a cos² θ` of the footprint's plane holds for
    /// the angle between every pixel's ray and its neighbours' (the exact
    /// angles, on a grid over a wide and a narrow picture, square and
    /// oblong pixels), and the smallest angle is no larger than the
    /// corner's; other nets have no plane.
    #[test]
    fn footprint_bounds_every_pixel_of_a_flat_picture() {
        for (window, (w, h)) in [
            (
                Window {
                    width: 1.6,
                    height: 1.6,
                },
                (1000, 1000),
            ),
            (
                Window {
                    width: 1.2,
                    height: 0.5,
                },
                (320, 240),
            ),
            (
                Window {
                    width: 0.1,
                    height: 0.1,
                },
                (64, 64),
            ),
        ] {
            let net = PixelNet::new(Net::Euclidean, window, 0.45);
            let fp = pixel_footprint(&net, w, h).unwrap();
            let (axis, a) = fp.plane.unwrap();
            assert_eq!(axis, DVec3::Z);
            let (dx, dy) = (1.0 / f64::from(w), 1.0 / f64::from(h));
            let mut checked = 0;
            for gi in 0..=20 {
                for gj in 0..=20 {
                    let x = -0.5 + f64::from(gi) / 20.0 * (1.0 - 2.0 * dx);
                    let y = -0.5 + f64::from(gj) / 20.0 * (1.0 - 2.0 * dy);
                    let Sample::Ray(u) = net.sample(x, y) else {
                        continue;
                    };
                    for (p, q) in [(x + dx, y), (x, y + dy)] {
                        let Sample::Ray(v) = net.sample(p, q) else {
                            continue;
                        };
                        let angle = u.angle_between(v);
                        let cos = u.dot(axis);
                        assert!(
                            angle >= a * cos * cos,
                            "{x} {y}: {angle} < {}",
                            a * cos * cos
                        );
                        checked += 1;
                    }
                }
            }
            assert!(checked > 400, "{checked}");
            // The smallest angle is no larger than the middle's.
            assert!(fp.smallest <= a / 0.99);
        }
        let disk = PixelNet::new(
            Net::GreatDisk,
            Window {
                width: 1.6,
                height: 1.6,
            },
            0.45,
        );
        assert_eq!(pixel_footprint(&disk, 100, 100).unwrap().plane, None);
    }
}
