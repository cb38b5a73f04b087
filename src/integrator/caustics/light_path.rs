//! The light subpath of a camera sample: from an emitter through mirrors and
//! glass (delta lobes) to the first vertex where a continuous lobe is
//! chosen, which must be Lambert.

use std::f64::consts::PI;

use super::connect::splat_to_camera;
use crate::bsdf::{BsdfFlags, GlassChoice, TransportMode};
use crate::color::Color;
use crate::emitters::cosine::cosine_hemisphere;
use crate::integrator::Splats;
use crate::integrator::scatter::{bsdf_at, emitter_choice, sample};
use crate::math::{Point3, Ray, Vec3, offset_origin};
use crate::render_scene::RenderScene;
use crate::sampler::Sampler;

/// Salt of the light subpath's sampler (see [`Sampler::fork`]).
const LIGHT_PATH_SALT: u64 = 0x11A7_C0DE_CA05_71C5;

/// The end `y` of a light subpath: a vertex where a continuous lobe was
/// chosen after at least one specular vertex, its continuous part Lambert.
#[derive(Clone, Copy, Debug)]
pub struct CausticVertex {
    pub point: Point3,
    /// Unit geometric normal on the side the light arrived from.
    pub geometric: Vec3,
    /// The BRDF of the Lambert part over the probability of choosing it.
    pub f: Color,
    /// The subpath's weight arriving at `y` (emission over densities,
    /// specular weights, shading-normal correction).
    pub beta: Color,
    /// Shading-normal correction `s_y = cos_shading / cos_geometric` of the
    /// arrival direction.
    pub shading_ratio: f64,
    /// Emission density of the light point and direction.
    pub emission_density: f64,
    /// Specular vertices between the light and `y` (at least 1).
    pub chain: u32,
    /// Shutter time of the sample.
    pub time: f64,
}

/// Traces the light subpath of the camera sample that `sampler` belongs to
/// (on its own forked sequence) with at most `max_chain` specular vertices,
/// and splats its connection to the camera into `splats`. Returns its
/// caustic vertex for the camera path's connections.
pub fn trace(
    scene: &RenderScene,
    time: f64,
    sampler: &Sampler,
    max_chain: u32,
    splats: &mut Splats,
) -> Option<CausticVertex> {
    splats.light_paths = 1;
    if max_chain == 0 {
        return None;
    }
    let mut sampler = sampler.fork(LIGHT_PATH_SALT);
    let share = scene.emitters().light_path_share();
    if share < 1.0 && sampler.next_f64() >= share {
        return None;
    }
    let select = emitter_choice(scene, &mut sampler);
    let u_point = sampler.next_2d();
    let u_side = sampler.next_f64();
    let u_direction = sampler.next_2d();
    let start = scene.emitters().sample_emission_point(
        &scene.camera_center(),
        time,
        select,
        u_point,
        u_side,
    )?;
    let direction = cosine_hemisphere(&start.normal, u_direction);
    let emission_density = start.density;
    // L_e |cos| / (p_area p_direction), with p_direction = cos / pi.
    let mut beta = start.emission * (PI / emission_density);
    let mut ray = Ray::new(
        offset_origin(&start.point, &start.normal, &direction),
        direction,
        time,
    );
    // Ending at its first hit unless that is a mirror or glass, the
    // subpath needs no ray when it cannot find one.
    if !scene.casters().may_hit(&ray) {
        return None;
    }
    let mut chain = 0;
    loop {
        let hit = scene.intersect(&ray)?;
        let at = scene.shade(&hit, &ray);
        let towards_light = -ray.direction;
        let bsdf = bsdf_at(scene, &at, &towards_light, GlassChoice::Fresnel)
            .transporting(TransportMode::Importance);
        if bsdf.is_black() {
            return None;
        }
        // A surface without delta lobes ends the subpath for sure: no
        // direction is drawn for it.
        let scattered = if bsdf.probability(BsdfFlags::CONTINUOUS) >= 1.0 {
            None
        } else {
            Some(sample(&bsdf, &towards_light, &mut sampler)?)
        };
        let Some(scattered) = scattered.filter(|s| s.is_delta()) else {
            if chain == 0 {
                // Direct light: next-event estimation's business.
                return None;
            }
            let lambert = bsdf.diffuse_f()?;
            let shading_ratio = at.normal.dot(&towards_light) / at.geometric.dot(&towards_light);
            if !(shading_ratio > 0.0 && shading_ratio.is_finite()) {
                return None;
            }
            let y = CausticVertex {
                point: at.point,
                geometric: at.geometric,
                f: lambert / bsdf.probability(BsdfFlags::CONTINUOUS),
                beta: beta * shading_ratio,
                shading_ratio,
                emission_density,
                chain,
                time,
            };
            let camera = scene.camera();
            let lens = if camera.has_lens() {
                sampler.next_2d()
            } else {
                [0.5, 0.5]
            };
            splat_to_camera(scene, camera, &y, lens, splats);
            return Some(y);
        };
        beta *= scattered.weight;
        if beta.is_black() {
            return None;
        }
        let direction = scattered.wi;
        chain += 1;
        if chain > max_chain {
            return None;
        }
        ray = Ray::new(at.spawn_origin(&direction), direction, time);
    }
}
