//! One lobe of a BSDF, in the local shading frame (z the shading normal on
//! the side of the outgoing direction `wo`; both directions point away from
//! the surface). Every lobe answers the same three questions:
//!
//! - `sample(wo, uc, u)`: a direction `wi` with `weight = eval / pdf`
//!   (`f |cos_i| / pdf`; for delta lobes the weight of the chosen direction)
//!   and the density `pdf` of the routine over the whole sphere; directions
//!   the lobe does not scatter into (below the surface) come with weight 0;
//! - `eval(wo, wi)`: `f(wo, wi) |cos_i|`, 0 for delta lobes;
//! - `pdf(wo, wi)`: the density with which `sample` produces `wi`, 0 for
//!   delta lobes.

use super::ConductorFresnel;
use super::conductor::Conductor;
use super::cook_torrance::CookTorrance;
use super::dielectric::Dielectric;
use super::dielectric::GlassChoice;
use super::flags::BsdfFlags;
use super::fresnel::DielectricFresnel;
use super::lambert::Lambert;
use super::osb_glossy::OsbGlossy;
use super::phong::Phong;
use super::rough_dielectric::RoughDielectric;
use crate::color::Color;
use crate::math::Vec3;

/// A sampled direction of one lobe (see the module documentation).
#[derive(Clone, Copy, Debug)]
pub struct LobeSample {
    pub wi: Vec3,
    pub weight: Color,
    pub pdf: f64,
    pub delta: bool,
}

