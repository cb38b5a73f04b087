//! The light side of a pass: one photon from an emitter (picked by power, a
//! point by area, a direction by the cosine), scattered by the BSDF
//! contract, handed to the gatherer at every surface after its first.
//! Direct light is the camera side's (one light sample at each visible
//! point), so a photon's first hit gathers nothing.
//!
//! Transport from the light's side differs from the camera's only by the
//! shading-normal correction of the adjoint BSDF (Veach 1997, 5.3): a
//! continuous bounce is weighted by `|wo.ns| |wi.ng| / (|wo.ng| |wi.ns|)`.
//! Refraction keeps radiance in this renderer (no eta^2), so it needs no
//! correction either way.

use std::f64::consts::PI;

use crate::bsdf::{BsdfFlags, GlassChoice};
use crate::color::Color;
use crate::emitters::cosine::cosine_hemisphere;
use crate::integrator::path::ROULETTE_DEPTH;
use crate::integrator::scatter::{bsdf_at, emitter_choice, sample};
use crate::math::{Point3, Ray, Vec3, offset_origin};
use crate::render_scene::RenderScene;
use crate::sampler::Sampler;

/// The largest shading-normal correction of one bounce (it grows without
/// bound at grazing geometric angles).
const MAX_SHADING_CORRECTION: f64 = 10.0;

/// A photon arriving at a surface.
#[derive(Clone, Copy, Debug)]
pub struct PhotonHit {
    pub point: Point3,
    /// Unit direction back towards where it came from.
    pub wi: Vec3,
    /// Its power in units of [`Emitters::photon_power_unit`](crate::emitters::Emitters::photon_power_unit).
    pub power: Color,
    /// Scattering vertices before this surface.
    pub bounces: u32,
}

/// Traces one photon drawn from `sampler` at shutter time `time`, calling
/// `gather` at every surface it reaches after its first bounce (from the
/// first in a photon-mapping look), while a
/// visible point there could still be on a path of at most `max_depth`
/// scattering vertices.
pub fn trace(
    scene: &RenderScene,
    sampler: &mut Sampler,
    time: f64,
    gather: &mut impl FnMut(&PhotonHit),
) {
    let Some((mut ray, mut power)) = emit(scene, sampler, time) else {
        return;
    };
    // A visible point is itself a scattering vertex: a photon after
    // `max_depth - 1` bounces can reach none.
    // A look's photons are gathered at their first `photon_hits` hits.
    let look_hits = scene
        .look()
        .photons
        .map_or(u32::MAX, |look| look.photon_hits);
    let last_bounce = scene
        .max_depth()
        .saturating_sub(1)
        .min(look_hits.saturating_sub(1));
    // Direct light is the camera side's light sample, except in a
    // photon-mapping look, whose photons bring it.
    let first_gather = if scene.look().photons.is_some() { 0 } else { 1 };
    let mut bounces = 0;
    loop {
        let Some(hit) = scene.intersect(&ray) else {
            return;
        };
        let at = scene.shade(&hit, &ray);
        let wo = -ray.direction;
        let bsdf = bsdf_at(scene, &at, &wo, GlassChoice::Fresnel);
        if bsdf.is_black() {
            return;
        }
        if bounces >= first_gather && bsdf.probability(BsdfFlags::CONTINUOUS) > 0.0 {
            gather(&PhotonHit {
                point: at.point,
                wi: wo,
                power,
                bounces,
            });
        }
        if bounces >= last_bounce {
            return;
        }
        let Some(scattered) = sample(&bsdf, &wo, sampler) else {
            return;
        };
        let mut weight = scattered.weight;
        if !scattered.is_delta() {
            weight *= shading_correction(&at.normal, &at.geometric, &wo, &scattered.wi);
        }
        let before = power;
        power *= weight;
        if power.is_black() || !power.is_finite() {
            return;
        }
        bounces += 1;
        if bounces >= ROULETTE_DEPTH {
            let survival = (power.luminance() / before.luminance()).min(1.0);
            if survival.is_nan() || sampler.next_f64() >= survival {
                return;
            }
            power = power / survival;
        }
        ray = Ray::new(at.spawn_origin(&scattered.wi), scattered.wi, time);
    }
}

/// A photon leaving an emitter at shutter time `time`: its ray and its
/// power in units of [`Emitters::photon_power_unit`](crate::emitters::Emitters::photon_power_unit)
/// (the photons' mean power is the emitters' total power).
pub fn emit(scene: &RenderScene, sampler: &mut Sampler, time: f64) -> Option<(Ray, Color)> {
    let emitters = scene.emitters();
    let unit = emitters.photon_power_unit();
    if !(unit > 0.0 && unit.is_finite()) {
        return None;
    }
    let look = scene.look().photons;
    let select = emitter_choice(scene, sampler);
    let u_point = sampler.next_2d();
    let u_side = sampler.next_f64();
    let u_direction = sampler.next_2d();
    // A photon-mapping look's emitters send light from their normal side.
    let u_side = if look.is_some() { 0.0 } else { u_side };
    let start =
        emitters.sample_photon_origin(&scene.camera_center(), time, select, u_point, u_side)?;
    let direction = cosine_hemisphere(&start.normal, u_direction);
    let power = match look {
        // L_e cos / (p_area cos / pi), in units of the unit.
        None => start.emission * (PI / (start.density * unit)),
        // The look's fixed power, each emitter with an equal share (see
        // `look::photons`).
        Some(look) => {
            let share = emitters.len() as f64 * start.probability;
            start.emission * (look.power * PI / (share * unit))
        }
    };
    let ray = Ray::new(
        offset_origin(&start.point, &start.normal, &direction),
        direction,
        time,
    );
    Some((ray, power))
}

/// The adjoint BSDF's shading-normal factor (see the module documentation).
fn shading_correction(shading: &Vec3, geometric: &Vec3, wo: &Vec3, wi: &Vec3) -> f64 {
    let numerator = wo.dot(shading).abs() * wi.dot(geometric).abs();
    let denominator = wo.dot(geometric).abs() * wi.dot(shading).abs();
    if denominator > 0.0 {
        (numerator / denominator).min(MAX_SHADING_CORRECTION)
    } else {
        0.0
    }
}
