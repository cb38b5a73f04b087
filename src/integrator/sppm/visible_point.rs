//! The camera side of a pass: a pixel's camera ray followed through mirrors
//! and glass (delta lobes) to the first vertex where a continuous lobe is
//! chosen, its visible point, where photons will be gathered. On the way it
//! collects what the path integrator would at those vertices: emission,
//! the background of a ray that misses, the PA1 lights, and at the visible
//! point one light sample (direct light; photons bring the rest), except
//! in a photon-mapping look, whose photons bring the direct light too.

use crate::bsdf::{Bsdf, BsdfFlags, GlassChoice};
use crate::color::Color;
use crate::integrator::path::light_sample;
use crate::integrator::scatter::{bsdf_at, miss, pa1_lights, sample};
use crate::look::SeenEmission;
use crate::math::{Point3, Ray, Vec3};
use crate::render_scene::RenderScene;
use crate::sampler::Sampler;
use crate::spectral::PathSpectrum;

/// Where a pixel gathers photons in one pass.
#[derive(Clone, Copy, Debug)]
pub struct VisiblePoint<'a> {
    pub point: Point3,
    /// Unit direction back along the camera path.
    pub wo: Vec3,
    /// The BSDF there (its continuous lobes reflect the photons).
    pub bsdf: Bsdf<'a>,
    /// The camera path's throughput over the probability of having chosen
    /// a continuous lobe here.
    pub beta: Color,
    /// Scattering vertices before it (mirror and glass).
    pub depth: u32,
}

impl VisiblePoint<'_> {
    /// `f(wo, wi)` of the continuous lobes for light arriving from the unit
    /// direction `wi` (0 from behind, or grazing).
    #[inline]
    pub fn reflectance(&self, wi: &Vec3) -> Color {
        let cosine = self.bsdf.normal().dot(wi).abs();
        if cosine < 1e-9 {
            return Color::BLACK;
        }
        self.bsdf.eval(&self.wo, wi) / cosine
    }
}

/// What a camera ray brings back in one pass.
#[derive(Clone, Copy, Debug)]
pub struct CameraPath<'a> {
    /// Radiance found on the way (emission, misses, PA1 lights, the light
    /// sample at the visible point).
    pub direct: Color,
    pub visible: Option<VisiblePoint<'a>>,
}

/// Follows the camera ray `ray` (see the module documentation).
pub fn trace<'a>(scene: &'a RenderScene, mut ray: Ray, sampler: &mut Sampler) -> CameraPath<'a> {
    let rgb = PathSpectrum::Rgb;
    let mut direct = Color::BLACK;
    let mut throughput = Color::WHITE;
    let mut depth = 0;
    loop {
        let Some(hit) = scene.intersect(&ray) else {
            direct += miss(scene, depth, throughput);
            break;
        };
        let at = scene.shade(&hit, &ray);
        if !at.material.emission.is_black() {
            direct += seen_emission(scene, throughput * at.material.emission, at.color);
        }
        if depth >= scene.max_depth() {
            break;
        }
        let wo = -ray.direction;
        let bsdf = bsdf_at(scene, &at, &wo, GlassChoice::Fresnel);
        if bsdf.is_black() {
            break;
        }
        direct += throughput * pa1_lights(scene, &at, &bsdf, &wo, &rgb);
        let Some(scattered) = sample(&bsdf, &wo, sampler) else {
            break;
        };
        if !scattered.is_delta() {
            let smooth = bsdf.probability(BsdfFlags::CONTINUOUS);
            // A photon-mapping look's photons are gathered from their first
            // hit: they bring the direct light, which a light sample would
            // add a second time.
            if scene.look().photons.is_none() {
                direct += throughput
                    * light_sample(
                        scene, &at, &bsdf, &wo, smooth, ray.time, sampler, &rgb, false,
                    );
            }
            return CameraPath {
                direct,
                visible: Some(VisiblePoint {
                    point: at.point,
                    wo,
                    bsdf,
                    beta: throughput / smooth,
                    depth,
                }),
            };
        }
        throughput *= scattered.weight;
        if throughput.is_black() {
            break;
        }
        depth += 1;
        ray = Ray::new(at.spawn_origin(&scattered.wi), scattered.wi, ray.time);
    }
    CameraPath {
        direct,
        visible: None,
    }
}

/// Emission `seen` by a camera path, by a photon-mapping look's rule
/// (`color`: the emitter's colour there).
fn seen_emission(scene: &RenderScene, seen: Color, color: Color) -> Color {
    match scene.look().photons.map(|look| look.seen_emission) {
        None | Some(SeenEmission::Plain) => seen,
        Some(SeenEmission::TimesColor) => seen * color,
        Some(SeenEmission::Clamped) => seen.map(|c| c.clamp(0.0, 1.0)),
    }
}
