//! yao-jz's progressive photon mapping, the estimator of the `yao` look
//! (`../shared/docs/looks.md`, "yao-jz+Computer-Graphics-THU"): not a
//! physical estimator, but that renderer's own sums, round after round:
//!
//! 1. a camera pass: `SAMPLES_PER_ROUND` rays per pixel, each jittered
//!    within half a pixel of the pixel's corner, that follow *every*
//!    weighted branch of a material at once (mirror, glass of index 1.5
//!    whatever the material says, diffuse), each with its weight, for at
//!    most `MAX_DEPTH + 1` hits. An emitter seen adds its emission times
//!    the branch's energy; a miss adds nothing (the background is black);
//!    a diffuse branch leaves a view point (its outward normal, the
//!    surface colour, the branch's energy times the diffuse weight);
//! 2. a photon pass from the point lights only (directional lights send
//!    none, emitting materials none), the photons shared equally, each
//!    leaving in a uniform direction with energy `brightness / photons`
//!    and the light's colour, and again following every branch. At each
//!    diffuse hit the view points within the round's radius `r` whose
//!    normal faces the photon take `photon colour x view colour x
//!    ((r - d) / r)^2 x energy x view energy / (diffuse hits before + 1)`;
//!    the photon then leaves along `normalize(n * u) sin(phi) + n
//!    cos(phi)` (`n * u` per component, `u` uniform on the sphere, `phi`
//!    the arc cosine of a uniform number), times the surface colour;
//! 3. each pixel adds the round's sum divided by the camera rays it has had
//!    in all rounds so far; then the radius shrinks by `RADIUS_DECAY` and
//!    the camera's energy (`1 / ln(rounds)` at first) grows by its inverse.
//!
//! Deterministic for any thread count: camera ray `s` of pixel `p` in
//! round `k` draws from (`p`, `k` x 8 + `s`, seed), photon `i` of round `k`
//!
//! The rounds and their parallel loops are `render::ppm_rounds`.

use std::f64::consts::PI;

use crate::color::Color;
use crate::integrator::sppm::grid::PointGrid;
use crate::integrator::sppm::pixel::Gathered;
use crate::math::{Point3, Ray, Vec3};
use crate::render_scene::RenderScene;
use crate::sampler::Sampler;
use crate::shading::{RenderMaterial, Shading};

/// Camera rays per pixel in each round.
pub const SAMPLES_PER_ROUND: u32 = 8;
/// Camera paths and photons end after a hit at this depth (the first hit
/// is at depth 0).
pub const MAX_DEPTH: u32 = 5;
/// The radius's factor after each round (the camera's energy's divisor).
pub const RADIUS_DECAY: f64 = 0.95;
/// The index of refraction of every glass.
pub const GLASS_INDEX: f64 = 1.5;
/// The fewest rounds: the camera's first energy is `1 / ln(rounds)`.
pub const MIN_ROUNDS: u32 = 2;

/// yao's rays do not leave from where they hit, nor from a point kept off
/// the surface by the rounding of its position: a mirror ray (and a glass
/// ray reflected inside) leaves from this far along the surface's own
/// normal, a refracted ray from [`REFRACTED_OFFSET`] along its direction,
/// a diffuse photon from [`DIFFUSE_OFFSET`] along the normal, whichever
/// side it then goes to, and every ray takes hits at any distance above 0.
/// A photon that leaves a surface through it thus finds that surface again.
pub const MIRROR_OFFSET: f64 = 1e-3;
pub const REFRACTED_OFFSET: f64 = 1e-2;
pub const DIFFUSE_OFFSET: f64 = 1e-4;

/// A camera branch below this energy ends.
const MIN_CAMERA_ENERGY: f64 = 1e-9;
/// Weights at or below this are not followed.
const MIN_WEIGHT: f64 = 1e-6;
/// A photon's diffuse weight must be above this to be gathered.
const MIN_PHOTON_DIFFUSE: f64 = 1e-5;
/// A view point takes a photon when its normal and the photon's direction
/// have a dot product below minus this.
const FACING: f64 = 1e-4;

/// Where a camera branch met a diffuse surface.
#[derive(Clone, Copy, Debug)]
pub struct ViewPoint {
    pub point: Point3,
    /// The surface's outward normal there.
    pub normal: Vec3,
    pub color: Color,
    /// The branch's energy times the diffuse weight.
    pub energy: f64,
    pub pixel: u32,
}

/// A material's weights as yao's PPM follows them, all at once.
struct Branches {
    diffuse: f64,
    mirror: f64,
    glass: f64,
}

fn branches(material: &RenderMaterial) -> Branches {
    let (mirror, glass, _) = material.lobes.mirror_and_glass();
    let diffuse = material
        .lobes
        .weighted()
        .filter(|(lobe, _)| !lobe.is_delta())
        .map(|(_, weight)| weight)
        .sum();
    Branches {
        diffuse,
        mirror,
        glass,
    }
}

fn reflected(d: &Vec3, n: &Vec3) -> Vec3 {
    d - n * (2.0 * d.dot(n))
}

