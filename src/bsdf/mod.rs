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

use std::f64::consts::FRAC_1_PI;

use arrayvec::ArrayVec;

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
#[derive(Clone, Debug)]
pub struct Bsdf {
    tangent: Vec3,
    bitangent: Vec3,
    normal: Vec3,
    lobes: ArrayVec<Lobe, MAX_LOBES>,
    weights: [f64; MAX_LOBES],
    /// Weight times albedo estimate: lobes are chosen in proportion.
    selection: [f64; MAX_LOBES],
    total_selection: f64,
    /// The part of `total_selection` of the continuous lobes.
    smooth_selection: f64,
    len: usize,
    smooth_lobes: usize,
    /// `sum w albedo / pi` of the Lambert lobes, and whether they are all
    /// of the continuous part (the common case, evaluated without a frame).
    lambert_f: Color,
    only_lambert: bool,
    reads_choice: bool,
    reads_direction: bool,
}

impl Bsdf {
    /// An empty BSDF (black) in the frame of the unit shading `normal`.
    #[inline(always)]
    pub fn new(normal: &Vec3) -> Bsdf {
        let (tangent, bitangent) = orthonormal_basis(normal);
        Bsdf {
            tangent,
            bitangent,
            normal: *normal,
            lobes: ArrayVec::new(),
            weights: [0.0; MAX_LOBES],
            selection: [0.0; MAX_LOBES],
            total_selection: 0.0,
            smooth_selection: 0.0,
            len: 0,
            smooth_lobes: 0,
            lambert_f: Color::BLACK,
            only_lambert: true,
            reads_choice: false,
            reads_direction: false,
        }
    }

    /// Empties it, in the frame of the unit shading `normal`.
    #[inline(always)]
    pub fn reset(&mut self, normal: &Vec3) {
        let (tangent, bitangent) = orthonormal_basis(normal);
        self.tangent = tangent;
        self.bitangent = bitangent;
        self.normal = *normal;
        self.lobes.clear();
        self.total_selection = 0.0;
        self.smooth_selection = 0.0;
        self.len = 0;
        self.smooth_lobes = 0;
        self.lambert_f = Color::BLACK;
        self.only_lambert = true;
        self.reads_choice = false;
        self.reads_direction = false;
    }

    /// Adds `lobe` with `weight` (lobes beyond [`MAX_LOBES`], non-positive
    /// weights and black lobes are dropped).
    #[inline(always)]
    pub fn push(&mut self, lobe: Lobe, weight: f64) {
        let selection = weight * lobe.albedo_estimate();
        let usable = weight.is_finite() && selection > 0.0 && selection.is_finite();
        if self.len == MAX_LOBES || !usable {
            return;
        }
        let delta = lobe.is_delta();
        self.reads_choice |= self.len > 0 || lobe.reads_choice();
        self.reads_direction |= !delta;
        self.lobes.push(lobe);
        self.weights[self.len] = weight;
        self.selection[self.len] = selection;
        self.total_selection += selection;
        if !delta {
            self.smooth_selection += selection;
            self.smooth_lobes += 1;
            match &self.lobes[self.len] {
                Lobe::Lambert(l) => self.lambert_f += l.albedo * (weight * FRAC_1_PI),
                _ => self.only_lambert = false,
            }
        }
        self.len += 1;
    }

    /// The lobes and their weights.
    pub fn lobes(&self) -> impl Iterator<Item = (&Lobe, f64)> {
        self.lobes[..self.len]
            .iter()
            .zip(self.weights[..self.len].iter().copied())
    }

    /// Whether it reflects nothing (no lobe): paths end here.
    #[inline]
    pub fn is_black(&self) -> bool {
        self.len == 0
    }

    /// The unit shading normal.
    pub fn normal(&self) -> Vec3 {
        self.normal
    }

    #[inline]
    pub fn to_local(&self, v: &Vec3) -> Vec3 {
        Vec3::new(
            v.dot(&self.tangent),
            v.dot(&self.bitangent),
            v.dot(&self.normal),
        )
    }

    #[inline]
    pub fn to_world(&self, v: &Vec3) -> Vec3 {
        self.tangent * v.x + self.bitangent * v.y + self.normal * v.z
    }

