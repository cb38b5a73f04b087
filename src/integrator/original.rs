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
use crate::look::{RayOrigins, Roulette};
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
        if !survives_roulette(
            scene.look().roulette,
            depth,
            &at.color,
            &mut throughput,
            sampler,
        ) {
            log.record(|| PathEvent::Ended {
                depth,
                why: "Russian roulette",
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

/// Hits before yangjunx21's roulette starts (it plays from the 6th on).
const SIGNED_ROULETTE_FROM: u32 = 6;

/// Whether the path goes on at its hit number `depth` (1 for the camera's)
/// of colour `color`, under the look's `roulette`; the survivor's
/// `throughput` is divided by its chance as the look does it.
fn survives_roulette(
    roulette: Roulette,
    depth: u32,
    color: &Color,
    throughput: &mut Color,
    sampler: &mut Sampler,
) -> bool {
    match roulette {
        Roulette::Never => true,
        Roulette::SignedUniform if depth < SIGNED_ROULETTE_FROM => true,
        Roulette::SignedUniform => {
            let p = color.r.max(color.g).max(color.b);
            // A black colour ends the path's light anyway (theirs divides
            // it by 0).
            if p > 0.0 && 2.0 * sampler.next_f64() - 1.0 < p {
                *throughput *= 1.0 / p;
                true
            } else {
                false
            }
        }
    }
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sampler::SamplerKind;

    /// The share of paths that go on at hit `depth` of colour `color` and
    /// the mean weight they carry on (0 for those that end), over many draws.
    fn survival(roulette: Roulette, depth: u32, color: Color) -> (f64, f64) {
        let draws = 20_000;
        let (mut kept, mut weight) = (0u32, 0.0);
        for i in 0..draws {
            let mut sampler = Sampler::new(SamplerKind::Independent, 3, i, 5);
            let mut throughput = Color::WHITE;
            if survives_roulette(roulette, depth, &color, &mut throughput, &mut sampler) {
                kept += 1;
                weight += throughput.g;
            }
        }
        (f64::from(kept) / draws as f64, weight / draws as f64)
    }

    #[test]
    fn the_signed_roulette_keeps_one_plus_p_halves_and_divides_by_p_from_the_sixth_hit() {
        let grey = Color::new(0.25, 0.75, 0.5);
        // p = 0.75: kept with probability 0.875, each carrying 1 / 0.75, so
        // the expected weight is 0.875 / 0.75 = 7/6, not 1.
        let (kept, weight) = survival(Roulette::SignedUniform, 6, grey);
        assert!((kept - 0.875).abs() < 0.01, "{kept}");
        assert!((weight - 7.0 / 6.0).abs() < 0.015, "{weight}");
        // Before the 6th hit, and without the roulette, every path goes on.
        assert_eq!(survival(Roulette::SignedUniform, 5, grey), (1.0, 1.0));
        assert_eq!(survival(Roulette::Never, 60, grey), (1.0, 1.0));
        // A black colour ends the path (its light is 0 anyway).
        assert_eq!(
            survival(Roulette::SignedUniform, 6, Color::BLACK),
            (0.0, 0.0)
        );
    }
}
