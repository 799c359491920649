//! The ICC colour profiles embedded in TIFF files (tag 34675,
//! `InterColorProfile`): TIFF has no colour-space tag of its own beyond
//! `PhotometricInterpretation = RGB`, and an embedded profile is what image
//! editors and colour-managed viewers read.
//!
//! The profiles are built here rather than shipped as a blob, so every
//! number in them is visible: an ICC version 2.1 display (`mntr`) RGB
//! profile with the sRGB primaries adapted to the D50 connection space by
//! the Bradford transform (the values IEC 61966-2-1 profiles carry), a D50
//! white point, and a tone reproduction curve that is either the sRGB curve
//! sampled at 1024 points or the identity (for linear data).

use crate::display::srgb_decode;

/// Which transfer curve the profile declares.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Curve {
    /// The sRGB transfer function.
    Srgb,
    /// Linear (gamma 1): for float samples of linear radiance.
    Linear,
}

/// Entries of the sampled sRGB curve: the ICC reader interpolates linearly
/// between them, which is within 2e-4 of the exact curve.
const CURVE_POINTS: usize = 1024;

/// The D50 connection-space white, as the ICC specification fixes it.
const D50: [f64; 3] = [0.9642, 1.0, 0.8249];

/// sRGB primaries in D50 XYZ (Bradford-adapted from D65).
const PRIMARIES: [[f64; 3]; 3] = [
    [0.436_074_7, 0.222_504_5, 0.013_932_2],
    [0.385_064_9, 0.716_878_6, 0.097_104_5],
    [0.143_080_4, 0.060_616_9, 0.714_173_3],
];

/// The whole profile, ready to embed.
pub fn rgb_profile(curve: Curve) -> Vec<u8> {
    let description = match curve {
        Curve::Srgb => "sRGB (hscene, IEC 61966-2-1 primaries and curve)",
        Curve::Linear => "Linear sRGB (hscene, sRGB primaries, gamma 1.0)",
    };
    let trc = match curve {
        Curve::Srgb => curv((0..CURVE_POINTS).map(|i| {
            let v = i as f64 / (CURVE_POINTS - 1) as f64;
            (srgb_decode(v) * 65535.0).round() as u16
        })),
        // A single entry is a gamma in u8Fixed8: 0x0100 = 1.0.
        Curve::Linear => curv([0x0100u16]),
    };
    let tags: Vec<([u8; 4], Vec<u8>)> = vec![
        (*b"desc", text_description(description)),
        (*b"cprt", text("No copyright, use freely")),
        (*b"wtpt", xyz(D50)),
        (*b"rXYZ", xyz(PRIMARIES[0])),
        (*b"gXYZ", xyz(PRIMARIES[1])),
        (*b"bXYZ", xyz(PRIMARIES[2])),
        (*b"rTRC", trc.clone()),
        (*b"gTRC", trc.clone()),
        (*b"bTRC", trc),
    ];
    let table_len = 4 + 12 * tags.len();
    let mut data = Vec::new();
    let mut entries = Vec::new();
    for (sig, body) in &tags {
        let offset = 128 + table_len + data.len();
        entries.extend_from_slice(sig);
        entries.extend_from_slice(&be32(offset));
        entries.extend_from_slice(&be32(body.len()));
        data.extend_from_slice(body);
        // Tag data starts on 4-byte boundaries.
        data.resize(data.len().next_multiple_of(4), 0);
    }
    let size = 128 + table_len + data.len();
    let mut out = Vec::with_capacity(size);
    out.extend_from_slice(&be32(size));
    out.extend_from_slice(&[0; 4]); // preferred CMM: none
    out.extend_from_slice(&[2, 0x10, 0, 0]); // version 2.1
    out.extend_from_slice(b"mntrRGB XYZ ");
    // Creation date: a fixed one, so that equal renders give equal files.
    for v in [2026u16, 1, 1, 0, 0, 0] {
        out.extend_from_slice(&v.to_be_bytes());
    }
    out.extend_from_slice(b"acsp");
    out.extend_from_slice(&[0; 24]); // platform, flags, manufacturer, model, attributes
    out.extend_from_slice(&[0; 4]); // rendering intent: perceptual
    out.extend_from_slice(&xyz_numbers(D50));
    out.extend_from_slice(&[0; 4]); // creator
    out.resize(128, 0); // profile ID and reserved bytes
    out.extend_from_slice(&be32(tags.len()));
    out.extend_from_slice(&entries);
    out.extend_from_slice(&data);
    debug_assert_eq!(out.len(), size);
    out
}

