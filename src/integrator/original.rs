//! The original renderer's estimator, iterative: emission at every vertex, at
//! most five scattering vertices, one lobe chosen per vertex by the rates.
//!
//! The original traced the diffuse and mirror lobes both (branching) and both
//! glass lobes at the first two bounces; choosing one lobe with probability
//! equal to its weight and dividing by that probability has the same expected
//! value, and costs one path per sample.

use crate::color::Color;
use crate::math::{Ray, Vec3};
use crate::sampler::Sampler;
use crate::sampling::{cosine_hemisphere, dielectric, reflect};
use crate::shading::Shading;

use super::SceneView;
use super::lights;

/// Scattering vertices of the original before a path ends.
pub const MAX_DEPTH: u32 = 5;

/// Diffuse rates at or below this are ignored (the original's threshold).
pub(super) const MIN_DIFFUSE_RATE: f64 = 1e-4;

pub fn radiance(view: &SceneView, mut ray: Ray, sampler: &mut Sampler) -> Color {
    let mut result = Color::BLACK;
    let mut throughput = Color::WHITE;
    let mut depth = 0;
    loop {
        let Some(hit) = view.world.intersect(&ray, 0.0, f64::INFINITY) else {
            if depth == 0 {
                result += throughput * view.scene.background;
            }
            break;
        };
        let at = Shading::new(view.scene, &hit, &ray);
        let material = at.material;
        result += throughput * material.emission;
        depth += 1;
        if depth > view.max_depth || at.color.is_black() {
            break;
        }
        let diffuse = if material.diffuse > MIN_DIFFUSE_RATE {
            material.diffuse
        } else {
            0.0
        };
        if diffuse > 0.0 && !view.direct_lights.is_empty() {
            result += throughput * lights::direct(view.world, view.direct_lights, &at) * diffuse;
        }
        let specular = material.specular.max(0.0);
        let refract = material.refract.max(0.0);
        let total = diffuse + specular + refract;
        if total <= 0.0 {
            break;
        }
        // One lobe, chosen with probability weight / total: the weight and the
        // probability cancel but for `total` (1 for normalised materials).
        throughput *= at.color * total;
        let pick = sampler.next_f64() * total;
        let direction = if pick < diffuse {
            cosine_hemisphere(&at.normal, sampler.next_2d())
        } else if pick < diffuse + specular {
            reflect(&ray.direction, &at.normal)
        } else {
            glass_direction(&ray, &at, sampler, &mut throughput)
        };
        ray = Ray::new(at.spawn_origin(&direction), direction, ray.time);
    }
    result
}

/// The glass lobe: smallpt's Russian roulette between reflection and
/// refraction (reflection only under total internal reflection), with its
/// weight folded into `throughput`.
pub(super) fn glass_direction(
    ray: &Ray,
    at: &Shading,
    sampler: &mut Sampler,
    throughput: &mut Color,
) -> Vec3 {
    let glass = dielectric(&ray.direction, &at.normal, at.entering, at.material.ior);
    match glass.refracted {
        None => glass.reflected,
        Some(refracted) => {
            let p = 0.25 + 0.5 * glass.reflectance;
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