/// The ray through yao's glass of index [`GLASS_INDEX`]: refracted, from
/// [`REFRACTED_OFFSET`] along its direction; on total internal reflection
/// reflected, from [`MIRROR_OFFSET`] along the surface's normal.
fn through_glass(at: &Shading, d: &Vec3, time: f64) -> Ray {
    let n = at.normal;
    let eta = if at.entering {
        1.0 / GLASS_INDEX
    } else {
        GLASS_INDEX
    };
    let cos_i = -d.dot(&n);
    let cos2t = 1.0 - eta * eta * (1.0 - cos_i * cos_i);
    if cos2t < 0.0 {
        return mirrored(at, d, time);
    }
    let direction = (d * eta + n * (eta * cos_i - cos2t.sqrt())).normalize();
    Ray::new(at.point + direction * REFRACTED_OFFSET, direction, time)
}

/// How a branch's ray leaves a hit ([`through_glass`], [`mirrored`]).
type Leave = fn(&Shading, &Vec3, f64) -> Ray;

/// The mirror ray, from [`MIRROR_OFFSET`] along the surface's normal.
fn mirrored(at: &Shading, d: &Vec3, time: f64) -> Ray {
    let origin = at.point + outward(at) * MIRROR_OFFSET;
    Ray::new(origin, reflected(d, &at.normal), time)
}

/// The surface's own normal (the shape's, whichever side the ray came
/// from), along which yao's rays leave.
fn outward(at: &Shading) -> Vec3 {
    if at.entering { at.normal } else { -at.normal }
}

pub fn uniform_sphere(u: [f64; 2]) -> Vec3 {
    let z = 1.0 - 2.0 * u[0];
    let r = (1.0 - z * z).max(0.0).sqrt();
    let phi = 2.0 * PI * u[1];
    Vec3::new(r * phi.cos(), r * phi.sin(), z)
}

/// One camera branch: adds what it sees to `seen` and its view points to
/// `points`.
pub fn camera_branch(
    scene: &RenderScene,
    ray: &Ray,
    energy: f64,
    depth: u32,
    pixel: u32,
    seen: &mut Color,
    points: &mut Vec<ViewPoint>,
) {
    if energy < MIN_CAMERA_ENERGY || depth > MAX_DEPTH {
        return;
    }
    // A miss adds the background, which yao's PPM sets to black.
    let Some(hit) = scene.intersect(ray) else {
        return;
    };
    let at = scene.shade(&hit, ray);
    if at.material.emission.r != 0.0 {
        *seen += at.material.emission * energy;
        return;
    }
    let weights = branches(at.material);
    let d = ray.direction;
    let leaving: [(f64, Leave); 2] = [(weights.glass, through_glass), (weights.mirror, mirrored)];
    for (weight, leave) in leaving {
        if weight > MIN_WEIGHT {
            let next = leave(&at, &d, ray.time);
            camera_branch(
                scene,
                &next,
                energy * weight,
                depth + 1,
                pixel,
                seen,
                points,
            );
        }
    }
    if weights.diffuse > MIN_WEIGHT {
        points.push(ViewPoint {
            point: at.point,
            normal: outward(&at),
            color: at.color,
            energy: energy * weights.diffuse,
            pixel,
        });
    }
}

/// What every photon of a round shares.
pub struct PhotonPass<'a> {
    pub scene: &'a RenderScene,
    pub grid: &'a PointGrid,
    pub points: &'a [ViewPoint],
    pub radius: f64,
    pub gathered: &'a Gathered,
}

impl PhotonPass<'_> {
    /// Follows a photon's ray and its branches, gathering at diffuse hits.
    pub fn trace(
        &self,
        ray: &Ray,
        color: Color,
        depth: u32,
        energy: f64,
        diffuse_hits: u32,
        sampler: &mut Sampler,
    ) {
        if depth > MAX_DEPTH {
            return;
        }
        let Some(hit) = self.scene.intersect(ray) else {
            return;
        };
        let at = self.scene.shade(&hit, ray);
        let weights = branches(at.material);
        let d = ray.direction;
        if weights.mirror > MIN_WEIGHT {
            let next = mirrored(&at, &d, ray.time);
            let energy = energy * weights.mirror;
            self.trace(&next, color, depth + 1, energy, diffuse_hits, sampler);
        }
        if weights.glass > MIN_WEIGHT {
            let next = through_glass(&at, &d, ray.time);
            let energy = energy * weights.glass;
            self.trace(&next, color, depth + 1, energy, diffuse_hits, sampler);
        }
        if weights.diffuse <= MIN_PHOTON_DIFFUSE {
            return;
        }
        let r = self.radius;
        let share = energy / (diffuse_hits + 1) as f64;
        self.grid.candidates(&at.point, |index| {
            let view = &self.points[index as usize];
            let distance = (view.point - at.point).norm();
            if distance > r || view.normal.dot(&d) >= -FACING {
                return;
            }
            let cone = ((r - distance) / r).powi(2);
            let value = color * view.color * (cone * share * view.energy);
            if value.is_finite() {
                self.gathered.add(view.pixel as usize, value);
            }
        });
        let n = outward(&at);
        let spread = n.component_mul(&uniform_sphere(sampler.next_2d()));
        let phi = sampler.next_f64().acos();
        let Some(spread) = spread.try_normalize(1e-12) else {
            return;
        };
        let Some(direction) = (spread * phi.sin() + n * phi.cos()).try_normalize(1e-12) else {
            return;
        };
        let next = Ray::new(at.point + n * DIFFUSE_OFFSET, direction, ray.time);
        let color = color * at.color;
        let energy = energy * weights.diffuse;
        self.trace(&next, color, depth + 1, energy, diffuse_hits + 1, sampler);
    }
}
