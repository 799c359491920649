//! Fog, the depth cue of hyperbolic space: the radiance a ray segment
//! carries to its origin is mixed towards the fog colour by the segment's
//! hyperbolic length `s`, `L' = L e^{-s/D} + C (1 - e^{-s/D})`, and a ray
//! that leaves the scene (infinite length) brings the fog colour itself.
//! Applied to every segment the Whitted integrator follows (primary, reflected,
//! refracted), so a mirror image is fogged by the whole path. Shadow rays
//! are not fogged: fog here is a depth cue, not a medium that absorbs the
//! lights' power.

use hscene_ir::{Fog, Rgb};

/// The radiance `c` seen through `s` of fog (`s >= 0`, hyperbolic length).
#[inline]
pub fn through_fog(fog: &Fog, c: Rgb, s: f64) -> Rgb {
    // exp(-s/D) underflows to 0 for long segments: the fog colour exactly.
    let keep = (-s / fog.distance).exp();
    c * keep + fog.color * (-(-s / fog.distance).exp_m1())
}

#[cfg(test)]
mod tests {
    use super::*;

    const FOG: Fog = Fog {
        color: Rgb {
            r: 0.5,
            g: 0.6,
            b: 0.7,
        },
        distance: 2.0,
    };

    #[test]
    fn mixes_by_the_exponential_of_the_length() {
        let c = Rgb::new(1.0, 0.0, 0.25);
        assert_eq!(through_fog(&FOG, c, 0.0), c);
        let k = (-0.5f64).exp();
        let got = through_fog(&FOG, c, 1.0);
        for (g, (x, f)) in got
            .channels()
            .iter()
            .zip(c.channels().iter().zip([0.5, 0.6, 0.7]))
        {
            assert!((g - (x * k + f * (1.0 - k))).abs() < 1e-15);
        }
        assert_eq!(through_fog(&FOG, c, 1e4), Rgb::new(0.5, 0.6, 0.7));
    }
}
