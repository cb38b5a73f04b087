//! The 8-bit mapping shared by the BMP and PNG writers.
//!
//! It reproduces the original PA writer, `int(c * 255)`: clamp to [0, 1], apply
//! `c^(1/gamma)` when a gamma is given, scale by 255 and truncate. NaN becomes 0.

use crate::color::Color;

/// Maps linear channel values to bytes for one gamma setting.
#[derive(Clone, Copy, Debug)]
pub(super) struct Quantizer {
    inverse_gamma: Option<f64>,
}

impl Quantizer {
    /// The PA framework writer's mapping: no gamma.
    pub(super) const FRAMEWORK: Quantizer = Quantizer {
        inverse_gamma: None,
    };

    /// Fails when the gamma is not a positive finite number.
    pub(super) fn new(gamma: Option<f64>) -> Result<Self, String> {
        match gamma {
            Some(g) if !(g.is_finite() && g > 0.0) => {
                Err(format!("gamma must be a positive number, got {g}"))
            }
            Some(g) => Ok(Quantizer {
                inverse_gamma: Some(1.0 / g),
            }),
            None => Ok(Quantizer {
                inverse_gamma: None,
            }),
        }
    }

    pub(super) fn channel(&self, value: f64) -> u8 {
        // `clamp` keeps NaN, so NaN is mapped to 0 first.
        let mut c = if value.is_nan() {
            0.0
        } else {
            value.clamp(0.0, 1.0)
        };
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

    #[test]
    fn truncates_like_the_original_writer() {
        let q = Quantizer::new(None).unwrap();
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
        let q = Quantizer::new(Some(2.2)).unwrap();
        assert_eq!(q.channel(0.5), (0.5f64.powf(1.0 / 2.2) * 255.0) as u8);
        assert_eq!(q.channel(1.0), 255);
        assert_eq!(q.channel(0.0), 0);
    }

    #[test]
    fn rejects_bad_gamma() {
        assert!(Quantizer::new(Some(0.0)).is_err());
        assert!(Quantizer::new(Some(-1.0)).is_err());
        assert!(Quantizer::new(Some(f64::NAN)).is_err());
    }
}
