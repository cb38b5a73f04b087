//! 1rubbishyuan's recursive estimator (the `rub` look), from its facts in
//! `../shared/docs/looks.md`. It is not a path tracer: its terms carry
//! ad-hoc factors and clamps, and it is reproduced as such.
//!
//! - Every call, the camera ray's included, first returns black with
//!   probability 0.2; the survivors are not reweighted, and nothing else
//!   limits the depth (here the look's depth, 64 calls, which 0.8^64 makes
//!   irrelevant).
//! - A miss returns the background at every depth; the caller's factors
//!   then apply to it as to any light.
//! - A hit on an emitter returns its emission and ends the call: times its
//!   `boost` after a bounce, without it for a camera ray.
//! - One number chooses the lobe against the weights `perDiffuse`, then
//!   `perDiffuse + perReflect`; everything else refracts.
//! - Normals are never turned toward the ray: `V` and the cosines are taken
//!   with the shape's own normal, so a back face gets `max(0, N.V) = 0`.
//! - Diffuse: `colour min(1, 1000 brdf(V, W) max(0, N.V) / (depth + 1)
//!   L(W))` per channel, `W = normalise(N + v)` with `v` a normalised cube
//!   sample turned into `N`'s hemisphere; plus the direct light: per
//!   emitting shape one uniform point, a shadow ray whose first hit must lie
//!   within 0.1 of that point's distance (whatever it hits: that hit's
//!   emission, boost included), `brdf(V, L) colour Le max(0, N.L) / d^2
//!   1500 / (depth + 1)`. `brdf` is rub's Cook-Torrance; a material without
//!   `cookTorrence` (whose pointer rub leaves uninitialised) gets `1 / pi`.
//! - Mirror: `colour min(1, max(0, N.V) / (depth + 1) L(R))`.
//! - Glass: with `c = -I.N`, `c > 0` refracts into the index (`1 / n`) when
//!   refraction is possible and a draw passes Schlick's reflectance (`R0`
//!   from that ratio); `c < 0` always reflects. `colour min(1, 2 L)`. A ray
//!   that leaves a sphere never hits that sphere again (rub's spheres ignore
//!   rays starting within 1e-4 of them): a ray refracted into one leaves it
//!   unrefracted.
//!
//! Not reproduced: the lens on its rim, the per-axis field of view, the 2.2
//! texture decode, the shared texel state and the plane formula of its
//! source; light points on spheres are uniform on the surface (rub's
//! normalised cube samples are nearly so).

use std::f64::consts::FRAC_1_PI;

use crate::bsdf::Lobe;
use crate::color::Color;
use crate::geometry::Shape;
use crate::math::{Ray, Vec3};
use crate::render_scene::RenderScene;
use crate::sampler::Sampler;
use crate::world::WorldHit;

/// The probability with which every call returns black.
pub const DEATH: f64 = 0.2;
/// The factor of the diffuse bounce's light.
pub const INDIRECT: f64 = 1000.0;
/// The factor of the direct light.
pub const DIRECT: f64 = 1500.0;
/// The factor of the light through glass.
pub const GLASS: f64 = 2.0;
/// How far a shadow ray's first hit may lie from the light point.
pub const SHADOW_SLACK: f64 = 0.1;

/// The radiance estimate of rub's renderer along the camera ray `ray`.
pub fn radiance(scene: &RenderScene, ray: Ray, sampler: &mut Sampler) -> Color {
    trace(scene, ray, None, 0, sampler)
}

/// What a hit's material scatters by, read from its lobes.
struct Scatter {
    /// The diffuse weight and rub's BRDF of it.
    diffuse: f64,
    cook_torrance: Option<crate::bsdf::cook_torrance::CookTorrance>,
    mirror: f64,
    ior: f64,
}

fn scatter_of(scene: &RenderScene, hit: &WorldHit) -> Scatter {
    let lobes = &scene.material(hit.material).lobes;
    let mut scatter = Scatter {
        diffuse: 0.0,
        cook_torrance: None,
        mirror: 0.0,
        ior: lobes.mirror_and_glass().2,
    };
    for (lobe, weight) in lobes.weighted() {
        match lobe {
            Lobe::CookTorrance(c) => {
                scatter.diffuse += weight;
                scatter.cook_torrance = Some(*c);
            }
            Lobe::Conductor(c) if c.is_delta() => scatter.mirror += weight,
            Lobe::Dielectric(_) => {}
            _ => scatter.diffuse += weight,
        }
    }
    scatter
}

impl Scatter {
    fn brdf(&self, n: &Vec3, v: &Vec3, l: &Vec3) -> f64 {
        match &self.cook_torrance {
            Some(c) => c.value_about(n, v, l),
            None => FRAC_1_PI,
        }
    }
}

/// The nearest hit of `ray`, a sphere it leaves (`leaving`) left out.
fn nearest(scene: &RenderScene, mut ray: Ray, leaving: Option<usize>) -> Option<WorldHit> {
    let hit = scene.intersect(&ray)?;
    let is_sphere = |index: usize| matches!(scene.world().primitive(index).shape, Shape::Sphere(_));
    if leaving == Some(hit.primitive) && is_sphere(hit.primitive) {
        ray.origin = scene.shade(&hit, &ray).spawn_origin(&ray.direction);
        return scene.intersect(&ray);
    }
    Some(hit)
}

