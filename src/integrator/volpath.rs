//! The path integrator of scenes with participating media: the default
//! estimator's NEE and MIS (power heuristic), with homogeneous media
//! between surfaces (`crate::medium`).
//!
//! The ray's current medium starts as the scene's (the camera is assumed
//! outside every bounded medium) and changes where a ray crosses the
//! surface of a material with an interior medium: inwards into it, outwards
//! back to the scene's. Along each segment in a medium a free flight
//! (chromatic, one-sample MIS over channels) either finds a scattering
//! point before the next surface, or passes it with its transmittance
//! weight. A medium vertex is a scattering vertex like a surface one (it
//! counts towards `max_depth`): it takes a light sample weighted by the
//! Henyey-Greenstein phase function and MIS-weighted against phase
//! sampling, then samples the phase function for the next direction.
//! Shadow rays (from surfaces and medium vertices) cross `interface`
//! surfaces and multiply the transmittance of every medium on the way;
//! any other surface blocks them. Interfaces neither scatter nor count as
//! vertices: the ray goes on unchanged, only its medium changes.
//!
//! The PA1 point, spot and directional lights are added at every vertex
//! with the transmittance on the way (at medium vertices: their irradiance
//! times the phase function). Light subpaths (caustics) do not account for
//! media and are off in such scenes (a note says so when rendering, see
//! `RenderScene::notices`).

use std::f64::consts::PI;

use crate::bsdf::{Bsdf, BsdfFlags, GlassChoice};
use crate::color::Color;
use crate::emitters::LightSample;
use crate::math::{Point3, Ray, Vec3};
use crate::medium::{Flight, Medium};
use crate::render_scene::{MAX_CROSSINGS, RenderScene, ShadowTarget};
use crate::sampler::Sampler;
use crate::shading::Shading;

use super::path::{ROULETTE_DEPTH, power_heuristic};
use super::point_lights;
use super::scatter::{bsdf_at, emitter_choice, miss, sample};

/// Where the current ray left a vertex by a continuous lobe or the phase
/// function: what MIS needs to weight the emission the ray finds.
#[derive(Clone, Copy)]
struct Origin {
    point: Point3,
    /// Density (solid angle) of the ray's direction, given that a
    /// continuous lobe was chosen (surfaces) or of the phase function.
    pdf: f64,
}

pub fn radiance(scene: &RenderScene, mut ray: Ray, sampler: &mut Sampler) -> Color {
    let mut result = Color::BLACK;
    let mut throughput = Color::WHITE;
    let mut depth = 0;
    let mut crossings = 0;
    let mut origin: Option<Origin> = None;
    let mut medium = scene.medium();
    loop {
        let hit = scene.intersect(&ray);
        if let Some(inside) = medium {
            let t_max = hit.as_ref().map_or(f64::INFINITY, |h| h.t);
            match inside.sample_flight(t_max, sampler.next_f64()) {
                Flight::Pass { weight } => throughput *= weight,
                Flight::Scatter { distance, weight } => {
                    throughput *= weight;
                    depth += 1;
                    if depth > scene.max_depth() || throughput.is_black() {
                        break;
                    }
                    crossings = 0;
                    let point = ray.at(distance);
                    let travel = ray.direction;
                    result += throughput
                        * medium_light_sample(scene, inside, &point, &travel, ray.time, sampler);
                    if !scene.direct_lights().is_empty() {
                        result += throughput * medium_pa1_lights(scene, inside, &point, &travel);
                    }
                    let u = sampler.next_2d();
                    let wi = inside.phase_sample(&travel, u, || sampler.next_f64());
                    origin = Some(Origin {
                        point,
                        pdf: inside.phase_eval(&travel, &wi),
                    });
                    if !roulette(&mut throughput, depth, sampler) {
                        break;
                    }
                    ray = Ray::new(point, wi, ray.time);
                    continue;
                }
            }
            if throughput.is_black() {
                break;
            }
        }
        let Some(hit) = hit else {
            result += miss(scene, depth, throughput);
            break;
        };
        let material = scene.material(hit.material);
        if material.interface {
            crossings += 1;
            if crossings > MAX_CROSSINGS {
                break;
            }
            let entering = hit.geometric_normal.dot(&ray.direction) < 0.0;
            medium = scene.medium_after(material, entering, medium);
            ray = hit.spawn_ray(ray.direction, ray.time);
            continue;
        }
        crossings = 0;
        let at = scene.shade(&hit, &ray);
        if !material.emission.is_black() {
            let weight = origin.map_or(1.0, |from| {
                power_heuristic(from.pdf, scene.emitters().pdf(&from.point, ray.time, &hit))
            });
            result += throughput * material.emission * weight;
        }
        depth += 1;
        if depth > scene.max_depth() {
            break;
        }
        let wo = -ray.direction;
        let bsdf = bsdf_at(scene, &at, &wo, GlassChoice::Fresnel);
        if bsdf.is_black() {
            break;
        }
        if !scene.direct_lights().is_empty() {
            result += throughput * surface_pa1_lights(scene, &at, &bsdf, &wo, medium);
        }
        let Some(scattered) = sample(&bsdf, &wo, sampler) else {
            break;
        };
        let direction = scattered.wi;
        origin = None;
        if !scattered.is_delta() {
            let smooth = bsdf.probability(BsdfFlags::CONTINUOUS);
            let light = sample_light(scene, &at.point, ray.time, sampler);
            if let Some(light) = light {
                let reflected = bsdf.eval(&wo, &light.direction);
                if !reflected.is_black() {
                    let start = if at.geometric.dot(&light.direction) < 0.0 {
                        scene.medium_after(material, at.entering, medium)
                    } else {
                        medium
                    };
                    let from = at.spawn_origin(&light.direction);
                    let seen = scene.transmittance(
                        from,
                        light.direction,
                        ShadowTarget::Surface(light.point),
                        start,
                        ray.time,
                    );
                    if !seen.is_black() {
                        let bsdf_pdf = bsdf.pdf(&wo, &light.direction) / smooth;
                        let weight = power_heuristic(light.pdf, bsdf_pdf);
                        result += throughput
                            * light.emission
                            * reflected
                            * seen
                            * (weight / (light.pdf * smooth));
                    }
                }
            }
            origin = Some(Origin {
                point: at.point,
                pdf: scattered.pdf / smooth,
            });
        }
        if at.geometric.dot(&direction) < 0.0 {
            medium = scene.medium_after(material, at.entering, medium);
        }
        throughput *= scattered.weight;
        if throughput.is_black() || !roulette(&mut throughput, depth, sampler) {
            break;
        }
        ray = Ray::new(at.spawn_origin(&direction), direction, ray.time);
    }
    debug_assert!(result.is_finite() || !throughput.is_finite());
    result
}

