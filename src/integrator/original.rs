//! The original renderer's estimator, iterative: emission at every vertex, at
//! most five scattering vertices, one lobe chosen per vertex by the rates.
//!
//! The original traced the diffuse and mirror lobes both (branching) and both
//! glass lobes at the first two bounces; choosing one lobe with probability
//! equal to its weight and dividing by that probability has the same expected
//! value, and costs one path per sample. Glass chooses between reflection
//! and refraction by smallpt's roulette.

use crate::bsdf::{BsdfFlags, GlassChoice};
use crate::color::Color;
use crate::geometry::single_precision;
use crate::look::RayOrigins;
use crate::math::Ray;
use crate::sampler::Sampler;
use crate::spectral::PathSpectrum;

use super::path_log::{PathEvent, PathLog, Term};
use super::scatter::{bsdf_at, miss, pa1_lights, sample};
use crate::render_scene::RenderScene;

/// Scattering vertices of the original before a path ends.
pub const MAX_DEPTH: u32 = 5;

pub fn radiance(
    scene: &RenderScene,
    mut ray: Ray,
    sampler: &mut Sampler,
    log: &mut impl PathLog,
) -> Color {
    let mut result = Color::BLACK;
    let mut throughput = Color::WHITE;
    let mut depth = 0;
    loop {
        let Some(hit) = scene.intersect(&ray) else {
            let background = miss(scene, depth, throughput);
            add(&mut result, log, depth + 1, Term::Background, background);
            log.record(|| PathEvent::Ended {
                depth: depth + 1,
                why: "the ray found nothing",
            });
            break;
        };
        let at = scene.shade(&hit, &ray);
        log.record(|| PathEvent::Hit {
            depth: depth + 1,
            point: at.point,
            normal: at.normal,
            material: hit.material,
            lobes: Box::new(at.material.lobes.clone()),
        });
        let emission = throughput * at.material.emission;
        add(&mut result, log, depth + 1, Term::Emission, emission);
        depth += 1;
        if depth > scene.max_depth() {
            log.record(|| PathEvent::Ended {
                depth,
                why: "the deepest hit",
            });
            break;
        }
        let wo = -ray.direction;
        let bsdf = bsdf_at(scene, &at, &wo, GlassChoice::Smallpt);
        if bsdf.is_black() {
            log.record(|| PathEvent::Ended {
                depth,
                why: "a black BSDF",
            });
            break;
        }
        let lights = throughput * pa1_lights(scene, &at, &bsdf, &wo, &PathSpectrum::Rgb);
        add(&mut result, log, depth, Term::DirectLights, lights);
        let Some(scattered) = sample(&bsdf, &wo, sampler) else {
            log.record(|| PathEvent::Ended {
                depth,
                why: "the BSDF gave no direction",
            });
            break;
        };
        throughput *= scattered.weight;
        log.record(|| PathEvent::Scattered {
            depth,
            wi: scattered.wi,
            weight: scattered.weight,
            pdf: scattered.pdf,
            flags: scattered.flags,
            throughput,
        });
        if throughput.is_black() {
            log.record(|| PathEvent::Ended {
                depth,
                why: "a black throughput",
            });
            break;
        }
        let direction = if scene.look().diffuse_about_modelled_normal
            && !at.entering
            && scattered.flags.contains(BsdfFlags::DIFFUSE_REFLECTION)
        {
            // The cosine lobe about the normal as modelled, which is
            // the mirror image of the one about the normal turned back
            // towards the ray.
            -scattered.wi
        } else {
            scattered.wi
        };
        let origin = match scene.look().ray_origins {
            RayOrigins::Offset => at.spawn_origin(&direction),
            RayOrigins::AtHit => ray.at(hit.t),
            RayOrigins::AtHitSinglePrecision => single_precision::point_at(&ray, hit.t),
        };
        ray = Ray::new(origin, direction, ray.time);
    }
    result
}

/// Adds `value`, a term of the sample, to `result`, and reports it.
#[inline(always)]
fn add(result: &mut Color, log: &mut impl PathLog, depth: u32, term: Term, value: Color) {
    *result += value;
    log.record(|| PathEvent::Added {
        depth,
        term,
        mis_weight: None,
        value,
    });
}