fn be32(n: usize) -> [u8; 4] {
    // Profiles here are a few kilobytes.
    (n as u32).to_be_bytes()
}

/// s15Fixed16 numbers.
fn xyz_numbers(v: [f64; 3]) -> Vec<u8> {
    v.iter()
        .flat_map(|c| ((c * 65536.0).round() as i32).to_be_bytes())
        .collect()
}

fn xyz(v: [f64; 3]) -> Vec<u8> {
    let mut out = b"XYZ \0\0\0\0".to_vec();
    out.extend(xyz_numbers(v));
    out
}

fn curv(points: impl IntoIterator<Item = u16>) -> Vec<u8> {
    let points: Vec<u16> = points.into_iter().collect();
    let mut out = b"curv\0\0\0\0".to_vec();
    out.extend_from_slice(&be32(points.len()));
    out.extend(points.iter().flat_map(|p| p.to_be_bytes()));
    out
}

fn text(s: &str) -> Vec<u8> {
    let mut out = b"text\0\0\0\0".to_vec();
    out.extend_from_slice(s.as_bytes());
    out.push(0);
    out
}

/// The version-2 `textDescriptionType`: ASCII, then empty Unicode and
/// ScriptCode descriptions.
fn text_description(s: &str) -> Vec<u8> {
    let mut out = b"desc\0\0\0\0".to_vec();
    out.extend_from_slice(&be32(s.len() + 1));
    out.extend_from_slice(s.as_bytes());
    out.push(0);
    out.extend_from_slice(&[0; 8]); // Unicode language code and count
    out.extend_from_slice(&[0; 3]); // ScriptCode code and count
    out.extend_from_slice(&[0; 67]); // ScriptCode description
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn u32_at(p: &[u8], at: usize) -> usize {
        u32::from_be_bytes([p[at], p[at + 1], p[at + 2], p[at + 3]]) as usize
    }

    /// The header's size is the profile's, the signature is in place, and
    /// every tag lies inside the profile on a 4-byte boundary.
    #[test]
    fn profiles_are_well_formed() {
        for curve in [Curve::Srgb, Curve::Linear] {
            let p = rgb_profile(curve);
            assert_eq!(u32_at(&p, 0), p.len());
            assert_eq!(&p[36..40], b"acsp");
            assert_eq!(&p[12..24], b"mntrRGB XYZ ");
            let count = u32_at(&p, 128);
            assert_eq!(count, 9);
            for k in 0..count {
                let at = 132 + 12 * k;
                let (offset, len) = (u32_at(&p, at + 4), u32_at(&p, at + 8));
                assert_eq!(offset % 4, 0);
                assert!(offset + len <= p.len());
            }
        }
    }

    /// The sampled curve is sRGB's: its middle entry is the linear value
    /// of an sRGB level of 511.5/1023.
    #[test]
    fn srgb_curve_samples_the_transfer_function() {
        let p = rgb_profile(Curve::Srgb);
        let at = p.windows(8).position(|w| w == b"curv\0\0\0\0").unwrap();
        assert_eq!(u32_at(&p, at + 8), CURVE_POINTS);
        let entry = |i: usize| u16::from_be_bytes([p[at + 12 + 2 * i], p[at + 13 + 2 * i]]);
        assert_eq!(entry(0), 0);
        assert_eq!(entry(CURVE_POINTS - 1), 65535);
        let mid = srgb_decode(512.0 / 1023.0) * 65535.0;
        assert!((f64::from(entry(512)) - mid).abs() <= 0.5);
    }
}