    /// Whether [`Bsdf::sample`] reads `uc`: a choice between lobes, or
    /// between reflection and refraction.
    #[inline]
    pub fn reads_choice(&self) -> bool {
        self.reads_choice
    }

    /// Whether [`Bsdf::sample`] reads `u`: a continuous lobe.
    #[inline]
    pub fn reads_direction(&self) -> bool {
        self.reads_direction
    }

    /// The probability of choosing lobe `i`.
    #[inline]
    fn probability(&self, i: usize) -> f64 {
        self.selection[i] / self.total_selection
    }

    /// The probability that [`Bsdf::sample`] chooses a continuous lobe.
    #[inline]
    pub fn smooth_probability(&self) -> f64 {
        if self.smooth_selection == self.total_selection {
            1.0
        } else {
            self.smooth_selection / self.total_selection
        }
    }

    /// `f` of the continuous part when it is made of Lambert lobes only
    /// (what a caustic connection needs); `None` when it is not, or empty.
    #[inline]
    pub fn lambert(&self) -> Option<Color> {
        (self.only_lambert && self.smooth_lobes > 0).then_some(self.lambert_f)
    }

    /// A direction for `wo`: `uc` chooses the lobe (and, rescaled, between
    /// reflection and refraction), `u` the direction of a continuous lobe.
    #[inline]
    pub fn sample(&self, wo: &Vec3, uc: f64, u: [f64; 2]) -> Option<BsdfSample> {
        let (index, uc) = self.choose(uc)?;
        let lobe = &self.lobes[index];
        let local_wo = match lobe {
            // Lambert does not look at wo.
            Lobe::Lambert(_) if self.smooth_lobes == 1 => Vec3::z(),
            _ => self.to_local(wo),
        };
        let sample = lobe.sample(&local_wo, uc, u)?;
        let probability = self.probability(index);
        let wi = self.to_world(&sample.wi);
        if sample.delta || self.smooth_lobes == 1 {
            return Some(BsdfSample {
                wi,
                weight: sample.weight * (self.weights[index] / probability),
                pdf: sample.pdf * probability,
                delta: sample.delta,
            });
        }
        let mut f = Color::BLACK;
        let mut pdf = 0.0;
        for i in 0..self.len {
            let other = &self.lobes[i];
            if other.is_delta() {
                continue;
            }
            f += other.eval(&local_wo, &sample.wi) * self.weights[i];
            let density = if i == index {
                sample.pdf
            } else {
                other.pdf(&local_wo, &sample.wi)
            };
            pdf += density * self.probability(i);
        }
        let weight = if pdf > 0.0 { f / pdf } else { Color::BLACK };
        Some(BsdfSample {
            wi,
            weight,
            pdf,
            delta: false,
        })
    }

    /// `f(wo, wi) |cos_i|` of the continuous lobes, with their weights.
    #[inline]
    pub fn eval(&self, wo: &Vec3, wi: &Vec3) -> Color {
        if self.only_lambert {
            return self.lambert_f * self.normal.dot(wi).max(0.0);
        }
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
    #[inline]
    pub fn pdf(&self, wo: &Vec3, wi: &Vec3) -> f64 {
        if self.only_lambert {
            let cosine = self.normal.dot(wi).max(0.0);
            return self.smooth_probability() * cosine * FRAC_1_PI;
        }
        let (wo, wi) = (self.to_local(wo), self.to_local(wi));
        (0..self.len)
            .filter(|&i| !self.lobes[i].is_delta())
            .map(|i| self.lobes[i].pdf(&wo, &wi) * self.probability(i))
            .sum()
    }

    /// The lobe that `uc` chooses, and `uc` rescaled to [0, 1) within it.
    #[inline]
    fn choose(&self, uc: f64) -> Option<(usize, f64)> {
        match self.len {
            0 => None,
            1 => Some((0, uc)),
            _ => {
                let target = uc * self.total_selection;
                let mut start = 0.0;
                for i in 0..self.len {
                    let width = self.selection[i];
                    if target < start + width || i + 1 == self.len {
                        let rescaled = ((target - start) / width).clamp(0.0, ONE_BELOW);
                        return Some((i, rescaled));
                    }
                    start += width;
                }
                None
            }
        }
    }
}

/// The largest f64 below 1.
const ONE_BELOW: f64 = 1.0 - f64::EPSILON / 2.0;