/// Russian roulette from [`ROULETTE_DEPTH`] on, as the default integrator
/// plays it; `false` ends the path.
fn roulette(throughput: &mut Color, depth: u32, sampler: &mut Sampler) -> bool {
    if depth < ROULETTE_DEPTH {
        return true;
    }
    let survival = throughput.max_component().sqrt().min(1.0);
    if survival < 1.0 {
        if sampler.next_f64() >= survival {
            return false;
        }
        *throughput = *throughput / survival;
    }
    true
}

/// An emitter point for a light sample from `point` (see
/// [`crate::emitters::Emitters::sample`]).
fn sample_light(
    scene: &RenderScene,
    point: &Point3,
    time: f64,
    sampler: &mut Sampler,
) -> Option<LightSample> {
    if scene.emitters().is_empty() {
        return None;
    }
    let select = emitter_choice(scene, sampler);
    let u = sampler.next_2d();
    scene.emitters().sample(point, time, select, u)
}

/// One light sample at a medium vertex reached by light travelling along
/// `travel`: `L_e T p / pdf_light * w_light` (the caller multiplies by the
/// throughput), MIS-weighted against phase sampling.
fn medium_light_sample(
    scene: &RenderScene,
    medium: &Medium,
    point: &Point3,
    travel: &Vec3,
    time: f64,
    sampler: &mut Sampler,
) -> Color {
    let Some(light) = sample_light(scene, point, time, sampler) else {
        return Color::BLACK;
    };
    let phase = medium.phase_eval(travel, &light.direction);
    let seen = scene.transmittance(
        *point,
        light.direction,
        ShadowTarget::Surface(light.point),
        Some(medium),
        time,
    );
    if seen.is_black() {
        return Color::BLACK;
    }
    let weight = power_heuristic(light.pdf, phase);
    light.emission * seen * (phase * weight / light.pdf)
}

/// The PA1 point, spot and directional lights at a surface (as
/// [`point_lights::direct`], with the transmittance of the media on the way
/// instead of an opaque-or-not shadow ray).
fn surface_pa1_lights(
    scene: &RenderScene,
    at: &Shading,
    bsdf: &Bsdf,
    wo: &Vec3,
    medium: Option<&Medium>,
) -> Color {
    let mut sum = Color::BLACK;
    for light in scene.direct_lights() {
        let Some(way) = point_lights::toward(light, &at.point) else {
            continue;
        };
        if at.geometric.dot(&way.to_light) <= 0.0 {
            continue;
        }
        let reflected = bsdf.eval(wo, &way.to_light);
        if reflected.is_black() {
            continue;
        }
        let from = at.spawn_origin(&way.to_light);
        let seen = scene.transmittance(
            from,
            way.to_light,
            ShadowTarget::Distance(way.distance),
            medium,
            0.0,
        );
        sum += reflected * way.color * seen * PI;
    }
    sum
}

/// The PA1 lights scattered at a medium vertex: their irradiance `pi *
/// colour` (the framework's convention, no distance falloff) times the
/// phase function and the transmittance on the way.
fn medium_pa1_lights(scene: &RenderScene, medium: &Medium, point: &Point3, travel: &Vec3) -> Color {
    let mut sum = Color::BLACK;
    for light in scene.direct_lights() {
        let Some(way) = point_lights::toward(light, point) else {
            continue;
        };
        let phase = medium.phase_eval(travel, &way.to_light);
        let seen = scene.transmittance(
            *point,
            way.to_light,
            ShadowTarget::Distance(way.distance),
            Some(medium),
            0.0,
        );
        sum += way.color * seen * (phase * PI);
    }
    sum
}
