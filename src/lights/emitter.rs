//! The world-space shapes that light sampling can pick a point on, with their
//! densities in solid angle as seen from a shading point.
//!
//! Planar shapes (triangles, parallelograms, ellipses) are sampled uniformly by
//! area: an affine transform keeps a uniform area density uniform, so a
//! transformed rectangle or disk is sampled in its world-space form. Spheres
//! are sampled in the cone they subtend from outside, and by area from inside
//! (or from their own surface). Emitters are two-sided, as in the original
//! estimator, which adds emission whichever side a ray hits.

use std::f64::consts::PI;

use super::cut::{Cap, CutPlane, Cuts};
use crate::camera::concentric_disk;
use crate::math::{Point3, Vec3, orthonormal_basis};
use crate::trig::sin_cos_turns;

/// Below this `|cos|` at the light, a sampled point is dropped (the density
/// in solid angle would be unbounded; such points carry no energy anyway).
const MIN_LIGHT_COSINE: f64 = 1e-12;

/// A reference point within this relative margin of a sphere's radius counts
/// as inside (area sampling), so points on the sphere itself are handled.
const SPHERE_SURFACE_MARGIN: f64 = 1e-6;

#[derive(Clone, Copy, Debug)]
pub enum EmitterShape {
    /// A sphere whose centre is `center + motion * time`, cut by the planes
    /// of `cuts` (none for a moving sphere).
    Sphere {
        center: Point3,
        motion: Vec3,
        radius: f64,
        cuts: Cuts,
    },
    Triangle {
        vertices: [Point3; 3],
    },
    /// `origin + s * edge_u + t * edge_v`, s and t in [0, 1].
    Parallelogram {
        origin: Point3,
        edge_u: Vec3,
        edge_v: Vec3,
    },
    /// `center + x * axis_u + y * axis_v` with `x^2 + y^2 <= 1` (a disk, or a
    /// disk under a non-uniform scale).
    Ellipse {
        center: Point3,
        axis_u: Vec3,
        axis_v: Vec3,
    },
}

/// A point chosen on an emitter, seen from the reference point.
#[derive(Clone, Copy, Debug)]
pub struct ShapeSample {
    pub point: Point3,
    /// Unit direction from the reference point to `point`.
    pub direction: Vec3,
    pub distance: f64,
    /// Density of `direction` in solid angle.
    pub pdf: f64,
}

impl EmitterShape {
    /// Surface area (world space).
    pub fn area(&self) -> f64 {
        match self {
            EmitterShape::Sphere { radius, .. } => 4.0 * PI * radius * radius,
            EmitterShape::Triangle {
                vertices: [a, b, c],
            } => 0.5 * (b - a).cross(&(c - a)).norm(),
            EmitterShape::Parallelogram { edge_u, edge_v, .. } => edge_u.cross(edge_v).norm(),
            EmitterShape::Ellipse { axis_u, axis_v, .. } => PI * axis_u.cross(axis_v).norm(),
        }
    }

    /// The area that shadow rays from `reference` can reach, past `planes`
    /// (infinite and opaque, as every plane is to a shadow ray): none when
    /// the shape lies wholly beyond one of them, a cut sphere's cap on that
    /// side (see [`Cuts::cap`]), else [`EmitterShape::area`].
    pub fn reachable_area(&self, reference: &Point3, planes: &[CutPlane]) -> f64 {
        let beyond = |plane: &CutPlane| {
            let side = plane.normal.dot(reference) - plane.offset;
            // From behind a one-sided plane every ray passes it.
            let opaque = !(plane.one_sided && side < 0.0);
            let towards = plane.normal * side.signum();
            opaque
                && side != 0.0
                && self
                    .extent_along(&towards)
                    .is_some_and(|extent| extent < plane.offset * side.signum())
        };
        if planes.iter().any(beyond) {
            return 0.0;
        }
        match self {
            EmitterShape::Sphere {
                center,
                radius,
                cuts,
                ..
            } => cuts
                .cap(center, *radius, reference)
                .map_or_else(|| self.area(), |cap| cap.area(*radius)),
            _ => self.area(),
        }
    }

