//! The default estimator: the original's expected image with next-event
//! estimation (NEE) and multiple importance sampling (MIS, power heuristic)
//! at diffuse vertices, light subpaths for caustics (see [`super::caustics`]),
//! and Russian roulette on the path throughput.
//!
//! Bookkeeping of path lengths, so that the expectation is the original's:
//! hit `k` (the camera hit is hit 1) adds its emission when `k <= max_depth + 1`,
//! and scattering happens at hits `1..=max_depth`. A light sample taken at
//! scattering vertex `k` stands for a path ending at hit `k + 1`, so NEE runs
//! at every scattering vertex (`1..=max_depth`, the last one included), and
//! the BSDF ray of that vertex, which finds hit `k + 1`, weights the emission
//! there by the matching MIS weight. Both strategies thus cover exactly the
//! same set of paths. Emission reached by a camera ray, after mirror or glass
//! vertices, or on an emitter that light sampling never picks (planes,
//! revolution surfaces, ellipsoids) counts fully, except for the paths that
//! light subpaths also make: a diffuse vertex (or the camera ray's first
//! vertex) `y`, found from a diffuse vertex `x`, then only mirror and glass
//! up to the emitter. Those are weighted against light tracing and the
//! connections by the ratio of `caustics`, which the path tracer's side
//! keeps as a `CausticTrack`.
//!
//! Each vertex samples its BSDF first. When the sample is a continuous
//! lobe's (diffuse, Phong, glossy), the vertex also takes a light sample,
//! weighted by the BSDF's `eval` over the probability of having chosen a
//! continuous lobe, and MIS weights both strategies with the BSDF's density
//! conditioned on that choice; after a delta lobe (mirror, smooth glass)
//! the emission found counts fully. Light subpaths connect only to, and
//! end only at, vertices whose continuous part is Lambert (the densities of
//! their MIS weights are the cosine's). A vertex reached by a delta lobe
//! splits its bounce (see [`super::split`]): the emission its continuation
//! finds through at most `MAX_CHAIN` mirror and glass vertices counts
//! `1 / SPLIT`, and the probes add the rest. The PA1 point and directional lights are added at every
//! vertex, as the original does.

use crate::bsdf::{Bsdf, BsdfFlags, GlassChoice, LobeSet};
use crate::color::Color;
use crate::look::Miss;
use crate::math::{Point3, Ray, Vec3};
use crate::sampler::Sampler;
use crate::shading::Shading;
use crate::spectral::PathSpectrum;

use super::caustics::track::{CausticTrack, camera_track, caustic_track, count_chain_vertex};
use super::caustics::{self, CausticVertex};
use super::path_log::{PathEvent, PathLog, Term};
use super::scatter::{bsdf_at, emitter_choice, miss, pa1_lights, sample};
use super::split;
use super::{CameraSample, Splats};
use crate::render_scene::{RenderScene, ShadowTarget};

/// Scattering vertices after which Russian roulette may end a path. Within
/// the original's five vertices every continuation pays for itself (ending
/// paths from the third vertex cost 5-17% efficiency on the report scenes);
/// roulette protects longer `--max-depth` paths.
pub(super) const ROULETTE_DEPTH: u32 = 5;

/// Where the current ray left a vertex by a continuous lobe: what MIS needs
/// to weight the emission the ray finds.
#[derive(Clone, Copy)]
struct SmoothOrigin {
    point: Point3,
    /// Density of the ray's direction given that a continuous lobe was chosen.
    pdf: f64,
    /// Whether the vertex's continuous part is Lambert (light subpaths
    /// connect to such vertices only).
    lambert: bool,
}

