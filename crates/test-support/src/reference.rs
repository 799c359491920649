//! High-precision reference geometry (320-bit floats, astro-float), against
//! which hgeom's f64 results are measured (hgeom's reference and derivation
//! tests, the `accuracy` example, the `thesis` benchmark). Every formula here
//! is the textbook one, evaluated naively: at 320 bits the cancellations that
//! f64 must avoid cost nothing.
//!
//! astro-float can fail in two places, both only when memory runs out:
//! building its constant cache and formatting a number. Either gives NaN,
//! which no accuracy bound accepts, so a test measuring against it fails
//! instead of the reference panicking.

use std::cell::RefCell;
use std::ops::{Add, Div, Mul, Neg, Sub};

use astro_float::{BigFloat, Consts, Radix, RoundingMode};
use hgeom::glam::{DVec3, DVec4};

const P: usize = 320;
const RM: RoundingMode = RoundingMode::ToEven;

thread_local! {
    /// astro-float's constant cache; `None` if it could not be built.
    static CC: RefCell<Option<Consts>> = RefCell::new(Consts::new().ok());
}

/// `f` with the constant cache, or NaN without one.
fn with_consts(f: impl FnOnce(&mut Consts) -> BigFloat) -> R {
    CC.with(|cc| match cc.borrow_mut().as_mut() {
        Some(cc) => R(f(cc)),
        None => R(BigFloat::nan(None)),
    })
}

/// A 320-bit real. Every operation rounds to nearest, ties to even.
#[derive(Clone, Debug)]
pub struct R(BigFloat);

impl R {
    /// `x` exactly (every f64 is a 320-bit real).
    pub fn f(x: f64) -> R {
        R(BigFloat::from_f64(x, P))
    }
    /// The nearest f64, through the decimal form (astro-float has no direct
    /// conversion); NaN if the value does not format or parse (a NaN or an
    /// infinity, or no memory).
    pub fn to_f64(&self) -> f64 {
        CC.with(|cc| {
            let mut cc = cc.borrow_mut();
            let cc = cc.as_mut()?;
            self.0.format(Radix::Dec, RM, cc).ok()
        })
        .and_then(|s| s.parse::<f64>().ok())
        .unwrap_or(f64::NAN)
    }
    /// The square root.
    pub fn sqrt(&self) -> R {
        R(self.0.sqrt(P, RM))
    }
    /// The natural logarithm.
    pub fn ln(&self) -> R {
        with_consts(|cc| self.0.ln(P, RM, cc))
    }
    /// `e^x`.
    pub fn exp(&self) -> R {
        with_consts(|cc| self.0.exp(P, RM, cc))
    }
    /// The inverse hyperbolic sine.
    pub fn asinh(&self) -> R {
        with_consts(|cc| self.0.asinh(P, RM, cc))
    }
    /// The hyperbolic sine.
    pub fn sinh(&self) -> R {
        with_consts(|cc| self.0.sinh(P, RM, cc))
    }
    /// The hyperbolic cosine.
    pub fn cosh(&self) -> R {
        with_consts(|cc| self.0.cosh(P, RM, cc))
    }
    /// The absolute value.
    pub fn abs(&self) -> R {
        R(self.0.abs())
    }
    /// Whether the value is negative (false for NaN): the sign test the root
    /// bracketing relies on.
    pub fn is_negative(&self) -> bool {
        self.0.is_negative()
    }
    /// `self < o`; false when either is NaN.
    pub fn lt(&self, o: &R) -> bool {
        self.0.cmp(&o.0).is_some_and(|c| c < 0)
    }
}

macro_rules! binop {
    ($tr:ident, $m:ident) => {
        impl $tr<&R> for &R {
            type Output = R;
            fn $m(self, o: &R) -> R {
                R(self.0.$m(&o.0, P, RM))
            }
        }
        impl $tr<R> for R {
            type Output = R;
            fn $m(self, o: R) -> R {
                R(self.0.$m(&o.0, P, RM))
            }
        }
        impl $tr<&R> for R {
            type Output = R;
            fn $m(self, o: &R) -> R {
                R(self.0.$m(&o.0, P, RM))
            }
        }
    };
}
binop!(Add, add);
binop!(Sub, sub);
binop!(Mul, mul);
binop!(Div, div);

impl Neg for R {
    type Output = R;
    fn neg(self) -> R {
        R(self.0.neg())
    }
}

/// A vector of R^{3,1}, time last.
#[derive(Clone, Debug)]
pub struct V4(pub [R; 4]);

impl V4 {
    /// `v` exactly.
    pub fn from_f64(v: DVec4) -> V4 {
        V4([R::f(v.x), R::f(v.y), R::f(v.z), R::f(v.w)])
    }
    /// Every component times `k`.
    pub fn scale(&self, k: &R) -> V4 {
        V4(self.0.clone().map(|c| c * k))
    }
    /// The componentwise sum.
    pub fn add(&self, o: &V4) -> V4 {
        V4(std::array::from_fn(|i| &self.0[i] + &o.0[i]))
    }
    /// The componentwise difference.
    pub fn sub(&self, o: &V4) -> V4 {
        V4(std::array::from_fn(|i| &self.0[i] - &o.0[i]))
    }
    /// Each component rounded to the nearest f64.
    pub fn to_f64(&self) -> DVec4 {
        DVec4::new(
            self.0[0].to_f64(),
            self.0[1].to_f64(),
            self.0[2].to_f64(),
            self.0[3].to_f64(),
        )
    }
}

