//! The Henyey-Greenstein phase function: the angular distribution of light
//! scattered in a medium, with one parameter `g` (the mean cosine of the
//! scattering angle; 0 is isotropic, > 0 forward, < 0 backward).

use std::f64::consts::PI;

use crate::math::{Vec3, orthonormal_basis};

/// Below this |g| the phase function is sampled as isotropic (the inverse
/// of its cumulative distribution divides by g).
const ISOTROPIC_LIMIT: f64 = 1e-4;

/// A Henyey-Greenstein lobe; `g` in (-1, 1).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HenyeyGreenstein {
    pub g: f64,
}

impl HenyeyGreenstein {
    /// Density (per steradian) of scattering by the angle whose cosine is
    /// `cos_theta`, measured from the direction the light travelled in:
    /// `(1 - g^2) / (4 pi (1 + g^2 - 2 g cos)^(3/2))`.
    #[inline]
    pub fn density(&self, cos_theta: f64) -> f64 {
        let g = self.g;
        let denominator = 1.0 + g * g - 2.0 * g * cos_theta;
        (1.0 - g * g) / (4.0 * PI * denominator * denominator.sqrt())
    }

    /// Value and density of scattering light travelling along `travel` into
    /// `wi` (both unit): the same number, as the phase function is its own
    /// sampling density.
    #[inline]
    pub fn eval(&self, travel: &Vec3, wi: &Vec3) -> f64 {
        self.density(travel.dot(wi))
    }

    /// A direction for light travelling along `travel` (unit), drawn in
    /// proportion to the phase function from the unit square `u`, by the
    /// inverse of its cumulative distribution in the cosine.
    pub fn sample(&self, travel: &Vec3, u: [f64; 2]) -> Vec3 {
        let g = self.g;
        let cos_theta = if g.abs() < ISOTROPIC_LIMIT {
            1.0 - 2.0 * u[0]
        } else {
            let ratio = (1.0 - g * g) / (1.0 - g + 2.0 * g * u[0]);
            (1.0 + g * g - ratio * ratio) / (2.0 * g)
        }
        .clamp(-1.0, 1.0);
        let sin_theta = (1.0 - cos_theta * cos_theta).max(0.0).sqrt();
        let phi = 2.0 * PI * u[1];
        let (s, t) = orthonormal_basis(travel);
        let wi = s * (sin_theta * phi.cos()) + t * (sin_theta * phi.sin()) + travel * cos_theta;
        debug_assert!((wi.norm() - 1.0).abs() < 1e-9);
        wi
    }
}
