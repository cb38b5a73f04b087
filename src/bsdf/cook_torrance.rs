//! The Cook-Torrance lobe of the rub dialect (`cookTorrence a F0 x`), as its
//! renderer defines it: `color F D G / max(4 cos_o cos_i, 0.001)` with GGX
//! `D` of `alpha = a` (and pi written as 3.14), Schlick's `F` on the half
//! vector from the scalar `F0`, and the Schlick-Smith product
//! `G = G1(cos_o) G1(cos_i)`, `G1(c) = c / (c (1 - k) + k)`,
//! `k = (a + 1)^2 / 8`. Sampled by the GGX visible normals of the same
//! `alpha` (a proposal, not its own distribution).

use super::LobeSample;
use super::microfacet::Ggx;
use crate::color::Color;
use crate::math::Vec3;

/// rub's value of pi (written as 3.14 in its source, on purpose here).
#[allow(clippy::approx_constant)]
const RUB_PI: f64 = 3.14;

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CookTorrance {
    pub color: Color,
    pub alpha: f64,
    pub f0: f64,
}

impl CookTorrance {
    fn value(&self, wo: &Vec3, wi: &Vec3) -> f64 {
        self.value_about(&Vec3::z(), wo, wi)
    }

    /// rub's scalar `F D G / max(4 cos_o cos_i, 0.001)` about the unit
    /// normal `n` (world directions; the colour and the cosine left out).
    pub fn value_about(&self, n: &Vec3, wo: &Vec3, wi: &Vec3) -> f64 {
        let Some(h) = (wo + wi).try_normalize(1e-12) else {
            return 0.0;
        };
        let (cos_o, cos_i, cos_h) = (n.dot(wo), n.dot(wi), n.dot(&h));
        let a2 = self.alpha * self.alpha;
        let t = cos_h * cos_h * (a2 - 1.0) + 1.0;
        let d = a2 / (RUB_PI * t * t);
        let k = (self.alpha + 1.0).powi(2) / 8.0;
        let g1 = |c: f64| c / (c * (1.0 - k) + k);
        let f = self.f0 + (1.0 - self.f0) * (1.0 - wo.dot(&h).clamp(0.0, 1.0)).powi(5);
        f * d * g1(cos_o) * g1(cos_i) / (4.0 * cos_o * cos_i).max(0.001)
    }

    pub fn sample(&self, wo: &Vec3, u: [f64; 2]) -> Option<LobeSample> {
        if wo.z <= 0.0 {
            return None;
        }
        let (wi, _, pdf) = Ggx { alpha: self.alpha }.sample_reflection(wo, u);
        Some(LobeSample::from_eval(wi, self.eval(wo, &wi), pdf))
    }

    pub fn eval(&self, wo: &Vec3, wi: &Vec3) -> Color {
        if wo.z <= 0.0 || wi.z <= 0.0 {
            return Color::BLACK;
        }
        self.color * (self.value(wo, wi) * wi.z)
    }

    pub fn pdf(&self, wo: &Vec3, wi: &Vec3) -> f64 {
        Ggx { alpha: self.alpha }.reflection_pdf(wo, wi)
    }
}
