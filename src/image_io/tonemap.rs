//! How linear radiance becomes a value for 8-bit output before gamma and
//! quantisation: an exposure and a tone curve (`render --exposure
//! --tonemap`). HDR outputs (PFM, EXR) are written without them.

/// A tone curve from exposed linear values in [0, inf) to [0, 1], applied to
/// each channel on its own.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Tonemap {
    /// The identity: values above 1 are clipped by the quantiser (the PA
    /// framework writer).
    #[default]
    None,
    /// Reinhard's `c / (1 + c)` on each channel (not on luminance: hues of
    /// bright colours move towards white, and no channel reaches 1).
    Reinhard,
    /// Krzysztof Narkowicz's fit of the ACES filmic curve,
    /// `c (2.51 c + 0.03) / (c (2.43 c + 0.59) + 0.14)` clipped to 1, on
    /// each channel, applied to the exposed value as it is (his fit was made
    /// for inputs scaled by 0.6 first: `--exposure -0.737` does that).
    Aces,
}

impl Tonemap {
    pub const ALL: [Tonemap; 3] = [Tonemap::None, Tonemap::Reinhard, Tonemap::Aces];

    pub fn name(self) -> &'static str {
        match self {
            Tonemap::None => "none",
            Tonemap::Reinhard => "reinhard",
            Tonemap::Aces => "aces",
        }
    }

    pub fn from_name(name: &str) -> Option<Tonemap> {
        Tonemap::ALL.into_iter().find(|t| t.name() == name)
    }

    /// The curve at `c` (>= 0, possibly infinite); `None` returns `c`.
    pub fn apply(self, c: f64) -> f64 {
        match self {
            Tonemap::None => c,
            _ if c == f64::INFINITY => 1.0,
            Tonemap::Reinhard => c / (1.0 + c),
            Tonemap::Aces => {
                let mapped = c * (2.51 * c + 0.03) / (c * (2.43 * c + 0.59) + 0.14);
                mapped.min(1.0)
            }
        }
    }
}

/// How linear values become 8-bit values (BMP, PNG): multiplied by
/// `2^exposure`, through the tone curve, clamped to [0, 1], raised to
/// `1 / gamma` when a gamma is given, scaled by 255 and truncated.
/// The default (exposure 0, no curve, no gamma) is the PA framework writer.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Encoding {
    pub exposure: f64,
    pub tonemap: Tonemap,
    pub gamma: Option<f64>,
}

impl Encoding {
    /// Only a gamma (no exposure, no curve).
    pub fn gamma(gamma: Option<f64>) -> Encoding {
        Encoding {
            gamma,
            ..Encoding::default()
        }
    }

    /// Fails when the gamma is not a positive finite number or the exposure
    /// is not finite.
    pub fn check(&self) -> Result<(), String> {
        if let Some(g) = self.gamma
            && !(g.is_finite() && g > 0.0)
        {
            return Err(format!("gamma must be a positive number, got {g}"));
        }
        if !self.exposure.is_finite() {
            return Err(format!(
                "exposure must be a finite number, got {}",
                self.exposure
            ));
        }
        Ok(())
    }

    /// Whether values pass unchanged up to the clamp (exposure 0, no curve).
    pub fn is_linear(&self) -> bool {
        self.exposure == 0.0 && self.tonemap == Tonemap::None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid() -> impl Iterator<Item = f64> {
        (0..4000).map(|i| i as f64 * 0.01)
    }

    #[test]
    fn every_curve_maps_zero_to_zero_and_is_monotone_into_the_unit_range() {
        for curve in [Tonemap::Reinhard, Tonemap::Aces] {
            assert_eq!(curve.apply(0.0), 0.0, "{curve:?}");
            assert_eq!(curve.apply(f64::INFINITY), 1.0, "{curve:?}");
            let mut previous = 0.0;
            for c in grid().skip(1) {
                let mapped = curve.apply(c);
                assert!(mapped >= previous, "{curve:?} falls at {c}");
                assert!((0.0..=1.0).contains(&mapped), "{curve:?}({c}) = {mapped}");
                previous = mapped;
            }
        }
    }

    #[test]
    fn reinhard_has_its_exact_values() {
        let r = Tonemap::Reinhard;
        assert_eq!(r.apply(1.0), 0.5);
        assert_eq!(r.apply(3.0), 0.75);
        assert_eq!(r.apply(0.25), 0.2);
        assert_eq!(r.apply(9.0), 0.9);
        // Below 1 everywhere: a channel never saturates.
        assert!(r.apply(1e12) < 1.0);
    }

    #[test]
    fn aces_is_strictly_increasing_until_it_clips_and_darkens_little_at_midtones() {
        let a = Tonemap::Aces;
        // Its value at 1: 2.54 / 3.16.
        assert!((a.apply(1.0) - 2.54 / 3.16).abs() < 1e-15);
        // Strictly increasing below the clip at c = (0.56 + sqrt(0.3584)) / 0.16 = 7.24.
        let mut previous = 0.0;
        for c in grid().skip(1).take_while(|&c| c < 7.2) {
            assert!(a.apply(c) > previous, "flat at {c}");
            previous = a.apply(c);
        }
        assert_eq!(a.apply(7.3), 1.0);
        assert!(a.apply(7.2) < 1.0);
        // A toe below 0.1, a shoulder above 1, nearly linear between.
        assert!(a.apply(0.01) < 0.01 && a.apply(0.5) > 0.5 && a.apply(2.0) < 2.0);
    }

    #[test]
    fn the_identity_is_the_default() {
        assert_eq!(Tonemap::default(), Tonemap::None);
        assert!(Encoding::default().is_linear());
        for c in grid() {
            assert_eq!(Tonemap::None.apply(c), c);
        }
        for t in Tonemap::ALL {
            assert_eq!(Tonemap::from_name(t.name()), Some(t));
        }
    }
}