    /// The largest `direction . p` over the points `p` of the shape (`None`
    /// for a moving sphere, which sweeps a region over the shutter).
    fn extent_along(&self, direction: &Vec3) -> Option<f64> {
        match *self {
            EmitterShape::Sphere {
                center,
                motion,
                radius,
                ..
            } => (motion == Vec3::zeros()).then(|| direction.dot(&center) + radius),
            EmitterShape::Triangle { vertices } => Some(
                vertices
                    .iter()
                    .map(|v| direction.dot(v))
                    .fold(f64::MIN, f64::max),
            ),
            EmitterShape::Parallelogram {
                origin,
                edge_u,
                edge_v,
            } => {
                let (u, v) = (direction.dot(&edge_u), direction.dot(&edge_v));
                Some(direction.dot(&origin) + u.max(0.0) + v.max(0.0))
            }
            EmitterShape::Ellipse {
                center,
                axis_u,
                axis_v,
            } => {
                let (u, v) = (direction.dot(&axis_u), direction.dot(&axis_v));
                Some(direction.dot(&center) + u.hypot(v))
            }
        }
    }

    /// A point on the shape for the uniform pair `u`, as seen from `reference`
    /// at shutter time `time`; `None` when the sample carries no density.
    pub fn sample(&self, reference: &Point3, time: f64, u: [f64; 2]) -> Option<ShapeSample> {
        match *self {
            EmitterShape::Sphere {
                center,
                motion,
                radius,
                cuts,
            } => sample_sphere(&(center + motion * time), radius, &cuts, reference, u),
            _ => {
                let (point, normal) = self.sample_area(time, u);
                from_area_sample(reference, &point, &normal, self.area())
            }
        }
    }

    /// The solid-angle density with which [`EmitterShape::sample`] from
    /// `reference` produces `point` (a point on the shape with unit normal
    /// `normal`, first along its ray from `reference`).
    pub fn pdf(&self, reference: &Point3, time: f64, point: &Point3, normal: &Vec3) -> f64 {
        match *self {
            EmitterShape::Sphere {
                center,
                motion,
                radius,
                cuts,
            } => {
                let center = center + motion * time;
                match cone(&center, radius, reference) {
                    Some(cone) => match cuts.cap(&center, radius, reference) {
                        Some(cap) => {
                            if cap.contains(&((point - center) / radius)) {
                                area_to_solid_angle(reference, point, normal, cap.area(radius))
                            } else {
                                0.0
                            }
                        }
                        None => cone.pdf,
                    },
                    None => {
                        area_to_solid_angle(reference, point, normal, 4.0 * PI * radius * radius)
                    }
                }
            }
            _ => area_to_solid_angle(reference, point, normal, self.area()),
        }
    }

    /// A uniform point on the surface at shutter time `time`, and its unit normal.
    pub fn sample_area(&self, time: f64, u: [f64; 2]) -> (Point3, Vec3) {
        match *self {
            EmitterShape::Triangle {
                vertices: [a, b, c],
            } => {
                // Uniform barycentrics by the square-root map.
                let s = u[0].sqrt();
                let (b1, b2) = (s * (1.0 - u[1]), s * u[1]);
                let point = a * (1.0 - b1 - b2) + b * b1 + c * b2;
                (point, (b - a).cross(&(c - a)).normalize())
            }
            EmitterShape::Parallelogram {
                origin,
                edge_u,
                edge_v,
            } => (
                origin + edge_u * u[0] + edge_v * u[1],
                edge_u.cross(&edge_v).normalize(),
            ),
            EmitterShape::Ellipse {
                center,
                axis_u,
                axis_v,
            } => {
                let (x, y) = concentric_disk(u);
                (
                    center + axis_u * x + axis_v * y,
                    axis_u.cross(&axis_v).normalize(),
                )
            }
            EmitterShape::Sphere {
                center,
                motion,
                radius,
                ..
            } => {
                let normal = uniform_sphere(u);
                (center + motion * time + normal * radius, normal)
            }
        }
    }
}

/// The cone a sphere subtends from an outside point.
struct Cone {
    /// Unit axis towards the centre.
    axis: Vec3,
    distance: f64,
    cos_max: f64,
    /// `1 - cos_max`, computed without cancellation.
    one_minus_cos_max: f64,
    /// Uniform density over the cone.
    pdf: f64,
}

