//! The BSDF contract: what a surface does with light, built per hit from
//! the material and the shading frame, and the only place where reflection
//! formulas live. The integrators and the light subpaths ask three things:
//!
//! - [`Bsdf::sample`]`(wo, uc, u)`: a direction `wi` with its weight
//!   `f |cos_i| / pdf`, its density and whether it is a delta direction;
//! - [`Bsdf::eval`]`(wo, wi)`: `f(wo, wi) |cos_i|` of the continuous lobes;
//! - [`Bsdf::pdf`]`(wo, wi)`: the density with which `sample` gives `wi`.
//!
//! A BSDF is a mixture of weighted lobes (`lobe`): the rates of the
//! original (`diffusionRate`, `specularRate`, `refractRate`) become the
//! weights of a diffuse, a conductor and a dielectric lobe, and the lobes
//! some dialects add (Phong, a GGX coat) come with weight 1 (`build`).
//! `sample` picks one lobe with probability proportional to its weight times
//! its mean tint. A delta lobe's sample is weighted by its own weight over
//! that probability; a continuous lobe's sample by the whole continuous
//! part, `sum w_j f_j |cos| / sum p_j pdf_j`, so that `eval` and `pdf` are
//! the mixture's. The continuous part's total probability is
//! [`Bsdf::smooth_probability`]: an integrator that samples lights only
//! when `sample` chose a continuous lobe divides by it.
//!
//! All directions are world-space unit vectors pointing away from the
//! surface; `wo` is on the side of the shading normal the BSDF was built
//! with.

pub mod build;
pub mod conductor;
pub mod cook_torrance;
pub mod dielectric;
pub mod fresnel;
pub mod lambert;
pub mod lobe;
pub mod microfacet;
pub mod phong;
pub mod rough_dielectric;

#[cfg(test)]
mod tests;

use crate::color::Color;
use crate::math::{Vec3, orthonormal_basis};

pub use build::{Rules, from_material};
pub use dielectric::GlassChoice;
pub use fresnel::DielectricFresnel;
pub use lambert::Lambert;
pub use lobe::{Lobe, LobeSample};

/// The most lobes one material makes (diffuse, conductor, dielectric, Phong, coat).
pub const MAX_LOBES: usize = 5;

/// A sampled direction of a BSDF.
#[derive(Clone, Copy, Debug)]
pub struct BsdfSample {
    /// World-space unit direction.
    pub wi: Vec3,
    /// `f |cos_i| / pdf`, with the lobe choice.
    pub weight: Color,
    /// For a continuous direction the mixture density of `wi` (solid
    /// angle, with the probabilities of the lobes); for a delta direction
    /// the probability of the lobe.
    pub pdf: f64,
    pub delta: bool,
}

/// A mixture of weighted lobes in one shading frame.
#[derive(Clone, Copy, Debug)]
pub struct Bsdf {
    tangent: Vec3,
    bitangent: Vec3,
    normal: Vec3,
    lobes: [Lobe; MAX_LOBES],
    weights: [f64; MAX_LOBES],
    /// Probability of choosing each lobe (sums to 1 unless all are black).
    probabilities: [f64; MAX_LOBES],
    len: usize,
}

const NO_LOBE: Lobe = Lobe::Lambert(Lambert {
    albedo: Color::BLACK,
});

impl Bsdf {
    /// An empty BSDF (black) in the frame of the unit shading `normal`.
    pub fn new(normal: &Vec3) -> Bsdf {
        let (tangent, bitangent) = orthonormal_basis(normal);
        Bsdf {
            tangent,
            bitangent,
            normal: *normal,
            lobes: [NO_LOBE; MAX_LOBES],
            weights: [0.0; MAX_LOBES],
            probabilities: [0.0; MAX_LOBES],
            len: 0,
        }
    }

    /// Adds `lobe` with `weight` (lobes beyond [`MAX_LOBES`], non-positive
    /// weights and black lobes are dropped).
    pub fn push(&mut self, lobe: Lobe, weight: f64) {
        let albedo = lobe.albedo_estimate();
        let usable = weight > 0.0 && weight.is_finite() && albedo > 0.0;
        if self.len == MAX_LOBES || !usable {
            return;
        }
        self.lobes[self.len] = lobe;
        self.weights[self.len] = weight;
        self.len += 1;
        let mut total = 0.0;
        for i in 0..self.len {
            self.probabilities[i] = self.weights[i] * self.lobes[i].albedo_estimate();
            total += self.probabilities[i];
        }
        for p in &mut self.probabilities[..self.len] {
            *p /= total;
        }
    }

    /// The lobes and their weights.
    pub fn lobes(&self) -> impl Iterator<Item = (&Lobe, f64)> {
        self.lobes[..self.len]
            .iter()
            .zip(self.weights[..self.len].iter().copied())
    }

    /// Whether it reflects nothing (no lobe): paths end here.
    pub fn is_black(&self) -> bool {
        self.len == 0
    }

    /// The unit shading normal.
    pub fn normal(&self) -> Vec3 {
        self.normal
    }

