//! Rough dielectrics: GGX microfacets that reflect or refract (Walter et
//! al., "Microfacet Models for Refraction through Rough Surfaces", 2007),
//! sampled by visible normals and a Fresnel roulette.
//!
//! Transmission is written in its symmetric form: Walter's radiance BSDF
//! times `eta_i / eta_o` (the index on the incoming side over that on the
//! outgoing side),
//!
//! `f = |wo.h| |wi.h| eta_o eta_i (1 - F) D G / (|cos_o| |cos_i| (eta_o wo.h + eta_i wi.h)^2)`,
//!
//! which is reciprocal, so that paths traced from the camera and from the
//! lights see the same lobe. Entering and leaving a closed object multiply
//! the two factors to 1, as the smooth glass of [`super::dielectric`] does.

use super::LobeSample;
use super::fresnel::{DielectricFresnel, dielectric};
use super::microfacet::{Ggx, reflect, refract};
use crate::color::Color;
use crate::math::Vec3;

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RoughDielectric {
    pub tint: Color,
    pub alpha: f64,
    /// Index on the side of the outgoing direction (+z).
    pub eta_above: f64,
    /// Index on the other side.
    pub eta_below: f64,
    pub fresnel: DielectricFresnel,
}

impl RoughDielectric {
    fn ggx(&self) -> Ggx {
        Ggx { alpha: self.alpha }
    }

    fn reflectance(&self, cos_h: f64) -> f64 {
        dielectric(self.fresnel, cos_h, self.eta_above, self.eta_below)
    }

    /// The microfacet normal that reflects `wo` into `wi`, if one faces `wo`.
    fn reflection_normal(wo: &Vec3, wi: &Vec3) -> Option<Vec3> {
        let h = (wo + wi).try_normalize(1e-12)?;
        (h.z > 0.0 && wo.dot(&h) > 0.0).then_some(h)
    }

    /// The microfacet normal that refracts `wo` into `wi` (the generalised
    /// half vector), if one does it from the front.
    fn refraction_normal(&self, wo: &Vec3, wi: &Vec3) -> Option<Vec3> {
        let h = -(wo * self.eta_above + wi * self.eta_below).try_normalize(1e-12)?;
        let h = if h.z < 0.0 { -h } else { h };
        (h.z > 0.0 && wo.dot(&h) > 0.0 && wi.dot(&h) < 0.0).then_some(h)
    }

    /// `eta_b^2 |wi.h| / (eta_a wo.h + eta_b wi.h)^2`: the density of `wi`
    /// per density of `h` for refraction.
    fn refraction_jacobian(&self, wo: &Vec3, wi: &Vec3, h: &Vec3) -> f64 {
        let denominator = self.eta_above * wo.dot(h) + self.eta_below * wi.dot(h);
        self.eta_below * self.eta_below * wi.dot(h).abs() / (denominator * denominator)
    }

    /// One of the two directions of a visible microfacet: `uc` against the
    /// reflectance decides. The weight is `eval / pdf` with the density of
    /// the whole routine (a steep microfacet may send a refraction above
    /// the surface or a reflection below it: such directions are counted
    /// with both ways to reach them, and carry the `eval` of their side).
    pub fn sample(&self, wo: &Vec3, uc: f64, u: [f64; 2]) -> Option<LobeSample> {
        if wo.z <= 0.0 {
            return None;
        }
        let h = self.ggx().sample_visible(wo, u);
        let reflectance = self.reflectance(wo.dot(&h));
        let wi = match refract(wo, &h, self.eta_above, self.eta_below) {
            Some(wi) if uc >= reflectance => wi,
            _ => reflect(wo, &h),
        };
        Some(LobeSample::from_eval(
            wi,
            self.eval(wo, &wi),
            self.pdf(wo, &wi),
        ))
    }

    pub fn eval(&self, wo: &Vec3, wi: &Vec3) -> Color {
        if wo.z <= 0.0 || wi.z == 0.0 {
            return Color::BLACK;
        }
        let ggx = self.ggx();
        let value = if wi.z > 0.0 {
            let Some(h) = RoughDielectric::reflection_normal(wo, wi) else {
                return Color::BLACK;
            };
            self.reflectance(wo.dot(&h)) * ggx.d(&h) * ggx.g(wo, wi, &h) / (4.0 * wo.z)
        } else {
            let Some(h) = self.refraction_normal(wo, wi) else {
                return Color::BLACK;
            };
            let denominator = self.eta_above * wo.dot(&h) + self.eta_below * wi.dot(&h);
            wo.dot(&h)
                * wi.dot(&h).abs()
                * self.eta_above
                * self.eta_below
                * (1.0 - self.reflectance(wo.dot(&h)))
                * ggx.d(&h)
                * ggx.g(wo, wi, &h)
                / (wo.z * denominator * denominator)
        };
        self.tint * value
    }

    /// The density of [`RoughDielectric::sample`] at `wi`: its reflections
    /// and refractions that reach `wi`.
    pub fn pdf(&self, wo: &Vec3, wi: &Vec3) -> f64 {
        if wo.z <= 0.0 {
            return 0.0;
        }
        let ggx = self.ggx();
        let mut pdf = 0.0;
        if let Some(h) = RoughDielectric::reflection_normal(wo, wi) {
            pdf += self.reflectance(wo.dot(&h)) * ggx.visible_pdf(wo, &h) / (4.0 * wo.dot(&h));
        }
        if let Some(h) = self.refraction_normal(wo, wi) {
            pdf += (1.0 - self.reflectance(wo.dot(&h)))
                * ggx.visible_pdf(wo, &h)
                * self.refraction_jacobian(wo, wi, &h);
        }
        pdf
    }
}
