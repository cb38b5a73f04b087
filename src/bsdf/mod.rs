//! The BSDF contract: what a surface does with light, built per hit from
//! the material and the shading frame, and the only place where reflection
//! formulas live. The integrators and the light subpaths ask three things:
//!
//! - [`Bsdf::sample`]`(wo, uc, u)`: a direction `wi` with its weight
//!   `f |cos_i| / pdf`, its density and its kind ([`BsdfFlags`]);
//! - [`Bsdf::eval`]`(wo, wi)`: `f(wo, wi) |cos_i|` of the continuous lobes;
//! - [`Bsdf::pdf`]`(wo, wi)`: the density with which `sample` gives `wi`.
//!
//! A BSDF is a mixture of weighted lobes (`lobe`): the rates of the
//! original (`diffusionRate`, `specularRate`, `refractRate`) become the
//! weights of a diffuse, a conductor and a dielectric lobe, and the lobes
//! some dialects add (Phong, a GGX coat) come with weight 1
//! (`render_scene::lobes` makes them from a material's description).
//! What does not depend on the hit is a [`LobeSet`], made once per material
//! before rendering; a [`Bsdf`] is a lobe set at one hit (its colour, its
//! shading frame, its side of a dielectric), a few words to make.
//! `sample` picks one lobe with probability proportional to its weight times
//! its mean tint. A delta lobe's sample is weighted by its own weight over
//! that probability; a continuous lobe's sample by the whole continuous
//! part, `sum w_j f_j |cos| / sum p_j pdf_j`, so that `eval` and `pdf` are
//! the mixture's. The continuous part's total probability is
//! [`Bsdf::probability`]`(BsdfFlags::CONTINUOUS)`: an integrator that
//! samples lights only when `sample` chose a continuous lobe divides by it.
//! Integrators ask what kind of scattering a BSDF or a sample does by its
//! [`BsdfFlags`] (`kinds`), never by naming a lobe.
//!
//! All directions are world-space unit vectors pointing away from the
//! surface; `wo` is on the side of the shading normal the BSDF was built
//! with.

mod angular;
pub mod conductor;
pub mod cook_torrance;
pub mod dielectric;
pub mod flags;
pub mod fresnel;
mod kinds;
pub mod lambert;
pub mod lobe;
mod lobe_set;
pub mod microfacet;
pub mod osb_glossy;
pub mod phong;
pub mod rough_dielectric;
mod rules;

#[cfg(test)]
mod kinds_tests;
#[cfg(test)]
mod tests;

use std::f64::consts::FRAC_1_PI;

use crate::color::Color;
use crate::math::{Vec3, orthonormal_basis};
use crate::spectral::Dispersion;

pub use angular::AngularWeights;
pub use conductor::ConductorFresnel;
pub use dielectric::GlassChoice;
pub use flags::{BsdfFlags, TransportMode};
pub use fresnel::DielectricFresnel;
pub use lambert::Lambert;
pub use lobe::{Lobe, LobeSample};
pub use lobe_set::LobeSet;
pub use microfacet::MIN_ROUGHNESS;
pub use rules::{LookLobes, Rules};

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
    /// The kind of the chosen lobe, on the side `wi` left to.
    pub flags: BsdfFlags,
}

impl BsdfSample {
    /// A delta direction (a mirror, smooth glass).
    #[inline]
    pub fn is_delta(&self) -> bool {
        self.flags.is_specular()
    }
}

/// A lobe set at one hit: a handful of words (the set, the hit's colour,
/// normal and side), everything else derived on demand, so that making one
/// per vertex costs next to nothing.
#[derive(Clone, Copy, Debug)]
pub struct Bsdf<'a> {
    set: &'a LobeSet,
    color: Color,
    normal: Vec3,
    entering: bool,
    rules: Rules,
    /// The outgoing direction's cosine (for angle-dependent weights).
    cos_o: f64,
    /// The geometric normal (on the side of `wo`) of a surface whose
    /// transport is not the same both ways (see [`BsdfFlags::NONRECIPROCAL`]).
    nonreciprocal: Option<Vec3>,
    mode: TransportMode,
}

/// The weights and probabilities of the lobes at one hit.
struct Mixture {
    weights: [f64; MAX_LOBES],
    probabilities: [f64; MAX_LOBES],
}