pub fn radiance(
    scene: &RenderScene,
    mut ray: Ray,
    sample_of: &CameraSample,
    sampler: &mut Sampler,
    splats: &mut Splats,
    log: &mut impl PathLog,
) -> Color {
    let mut result = Color::BLACK;
    // RGB until a dispersive dielectric splits the path (see `spectral`),
    // or one wavelength from the start in Cambrian's look.
    let (mut spectrum, mut throughput) = if scene.cambrian_wavelengths() {
        PathSpectrum::cambrian(sampler.next_f64(), sampler.next_f64())
    } else {
        (PathSpectrum::Rgb, Color::WHITE)
    };
    let mut depth = 0;
    // `None`: the ray came from the camera or a delta lobe (weight 1).
    let mut origin: Option<SmoothOrigin> = None;
    let mut track: Option<CausticTrack> = None;
    // The weight of emission found after the last continuous lobe and one
    // or more delta vertices: `1 / SPLIT` when that lobe's vertex was split
    // (see `split`), else 1.
    let mut chain_share = 1.0;
    // Delta vertices since the last continuous lobe (the probes follow at
    // most `split::MAX_CHAIN`).
    let mut delta_run = 0;
    // The light subpath of the caustic connections; every camera sample
    // traces one (light tracing divides by their number).
    let light_path: Option<CausticVertex> = if scene.light_paths() {
        let max_chain = scene.max_depth().saturating_sub(1);
        caustics::trace(scene, ray.time, sampler, max_chain, splats)
    } else {
        None
    };
    loop {
        let Some(hit) = scene.intersect(&ray) else {
            let background = if spectrum.is_rgb() {
                miss(scene, depth, throughput)
            } else {
                miss_split(scene, depth, throughput, &spectrum)
            };
            add(
                &mut result,
                log,
                depth + 1,
                Term::Background,
                None,
                background,
            );
            log.record(|| PathEvent::Ended {
                depth: depth + 1,
                why: "the ray found nothing",
            });
            break;
        };
        let at = scene.shade(&hit, &ray);
        let material = at.material;
        log.record(|| PathEvent::Hit {
            depth: depth + 1,
            point: at.point,
            normal: at.normal,
            material: hit.material,
            lobes: Box::new(material.lobes.clone()),
        });
        if !material.emission.is_black() {
            let weight = match (origin, track) {
                (None, Some(track)) if track.chain > 0 => {
                    match track.edge.density(scene, sample_of) {
                        Some(edge) => {
                            let density =
                                caustics::emission_density(scene, ray.time, &hit, &-ray.direction);
                            caustics::path_weight(edge, track.shading_ratio, density)
                        }
                        None => 1.0,
                    }
                }
                (None, _) if delta_run <= split::MAX_CHAIN => chain_share,
                (None, _) => 1.0,
                (Some(from), _) => {
                    let light_pdf = scene.emitters().pdf(&from.point, ray.time, &hit);
                    power_heuristic(from.pdf, light_pdf)
                }
            };
            let emission = throughput * spectrum.factor(material.emission) * weight;
            add(
                &mut result,
                log,
                depth + 1,
                Term::Emission,
                Some(weight),
                emission,
            );
        }
        depth += 1;
        if depth > scene.max_depth() {
            log.record(|| PathEvent::Ended {
                depth,
                why: "the deepest hit",
            });
            break;
        }
        let wo = -ray.direction;
        // The lobes at the path's wavelength, when they depend on it.
        let dispersed;
        let mut bsdf = bsdf_at(scene, &at, &wo, GlassChoice::Fresnel);
        if bsdf.is_black() {
            log.record(|| PathEvent::Ended {
                depth,
                why: "a black BSDF",
            });
            break;
        }
        if bsdf.dispersion().is_some() {
            dispersed = disperse(&bsdf, &mut spectrum, &mut throughput, sampler);
            bsdf = bsdf.with_set(&dispersed);
        }
        let lights = throughput * pa1_lights(scene, &at, &bsdf, &wo, &spectrum);
        add(&mut result, log, depth, Term::DirectLights, None, lights);
        if depth == scene.max_depth()
            && scene.light_sample_ends_paths()
            && bsdf.diffuse_f().is_some()
            && bsdf.probability(BsdfFlags::CONTINUOUS) >= 1.0
        {
            // The last vertex: its bounce could only find emission, which
            // the light sample then counts alone (weight 1, no MIS).
            let last = throughput
                * light_sample(
                    scene, &at, &bsdf, &wo, 1.0, ray.time, sampler, &spectrum, false,
                );
            add(&mut result, log, depth, Term::LastLightSample, None, last);
            log.record(|| PathEvent::Ended {
                depth,
                why: "the last vertex's light sample",
            });
            break;
        }
        let Some(scattered) = sample(&bsdf, &wo, sampler) else {
            log.record(|| PathEvent::Ended {
                depth,
                why: "the BSDF gave no direction",
            });
            break;
        };
        // Where the ray that found this vertex came from (for the caustic track).
        let arrived_from = origin.take();
        let split_here = split::splits(scene, depth, arrived_from.is_none());
        if split_here && bsdf.probability(BsdfFlags::CONTINUOUS) > 0.0 {
            let chain = throughput
                * split::chain_emission(
                    scene, &at, &bsdf, &wo, depth, ray.time, sampler, &spectrum,
                );
            add(&mut result, log, depth, Term::SplitChain, None, chain);
        }
        let direction = scattered.wi;
        if scattered.is_delta() {
            if scattered.flags.contains(BsdfFlags::NONRECIPROCAL) {
                track = None;
            }
            count_chain_vertex(&mut track);
            delta_run += 1;
        } else {
            delta_run = 0;
            let smooth = bsdf.probability(BsdfFlags::CONTINUOUS);
            let direct = throughput
                * light_sample(
                    scene, &at, &bsdf, &wo, smooth, ray.time, sampler, &spectrum, true,
                );
            add(&mut result, log, depth, Term::LightSample, None, direct);
            let lambert = bsdf.diffuse_f();
            if let Some(f) = lambert
                && let Some(y) = light_path.filter(|y| depth + 1 + y.chain <= scene.max_depth())
            {
                let connection = throughput * caustics::connect(scene, &at, f / smooth, &y);
                add(&mut result, log, depth, Term::Connection, None, connection);
            }
            track = match arrived_from {
                _ if !scene.light_paths() || lambert.is_none() => None,
                Some(from) if from.lambert => {
                    caustic_track(&from.point, from.pdf, &at, &ray, &direction)
                }
                None if depth == 1 => camera_track(&at, &direction),
                _ => None,
            };
            chain_share = if split_here {
                1.0 / split::SPLIT as f64
            } else {
                1.0
            };
            origin = Some(SmoothOrigin {
                point: at.point,
                pdf: scattered.pdf / smooth,
                lambert: lambert.is_some(),
            });
        }
        throughput *= spectrum.factor(scattered.weight);
        log.record(|| PathEvent::Scattered {
            depth,
            wi: direction,
            weight: scattered.weight,
            pdf: scattered.pdf,
            flags: scattered.flags,
            throughput,
        });
        if spectrum.is_dark(&throughput) {
            log.record(|| PathEvent::Ended {
                depth,
                why: "a dark throughput",
            });
            break;
        }
        if depth >= ROULETTE_DEPTH {
            // The square root keeps dim paths alive longer than the plain
            // throughput would (10% better efficiency on the report scenes).
            let survival = spectrum.roulette_level(&throughput).sqrt().min(1.0);
            if survival < 1.0 {
                if sampler.next_f64() >= survival {
                    log.record(|| PathEvent::Ended {
                        depth,
                        why: "Russian roulette",
                    });
                    break;
                }
                log.record(|| PathEvent::Survived {
                    depth,
                    probability: survival,
                });
                throughput = throughput / survival;
            }
        }
        ray = Ray::new(at.spawn_origin(&direction), direction, ray.time);
    }
    debug_assert!(result.is_finite() || !throughput.is_finite());
    result
}