fn trace(
    scene: &RenderScene,
    ray: Ray,
    leaving: Option<usize>,
    depth: u32,
    sampler: &mut Sampler,
) -> Color {
    if depth >= scene.max_depth().max(1) || sampler.next_f64() < DEATH {
        return Color::BLACK;
    }
    let Some(hit) = nearest(scene, ray, leaving) else {
        return scene.background();
    };
    let at = scene.shade(&hit, &ray);
    let material = at.material;
    if !material.emission.is_black() {
        return if depth == 0 && material.boost != 0.0 {
            material.emission / material.boost
        } else {
            material.emission
        };
    }
    // The shape's own normal, not turned toward the ray.
    let n = if at.entering { at.normal } else { -at.normal };
    let v = -ray.direction;
    let cos_v = n.dot(&v).max(0.0);
    let scale = 1.0 / f64::from(depth + 1);
    let scatter = scatter_of(scene, &hit);
    let choice = sampler.next_f64();
    let next = |direction: Vec3, sampler: &mut Sampler| {
        let origin = at.spawn_origin(&direction);
        trace(
            scene,
            Ray::new(origin, direction, ray.time),
            Some(hit.primitive),
            depth + 1,
            sampler,
        )
    };
    let clamped = |c: Color| c.map(|x| x.min(1.0));
    if choice < scatter.diffuse {
        let w = diffuse_direction(&n, sampler);
        let brdf = scatter.brdf(&n, &v, &w);
        let indirect = clamped(next(w, sampler) * (INDIRECT * brdf * cos_v * scale));
        at.color * indirect + direct(scene, &at, &n, &v, &scatter, scale, sampler)
    } else if choice < scatter.diffuse + scatter.mirror {
        let r = reflect(&ray.direction, &n);
        at.color * clamped(next(r, sampler) * (cos_v * scale))
    } else {
        let d = ray.direction;
        let c = -d.dot(&n);
        let reflectance_draw = sampler.next_f64();
        let direction = if c > 0.0 {
            let eta = 1.0 / scatter.ior;
            let r0 = ((1.0 - eta) / (1.0 + eta)).powi(2);
            let schlick = r0 + (1.0 - r0) * (1.0 - c).powi(5);
            match refract(&d, &n, c, eta) {
                Some(t) if reflectance_draw >= schlick => t,
                _ => reflect(&d, &n),
            }
        } else {
            reflect(&d, &n)
        };
        at.color * clamped(next(direction, sampler) * GLASS)
    }
}

/// `normalise(N + v)`, `v` a normalised point of the cube `[-1, 1]^3`
/// turned into `N`'s hemisphere.
fn diffuse_direction(n: &Vec3, sampler: &mut Sampler) -> Vec3 {
    loop {
        let v = Vec3::new(
            2.0 * sampler.next_f64() - 1.0,
            2.0 * sampler.next_f64() - 1.0,
            2.0 * sampler.next_f64() - 1.0,
        );
        let Some(v) = v.try_normalize(1e-9) else {
            continue;
        };
        let v = if v.dot(n) < 0.0 { -v } else { v };
        if let Some(w) = (n + v).try_normalize(1e-9) {
            return w;
        }
    }
}

fn reflect(d: &Vec3, n: &Vec3) -> Vec3 {
    d - n * (2.0 * d.dot(n))
}

/// The direction `d` refracted through the normal `n` it meets at `c =
/// -d.n > 0`, with the index ratio `eta`; `None` on total reflection.
fn refract(d: &Vec3, n: &Vec3, c: f64, eta: f64) -> Option<Vec3> {
    let k = 1.0 - eta * eta * (1.0 - c * c);
    (k >= 0.0).then(|| (d * eta + n * (eta * c - k.sqrt())).normalize())
}

/// The direct light at a diffuse hit: one point per emitting shape.
fn direct(
    scene: &RenderScene,
    at: &crate::shading::Shading,
    n: &Vec3,
    v: &Vec3,
    scatter: &Scatter,
    scale: f64,
    sampler: &mut Sampler,
) -> Color {
    let mut sum = Color::BLACK;
    for emitter in scene.emitters().entries() {
        let u = [sampler.next_f64(), sampler.next_f64()];
        // Shadow rays are built at time 0.
        let Some((point, _)) = emitter.sample_area(0.0, u) else {
            continue;
        };
        let to_light = point - at.point;
        let distance = to_light.norm();
        let Some(l) = to_light.try_normalize(1e-12) else {
            continue;
        };
        let cos_l = n.dot(&l);
        if cos_l <= 0.0 {
            continue;
        }
        let shadow = Ray::new(at.spawn_origin(&l), l, 0.0);
        let Some(blocker) = scene.intersect(&shadow) else {
            continue;
        };
        if (blocker.t - distance).abs() > SHADOW_SLACK {
            continue;
        }
        let emission = scene.material(blocker.material).emission;
        let factor = scatter.brdf(n, v, &l) * cos_l / (distance * distance) * DIRECT * scale;
        sum += at.color * emission * factor;
    }
    sum
}
