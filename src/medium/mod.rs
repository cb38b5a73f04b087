//! Participating media: a homogeneous medium (absorption and scattering
//! coefficients per RGB channel, a Henyey-Greenstein phase function), its
//! transmittance along a segment and free-flight distance sampling.
//!
//! Distances are sampled for one channel chosen uniformly, and weighted by
//! the one-sample MIS (balance heuristic) over the three channels, as in
//! PBRT v3's `HomogeneousMedium::Sample`: the density of a distance `t` is
//! the mean over channels of `sigma_t e^(-sigma_t t)` (a scattering point)
//! or of `e^(-sigma_t t_max)` (no collision before `t_max`).

mod mist;
mod phase;
#[cfg(test)]
mod tests;

pub use mist::{CambrianLobe, Mist, cambrian_mean_cosine};
pub use phase::HenyeyGreenstein;

use crate::color::Color;
use crate::math::Vec3;

/// A homogeneous medium, in units of inverse scene length.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Medium {
    pub sigma_a: Color,
    pub sigma_s: Color,
    pub phase: HenyeyGreenstein,
    /// When the medium is Cambrian's mist: its lobe instead of `phase`
    /// (see [`CambrianLobe`]), and its absorption over the whole segment
    /// a path scatters in (see [`Medium::sample_flight`]).
    pub cambrian_mist: Option<CambrianLobe>,
}

/// What a free flight through a medium found before `t_max`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Flight {
    /// A scattering point at `distance`; the path throughput is multiplied
    /// by `weight` (`sigma_s T(distance) / pdf`).
    Scatter { distance: f64, weight: Color },
    /// No collision before `t_max`; the throughput is multiplied by `weight`
    /// (`T(t_max) / P(no collision)`).
    Pass { weight: Color },
}

impl Medium {
    /// The extinction coefficient `sigma_a + sigma_s`.
    #[inline]
    pub fn sigma_t(&self) -> Color {
        self.sigma_a + self.sigma_s
    }

    /// Transmittance `e^(-sigma_t d)` per channel over a distance `d >= 0`
    /// (which may be infinite: a channel without extinction stays 1).
    #[inline]
    pub fn transmittance(&self, distance: f64) -> Color {
        self.sigma_t()
            .map(|sigma| channel_transmittance(sigma, distance))
    }

    /// Whether the medium scatters light at all (a pure absorber only
    /// attenuates, and is crossed without sampling a distance).
    #[inline]
    pub fn scatters(&self) -> bool {
        !self.sigma_s.is_black()
    }

    /// Value and density (the same number) of scattering a path that
    /// travels along `travel` into `wi` (both unit).
    #[inline]
    pub fn phase_eval(&self, travel: &Vec3, wi: &Vec3) -> f64 {
        match &self.cambrian_mist {
            Some(lobe) => lobe.density(travel, wi),
            None => self.phase.eval(travel, wi),
        }
    }

    /// A direction for a path travelling along `travel` (unit), drawn in
    /// proportion to [`Medium::phase_eval`] from `u` (and, for Cambrian's
    /// lobe, one more number from `third`).
    pub fn phase_sample(&self, travel: &Vec3, u: [f64; 2], third: impl FnOnce() -> f64) -> Vec3 {
        match &self.cambrian_mist {
            Some(lobe) => lobe.sample(travel, [u[0], u[1], third()]),
            None => self.phase.sample(travel, u),
        }
    }

    /// A free flight from a point along a ray whose next surface is at
    /// `t_max` (infinite when there is none), from one uniform number `u`.
    /// Cambrian's mist scatters a path at `x` with the density
    /// `sigma_s e^(-sigma_s x)` times its survival over the whole segment,
    /// `e^(-sigma_a t_max)` (`src/main.cpp`: the kill is drawn over the
    /// segment before the scattering point), where a medium's survival runs
    /// to the point only: its scattering weight takes the rest,
    /// `e^(-sigma_a (t_max - x))`. Crossing the segment is the same for
    /// both.
    pub fn sample_flight(&self, t_max: f64, u: f64) -> Flight {
        if !self.scatters() {
            return Flight::Pass {
                weight: self.transmittance(t_max),
            };
        }
        let sigma_t = self.sigma_t();
        let scaled = 3.0 * u;
        let channel = (scaled as usize).min(2);
        let u = (scaled - channel as f64).clamp(0.0, 1.0 - f64::EPSILON);
        let sigma = [sigma_t.r, sigma_t.g, sigma_t.b][channel];
        let distance = if sigma > 0.0 {
            -(1.0 - u).ln() / sigma
        } else {
            f64::INFINITY
        };
        if distance < t_max {
            let transmittance = self.transmittance(distance);
            let pdf = (sigma_t * transmittance).average();
            if pdf <= 0.0 || !pdf.is_finite() {
                return Flight::Scatter {
                    distance,
                    weight: Color::BLACK,
                };
            }
            let mut weight = self.sigma_s * transmittance / pdf;
            if self.cambrian_mist.is_some() {
                // Cambrian kills a path with the chance of absorption over
                // the whole segment to the next surface (none: black), and
                // only then lets it scatter on the way.
                weight *= self
                    .sigma_a
                    .map(|sigma| channel_transmittance(sigma, t_max - distance));
            }
            Flight::Scatter { distance, weight }
        } else {
            let transmittance = self.transmittance(t_max);
            let pdf = transmittance.average();
            let weight = if pdf > 0.0 {
                transmittance / pdf
            } else {
                Color::BLACK
            };
            Flight::Pass { weight }
        }
    }
}

/// `e^(-sigma d)`, 1 for a channel without extinction at any distance.
#[inline]
fn channel_transmittance(sigma: f64, distance: f64) -> f64 {
    if sigma <= 0.0 {
        1.0
    } else {
        (-sigma * distance).exp()
    }
}
