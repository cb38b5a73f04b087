//! The original renderer's estimator, iterative: emission at every vertex, at
//! most five scattering vertices, one lobe chosen per vertex by the rates.
//!
//! The original traced the diffuse and mirror lobes both (branching) and both
//! glass lobes at the first two bounces; choosing one lobe with probability
//! equal to its weight and dividing by that probability has the same expected
//! value, and costs one path per sample. Glass chooses between reflection
//! and refraction by smallpt's roulette.

use crate::bsdf::GlassChoice;
use crate::color::Color;
use crate::look::RayOrigins;
use crate::math::Ray;
use crate::sampler::Sampler;
use crate::spectral::PathSpectrum;

use super::scatter::{bsdf_at, miss, pa1_lights, sample};
use crate::render_scene::RenderScene;

/// Scattering vertices of the original before a path ends.
pub const MAX_DEPTH: u32 = 5;

pub fn radiance(scene: &RenderScene, mut ray: Ray, sampler: &mut Sampler) -> Color {
    let mut result = Color::BLACK;
    let mut throughput = Color::WHITE;
    let mut depth = 0;
    loop {
        let Some(hit) = scene.intersect(&ray) else {
            result += miss(scene, depth, throughput);
            break;
        };
        let at = scene.shade(&hit, &ray);
        result += throughput * at.material.emission;
        depth += 1;
        if depth > scene.max_depth() {
            break;
        }
        let wo = -ray.direction;
        let bsdf = bsdf_at(scene, &at, &wo, GlassChoice::Smallpt);
        if bsdf.is_black() {
            break;
        }
        result += throughput * pa1_lights(scene, &at, &bsdf, &wo, &PathSpectrum::Rgb);
        let Some(scattered) = sample(&bsdf, &wo, sampler) else {
            break;
        };
        throughput *= scattered.weight;
        if throughput.is_black() {
            break;
        }
        let direction = scattered.wi;
        let origin = match scene.look().ray_origins {
            RayOrigins::Offset => at.spawn_origin(&direction),
            RayOrigins::AtHit => ray.at(hit.t),
        };
        ray = Ray::new(origin, direction, ray.time);
    }
    result
}
