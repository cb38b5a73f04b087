//! CaveSpiderLZJ's path tracer (the `cav` look), from the facts of its
//! code (CaveSpiderLZJ/PathTracingFinal: `src/main.cpp` at `6970e2d`,
//! `include/triangle.hpp`, `transform.hpp`, `group.hpp`, `plane.hpp` at
//! `d730b9c`, `sphere.hpp`, `object3d.hpp`), including the normals it does
//! not normalise:
//!
//! - One lobe per hit, drawn against `reflect = fbase + fscale (1 -
//!   dotIN)^power`, then `refract = fbase + fscale - reflect`, the rest
//!   diffuse; the path's colour is multiplied by the hit's colour whatever
//!   the lobe, and every hit adds its emission. From the 5th hit the path
//!   goes on with probability max(colour) (divided by it) and no further
//!   than the 9th hit, whose emission still counts.
//! - A triangle's normal is its winding's, not turned towards the ray, so
//!   a ray inside a mesh is inside (total reflection where `sin x ior >=
//!   1`, else `fscale` scaled by `1 / (1 - sqrt(1 - 1/ior^2))^power`);
//!   spheres (inward from inside), planes and surfaces of revolution turn
//!   theirs towards the ray, so rays meeting them always enter.
//! - A transformed shape's normal is the inverse transpose times the
//!   object's unit normal, never normalised: its length `k` is that of the
//!   scaled normal (1/2 on the x faces of a cube scaled by 2). Its tracer
//!   then uses it as given: `dotIN = -d.n`, the mirror direction `d - 2 n
//!   (d.n)` (not normalised either: with `k^2 < 1/2` it keeps going through
//!   the surface, shorter), the refracted direction `normalize(tan x
//!   normalize(foot - origin) - n)` with `foot = p + n (n.(origin - p))`,
//!   the diffuse one about `n` with its second tangent `n x u` of length
//!   `k`.
//! - A ray of direction `d` (not unit after such a mirror) meets planes and
//!   meshes at `t` in units of `d`, but spheres at `t` in units of length
//!   along `d / |d|`, at the point `origin + d t`: short of the sphere by
//!   `|d|`. The nearest `t` wins, so a shortened ray meets the radius-600
//!   light spheres of its scenes (just above the ceiling) before the
//!   ceiling, and collects their light in mid-air (see
//!   `world::Primitive::intersect`).
//!
//! Rays leave a hit from the hit point (cav's spheres add their own 1e-5
//! along the ray) and meet nothing nearer than cav's 1e-4 plus that offset.

use std::f64::consts::TAU;

use crate::bsdf::LobeSet;
use crate::color::Color;
use crate::geometry::{Shape, cav_sphere};
use crate::math::{Ray, Vec3};
use crate::render_scene::RenderScene;
use crate::sampler::Sampler;

use super::scatter::miss;

/// Hits after which cav's roulette plays (`RR`).
const ROULETTE_AFTER: u32 = 4;

/// The nearest hit cav accepts from a ray leaving a surface: its `TMIN`
/// beyond its `DELTA`.
const T_MIN: f64 = cav_sphere::MIN_DISTANCE as f64 + cav_sphere::LEAVING_OFFSET;