impl LobeSample {
    /// A direction of a continuous lobe with its `eval` and density: the
    /// weight is their ratio (0 where either vanishes).
    pub fn from_eval(wi: Vec3, eval: Color, pdf: f64) -> LobeSample {
        let weight = if pdf > 0.0 && !eval.is_black() {
            eval / pdf
        } else {
            Color::BLACK
        };
        LobeSample {
            wi,
            weight,
            pdf,
            delta: false,
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Lobe {
    Lambert(Lambert),
    Conductor(Conductor),
    Dielectric(Dielectric),
    RoughDielectric(RoughDielectric),
    Phong(Phong),
    CookTorrance(CookTorrance),
    OsbGlossy(OsbGlossy),
}

impl Lobe {
    /// Whether it scatters into single directions (mirror, smooth glass).
    #[inline]
    pub fn is_delta(&self) -> bool {
        match self {
            Lobe::Conductor(c) => c.is_delta(),
            Lobe::Dielectric(_) => true,
            _ => false,
        }
    }

    /// What kind of scattering it does.
    #[inline]
    pub fn flags(&self) -> BsdfFlags {
        let kind = match self {
            Lobe::Lambert(_) => BsdfFlags::DIFFUSE,
            Lobe::Conductor(c) if c.is_delta() => BsdfFlags::SPECULAR,
            Lobe::Dielectric(_) => BsdfFlags::SPECULAR,
            _ => BsdfFlags::GLOSSY,
        };
        let sides = match self {
            Lobe::Dielectric(_) | Lobe::RoughDielectric(_) => {
                BsdfFlags::REFLECTION | BsdfFlags::TRANSMISSION
            }
            _ => BsdfFlags::REFLECTION,
        };
        kind | sides
    }

    /// About how much the lobe reflects (its mean tint; a Schlick term's
    /// mean over the cosine-weighted hemisphere): what lobes are chosen by.
    /// 0 for a lobe that reflects nothing.
    #[inline]
    pub fn albedo_estimate(&self) -> f64 {
        let tint = match self {
            Lobe::Lambert(l) => l.albedo,
            Lobe::Conductor(c) => match c.fresnel {
                ConductorFresnel::Constant => c.tint,
                // The mean of (1 - cos)^5 under the cosine is 1/21.
                ConductorFresnel::Schlick => c.tint.map(|f0| f0 + (1.0 - f0) / 21.0),
            },
            Lobe::Dielectric(d) => d.tint,
            Lobe::RoughDielectric(d) => d.tint,
            Lobe::Phong(p) => p.color,
            Lobe::CookTorrance(c) => c.color,
            Lobe::OsbGlossy(g) => g.color,
        };
        tint.average().max(0.0)
    }

    #[inline]
    /// The colour that scales the lobe.
    pub fn tint(&self) -> Color {
        match self {
            Lobe::Lambert(l) => l.albedo,
            Lobe::Conductor(c) => c.tint,
            Lobe::Dielectric(d) => d.tint,
            Lobe::RoughDielectric(d) => d.tint,
            Lobe::Phong(p) => p.color,
            Lobe::CookTorrance(c) => c.color,
            Lobe::OsbGlossy(g) => g.color,
        }
    }

    #[inline]
    pub fn set_tint(&mut self, tint: Color) {
        match self {
            Lobe::Lambert(l) => l.albedo = tint,
            Lobe::Conductor(c) => c.tint = tint,
            Lobe::Dielectric(d) => d.tint = tint,
            Lobe::RoughDielectric(d) => d.tint = tint,
            Lobe::Phong(p) => p.color = tint,
            Lobe::CookTorrance(c) => c.color = tint,
            Lobe::OsbGlossy(g) => g.color = tint,
        }
    }

    /// A dielectric (given as seen from outside) of index `ior` inside;
    /// other lobes have no index.
    #[inline]
    pub fn set_ior(&mut self, ior: f64) {
        match self {
            Lobe::Dielectric(d) => d.eta_below = ior,
            Lobe::RoughDielectric(d) => d.eta_below = ior,
            _ => {}
        }
    }

    /// A dielectric given as seen from outside, seen from the side of the
    /// outgoing direction (`entering`: the outside), with the rendering's
    /// Fresnel term (`None`: its own) and glass choice. Other lobes are
    /// the same from both sides.
    #[inline]
    pub fn set_side(
        &mut self,
        entering: bool,
        fresnel: Option<DielectricFresnel>,
        glass: GlassChoice,
    ) {
        match self {
            Lobe::Dielectric(d) => {
                if !entering {
                    std::mem::swap(&mut d.eta_above, &mut d.eta_below);
                }
                if let Some(fresnel) = fresnel {
                    d.fresnel = fresnel;
                }
                d.choice = glass;
            }
            Lobe::RoughDielectric(d) => {
                if !entering {
                    std::mem::swap(&mut d.eta_above, &mut d.eta_below);
                }
                if let Some(fresnel) = fresnel {
                    d.fresnel = fresnel;
                }
            }
            _ => {}
        }
    }

    #[inline]
    pub fn sample(&self, wo: &Vec3, uc: f64, u: [f64; 2]) -> Option<LobeSample> {
        match self {
            Lobe::Lambert(l) => Some(l.sample(u)),
            Lobe::Conductor(c) => c.sample(wo, u),
            Lobe::Dielectric(d) => Some(d.sample(wo, uc)),
            Lobe::RoughDielectric(d) => d.sample(wo, uc, u),
            Lobe::Phong(p) => Some(p.sample(wo, u)),
            Lobe::CookTorrance(c) => c.sample(wo, u),
            Lobe::OsbGlossy(g) => Some(g.sample(wo, u)),
        }
    }

    pub fn eval(&self, wo: &Vec3, wi: &Vec3) -> Color {
        match self {
            Lobe::Lambert(l) => l.eval(wi),
            Lobe::Conductor(c) => c.eval(wo, wi),
            Lobe::Dielectric(_) => Color::BLACK,
            Lobe::RoughDielectric(d) => d.eval(wo, wi),
            Lobe::Phong(p) => p.eval(wo, wi),
            Lobe::CookTorrance(c) => c.eval(wo, wi),
            Lobe::OsbGlossy(g) => g.eval(wo, wi),
        }
    }

    pub fn pdf(&self, wo: &Vec3, wi: &Vec3) -> f64 {
        match self {
            Lobe::Lambert(l) => l.pdf(wi),
            Lobe::Conductor(c) => c.pdf(wo, wi),
            Lobe::Dielectric(_) => 0.0,
            Lobe::RoughDielectric(d) => d.pdf(wo, wi),
            Lobe::Phong(p) => p.pdf(wo, wi),
            Lobe::CookTorrance(c) => c.pdf(wo, wi),
            Lobe::OsbGlossy(g) => g.pdf(wi),
        }
    }
}
