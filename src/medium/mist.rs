//! Cambrian's camera mist as a physical medium filling the scene.

use super::{HenyeyGreenstein, Medium};
use crate::color::Color;
use crate::math::Vec3;

/// Cambrian's camera `mist e s b` (`../shared/docs/looks.md`): over a
/// segment of length `t` a path dies with probability `1 - e^t`, else it
/// scatters with probability `1 - s^t` at an exponentially distributed
/// point, towards `normalise((U - 0.5, U, U - 0.5) - b d)` (`d` the ray's
/// direction, `U` uniform numbers).
///
/// | Cambrian | physical medium filling the scene |
/// |---|---|
/// | `e` (survival per unit length) | `sigmaA = -ln e` (grey) |
/// | `s` (no scattering per unit length) | `sigmaS = -ln s` (grey) |
/// | `b` and the upward shift | `g` = the mean cosine of Cambrian's directions, averaged over ray directions |
///
/// The probability of crossing a segment unchanged is the same, `(e s)^t`.
/// Cambrian's lobe points upwards whatever the ray's direction, which no
/// phase function (a function of the scattering angle only) can do: its
/// mean cosine is kept, its upward drift is not.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mist {
    pub survival: f64,
    pub scatter_survival: f64,
    pub bias: f64,
}

impl Mist {
    /// The physical medium of the table above.
    pub fn medium(&self) -> Medium {
        Medium {
            sigma_a: Color::gray(-self.survival.ln()),
            sigma_s: Color::gray(-self.scatter_survival.ln()),
            phase: HenyeyGreenstein {
                g: cambrian_mean_cosine(self.bias).clamp(-0.99, 0.99),
            },
        }
    }
}

/// The mean cosine between a ray's direction `d` and Cambrian's scattered
/// direction `normalise((U - 0.5, U, U - 0.5) - b d)`, averaged over `d`
/// (a Fibonacci sphere of 64 directions) and the three uniform numbers (a
/// 12^3 midpoint grid): a deterministic quadrature, accurate to about 1e-3.
pub fn cambrian_mean_cosine(bias: f64) -> f64 {
    const DIRECTIONS: usize = 64;
    const STEPS: usize = 12;
    let mut total = 0.0;
    let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
    for k in 0..DIRECTIONS {
        let y = 1.0 - 2.0 * (k as f64 + 0.5) / DIRECTIONS as f64;
        let r = (1.0 - y * y).sqrt();
        let phi = golden * k as f64;
        let d = Vec3::new(r * phi.cos(), y, r * phi.sin());
        for i in 0..STEPS * STEPS * STEPS {
            let u = |j: usize| (j as f64 + 0.5) / STEPS as f64;
            let (a, b, c) = (i % STEPS, (i / STEPS) % STEPS, i / (STEPS * STEPS));
            let v = Vec3::new(u(a) - 0.5, u(b), u(c) - 0.5) - d * bias;
            let length = v.norm();
            if length > 0.0 {
                total += v.dot(&d) / length;
            }
        }
    }
    total / (DIRECTIONS * STEPS * STEPS * STEPS) as f64
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cambrian_mist_keeps_the_chance_of_crossing_unchanged() {
        let mist = Mist {
            survival: 0.998,
            scatter_survival: 0.9985,
            bias: 0.2,
        };
        let medium = mist.medium();
        let t = 37.0;
        let crossing = (mist.survival * mist.scatter_survival).powf(t);
        assert!((medium.transmittance(t).g - crossing).abs() < 1e-12);
        // Without bias Cambrian's lobe is symmetric about the horizontal
        // plane: mean cosine 0 over all directions; a bias turns it back.
        assert!(cambrian_mean_cosine(0.0).abs() < 2e-3);
        let g = medium.phase.g;
        assert!(g < -0.1 && g > -0.5, "{g}");
    }
}
