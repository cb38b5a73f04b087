//! osb's `glossy 1` diffuse branch, as its renderer computes it
//! (`../shared/docs/looks.md`, section one-step-beh1nd): the direction is
//! cosine-sampled as for Lambert, and the sample's weight is
//! `clamp01(rho / pi + 20 F D G / (4 pi)) / 0.9` per channel, with GGX `D`
//! of `alpha = 0.1` at the half vector, Schlick's `F` of a fixed `F0 = 0.2`
//! at the sampled direction, and `G = 1 / ((c_i (1 - k) + k)(c_o (1 - k) + k))`,
//! `k = (alpha + 1)^2 / 8`. There is no cosine or density factor: the weight
//! replaces the albedo. As a lobe: `f = weight / pi`, so that `f cos / pdf`
//! is that weight and light samples see the same function.

use std::f64::consts::PI;

use super::LobeSample;
use super::lambert::cosine_hemisphere;
use crate::color::Color;
use crate::math::Vec3;

/// osb's fixed roughness and normal-incidence reflectance.
const ALPHA: f64 = 0.1;
const F0: f64 = 0.2;
/// The factor osb's renderer gives the specular term.
const SPECULAR_SCALE: f64 = 20.0;
/// osb divides every glossy weight by its roulette survival, 0.9.
const SURVIVAL: f64 = 0.9;

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OsbGlossy {
    /// `rho`: the diffuse colour.
    pub color: Color,
}

impl OsbGlossy {
    /// The weight of a sample towards `wi` seen from `wo`.
    fn weight(&self, wo: &Vec3, wi: &Vec3) -> Color {
        let Some(h) = (wo + wi).try_normalize(1e-12) else {
            return Color::BLACK;
        };
        let a2 = ALPHA * ALPHA;
        let cos_h = h.z.max(0.0);
        let t = cos_h * cos_h * (a2 - 1.0) + 1.0;
        let d = a2 / (PI * t * t);
        let fresnel = F0 + (1.0 - F0) * (1.0 - wi.z.abs()).powi(5);
        let k = (ALPHA + 1.0).powi(2) / 8.0;
        let g = 1.0 / ((wi.z.abs() * (1.0 - k) + k) * (wo.z.abs() * (1.0 - k) + k));
        let specular = SPECULAR_SCALE * fresnel * d * g / (4.0 * PI);
        self.color
            .map(|rho| (rho / PI + specular).clamp(0.0, 1.0) / SURVIVAL)
    }

    pub fn sample(&self, wo: &Vec3, u: [f64; 2]) -> LobeSample {
        let wi = cosine_hemisphere(u);
        LobeSample {
            wi,
            weight: self.weight(wo, &wi),
            pdf: wi.z / PI,
            delta: false,
        }
    }

    pub fn eval(&self, wo: &Vec3, wi: &Vec3) -> Color {
        if wi.z <= 0.0 {
            return Color::BLACK;
        }
        self.weight(wo, wi) * (wi.z / PI)
    }

    pub fn pdf(&self, wi: &Vec3) -> f64 {
        wi.z.max(0.0) / PI
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_weight_is_osb_s_formula_worked_by_hand() {
        let lobe = OsbGlossy {
            color: Color::new(0.7, 0.0, 1.0),
        };
        // Seen from the normal, light 80 degrees off it: the half vector is
        // 40 degrees off the normal.
        let theta = 80f64.to_radians();
        let wo = Vec3::z();
        let wi = Vec3::new(theta.sin(), 0.0, theta.cos());
        let cos_h = 40f64.to_radians().cos();
        let d = 0.01 / (PI * (cos_h * cos_h * (0.01 - 1.0) + 1.0).powi(2));
        let f = 0.2 + 0.8 * (1.0 - theta.cos()).powi(5);
        let k = 1.1f64 * 1.1 / 8.0;
        let g = 1.0 / ((theta.cos() * (1.0 - k) + k) * 1.0);
        let specular = 20.0 * f * d * g / (4.0 * PI);
        assert!(specular > 0.04 && specular < 0.06, "{specular}");
        let w = lobe.weight(&wo, &wi);
        assert!((w.r - (0.7 / PI + specular) / 0.9).abs() < 1e-12);
        assert!((w.g - specular / 0.9).abs() < 1e-12);
        // 1 / pi + specular is below 1: no clamping yet.
        assert!((w.b - (1.0 / PI + specular) / 0.9).abs() < 1e-12);
    }

    #[test]
    fn at_the_mirror_direction_the_weight_saturates() {
        let lobe = OsbGlossy {
            color: Color::gray(0.7),
        };
        let wo = Vec3::new(0.3, 0.0, 0.954).normalize();
        let wi = Vec3::new(-wo.x, -wo.y, wo.z);
        // D at h = n is 1 / (pi alpha^2) ~ 31.8: the sum clamps to 1.
        assert!((lobe.weight(&wo, &wi).g - 1.0 / 0.9).abs() < 1e-12);
    }

    #[test]
    fn a_sample_s_weight_is_eval_over_pdf() {
        let lobe = OsbGlossy {
            color: Color::new(0.2, 0.5, 0.9),
        };
        let wo = Vec3::new(0.2, -0.4, 0.894).normalize();
        for u in [[0.1, 0.2], [0.7, 0.9], [0.45, 0.05]] {
            let s = lobe.sample(&wo, u);
            let ratio = lobe.eval(&wo, &s.wi) / lobe.pdf(&s.wi);
            for (a, b) in [
                (ratio.r, s.weight.r),
                (ratio.g, s.weight.g),
                (ratio.b, s.weight.b),
            ] {
                assert!((a - b).abs() < 1e-12, "{a} {b}");
            }
        }
    }
}
