//! The lobes of the rates material, shared by both integrators and the light
//! subpaths: which lobe a vertex scatters into (chosen by rate), the choice
//! of an emitter, the PA1 lights of the diffuse part, and smallpt's glass.

use crate::color::Color;
use crate::math::{Ray, Vec3};
use crate::sampler::Sampler;
use crate::sampling::dielectric;
use crate::scene::model::Material;
use crate::shading::Shading;

use super::{SceneView, lights};

/// Diffuse rates at or below this are ignored (the original's threshold).
pub const MIN_DIFFUSE_RATE: f64 = 1e-4;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Lobe {
    Diffuse,
    Mirror,
    Glass,
}

/// The lobe weights of a material, as the original reads them.
#[derive(Clone, Copy, Debug)]
pub struct Lobes {
    pub diffuse: f64,
    pub specular: f64,
    pub refract: f64,
}

impl Lobes {
    pub fn of(material: &Material) -> Lobes {
        Lobes {
            diffuse: if material.diffuse > MIN_DIFFUSE_RATE {
                material.diffuse
            } else {
                0.0
            },
            specular: material.specular.max(0.0),
            refract: material.refract.max(0.0),
        }
    }

    /// Sum of the weights (1 for normalised materials).
    pub fn total(&self) -> f64 {
        self.diffuse + self.specular + self.refract
    }

    /// The lobe to scatter into, spending a sample dimension (for
    /// [`Lobes::pick`]) only when there is a choice to make, so that the
    /// stratified dimensions go to directions.
    pub fn choose(&self, sampler: &mut Sampler) -> Lobe {
        match self.only() {
            Some(lobe) => lobe,
            None => self.pick(sampler.next_f64()),
        }
    }

    /// The lobe when only one has a weight (no choice to make), else `None`.
    fn only(&self) -> Option<Lobe> {
        match (self.diffuse > 0.0, self.specular > 0.0, self.refract > 0.0) {
            (true, false, false) => Some(Lobe::Diffuse),
            (false, true, false) => Some(Lobe::Mirror),
            (false, false, true) => Some(Lobe::Glass),
            _ => None,
        }
    }

    /// One lobe, with probability weight / total; `u` in [0, 1). Weight and
    /// probability cancel but for `total`, which the caller multiplies in.
    pub fn pick(&self, u: f64) -> Lobe {
        let pick = u * self.total();
        if pick < self.diffuse {
            Lobe::Diffuse
        } else if pick < self.diffuse + self.specular {
            Lobe::Mirror
        } else {
            Lobe::Glass
        }
    }
}

/// The number that picks an emitter for a light sample or light subpath: a
/// sample dimension only when there is more than one emitter to pick.
pub fn emitter_choice(view: &SceneView, sampler: &mut Sampler) -> f64 {
    if view.emitters.len() > 1 {
        sampler.next_f64()
    } else {
        0.5
    }
}

/// Radiance of the PA1 point and directional lights at this vertex, weighted
/// by the diffuse rate (the caller multiplies by the throughput).
pub fn pa1_lights(view: &SceneView, at: &Shading, lobes: &Lobes) -> Color {
    if lobes.diffuse > 0.0 && !view.direct_lights.is_empty() {
        lights::direct(view.world, view.direct_lights, at) * lobes.diffuse
    } else {
        Color::BLACK
    }
}

/// How the glass lobe chooses between reflection and refraction.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GlassChoice {
    /// smallpt's roulette: reflect with probability 0.25 + Re / 2.
    Smallpt,
    /// Reflect with probability Re: the weights become exactly 1, which has
    /// the same expectation and less variance.
    Fresnel,
}

/// The glass lobe: a roulette between reflection and refraction (reflection
/// only under total internal reflection), with its weight folded into
/// `throughput`.
pub fn glass_direction(
    ray: &Ray,
    at: &Shading,
    sampler: &mut Sampler,
    throughput: &mut Color,
    choice: GlassChoice,
) -> Vec3 {
    let glass = dielectric(&ray.direction, &at.normal, at.entering, at.material.ior);
    match glass.refracted {
        None => glass.reflected,
        Some(refracted) => {
            let p = match choice {
                GlassChoice::Smallpt => 0.25 + 0.5 * glass.reflectance,
                GlassChoice::Fresnel => glass.reflectance.clamp(1e-6, 1.0 - 1e-6),
            };
            if sampler.next_f64() < p {
                *throughput *= glass.reflectance / p;
                glass.reflected
            } else {
                *throughput *= (1.0 - glass.reflectance) / (1.0 - p);
                refracted
            }
        }
    }
}
