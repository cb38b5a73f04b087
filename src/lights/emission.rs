//! Light leaving the emitters: the first vertex of a light subpath, and the
//! density with which a given light point would have been sampled, for the
//! MIS weights of the caustic connections.
//!
//! A point is chosen on an emitter (picked by power, as for next-event
//! estimation) uniformly by area, with the side light leaves to: outwards
//! for spheres, either side (each with probability 1/2) for the two-sided
//! planar emitters. A static sphere cut by infinite planes is sampled on the
//! cap on the viewpoint's side: no path from the camera can reach the rest of
//! it (see `cut`), and the density of every other point is zero, so paths
//! that reach one anyway are left to the path tracer.

use std::f64::consts::PI;

use super::Emitters;
use super::emitter::{EmitterShape, uniform_sphere};
use crate::color::Color;
use crate::math::{Point3, Vec3};
use crate::world::WorldHit;

/// A light point for a light subpath to leave from.
#[derive(Clone, Copy, Debug)]
pub struct EmissionPoint {
    pub point: Point3,
    /// Unit normal of the side light leaves to.
    pub normal: Vec3,
    pub emission: Color,
    /// Area density of the point, with the emitter's pick probability and
    /// the probability of the side (1/2 for two-sided emitters).
    pub density: f64,
}

impl Emitters {
    /// Picks an emitter with `select`, a point on it with `u_point` and, for
    /// two-sided emitters, a side with `u_side`; `viewpoint` (the camera)
    /// chooses the cap of a cut sphere.
    pub fn sample_emission_point(
        &self,
        viewpoint: &Point3,
        time: f64,
        select: f64,
        u_point: [f64; 2],
        u_side: f64,
    ) -> Option<EmissionPoint> {
        let (index, probability) = self.distribution.as_ref()?.sample(select);
        let emitter = &self.entries[index];
        let (point, normal, area_density, sides) =
            emission_point(&emitter.shape, viewpoint, time, u_point, u_side)?;
        let density = probability * area_density / sides;
        (density > 0.0 && density.is_finite()).then_some(EmissionPoint {
            point,
            normal,
            emission: emitter.emission,
            density,
        })
    }

    /// The density (as in [`EmissionPoint::density`]) of the light point of
    /// `hit` for light leaving it in `direction`: 0 for points that
    /// [`Emitters::sample_emission_point`] never gives, and for directions
    /// into a sphere.
    pub fn emission_point_density(
        &self,
        viewpoint: &Point3,
        time: f64,
        hit: &WorldHit,
        direction: &Vec3,
    ) -> f64 {
        let Some((index, probability)) = self.entry_of(hit) else {
            return 0.0;
        };
        let shape = &self.entries[index].shape;
        match *shape {
            EmitterShape::Sphere {
                center,
                motion,
                radius,
                cuts,
            } => {
                let center = center + motion * time;
                let outward = (hit.point - center) / radius;
                if outward.dot(direction) <= 0.0 {
                    return 0.0;
                }
                match cuts.cap(&center, radius, viewpoint) {
                    Some(cap) if cap.contains(&outward) => probability / cap.area(radius),
                    Some(_) => 0.0,
                    None => probability / (4.0 * PI * radius * radius),
                }
            }
            _ => {
                let area = shape.area();
                if area > 0.0 {
                    probability / area * 0.5
                } else {
                    0.0
                }
            }
        }
    }
}

/// A point of `shape` for light to leave: `(point, unit normal of the side
/// emitted into, area density, number of sides)`. `u_side` picks the side of
/// a two-sided shape.
fn emission_point(
    shape: &EmitterShape,
    viewpoint: &Point3,
    time: f64,
    u: [f64; 2],
    u_side: f64,
) -> Option<(Point3, Vec3, f64, f64)> {
    match *shape {
        EmitterShape::Sphere {
            center,
            motion,
            radius,
            cuts,
        } => {
            let center = center + motion * time;
            let (normal, area) = match cuts.cap(&center, radius, viewpoint) {
                Some(cap) => (cap.sample(u), cap.area(radius)),
                None => (uniform_sphere(u), 4.0 * PI * radius * radius),
            };
            Some((center + normal * radius, normal, 1.0 / area, 1.0))
        }
        _ => {
            let area = shape.area();
            if !(area > 0.0 && area.is_finite()) {
                return None;
            }
            let (point, normal) = shape.sample_area(time, u);
            let normal = if u_side < 0.5 { normal } else { -normal };
            Some((point, normal, 1.0 / area, 2.0))
        }
    }
}