pub fn radiance(scene: &RenderScene, mut ray: Ray, sampler: &mut Sampler) -> Color {
    let max_depth = scene.max_depth();
    let mut result = Color::BLACK;
    let mut past = Color::WHITE;
    let mut depth = 0;
    let mut t_min = 0.0;
    loop {
        let Some(hit) = scene.world().intersect(&ray, t_min, f64::INFINITY) else {
            result += miss(scene, depth, past);
            break;
        };
        let at = scene.shade(&hit, &ray);
        let emission = at.material.emission;
        let point = ray.at(hit.t);
        let d = ray.direction;
        let (mut n, turns) = cav_normal(scene, hit.primitive, &hit.geometric_normal);
        let mut outside = true;
        if d.dot(&n) > 0.0 {
            n = -n;
            outside = turns;
        }
        depth += 1;
        let mut ratio = 1.0;
        if depth > ROULETTE_AFTER {
            let c = at.color;
            let most = c.r.max(c.g).max(c.b);
            if sampler.next_f64() < most && depth <= max_depth {
                ratio = 1.0 / most;
            } else {
                result += emission * past;
                break;
            }
        }
        let weights = Weights::of(&at.material.lobes, &d, &n, outside);
        result += emission * past;
        past = past * at.color * ratio;
        let choice = sampler.next_f64();
        let direction = if choice <= weights.reflect {
            d - n * (2.0 * d.dot(&n))
        } else if choice <= weights.reflect + weights.refract {
            let foot = point + n * n.dot(&(ray.origin - point));
            let along = (foot - ray.origin).normalize();
            (along * weights.tan - n).normalize()
        } else {
            diffuse_direction(&n, sampler.next_2d())
        };
        if past.is_black() || !direction.iter().all(|c| c.is_finite()) {
            break;
        }
        ray = Ray::new(point, direction, ray.time);
        t_min = T_MIN;
    }
    result
}

/// The normal cav's tracer receives for a hit of primitive `primitive`
/// whose unit geometric normal is `normal`: scaled by the length the
/// primitive's transform gives it, and whether the shape turns it towards
/// the ray (all but triangles, under the look's `every_hit_enters`).
fn cav_normal(scene: &RenderScene, primitive: usize, normal: &Vec3) -> (Vec3, bool) {
    let primitive = scene.world().primitive(primitive);
    let turns = scene.look().every_hit_enters
        && !matches!(primitive.shape, Shape::Mesh { .. } | Shape::Triangle(_));
    let length = match &primitive.transform {
        // n_world = N n_object / |N n_object| with N the inverse transpose,
        // so |N n_object| = 1 / |N^-1 n_world| and N^-1 = M^T.
        Some(transform) => {
            let back = transform.matrix.fixed_view::<3, 3>(0, 0).transpose() * normal;
            1.0 / back.norm()
        }
        None => 1.0,
    };
    (normal * length, turns)
}

/// cav's lobe weights at a hit, and the tangent of its refraction angle.
struct Weights {
    reflect: f64,
    refract: f64,
    tan: f64,
}

impl Weights {
    fn of(lobes: &LobeSet, d: &Vec3, n: &Vec3, outside: bool) -> Weights {
        let (base, scale, power) = lobes
            .angular()
            .map_or((0.0, 0.0, 1.0), |a| (a.base, a.scale, a.power));
        let ior = lobes.ior();
        let dot_in = -d.dot(n);
        let falloff = (1.0 - dot_in).powf(power);
        let sine = (1.0 - dot_in * dot_in).sqrt();
        let tan_of = |s: f64| (s * s / (1.0 - s * s)).sqrt();
        if outside {
            let reflect = base + scale * falloff;
            let s = sine / ior;
            return Weights {
                reflect,
                refract: base + scale - reflect,
                tan: tan_of(s),
            };
        }
        let s = sine * ior;
        if s >= 1.0 {
            return Weights {
                reflect: base + scale,
                refract: 0.0,
                tan: 0.0,
            };
        }
        let eta = 1.0 / (1.0 - (1.0 - 1.0 / (ior * ior)).sqrt()).powf(power);
        let reflect = base + scale * eta * falloff;
        Weights {
            reflect,
            refract: base + scale - reflect,
            tan: tan_of(s),
        }
    }
}

/// cav's diffuse direction about `n` (any length) from `u`: a disk sample
/// in the tangents `normalize((0,1,0) or (1,0,0) x n)` and `n x` that,
/// lifted along `n`, normalised.
fn diffuse_direction(n: &Vec3, u: [f64; 2]) -> Vec3 {
    let theta = TAU * u[0];
    let r = u[1];
    let rs = r.sqrt();
    let axis = if n.x > 0.1 { Vec3::y() } else { Vec3::x() };
    let t1 = axis.cross(n).normalize();
    let t2 = n.cross(&t1);
    (t1 * (rs * theta.cos()) + t2 * (rs * theta.sin()) + n * (1.0 - r).sqrt()).normalize()
}
