//! Cambrian's own way of rendering dispersion, for its look: one
//! wavelength per camera sample, and the sample's RGB radiance multiplied
//! by an RGB colour of that wavelength (`../shared/docs/looks.md`, section
//! cambrian-pathtracer: Cambrian-yzt/PathTracer `src/main.cpp`,
//! `include/wavelength.hpp`).
//!
//! - The wavelength: with probability 0.15 uniform over 380-480 nm, else
//!   uniform over 380-750 nm. (Another version of Cambrian's code, at
//!   commit 36b3570, draws 380-580 half of the time; its mean colour has
//!   blue/green 0.79, where `bunny_only.png`'s lit floor has 0.947 and
//!   this draw 0.945.)
//! - Its colour: the piecewise-linear spectrum-to-RGB ramp with a fall-off
//!   to 0.3 at both ends (380-440 and 645-750 nm), each channel raised to
//!   the power 0.8 and clamped to 1.
//!
//! Its mean over the draw is about (0.49, 0.38, 0.36): Cambrian's
//! dispersive images are darker and redder than the same scene without
//! the flag.

use crate::color::Color;

/// The draws confined to the blue end.
const BLUE_SHARE: f64 = 0.15;

/// The wavelength (nm) of uniform numbers `u` (which range) and `v` (where).
pub fn wavelength(u: f64, v: f64) -> f64 {
    if u < BLUE_SHARE {
        380.0 + v * (480.0 - 380.0)
    } else {
        380.0 + v * (750.0 - 380.0)
    }
}

/// Cambrian's RGB weight of wavelength `nm`.
pub fn weight(nm: f64) -> Color {
    const GAMMA: f64 = 0.8;
    let p = |x: f64| x.max(0.0).powf(GAMMA).min(1.0);
    let (r, g, b) = if (380.0..=440.0).contains(&nm) {
        let attenuation = 0.3 + 0.7 * (nm - 380.0) / 60.0;
        (p((440.0 - nm) / 60.0 * attenuation), 0.0, p(attenuation))
    } else if (440.0..=490.0).contains(&nm) {
        (0.0, p((nm - 440.0) / 50.0), 1.0)
    } else if (490.0..=510.0).contains(&nm) {
        (0.0, 1.0, p((510.0 - nm) / 20.0))
    } else if (510.0..=580.0).contains(&nm) {
        (p((nm - 510.0) / 70.0), 1.0, 0.0)
    } else if (580.0..=645.0).contains(&nm) {
        (1.0, p((645.0 - nm) / 65.0), 0.0)
    } else if (645.0..=750.0).contains(&nm) {
        (p(0.3 + 0.7 * (750.0 - nm) / 105.0), 0.0, 0.0)
    } else {
        (0.0, 0.0, 0.0)
    };
    Color::new(r, g, b)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_ramp_at_its_corners() {
        let close = |a: Color, b: [f64; 3]| {
            (a.r - b[0]).abs() < 1e-12 && (a.g - b[1]).abs() < 1e-12 && (a.b - b[2]).abs() < 1e-12
        };
        assert!(close(
            weight(380.0),
            [0.3f64.powf(0.8), 0.0, 0.3f64.powf(0.8)]
        ));
        assert!(close(weight(440.0), [0.0, 0.0, 1.0]));
        assert!(close(weight(510.0), [0.0, 1.0, 0.0]));
        assert!(close(weight(545.0), [0.5f64.powf(0.8), 1.0, 0.0]));
        assert!(close(weight(645.0), [1.0, 0.0, 0.0]));
        assert!(close(weight(750.0), [0.3f64.powf(0.8), 0.0, 0.0]));
        assert!(close(weight(800.0), [0.0, 0.0, 0.0]));
    }

    #[test]
    fn its_mean_over_the_draw_darkens_the_image() {
        // Midpoint quadrature over both numbers.
        let n = 2000;
        let mut sum = Color::BLACK;
        for i in 0..100 {
            for j in 0..n {
                let u = (i as f64 + 0.5) / 100.0;
                sum += weight(wavelength(u, (j as f64 + 0.5) / n as f64));
            }
        }
        let mean = sum / (100 * n) as f64;
        for (got, want) in [(mean.r, 0.486), (mean.g, 0.381), (mean.b, 0.360)] {
            assert!((got - want).abs() < 0.005, "{mean:?}");
        }
        assert_eq!(wavelength(0.1, 0.0), 380.0);
        assert_eq!(wavelength(0.1, 1.0), 480.0);
        assert_eq!(wavelength(0.7, 1.0), 750.0);
    }
}
