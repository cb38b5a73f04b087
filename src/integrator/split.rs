//! Splitting the bounce of a diffuse vertex seen through mirrors and glass.
//!
//! A path `camera .. S v S1 .. Sm light` (`v` a vertex where a continuous
//! lobe is chosen, reached through a mirror or glass vertex `S`, and left
//! through mirror and glass to an emitter) has one strategy only: the path
//! tracer's bounce from `v`. A light subpath cannot be connected to `v`
//! (its predecessor is specular) and `v`'s light sample cannot cross the
//! chain. These are the caustics seen in a mirror or through glass, rare
//! samples of great weight that decide the path integrator's error on the
//! course scenes (docs/performance.md, "Where the time goes").
//!
//! So at such a vertex `v` the path tracer estimates that part of the
//! light, the emission found at the end of a chain of one or more delta
//! vertices after a continuous lobe, from `SPLIT` bounces instead of one:
//! the path's own bounce counts it with weight `1 / SPLIT`, and `SPLIT - 1`
//! probes (`chain_emission`) draw the same BSDF at `v` and follow only
//! delta lobes, each counting it with weight `1 / SPLIT`. The probes are
//! drawn whatever lobe the path chooses at `v`, so the estimate is the
//! mean of `SPLIT` independent estimates of the same expectation: the
//! image's expectation is unchanged. A probe that finds a surface without
//! delta lobes ends there: one ray, or none when it cannot find a mirror
//! or glass object at all (see `casters`).

use crate::bsdf::{Bsdf, GlassChoice};
use crate::color::Color;
use crate::math::{Ray, Vec3};
use crate::sampler::Sampler;
use crate::shading::Shading;
use crate::spectral::PathSpectrum;

use super::path::ROULETTE_DEPTH;
use super::scatter::{bsdf_at, sample};
use crate::render_scene::RenderScene;

/// Bounces that estimate the chain emission of a split vertex.
pub const SPLIT: u32 = 8;

/// Delta vertices a probe goes through at most; emission found after
/// longer chains counts fully on the path (it is rare, and a scene of
/// facing mirrors under a look without a depth limit would otherwise send
/// every probe to the limit).
pub const MAX_CHAIN: u32 = 4;

/// Salt of the probes' sampler (see [`Sampler::fork`]), per vertex depth.
const PROBE_SALT: u64 = 0x5B11_7C0A_5710_9E00;

/// Whether the path tracer splits the bounce of a vertex at `depth` (hits
/// counted from the camera's, 1) that was reached by a delta lobe: among
/// the vertices before Russian roulette may end a path (all of the
/// original's but its last, which has nothing left to find).
#[inline]
pub fn splits(scene: &RenderScene, depth: u32, arrived_by_delta: bool) -> bool {
    scene.light_paths()
        && arrived_by_delta
        && depth > 1
        && depth < scene.max_depth()
        && depth < ROULETTE_DEPTH
}

/// The probes' estimate, `SPLIT - 1` bounces from `at` (hit `depth`, left
/// towards `wo` with `bsdf`) each weighted `1 / SPLIT`, of the emission
/// found after a continuous lobe and then one or more delta vertices, as
/// the path's `spectrum` sees it; the caller multiplies by the throughput.
#[allow(clippy::too_many_arguments)]
pub fn chain_emission(
    scene: &RenderScene,
    at: &Shading,
    bsdf: &Bsdf,
    wo: &Vec3,
    depth: u32,
    time: f64,
    sampler: &Sampler,
    spectrum: &PathSpectrum,
) -> Color {
    let mut sampler = sampler.fork(PROBE_SALT ^ depth as u64);
    let mut sum = Color::BLACK;
    for _ in 1..SPLIT {
        let Some(bounce) = sample(bsdf, wo, &mut sampler) else {
            continue;
        };
        if bounce.is_delta() {
            continue;
        }
        let weight = spectrum.factor(bounce.weight);
        let ray = Ray::new(at.spawn_origin(&bounce.wi), bounce.wi, time);
        if !scene.casters().may_hit(&ray) {
            continue;
        }
        sum += follow_chain(scene, ray, weight, depth, spectrum, &mut sampler).emission;
    }
    sum / SPLIT as f64
}

