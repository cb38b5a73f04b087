//! Whitted-style ray tracing, as two coursework renderers did it: at each
//! hit the framework's Phong term over the point and directional lights,
//! then the mirror and refracted rays, each followed to its own end (a
//! tree of at most 2^depth branches, recursion bounded by the look's depth
//! and by [`MAX_WHITTED_DEPTH`]).
//!
//! - [`radiance_shadowed`] (jefflyy's): a shadow ray per light, lights
//!   behind the surface skipped; a point that no light reaches takes the
//!   **background colour** as its local colour; the mirror and refracted
//!   rays weighted by the material's fixed mirror and glass weights
//!   (`reflective`, `transmissive`), untinted, refraction by its index (no
//!   ray on total internal reflection); branches whose weight falls below
//!   1e-3 end black.
//! - [`radiance_unshadowed`] (emily-jia's): no shadow rays; the mirror ray
//!   weighted `r ks` and the "refracted" ray `1 - r`, untinted, with `r`
//!   Schlick's of the index ratio. Its parser leaves every index at 1,
//!   which makes the refracted ray of a front-facing hit the mirror ray and
//!   that of a back-facing hit the ray itself, and `r = (1 - |cos|)^5`.
//!
//! A ray that misses brings back the background at every depth; emitting
//! materials add their emission where they are hit.

use crate::color::Color;
use crate::math::{Ray, Vec3};
use crate::render_scene::{RenderScene, ShadowTarget};

use super::raycast::{phong, toward_light};

/// Recursion depth beyond which no branch is followed, whatever
/// `--max-depth` says (the tree doubles with each level).
pub const MAX_WHITTED_DEPTH: u32 = 16;

/// Weight below which jefflyy's branches end.
const SMALLEST_WEIGHT: f64 = 1e-3;

/// jefflyy's Whitted estimator with shadow rays, `hits` surface hits deep.
pub fn radiance_shadowed(scene: &RenderScene, ray: Ray, hits: u32) -> Color {
    shadowed(scene, ray, hits.min(MAX_WHITTED_DEPTH), 1.0)
}

fn shadowed(scene: &RenderScene, ray: Ray, hits: u32, weight: f64) -> Color {
    if weight < SMALLEST_WEIGHT || hits == 0 {
        return Color::BLACK;
    }
    let Some(hit) = scene.intersect(&ray) else {
        return scene.background();
    };
    let at = scene.shade(&hit, &ray);
    let v = -ray.direction;
    let mut local = Color::BLACK;
    let mut lit = false;
    for light in scene.lights() {
        let Some(toward) = toward_light(light, &at.point) else {
            continue;
        };
        let l = toward.direction;
        if at.normal.dot(&l) <= 0.0 {
            continue;
        }
        let origin = at.spawn_origin(&l);
        if scene.unoccluded(origin, l, ShadowTarget::Distance(toward.distance), ray.time) {
            lit = true;
            local += phong(&at, &v, &l) * toward.color;
        }
    }
    let mut color = at.material.emission + if lit { local } else { scene.background() };
    if hits == 1 {
        return color;
    }
    let (mirror, glass, ior) = at.material.lobes.mirror_and_glass();
    let d = ray.direction;
    let n = at.normal;
    if mirror > 0.0 {
        let r = mirror_direction(&d, &n);
        let next = Ray::new(at.spawn_origin(&r), r, ray.time);
        color += shadowed(scene, next, hits - 1, weight * mirror) * mirror;
    }
    if glass > 0.0 {
        let eta = if at.entering { 1.0 / ior } else { ior };
        if let Some(t) = refracted(&d, &n, eta) {
            let next = Ray::new(at.spawn_origin(&t), t, ray.time);
            color += shadowed(scene, next, hits - 1, weight * glass) * glass;
        }
    }
    color
}

/// emily-jia's Whitted estimator without shadow rays, `hits` surface hits
/// deep (its last hit adds its local term only).
pub fn radiance_unshadowed(scene: &RenderScene, ray: Ray, hits: u32) -> Color {
    unshadowed(scene, ray, hits.min(MAX_WHITTED_DEPTH))
}

fn unshadowed(scene: &RenderScene, ray: Ray, hits: u32) -> Color {
    if hits == 0 {
        return Color::BLACK;
    }
    let Some(hit) = scene.intersect(&ray) else {
        return scene.background();
    };
    let at = scene.shade(&hit, &ray);
    let v = -ray.direction;
    let mut color = at.material.emission;
    for light in scene.lights() {
        if let Some(toward) = toward_light(light, &at.point) {
            color += phong(&at, &v, &toward.direction) * toward.color;
        }
    }
    if hits == 1 {
        return color;
    }
    let d = ray.direction;
    // Index 1 on both sides: Schlick's r0 is 0.
    let r = (1.0 - d.dot(&at.normal).abs()).powi(5);
    let mirror = mirror_direction(&d, &at.normal);
    let reflected = unshadowed(
        scene,
        Ray::new(at.spawn_origin(&mirror), mirror, ray.time),
        hits - 1,
    );
    // The refracted ray at index ratio 1: the mirror ray from the front,
    // the ray itself from the back (the normal as the shape gives it).
    let front = d.dot(&hit.geometric_normal) < 0.0;
    let transmitted = if front {
        reflected
    } else {
        unshadowed(scene, Ray::new(at.spawn_origin(&d), d, ray.time), hits - 1)
    };
    let ks = at.material.phong.map_or(Color::BLACK, |p| p.color);
    color + ks * reflected * r + transmitted * (1.0 - r)
}

/// `d` mirrored about the unit normal `n`.
fn mirror_direction(d: &Vec3, n: &Vec3) -> Vec3 {
    (d - n * (2.0 * d.dot(n))).normalize()
}

/// `d` refracted through a surface of unit normal `n` (on the side `d`
/// comes from) with index ratio `eta` (incident over transmitted); `None`
/// on total internal reflection.
fn refracted(d: &Vec3, n: &Vec3, eta: f64) -> Option<Vec3> {
    let cos_i = -d.dot(n);
    let sin2_t = eta * eta * (1.0 - cos_i * cos_i);
    if sin2_t >= 1.0 {
        return None;
    }
    let cos_t = (1.0 - sin2_t).sqrt();
    Some((d * eta + n * (eta * cos_i - cos_t)).normalize())
}
