//! The 8-bit mapping shared by the BMP and PNG writers.
//!
//! By default it reproduces the original PA writer, `int(c * 255)`: clamp to
//! [0, 1], apply `c^(1/gamma)` when a gamma is given, scale by 255 and
//! truncate. NaN becomes 0. An [`Encoding`] may first multiply by
//! `2^exposure` and apply a tone curve (see `tonemap`).

use crate::color::Color;

use super::tonemap::{Encoding, Tonemap};

/// Maps linear channel values to bytes for one encoding.
#[derive(Clone, Copy, Debug)]
pub(super) struct Quantizer {
    /// `2^exposure`.
    scale: f64,
    tonemap: Tonemap,
    inverse_gamma: Option<f64>,
}

impl Quantizer {
    /// The PA framework writer's mapping: no exposure, curve or gamma.
    pub(super) const FRAMEWORK: Quantizer = Quantizer {
        scale: 1.0,
        tonemap: Tonemap::None,
        inverse_gamma: None,
    };

    /// Fails when the gamma is not a positive finite number or the
    /// exposure is not finite.
    pub(super) fn new(encoding: &Encoding) -> Result<Self, String> {
        encoding.check()?;
        Ok(Quantizer {
            scale: encoding.exposure.exp2(),
            tonemap: encoding.tonemap,
            inverse_gamma: encoding.gamma.map(|g| 1.0 / g),
        })
    }

    pub(super) fn channel(&self, value: f64) -> u8 {
        // `clamp` keeps NaN, so NaN is mapped to 0 first.
        let mut c = if value.is_nan() {
            0.0
        } else {
            self.tonemap.apply((value * self.scale).max(0.0))
        };
        c = c.clamp(0.0, 1.0);
        if let Some(exponent) = self.inverse_gamma {
            c = c.powf(exponent);
        }
        // Truncation, as `int(c * 255)`; `as` saturates so 1.0 gives 255.
        (c * 255.0) as u8
    }

    pub(super) fn rgb(&self, color: Color) -> [u8; 3] {
        [
            self.channel(color.r),
            self.channel(color.g),
            self.channel(color.b),
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn quantizer(exposure: f64, tonemap: Tonemap, gamma: Option<f64>) -> Quantizer {
        Quantizer::new(&Encoding {
            exposure,
            tonemap,
            gamma,
        })
        .unwrap()
    }

    #[test]
    fn truncates_like_the_original_writer() {
        let q = quantizer(0.0, Tonemap::None, None);
        assert_eq!(q.channel(0.0), 0);
        assert_eq!(q.channel(1.0), 255);
        assert_eq!(q.channel(0.999), 254);
        assert_eq!(q.channel(0.5), 127);
        assert_eq!(q.channel(-3.0), 0);
        assert_eq!(q.channel(7.0), 255);
        assert_eq!(q.channel(f64::NAN), 0);
        assert_eq!(q.channel(f64::INFINITY), 255);
    }

    #[test]
    fn gamma_brightens_midtones() {
        let q = quantizer(0.0, Tonemap::None, Some(2.2));
        assert_eq!(q.channel(0.5), (0.5f64.powf(1.0 / 2.2) * 255.0) as u8);
        assert_eq!(q.channel(1.0), 255);
        assert_eq!(q.channel(0.0), 0);
    }

    #[test]
    fn exposure_scales_by_powers_of_two_before_the_curve_and_the_gamma() {
        let q = quantizer(1.0, Tonemap::None, None);
        assert_eq!(q.channel(0.25), 127);
        assert_eq!(q.channel(0.6), 255);
        let q = quantizer(-2.0, Tonemap::None, None);
        assert_eq!(q.channel(2.0), 127);
        // Reinhard of 2^1 * 1 = 2 is 2/3, then gamma 2.
        let q = quantizer(1.0, Tonemap::Reinhard, Some(2.0));
        assert_eq!(q.channel(1.0), ((2.0f64 / 3.0).sqrt() * 255.0) as u8);
        // Negative, NaN and infinite values stay in range under every curve.
        for tonemap in Tonemap::ALL {
            let q = quantizer(3.0, tonemap, None);
            assert_eq!(q.channel(-1.0), 0);
            assert_eq!(q.channel(f64::NAN), 0);
            assert_eq!(q.channel(f64::INFINITY), 255);
        }
    }

    #[test]
    fn rejects_bad_gamma_and_exposure() {
        for gamma in [0.0, -1.0, f64::NAN] {
            assert!(Quantizer::new(&Encoding::gamma(Some(gamma))).is_err());
        }
        for exposure in [f64::NAN, f64::INFINITY] {
            let encoding = Encoding {
                exposure,
                ..Encoding::default()
            };
            assert!(Quantizer::new(&encoding).is_err());
        }
    }
}
