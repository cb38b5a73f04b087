//! What every estimator does at a surface, written against the BSDF
//! contract: build the BSDF of a hit, sample it spending sample dimensions
//! only on what it reads, pick an emitter, and add the PA1 lights.

use crate::bsdf::{Bsdf, BsdfFlags, BsdfSample, GlassChoice, Rules};
use crate::color::Color;
use crate::look::Miss;
use crate::math::Vec3;
use crate::render_scene::RenderScene;
use crate::sampler::Sampler;
use crate::shading::Shading;
use crate::spectral::PathSpectrum;

use super::point_lights;

/// The BSDF of `at` for light leaving towards `wo`, with the look's
/// conventions and the estimator's way of choosing between reflection and
/// refraction.
#[inline(always)]
pub fn bsdf_at<'a>(
    scene: &RenderScene,
    at: &Shading<'a>,
    wo: &Vec3,
    glass: GlassChoice,
) -> Bsdf<'a> {
    let rules = Rules {
        fresnel: scene.look().fresnel,
        glass,
    };
    at.bsdf(wo, rules)
}

/// A direction from `bsdf` for `wo`: the lobe choice and the direction are
/// drawn from `sampler` only when the BSDF reads them (a perfect mirror
/// reads nothing), so that the stratified dimensions go to real choices.
#[inline(always)]
pub fn sample(bsdf: &Bsdf, wo: &Vec3, sampler: &mut Sampler) -> Option<BsdfSample> {
    let flags = bsdf.flags();
    let choice =
        bsdf.set().len() > 1 || flags.contains(BsdfFlags::REFLECTION | BsdfFlags::TRANSMISSION);
    let uc = if choice { sampler.next_f64() } else { 0.5 };
    let u = if flags.intersects(BsdfFlags::CONTINUOUS) {
        sampler.next_2d()
    } else {
        [0.5, 0.5]
    };
    bsdf.sample(wo, uc, u)
}

/// The number that picks an emitter for a light sample or light subpath: a
/// sample dimension only when there is more than one emitter to pick.
pub fn emitter_choice(scene: &RenderScene, sampler: &mut Sampler) -> f64 {
    if scene.emitters().len() > 1 {
        sampler.next_f64()
    } else {
        0.5
    }
}

/// Radiance of the PA1 point and directional lights at this vertex (the
/// caller multiplies by the throughput).
pub fn pa1_lights(
    scene: &RenderScene,
    at: &Shading,
    bsdf: &Bsdf,
    wo: &Vec3,
    spectrum: &PathSpectrum,
) -> Color {
    if scene.direct_lights().is_empty() {
        Color::BLACK
    } else {
        point_lights::direct(scene, at, bsdf, wo, spectrum)
    }
}

/// What a ray that finds nothing adds, after `depth` scattering vertices
/// with `throughput` (the look's rule).
#[inline]
pub fn miss(scene: &RenderScene, depth: u32, throughput: Color) -> Color {
    let background = scene.background();
    match scene.look().miss {
        Miss::CameraBackground if depth == 0 => throughput * background,
        Miss::CameraBackground | Miss::Black => Color::BLACK,
        Miss::Weighted => throughput * background,
        Miss::Unweighted => background,
    }
}
