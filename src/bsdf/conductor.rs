//! Conductors: a perfect mirror, or GGX microfacets sampled by their
//! visible normals, with a constant or Schlick Fresnel term.
//!
//! With visible-normal sampling the weight of a sample is `F G1(wi)`: the
//! only energy a rough conductor of reflectance 1 loses is that of light
//! shadowed after one reflection (single scattering).

use super::LobeSample;
use super::fresnel::schlick;
use super::microfacet::{Ggx, MIN_ROUGHNESS};
use crate::color::Color;
use crate::math::Vec3;

/// The Fresnel term of a conductor.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ConductorFresnel {
    /// The colour itself at every angle (the coursework metals, and
    /// Mitsuba's conductor of material `none`).
    Constant,
    /// Schlick's approximation from the colour as the reflectance at normal
    /// incidence.
    Schlick,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Conductor {
    /// Reflectance (constant Fresnel) or reflectance at normal incidence
    /// (Schlick).
    pub tint: Color,
    pub alpha: f64,
    pub fresnel: ConductorFresnel,
}

impl Conductor {
    /// Whether it is a perfect mirror (a delta lobe).
    pub fn is_delta(&self) -> bool {
        self.alpha < MIN_ROUGHNESS
    }

    fn fresnel(&self, cos: f64) -> Color {
        match self.fresnel {
            ConductorFresnel::Constant => self.tint,
            ConductorFresnel::Schlick => schlick(self.tint, cos),
        }
    }

    pub fn sample(&self, wo: &Vec3, u: [f64; 2]) -> Option<LobeSample> {
        if self.is_delta() {
            return Some(LobeSample {
                wi: Vec3::new(-wo.x, -wo.y, wo.z),
                weight: self.fresnel(wo.z.abs()),
                pdf: 1.0,
                delta: true,
            });
        }
        if wo.z <= 0.0 {
            return None;
        }
        let ggx = Ggx { alpha: self.alpha };
        let (wi, h, pdf) = ggx.sample_reflection(wo, u);
        let weight = if wi.z > 0.0 {
            self.fresnel(wo.dot(&h)) * ggx.g1(&wi, &h)
        } else {
            Color::BLACK
        };
        Some(LobeSample {
            wi,
            weight,
            pdf,
            delta: false,
        })
    }

    pub fn eval(&self, wo: &Vec3, wi: &Vec3) -> Color {
        if self.is_delta() || wo.z <= 0.0 || wi.z <= 0.0 {
            return Color::BLACK;
        }
        let Some(h) = (wo + wi).try_normalize(1e-12) else {
            return Color::BLACK;
        };
        let ggx = Ggx { alpha: self.alpha };
        // F D G / (4 cos_o cos_i), times cos_i.
        self.fresnel(wo.dot(&h)) * (ggx.d(&h) * ggx.g(wo, wi, &h) / (4.0 * wo.z))
    }

    pub fn pdf(&self, wo: &Vec3, wi: &Vec3) -> f64 {
        if self.is_delta() {
            return 0.0;
        }
        Ggx { alpha: self.alpha }.reflection_pdf(wo, wi)
    }
}