impl<'a> Bsdf<'a> {
    /// `set` at a hit: `color` its colour there (texture or constant),
    /// `normal` the unit shading normal on the side of the outgoing
    /// direction, `entering` whether that side is the outside, `cos_o` the
    /// outgoing direction's cosine (for angle-dependent weights).
    #[inline(always)]
    pub fn new(
        set: &'a LobeSet,
        color: Color,
        normal: &Vec3,
        entering: bool,
        cos_o: f64,
        rules: Rules,
    ) -> Bsdf<'a> {
        Bsdf {
            set,
            color,
            normal: *normal,
            entering,
            rules,
            cos_o,
            nonreciprocal: None,
            mode: TransportMode::Radiance,
        }
    }

    /// How the index of its dielectric lobe depends on the wavelength:
    /// where a path must be split (see [`crate::spectral`]).
    #[inline]
    pub fn dispersion(&self) -> Option<Dispersion> {
        self.set.dispersion
    }

    /// The same BSDF over `set` (its lobe set with another index, see
    /// [`LobeSet::with_ior`]).
    #[inline]
    pub fn with_set<'b>(&self, set: &'b LobeSet) -> Bsdf<'b> {
        Bsdf {
            set,
            color: self.color,
            normal: self.normal,
            entering: self.entering,
            rules: self.rules,
            cos_o: self.cos_o,
            nonreciprocal: self.nonreciprocal,
            mode: self.mode,
        }
    }

    /// Its lobe set.
    #[inline]
    pub fn set(&self) -> &'a LobeSet {
        self.set
    }

    /// Runs `f` with the lobes' weights and probabilities: the set's when
    /// they do not depend on the hit, else computed here.
    #[inline]
    fn with_mixture<R>(&self, f: impl FnOnce(&[f64; MAX_LOBES], &[f64; MAX_LOBES]) -> R) -> R {
        if self.set.fixed {
            return f(&self.set.weights, &self.set.fixed_probabilities);
        }
        let mixture = self.mixture();
        f(&mixture.weights, &mixture.probabilities)
    }

    /// The weights and probabilities at this hit (lobes chosen by weight
    /// times albedo estimate; all zero when it reflects nothing).
    fn mixture(&self) -> Mixture {
        let set = self.set;
        let mut weights = set.weights;
        if let Some(angular) = &set.angular {
            let (d, s, r) = angular.weights(self.cos_o, self.entering, set.ior);
            weights[..3].copy_from_slice(&[d, s, r]);
        }
        let mut probabilities = [0.0; MAX_LOBES];
        let mut total = 0.0;
        for (i, p) in probabilities.iter_mut().enumerate().take(set.lobes.len()) {
            let selection = weights[i] * self.lobe(i).albedo_estimate();
            *p = if selection.is_finite() {
                selection.max(0.0)
            } else {
                0.0
            };
            total += *p;
        }
        if total > 0.0 {
            for p in &mut probabilities {
                *p /= total;
            }
        }
        Mixture {
            weights,
            probabilities,
        }
    }

    /// The tint lobe `i` has at this hit.
    #[inline]
    fn tint(&self, i: usize) -> Color {
        if self.set.tinted[i] {
            self.color
        } else {
            self.set.lobes[i].tint()
        }
    }

    /// Lobe `i` at this hit: its tint, its side of a dielectric, the
    /// rendering's Fresnel term and glass choice.
    #[inline]
    fn lobe(&self, i: usize) -> Lobe {
        let mut lobe = self.set.lobes[i];
        if self.set.tinted[i] {
            lobe.set_tint(self.color);
        }
        let fresnel = self.set.follows_rules[i].then_some(self.rules.fresnel);
        lobe.set_side(self.entering, fresnel, self.rules.glass);
        lobe
    }

    /// Whether it reflects nothing: paths end here.
    #[inline]
    pub fn is_black(&self) -> bool {
        if self.set.fixed {
            self.set.lobes.is_empty()
                || self.color.average() <= 0.0
                || self.color.average().is_nan()
        } else {
            self.with_mixture(|_, p| p.iter().all(|&p| p <= 0.0))
        }
    }

    /// The unit shading normal.
    pub fn normal(&self) -> Vec3 {
        self.normal
    }

    /// The tangent and bitangent of the shading frame.
    #[inline]
    fn frame(&self) -> (Vec3, Vec3) {
        orthonormal_basis(&self.normal)
    }

    pub fn to_local(&self, v: &Vec3) -> Vec3 {
        let (tangent, bitangent) = self.frame();
        Vec3::new(v.dot(&tangent), v.dot(&bitangent), v.dot(&self.normal))
    }

    pub fn to_world(&self, v: &Vec3) -> Vec3 {
        let (tangent, bitangent) = self.frame();
        tangent * v.x + bitangent * v.y + self.normal * v.z
    }

    /// A direction for `wo`: `uc` chooses the lobe (and, rescaled, between
    /// reflection and refraction), `u` the direction of a continuous lobe.
    #[inline(always)]
    pub fn sample(&self, wo: &Vec3, uc: f64, u: [f64; 2]) -> Option<BsdfSample> {
        if self.set.single_lambert {
            // The common case: one tinted Lambert lobe.
            let weight = self.color * self.set.weights[0];
            let wi = lambert::cosine_hemisphere(u);
            return self.transported(BsdfSample {
                wi: self.to_world(&wi),
                weight,
                pdf: wi.z * FRAC_1_PI,
                flags: BsdfFlags::DIFFUSE_REFLECTION,
            });
        }
        let sample = self.with_mixture(|weights, probabilities| {
            self.sample_mixture(wo, uc, u, weights, probabilities)
        })?;
        self.transported(sample)
    }

    #[inline(never)]
    fn sample_mixture(
        &self,
        wo: &Vec3,
        uc: f64,
        u: [f64; 2],
        weights: &[f64; MAX_LOBES],
        probabilities: &[f64; MAX_LOBES],
    ) -> Option<BsdfSample> {
        let (index, uc) = choose(probabilities, self.set.lobes.len(), uc)?;
        let lobe = self.lobe(index);
        let local_wo = self.to_local(wo);
        let sample = lobe.sample(&local_wo, uc, u)?;
        let probability = probabilities[index];
        let wi = self.to_world(&sample.wi);
        let flags = kinds::on_side(lobe.flags(), sample.wi.z);
        if sample.delta || self.set.smooth_lobes == 1 {
            return Some(BsdfSample {
                wi,
                weight: sample.weight * (weights[index] / probability),
                pdf: sample.pdf * probability,
                flags,
            });
        }
        let mut f = Color::BLACK;
        let mut pdf = 0.0;
        for i in 0..self.set.lobes.len() {
            if self.set.lobes[i].is_delta() {
                continue;
            }
            let other = self.lobe(i);
            f += other.eval(&local_wo, &sample.wi) * weights[i];
            let density = if i == index {
                sample.pdf
            } else {
                other.pdf(&local_wo, &sample.wi)
            };
            pdf += density * probabilities[i];
        }
        let weight = if pdf > 0.0 { f / pdf } else { Color::BLACK };
        Some(BsdfSample {
            wi,
            weight,
            pdf,
            flags,
        })
    }

    /// `f(wo, wi) |cos_i|` of the continuous lobes, with their weights.
    #[inline(always)]
    pub fn eval(&self, wo: &Vec3, wi: &Vec3) -> Color {
        if self.set.single_lambert {
            let f = self.color * (self.set.weights[0] * FRAC_1_PI);
            return f * self.normal.dot(wi).max(0.0);
        }
        self.eval_mixture(wo, wi)
    }

    #[inline(never)]
    fn eval_mixture(&self, wo: &Vec3, wi: &Vec3) -> Color {
        if self.set.continuous.is_diffuse_reflection_only() {
            return self.diffuse_f().unwrap_or(Color::BLACK) * self.normal.dot(wi).max(0.0);
        }
        let (wo, wi) = (self.to_local(wo), self.to_local(wi));
        self.with_mixture(|weights, _| {
            let mut f = Color::BLACK;
            for (i, weight) in weights.iter().enumerate().take(self.set.lobes.len()) {
                if !self.set.lobes[i].is_delta() {
                    f += self.lobe(i).eval(&wo, &wi) * *weight;
                }
            }
            f
        })
    }

    /// The density (solid angle) with which [`Bsdf::sample`] gives `wi`,
    /// over its continuous lobes.
    #[inline(always)]
    pub fn pdf(&self, wo: &Vec3, wi: &Vec3) -> f64 {
        if self.set.single_lambert {
            return self.normal.dot(wi).max(0.0) * FRAC_1_PI;
        }
        self.pdf_mixture(wo, wi)
    }

    #[inline(never)]
    fn pdf_mixture(&self, wo: &Vec3, wi: &Vec3) -> f64 {
        if self.set.continuous.is_diffuse_reflection_only() {
            let cosine = self.normal.dot(wi).max(0.0);
            return self.probability(BsdfFlags::CONTINUOUS) * cosine * FRAC_1_PI;
        }
        let (wo, wi) = (self.to_local(wo), self.to_local(wi));
        self.with_mixture(|_, probabilities| {
            (0..self.set.lobes.len())
                .filter(|&i| !self.set.lobes[i].is_delta())
                .map(|i| self.lobe(i).pdf(&wo, &wi) * probabilities[i])
                .sum()
        })
    }
}

/// The lobe that `uc` chooses among the first `n` by their probabilities,
/// and `uc` rescaled to [0, 1) within it.
#[inline]
fn choose(probabilities: &[f64; MAX_LOBES], n: usize, uc: f64) -> Option<(usize, f64)> {
    if n == 1 {
        return (probabilities[0] > 0.0).then_some((0, uc));
    }
    let mut start = 0.0;
    let mut last = None;
    for (i, &width) in probabilities.iter().enumerate().take(n) {
        if width <= 0.0 {
            continue;
        }
        if uc < start + width {
            let rescaled = ((uc - start) / width).clamp(0.0, ONE_BELOW);
            return Some((i, rescaled));
        }
        start += width;
        last = Some(i);
    }
    // Rounding: the probabilities summed to a little less than uc.
    last.map(|i| (i, ONE_BELOW))
}

/// The largest f64 below 1.
const ONE_BELOW: f64 = 1.0 - f64::EPSILON / 2.0;
