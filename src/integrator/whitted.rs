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
//! - [`radiance_unshadowed`] (emily-jia's,
//!   `emily-jia/graphic_homework:src/RayTracer.cpp`): no shadow rays; the
//!   mirror ray weighted `r ks` and the "refracted" ray `1 - r`, untinted.
//!   A ray carries the index of the medium it travels in (1 from the
//!   camera; a refracted ray takes the index of the material it refracted
//!   through); `r` is Schlick's with `r0` from the two indices and the
//!   cosine of the ray (into a denser material) or of the refracted ray
//!   (into a lighter one). Its refracted direction is
//!   `n cos_t + (d - (n.d) n) eta` with `n` the normal as the shape gives
//!   it, whichever side the ray comes from; where `cos_t^2 < 1e-3` there is
//!   none (and `r` takes the cosine 0 into a lighter material). Its parser
//!   leaves every scene material at index 1, which makes the refracted ray
//!   of a front-facing hit the mirror ray and that of a back-facing hit the
//!   ray itself, and `r = (1 - |cos|)^5`; its `.mtl` materials have their
//!   `Ni` (see `render_scene::emily_jia_mtl`).
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
    unshadowed(scene, ray, hits.min(MAX_WHITTED_DEPTH), 1.0)
}

/// Below this squared cosine emily-jia's tracer makes no refracted ray.
const GRAZING: f64 = 1e-3;

/// The radiance along `ray`, which travels in a medium of index `index`.
fn unshadowed(scene: &RenderScene, ray: Ray, hits: u32, index: f64) -> Color {
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
    let mirror = mirror_direction(&d, &at.normal);
    let reflected = unshadowed(
        scene,
        Ray::new(at.spawn_origin(&mirror), mirror, ray.time),
        hits - 1,
        index,
    );
    // The "refracted" ray, by the normal as the shape gives it.
    let n = hit.geometric_normal;
    let (_, _, beyond) = at.material.lobes.mirror_and_glass();
    let cos = n.dot(&d);
    let eta = index / beyond;
    let cos_t_squared = 1.0 - eta * eta * (1.0 - cos * cos);
    let denser = index <= beyond;
    let (transmitted, cos_r) = if cos_t_squared < GRAZING {
        (Color::BLACK, if denser { cos } else { 0.0 })
    } else {
        let t = (n * cos_t_squared.sqrt() + (d - n * cos) * eta).normalize();
        let next = Ray::new(at.spawn_origin(&t), t, ray.time);
        let cos_r = if denser { cos } else { t.dot(&n) };
        (unshadowed(scene, next, hits - 1, beyond), cos_r)
    };
    let r0 = ((beyond - index) / (beyond + index)).powi(2);
    let r = r0 + (1.0 - r0) * (1.0 - cos_r.abs()).powi(5);
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