/// `None` when `reference` is inside the sphere or on its surface.
fn cone(center: &Point3, radius: f64, reference: &Point3) -> Option<Cone> {
    let offset = center - reference;
    let distance_squared = offset.norm_squared();
    let radius_squared = radius * radius;
    if distance_squared <= radius_squared * (1.0 + SPHERE_SURFACE_MARGIN) {
        return None;
    }
    let distance = distance_squared.sqrt();
    let sin2_max = radius_squared / distance_squared;
    let cos_max = (1.0 - sin2_max).max(0.0).sqrt();
    let one_minus_cos_max = sin2_max / (1.0 + cos_max);
    Some(Cone {
        axis: offset / distance,
        distance,
        cos_max,
        one_minus_cos_max,
        pdf: 1.0 / (2.0 * PI * one_minus_cos_max),
    })
}

fn sample_sphere(
    center: &Point3,
    radius: f64,
    cuts: &Cuts,
    reference: &Point3,
    u: [f64; 2],
) -> Option<ShapeSample> {
    let Some(cone) = cone(center, radius, reference) else {
        let normal = uniform_sphere(u);
        let point = center + normal * radius;
        return from_area_sample(reference, &point, &normal, 4.0 * PI * radius * radius);
    };
    if let Some(cap) = cuts.cap(center, radius, reference) {
        return sample_cap(center, radius, &cap, reference, u);
    }
    // cos(theta) uniform in [cos_max, 1].
    let one_minus_cos = u[0] * cone.one_minus_cos_max;
    let cos_theta = 1.0 - one_minus_cos;
    let sin_theta = (one_minus_cos * (2.0 - one_minus_cos)).max(0.0).sqrt();
    let (sin_phi, cos_phi) = sin_cos_turns(u[1]);
    let (t, b) = orthonormal_basis(&cone.axis);
    // Unit to rounding in the orthonormal frame of the axis.
    let direction = t * (sin_theta * cos_phi) + b * (sin_theta * sin_phi) + cone.axis * cos_theta;
    // Nearest intersection along the direction: d cos - sqrt(r^2 - d^2 sin^2).
    let d = cone.distance;
    let perpendicular2 = d * d * sin_theta * sin_theta;
    let half_chord = (radius * radius - perpendicular2).max(0.0).sqrt();
    let distance = d * cos_theta - half_chord;
    debug_assert!(cos_theta >= cone.cos_max - 1e-9);
    if !(distance > 0.0 && distance.is_finite()) {
        return None;
    }
    Some(ShapeSample {
        point: reference + direction * distance,
        direction,
        distance,
        pdf: cone.pdf,
    })
}

/// A uniform point of `cap` as seen from `reference` outside the sphere; the
/// points facing away from it (hidden by the sphere itself) are dropped.
fn sample_cap(
    center: &Point3,
    radius: f64,
    cap: &Cap,
    reference: &Point3,
    u: [f64; 2],
) -> Option<ShapeSample> {
    let normal = cap.sample(u);
    let point = center + normal * radius;
    if normal.dot(&(reference - point)) <= 0.0 {
        return None;
    }
    from_area_sample(reference, &point, &normal, cap.area(radius))
}

/// A uniformly chosen area point turned into a direction with its solid-angle density.
fn from_area_sample(
    reference: &Point3,
    point: &Point3,
    normal: &Vec3,
    area: f64,
) -> Option<ShapeSample> {
    let offset = point - reference;
    let distance = offset.norm();
    if !(distance > 0.0 && distance.is_finite()) {
        return None;
    }
    let direction = offset / distance;
    let pdf = area_to_solid_angle(reference, point, normal, area);
    (pdf > 0.0 && pdf.is_finite()).then_some(ShapeSample {
        point: *point,
        direction,
        distance,
        pdf,
    })
}

/// `dist^2 / (|cos_light| * area)`: a uniform area density seen from `reference`.
fn area_to_solid_angle(reference: &Point3, point: &Point3, normal: &Vec3, area: f64) -> f64 {
    let offset = point - reference;
    let distance_squared = offset.norm_squared();
    let distance = distance_squared.sqrt();
    if !(distance > 0.0 && area > 0.0) {
        return 0.0;
    }
    let cosine = normal.dot(&offset).abs() / distance;
    if cosine < MIN_LIGHT_COSINE {
        return 0.0;
    }
    distance_squared / (cosine * area)
}

/// A uniform unit vector.
pub(super) fn uniform_sphere(u: [f64; 2]) -> Vec3 {
    let z = 1.0 - 2.0 * u[0];
    let r = (1.0 - z * z).max(0.0).sqrt();
    let (sin, cos) = sin_cos_turns(u[1]);
    Vec3::new(r * cos, r * sin, z)
}