/// Adds `value`, a term of the sample, to `result`, and reports it.
#[inline(always)]
fn add(
    result: &mut Color,
    log: &mut impl PathLog,
    depth: u32,
    term: Term,
    mis_weight: Option<f64>,
    value: Color,
) {
    *result += value;
    log.record(|| PathEvent::Added {
        depth,
        term,
        mis_weight,
        value,
    });
}

/// The lobes of `bsdf` (dispersive) at the path's wavelength, splitting
/// an RGB path first; kept out of the loop, which RGB paths run.
#[cold]
#[inline(never)]
fn disperse(
    bsdf: &Bsdf,
    spectrum: &mut PathSpectrum,
    throughput: &mut Color,
    sampler: &mut Sampler,
) -> LobeSet {
    let Some(dispersion) = bsdf.dispersion() else {
        return bsdf.set().clone();
    };
    if spectrum.is_rgb() {
        spectrum.split(&dispersion, sampler.next_f64(), throughput);
    }
    bsdf.set().with_ior(dispersion.ior(spectrum))
}

/// What a ray of a split path that finds nothing adds: the background as
/// the path's wavelength or channel sees it.
fn miss_split(
    scene: &RenderScene,
    depth: u32,
    throughput: Color,
    spectrum: &PathSpectrum,
) -> Color {
    let background = scene.background();
    match scene.look().miss {
        Miss::Weighted => throughput * spectrum.factor(background),
        Miss::Unweighted => spectrum.seen(background),
        // A split path has scattered, so depth > 0.
        Miss::CameraBackground | Miss::Black => {
            debug_assert!(depth > 0);
            Color::BLACK
        }
    }
}

/// One light sample at a vertex that chose a continuous lobe (of total
/// probability `smooth`), MIS-weighted against BSDF sampling:
/// `L_e f |cos| / (pdf_light smooth) * w_light`, the emission and the BSDF
/// each as the path's `spectrum` sees them. The caller multiplies by the
/// throughput.
#[allow(clippy::too_many_arguments)]
pub(super) fn light_sample(
    scene: &RenderScene,
    at: &Shading,
    bsdf: &Bsdf,
    wo: &Vec3,
    smooth: f64,
    time: f64,
    sampler: &mut Sampler,
    spectrum: &PathSpectrum,
    mis: bool,
) -> Color {
    if scene.emitters().is_empty() {
        return Color::BLACK;
    }
    let select = emitter_choice(scene, sampler);
    let u = sampler.next_2d();
    let Some(light) = scene.emitters().sample(&at.point, time, select, u) else {
        return Color::BLACK;
    };
    let reflected = bsdf.eval(wo, &light.direction);
    if reflected.is_black() {
        return Color::BLACK;
    }
    let origin = at.spawn_origin(&light.direction);
    if !scene.unoccluded(
        origin,
        light.direction,
        ShadowTarget::Surface(light.point),
        time,
    ) {
        return Color::BLACK;
    }
    let weight = if mis {
        power_heuristic(light.pdf, bsdf.pdf(wo, &light.direction) / smooth)
    } else {
        1.0
    };
    spectrum.factor(light.emission) * spectrum.factor(reflected) * (weight / (light.pdf * smooth))
}

/// The power heuristic (exponent 2) for one sample of density `f` against
/// another strategy of density `g`.
pub(super) fn power_heuristic(f: f64, g: f64) -> f64 {
    let (f2, g2) = (f * f, g * g);
    if f2 + g2 > 0.0 { f2 / (f2 + g2) } else { 0.0 }
}