/// What a probe found: the emission, weighted, and the delta vertices it
/// went through.
#[derive(Clone, Copy, Debug)]
struct Chain {
    emission: Color,
    delta_vertices: u32,
}

/// Follows `ray`, the first bounce from hit `depth` with `weight`, through at most
/// [`MAX_CHAIN`] delta vertices: the emission found after one or more of
/// them, up to hit `max_depth + 1` as on the path. Hit `depth + 1`, where
/// the chain starts, has no delta vertex before it (its emission is the
/// light sample's business).
fn follow_chain(
    scene: &RenderScene,
    mut ray: Ray,
    mut weight: Color,
    depth: u32,
    spectrum: &PathSpectrum,
    sampler: &mut Sampler,
) -> Chain {
    let mut found = Chain {
        emission: Color::BLACK,
        delta_vertices: 0,
    };
    let mut hit_depth = depth + 1;
    while let Some(hit) = scene.intersect(&ray) {
        let material = scene.material(hit.material);
        let emission = material.emission;
        if found.delta_vertices > 0 && !emission.is_black() {
            found.emission += weight * spectrum.factor(emission);
        }
        // Most probes end here, on a surface without delta lobes, for the
        // price of the ray.
        if hit_depth > scene.max_depth()
            || found.delta_vertices == MAX_CHAIN
            || !material.lobes.has_delta()
        {
            break;
        }
        let here = scene.shade(&hit, &ray);
        let towards = -ray.direction;
        let here_bsdf = bsdf_at(scene, &here, &towards, GlassChoice::Fresnel);
        let Some(next) = sample(&here_bsdf, &towards, sampler) else {
            break;
        };
        if !next.is_delta() {
            break;
        }
        weight *= spectrum.factor(next.weight);
        if spectrum.is_dark(&weight) {
            break;
        }
        found.delta_vertices += 1;
        hit_depth += 1;
        ray = Ray::new(here.spawn_origin(&next.wi), next.wi, ray.time);
    }
    found
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::integrator::original::MAX_DEPTH;
    use crate::look::Look;
    use crate::math::Point3;
    use crate::render_scene::SceneSettings;
    use crate::sampler::SamplerKind;
    use crate::scene::model::{Material, Object, Scene};

    const ALBEDO: f64 = 0.6;
    const MIRROR: f64 = 0.9;
    const EMISSION: f64 = 3.0;

    /// A tiny Lambert ball at height 1 over an emissive floor (y = 0),
    /// under a mirror ceiling at y = 2 when `mirror`: every bounce from the
    /// ball's top reaches the floor through the mirror.
    fn scene(mirror: bool) -> Scene {
        let materials = vec![
            Material {
                color: Color::gray(ALBEDO),
                ..Material::default()
            },
            Material {
                color: Color::gray(MIRROR),
                diffuse: 0.0,
                specular: 1.0,
                ..Material::default()
            },
            Material {
                color: Color::BLACK,
                emission: Color::gray(EMISSION),
                ..Material::default()
            },
        ];
        let mut objects = vec![
            Object::Sphere {
                center: Point3::new(0.0, 1.0, 0.0),
                radius: 1e-3,
                motion: Vec3::zeros(),
                material: 0,
            },
            Object::Plane {
                normal: Vec3::y(),
                offset: 0.0,
                material: 2,
            },
        ];
        if mirror {
            objects.push(Object::Plane {
                normal: Vec3::y(),
                offset: 2.0,
                material: 1,
            });
        }
        Scene::new(materials, Object::Group(objects))
    }

    /// `scene` in the original look, with paths of `max_depth` vertices.
    fn ready(scene: Scene, max_depth: u32) -> RenderScene {
        let settings = SceneSettings {
            max_depth,
            ..SceneSettings::defaults(&scene, Look::ORIGINAL)
        };
        RenderScene::build(scene, &settings)
    }

    /// The probes' estimate from the top of the ball, as hit `depth`.
    fn probes(scene: Scene, depth: u32) -> Color {
        let scene = ready(scene, MAX_DEPTH);
        let ray = Ray::new(Point3::new(0.0, 1.5, 0.0), -Vec3::y(), 0.0);
        let hit = scene.intersect(&ray).unwrap();
        assert_eq!(hit.primitive, 0);
        let at = scene.shade(&hit, &ray);
        let wo = -ray.direction;
        let bsdf = bsdf_at(&scene, &at, &wo, GlassChoice::Fresnel);
        let sampler = Sampler::new(SamplerKind::Independent, 7, 3, 11);
        let spectrum = PathSpectrum::Rgb;
        chain_emission(&scene, &at, &bsdf, &wo, depth, 0.0, &sampler, &spectrum)
    }

    #[test]
    fn each_probe_brings_the_emission_behind_the_mirror_with_weight_one_over_split() {
        let scene = scene(true);
        // Each probe: the Lambert weight (the albedo), the mirror's, the
        // floor's emission; the path's own bounce is the missing share.
        let expected = ALBEDO * MIRROR * EMISSION * (SPLIT - 1) as f64 / SPLIT as f64;
        for depth in [2, MAX_DEPTH - 1] {
            let got = probes(scene.clone(), depth);
            for channel in [got.r, got.g, got.b] {
                assert!((channel - expected).abs() < 1e-9, "depth {depth}: {got:?}");
            }
        }
        // From the last scattering vertex the floor would be hit
        // `max_depth + 2`: beyond the original's paths.
        assert!(probes(scene, MAX_DEPTH).is_black());
    }

    #[test]
    fn emission_found_without_a_delta_vertex_is_left_to_light_sampling() {
        // An emissive ceiling instead of the mirror: every bounce finds
        // emission with no delta vertex between, light sampling's part.
        let mut scene = scene(false);
        if let Object::Group(objects) = &mut scene.root {
            objects.push(Object::Plane {
                normal: Vec3::y(),
                offset: 2.0,
                material: 2,
            });
        }
        assert!(probes(scene, 2).is_black());
    }

    #[test]
    fn probes_between_facing_mirrors_stop_after_max_chain_delta_vertices() {
        // A mirror floor under the mirror ceiling, and a look without a
        // depth limit: a slanted ray would bounce to the limit. A small
        // sphere light out of the ray's way, for light subpaths to start
        // from.
        let mut scene = scene(true);
        if let Object::Group(objects) = &mut scene.root {
            objects[1] = Object::Plane {
                normal: Vec3::y(),
                offset: 0.0,
                material: 1,
            };
            objects.push(Object::Sphere {
                center: Point3::new(3.0, 1.0, 5.0),
                radius: 0.1,
                motion: Vec3::zeros(),
                material: 2,
            });
        }
        let scene = ready(scene, 64);
        let ray = Ray::new(
            Point3::new(0.0, 1.01, 0.0),
            Vec3::new(0.3, 1.0, 0.0).normalize(),
            0.0,
        );
        let mut sampler = Sampler::new(SamplerKind::Independent, 1, 2, 3);
        let chain = follow_chain(
            &scene,
            ray,
            Color::WHITE,
            2,
            &PathSpectrum::Rgb,
            &mut sampler,
        );
        assert_eq!(chain.delta_vertices, MAX_CHAIN);
        assert!(chain.emission.is_black());
        // Nor are vertices split where Russian roulette may end the path.
        assert!(scene.light_paths());
        assert!(splits(&scene, ROULETTE_DEPTH - 1, true));
        assert!(!splits(&scene, ROULETTE_DEPTH, true));
    }

    #[test]
    fn only_vertices_reached_by_a_delta_lobe_before_the_last_are_split() {
        // A small sphere light to sample (the floor is not one).
        let mut scene = scene(true);
        if let Object::Group(objects) = &mut scene.root {
            objects.push(Object::Sphere {
                center: Point3::new(3.0, 1.0, 0.0),
                radius: 0.1,
                motion: Vec3::zeros(),
                material: 2,
            });
        }
        let scene = ready(scene, MAX_DEPTH);
        assert!(scene.light_paths());
        let max_depth = scene.max_depth();
        assert!(splits(&scene, 2, true));
        assert!(splits(&scene, max_depth - 1, true));
        assert!(!splits(&scene, max_depth, true), "nothing left to find");
        assert!(!splits(&scene, 1, true), "the camera's vertex");
        assert!(!splits(&scene, 3, false), "reached from a diffuse vertex");
    }
}
