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
/// phase function (a function of the scattering angle only) can do: the
/// medium scatters by [`CambrianLobe`] itself; `g` keeps its mean cosine
/// for what reads a Henyey-Greenstein `g` (the render summary).
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
            cambrian_mist: Some(CambrianLobe { bias: self.bias }),
        }
    }
}

/// Cambrian's scattering direction (`Cambrian-yzt/PathTracer:src/main.cpp`,
/// the mist): `normalise((U - 0.5, U, U - 0.5) - b d)` for a path
/// travelling along `d`, a point uniform in the unit box `[-0.5, 0.5] x
/// [0, 1] x [-0.5, 0.5]` moved back by `b d`, seen from the scattering
/// point. Its density per steradian in a direction `w` is the box's
/// volume along that ray, `(r1^3 - r0^3) / 3` for the distances `r0 <
/// r1` at which the ray from the point enters and leaves the box (the box
/// has volume 1, and a volume element is `r^2 dr dw`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CambrianLobe {
    pub bias: f64,
}

impl CambrianLobe {
    /// The box's corners for a path travelling along `travel`.
    fn corners(&self, travel: &Vec3) -> (Vec3, Vec3) {
        let shift = travel * self.bias;
        (
            Vec3::new(-0.5, 0.0, -0.5) - shift,
            Vec3::new(0.5, 1.0, 0.5) - shift,
        )
    }

    /// Density per steradian of scattering along `travel` into `wi` (unit).
    pub fn density(&self, travel: &Vec3, wi: &Vec3) -> f64 {
        let (low, high) = self.corners(travel);
        let (mut near, mut far) = (0.0f64, f64::INFINITY);
        for axis in 0..3 {
            if wi[axis] == 0.0 {
                if low[axis] > 0.0 || high[axis] < 0.0 {
                    return 0.0;
                }
                continue;
            }
            let (a, b) = (low[axis] / wi[axis], high[axis] / wi[axis]);
            near = near.max(a.min(b));
            far = far.min(a.max(b));
        }
        if far > near {
            (far.powi(3) - near.powi(3)) / 3.0
        } else {
            0.0
        }
    }

    /// Cambrian's direction from three uniform numbers `u`.
    pub fn sample(&self, travel: &Vec3, u: [f64; 3]) -> Vec3 {
        let v = Vec3::new(u[0] - 0.5, u[1], u[2] - 0.5) - travel * self.bias;
        let length = v.norm();
        if length > 0.0 { v / length } else { *travel }
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
    use crate::rng::Rng;

    /// Unit directions of a Fibonacci sphere, each standing for 4 pi / n
    /// steradians.
    fn sphere(n: usize) -> impl Iterator<Item = Vec3> {
        let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
        (0..n).map(move |k| {
            let y = 1.0 - 2.0 * (k as f64 + 0.5) / n as f64;
            let r = (1.0 - y * y).sqrt();
            let phi = golden * k as f64;
            Vec3::new(r * phi.cos(), y, r * phi.sin())
        })
    }

    #[test]
    fn cambrian_mist_density_integrates_to_one_and_matches_its_samples() {
        let travel = Vec3::new(0.3, -0.8, 0.52).normalize();
        for bias in [0.0, 0.2, 0.9] {
            let lobe = CambrianLobe { bias };
            let n = 200_000;
            let cell = 4.0 * std::f64::consts::PI / n as f64;
            let total: f64 = sphere(n).map(|w| lobe.density(&travel, &w) * cell).sum();
            assert!((total - 1.0).abs() < 0.01, "{bias}: {total}");
            // The share of samples within 60 degrees of up is the density's
            // integral over that cap.
            let up = |w: &Vec3| w.y > 0.5;
            let cap: f64 = sphere(n)
                .filter(up)
                .map(|w| lobe.density(&travel, &w) * cell)
                .sum();
            let mut rng = Rng::new(7, 1);
            let draws = 100_000;
            let hits = (0..draws)
                .filter(|_| {
                    let u = [rng.next_f64(), rng.next_f64(), rng.next_f64()];
                    up(&lobe.sample(&travel, u))
                })
                .count();
            let share = hits as f64 / draws as f64;
            assert!((share - cap).abs() < 0.01, "{bias}: {share} {cap}");
        }
    }

    #[test]
    fn cambrian_mist_drifts_upwards_for_a_path_going_down() {
        // A path travelling straight down still scatters upwards on
        // average, as Cambrian's mist does; a phase function would send it
        // on downwards with a forward g, or back up as much as sideways.
        let lobe = CambrianLobe { bias: 0.2 };
        let down = -Vec3::y();
        let n = 100_000;
        let cell = 4.0 * std::f64::consts::PI / n as f64;
        let mean_y: f64 = sphere(n)
            .map(|w| w.y * lobe.density(&down, &w) * cell)
            .sum();
        assert!(mean_y > 0.5, "{mean_y}");
    }

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