    pub fn to_local(&self, v: &Vec3) -> Vec3 {
        Vec3::new(
            v.dot(&self.tangent),
            v.dot(&self.bitangent),
            v.dot(&self.normal),
        )
    }

    pub fn to_world(&self, v: &Vec3) -> Vec3 {
        self.tangent * v.x + self.bitangent * v.y + self.normal * v.z
    }

    /// Whether [`Bsdf::sample`] reads `uc`: a choice between lobes, or
    /// between reflection and refraction.
    pub fn reads_choice(&self) -> bool {
        self.len > 1 || self.lobes[..self.len].iter().any(Lobe::reads_choice)
    }

    /// Whether [`Bsdf::sample`] reads `u`: a continuous lobe.
    pub fn reads_direction(&self) -> bool {
        self.lobes[..self.len].iter().any(Lobe::reads_direction)
    }

    /// The probability that [`Bsdf::sample`] chooses a continuous lobe.
    pub fn smooth_probability(&self) -> f64 {
        (0..self.len)
            .filter(|&i| !self.lobes[i].is_delta())
            .map(|i| self.probabilities[i])
            .sum()
    }

    /// `f` of the continuous part when it is made of Lambert lobes only
    /// (what a caustic connection needs); `None` when it is not, or empty.
    pub fn lambert(&self) -> Option<Color> {
        let mut albedo = Color::BLACK;
        let mut any = false;
        for (lobe, weight) in self.lobes() {
            match lobe {
                Lobe::Lambert(l) => {
                    albedo += l.albedo * weight;
                    any = true;
                }
                other if other.is_delta() => {}
                _ => return None,
            }
        }
        any.then(|| albedo * std::f64::consts::FRAC_1_PI)
    }

    /// A direction for `wo`: `uc` chooses the lobe (and, rescaled, between
    /// reflection and refraction), `u` the direction of a continuous lobe.
    pub fn sample(&self, wo: &Vec3, uc: f64, u: [f64; 2]) -> Option<BsdfSample> {
        let (index, uc) = self.choose(uc)?;
        let lobe = &self.lobes[index];
        let local_wo = self.to_local(wo);
        let sample = lobe.sample(&local_wo, uc, u)?;
        let probability = self.probabilities[index];
        let wi = self.to_world(&sample.wi);
        if sample.delta {
            return Some(BsdfSample {
                wi,
                weight: sample.weight * (self.weights[index] / probability),
                pdf: probability,
                delta: true,
            });
        }
        let smooth_lobes = (0..self.len).filter(|&i| !self.lobes[i].is_delta()).count();
        let (weight, pdf) = if smooth_lobes == 1 {
            (
                sample.weight * (self.weights[index] / probability),
                sample.pdf * probability,
            )
        } else {
            let mut f = Color::BLACK;
            let mut pdf = 0.0;
            for i in (0..self.len).filter(|&i| !self.lobes[i].is_delta()) {
                f += self.lobes[i].eval(&local_wo, &sample.wi) * self.weights[i];
                pdf += if i == index {
                    sample.pdf
                } else {
                    self.lobes[i].pdf(&local_wo, &sample.wi)
                } * self.probabilities[i];
            }
            let weight = if pdf > 0.0 { f / pdf } else { Color::BLACK };
            (weight, pdf)
        };
        Some(BsdfSample {
            wi,
            weight,
            pdf,
            delta: false,
        })
    }

    /// `f(wo, wi) |cos_i|` of the continuous lobes, with their weights.
    pub fn eval(&self, wo: &Vec3, wi: &Vec3) -> Color {
        let (wo, wi) = (self.to_local(wo), self.to_local(wi));
        let mut f = Color::BLACK;
        for (lobe, weight) in self.lobes() {
            if !lobe.is_delta() {
                f += lobe.eval(&wo, &wi) * weight;
            }
        }
        f
    }

    /// The density (solid angle) with which [`Bsdf::sample`] gives `wi`,
    /// over its continuous lobes.
    pub fn pdf(&self, wo: &Vec3, wi: &Vec3) -> f64 {
        let (wo, wi) = (self.to_local(wo), self.to_local(wi));
        (0..self.len)
            .filter(|&i| !self.lobes[i].is_delta())
            .map(|i| self.lobes[i].pdf(&wo, &wi) * self.probabilities[i])
            .sum()
    }

    /// The lobe that `uc` chooses, and `uc` rescaled to [0, 1) within it.
    fn choose(&self, uc: f64) -> Option<(usize, f64)> {
        if self.len == 0 {
            return None;
        }
        let mut start = 0.0;
        for i in 0..self.len {
            let p = self.probabilities[i];
            if uc < start + p || i + 1 == self.len {
                let rescaled = if p > 0.0 {
                    ((uc - start) / p).clamp(0.0, ONE_BELOW)
                } else {
                    0.0
                };
                return Some((i, rescaled));
            }
            start += p;
        }
        None
    }
}

/// The largest f64 below 1.
const ONE_BELOW: f64 = 1.0 - f64::EPSILON / 2.0;
