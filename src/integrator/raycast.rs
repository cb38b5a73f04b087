//! The course framework's ray casting (the PA1 look): the first hit only,
//! shaded for every point and directional light by the framework's Phong
//! term, with no shadows, no ambient light and no bounces.
//!
//! `kd max(0, n . l) + ks max(0, v . r)^shininess`, times the light's
//! colour, with `r = 2 (n . l) n - l` from the unclamped `n . l` and `v`
//! towards the eye; the specular term is not gated by `n . l`, and lights
//! do not fall off with distance (Achazwl's and aliezlo's `rc`, looks.md).
//! `kd` is the material's colour or texel, `ks` and the exponent its
//! `specularColor` and `shininess`. A ray that misses gives the background.

use crate::color::Color;
use crate::math::{Ray, Vec3};
use crate::scene::model::Light;

use crate::render_scene::RenderScene;

pub fn radiance(scene: &RenderScene, ray: Ray) -> Color {
    let Some(hit) = scene.intersect(&ray) else {
        return scene.background();
    };
    let at = scene.shade(&hit, &ray);
    let n = at.normal;
    let v = -ray.direction;
    let (ks, exponent) = at
        .material
        .phong
        .map_or((Color::BLACK, 0.0), |p| (p.color, p.exponent));
    let mut sum = at.material.emission;
    for light in scene.lights() {
        let (l, color) = match light {
            Light::Point { position, color } => match (position - at.point).try_normalize(1e-300) {
                Some(l) => (l, *color),
                None => continue,
            },
            Light::Directional { direction, color } => match (-direction).try_normalize(1e-300) {
                Some(l) => (l, *color),
                None => continue,
            },
            Light::Spot {
                position,
                direction,
                color,
                exponent,
            } => match (position - at.point).try_normalize(1e-300) {
                Some(l) => (l, *color * direction.dot(&-l).max(0.0).powf(*exponent)),
                None => continue,
            },
            Light::Disk { .. } | Light::Area { .. } => continue,
        };
        let cos = n.dot(&l);
        let diffuse = at.color * cos.max(0.0);
        let r: Vec3 = n * (2.0 * cos) - l;
        let specular = if ks.is_black() {
            Color::BLACK
        } else {
            ks * v.dot(&r).max(0.0).powf(exponent)
        };
        sum += (diffuse + specular) * color;
    }
    sum
}