/// The Lorentz form.
pub fn ldot(a: &V4, b: &V4) -> R {
    &a.0[0] * &b.0[0] + &a.0[1] * &b.0[1] + &a.0[2] * &b.0[2] - &a.0[3] * &b.0[3]
}

fn norm_sq3(c: DVec3) -> R {
    let (x, y, z) = (R::f(c.x), R::f(c.y), R::f(c.z));
    &x * &x + &y * &y + &z * &z
}

/// `1 - |c|^2` of exactly given ball coordinates.
pub fn gap(c: DVec3) -> R {
    R::f(1.0) - norm_sq3(c)
}

/// The hyperboloid point of exactly given ball coordinates.
pub fn hyperboloid(c: DVec3) -> V4 {
    let g = gap(c);
    let two = R::f(2.0);
    let s = |x: f64| (&two * &R::f(x)) / &g;
    V4([s(c.x), s(c.y), s(c.z), (R::f(1.0) + norm_sq3(c)) / &g])
}

/// The null vector `(xi, 1)` of an ideal point given by a (not necessarily
/// unit) f64 direction, normalised exactly.
pub fn ideal(dir: DVec3) -> V4 {
    let n = norm_sq3(dir).sqrt();
    V4([
        R::f(dir.x) / &n,
        R::f(dir.y) / &n,
        R::f(dir.z) / &n,
        R::f(1.0),
    ])
}

/// Hyperbolic distance between exactly given ball points:
/// `2 asinh(|x-y| / sqrt((1-|x|^2)(1-|y|^2)))`.
pub fn distance(x: DVec3, y: DVec3) -> R {
    let (dx, dy, dz) = (
        R::f(x.x) - R::f(y.x),
        R::f(x.y) - R::f(y.y),
        R::f(x.z) - R::f(y.z),
    );
    let chord = (&dx * &dx + &dy * &dy + &dz * &dz).sqrt();
    R::f(2.0) * (chord / (gap(x) * gap(y)).sqrt()).asinh()
}

/// Hyperbolic distance between hyperboloid points: `2 asinh(|X-Y|_L / 2)`.
pub fn distance_h(x: &V4, y: &V4) -> R {
    let d = x.sub(y);
    R::f(2.0) * (ldot(&d, &d).abs().sqrt() / R::f(2.0)).asinh()
}

/// The geodesic from the origin in the exactly normalised f64 direction
/// `dir`: the point at arc length `t`.
pub fn from_origin(dir: DVec3, t: &R) -> V4 {
    let n = norm_sq3(dir).sqrt();
    let s = t.sinh();
    V4([
        R::f(dir.x) / &n * &s,
        R::f(dir.y) / &n * &s,
        R::f(dir.z) / &n * &s,
        t.cosh(),
    ])
}

/// A root of `f` near `t0` (the f64 answer being checked), by bracketing and
/// bisection to 1e-40. `None` if no sign change is found near `t0`.
pub fn root_near(t0: f64, f: impl Fn(&R) -> R) -> Option<R> {
    let mut delta = 1e-12 * t0.abs().max(1e-3);
    for _ in 0..14 {
        let lo = R::f(t0 - delta);
        let hi = R::f(t0 + delta);
        let (flo, fhi) = (f(&lo), f(&hi));
        if flo.is_negative() != fhi.is_negative() {
            return Some(bisect(lo, hi, flo.is_negative(), &f));
        }
        delta *= 8.0;
    }
    None
}

fn bisect(mut lo: R, mut hi: R, lo_negative: bool, f: &impl Fn(&R) -> R) -> R {
    let half = R::f(0.5);
    for _ in 0..200 {
        let mid = (&lo + &hi) * &half;
        if f(&mid).is_negative() == lo_negative {
            lo = mid;
        } else {
            hi = mid;
        }
        if (&hi - &lo).abs().lt(&R::f(1e-45)) {
            break;
        }
    }
    (&lo + &hi) * &half
}

/// `sinh^2` of the distance from `x` to the h-line through the hyperboloid
/// points `a` and `b`, from the Gram matrix of `a, b`:
/// `sinh^2 d = -1 - (b1^2 + b2^2 - 2 c b1 b2) / (c^2 - 1)` with
/// `b1 = <x,a>`, `b2 = <x,b>`, `c = -<a,b>`.
pub fn sinh2_to_line(x: &V4, a: &V4, b: &V4) -> R {
    let (b1, b2) = (ldot(x, a), ldot(x, b));
    let c = -ldot(a, b);
    let num = &b1 * &b1 + &b2 * &b2 - R::f(2.0) * &c * &b1 * &b2;
    -R::f(1.0) - num / (&c * &c - R::f(1.0))
}

/// `sinh^2` of the distance from `x` to the segment `a b`: to the line when
/// the foot of the perpendicular falls between the ends (both angles at the
/// ends of triangle `x a b` at most 90 degrees), else to the nearer end.
pub fn sinh2_to_segment(x: &V4, a: &V4, b: &V4) -> R {
    let ab = ldot(a, b);
    // Tangent at a towards b is proportional to b + <a,b> a.
    let ua = b.add(&a.scale(&ab));
    let ub = a.add(&b.scale(&ab));
    let one = R::f(1.0);
    if ldot(x, &ua).is_negative() {
        let c = ldot(x, a);
        &c * &c - &one
    } else if ldot(x, &ub).is_negative() {
        let c = ldot(x, b);
        &c * &c - &one
    } else {
        sinh2_to_line(x, a, b)
    }
}
