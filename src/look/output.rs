//! The curve a renderer applies to a pixel's average before the framework
//! writer (clamp to [0, 1], `int(c * 255)`) stores it: most coursework
//! renderers apply none; a few encode (`../shared/docs/looks.md`, each
//! renderer's "Output" fact).

use crate::image_io::Image;

/// What a renderer does to a pixel's average before the framework writer.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum OutputCurve {
    /// Nothing: the framework writer alone (linear values, truncated).
    #[default]
    Framework,
    /// `sqrt(c)` (gamma 2): 1rubbishyuan, chen-yingfa.
    SquareRoot,
    /// `c^0.6` (gamma about 1.67): Bowen-Xu04.
    Power06,
    /// `clamp(c)^(1/2.2)` rounded to the nearest `k/255` (smallpt's
    /// `toInt`, `+ 0.5`): yangjunx21.
    Gamma22Rounded,
}

impl OutputCurve {
    /// The value the framework writer then receives for a channel `c`
    /// (linear, any value). NaN stays NaN (the writer maps it to 0).
    pub fn apply_channel(self, c: f64) -> f64 {
        if c.is_nan() {
            return c;
        }
        let c = c.clamp(0.0, 1.0);
        match self {
            OutputCurve::Framework => c,
            OutputCurve::SquareRoot => c.sqrt(),
            OutputCurve::Power06 => c.powf(0.6),
            OutputCurve::Gamma22Rounded => (c.powf(1.0 / 2.2) * 255.0 + 0.5).floor() / 255.0,
        }
    }

    /// Applies the curve to every channel of `image` (for 8-bit outputs:
    /// the values are display values afterwards).
    pub fn apply(self, image: &mut Image) {
        if self == OutputCurve::Framework {
            return;
        }
        for pixel in &mut image.pixels {
            *pixel = pixel.map(|c| self.apply_channel(c));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The byte the framework writer stores for an encoded value.
    fn byte(v: f64) -> u8 {
        (v.clamp(0.0, 1.0) * 255.0) as u8
    }

    #[test]
    fn the_framework_writer_alone_truncates_linear_values() {
        assert_eq!(byte(OutputCurve::Framework.apply_channel(0.25)), 63);
    }

    #[test]
    fn the_square_root_writes_a_quarter_as_half() {
        assert_eq!(byte(OutputCurve::SquareRoot.apply_channel(0.25)), 127);
    }

    #[test]
    fn the_power_06_lifts_a_quarter_to_0_435() {
        // 0.25^0.6 * 255 = 110.995...
        assert_eq!(byte(OutputCurve::Power06.apply_channel(0.25)), 110);
    }

    #[test]
    fn the_rounded_gamma_rounds_where_the_writer_would_truncate() {
        // 0.5^(1/2.2) * 255 = 186.08...: 186 either way; 0.2^(1/2.2) * 255 =
        // 122.69...: rounded to 123 where truncation gives 122.
        assert_eq!(byte(OutputCurve::Gamma22Rounded.apply_channel(0.5)), 186);
        assert_eq!(byte(OutputCurve::Gamma22Rounded.apply_channel(0.2)), 123);
        assert_eq!(byte(0.2f64.powf(1.0 / 2.2)), 122);
        for k in 0..=255 {
            let c = (k as f64 / 255.0).powf(2.2);
            assert_eq!(byte(OutputCurve::Gamma22Rounded.apply_channel(c)), k as u8);
        }
    }

    #[test]
    fn values_beyond_one_are_clamped_before_the_curve() {
        for curve in [OutputCurve::SquareRoot, OutputCurve::Gamma22Rounded] {
            assert_eq!(curve.apply_channel(4.0), 1.0);
            assert_eq!(curve.apply_channel(-1.0), 0.0);
        }
    }
}
