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

use super::cut::Cap;
use super::{Distribution, Emitter, Emitters, LightPathStarts};
use crate::color::Color;
use crate::geometry::Sphere;
use crate::geometry::surface_samples::uniform_sphere;
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
    /// The probability of having picked its emitter (table entry).
    pub probability: f64,
}

/// Emitters that subtend more than this solid angle (steradians) from the
/// caustic casters start no light subpaths: through a mirror the path tracer
/// finds them often enough (a cosine-sampled bounce hits a light of solid
/// angle `w` with probability about `w / pi`), and light subpaths from them
/// would cost more than they save (a sky-sized light over mirror dragons).
pub const MAX_LIGHT_PATH_SOLID_ANGLE: f64 = 1.0;

impl Emitters {
    /// Lets light subpaths start only on the emitters (whole primitives:
    /// all triangles of a mesh together) that subtend at most
    /// [`MAX_LIGHT_PATH_SOLID_ANGLE`] from `reference`; whether any is left.
    pub fn restrict_light_paths(&mut self, reference: &Point3) -> bool {
        let mut firsts: Vec<usize> = self
            .first_entry
            .iter()
            .filter(|&&first| first != super::NONE)
            .map(|&first| first as usize)
            .collect();
        firsts.sort_unstable();
        let Some(all) = &self.distribution else {
            return false;
        };
        let mut weights: Vec<f64> = (0..self.entries.len()).map(|i| all.pmf(i)).collect();
        let mut excluded = false;
        for (k, &first) in firsts.iter().enumerate() {
            let end = firsts.get(k + 1).copied().unwrap_or(self.entries.len());
            let solid_angle: f64 = self.entries[first..end]
                .iter()
                .map(|e| solid_angle(e, reference))
                .sum();
            if solid_angle > MAX_LIGHT_PATH_SOLID_ANGLE {
                weights[first..end].iter_mut().for_each(|w| *w = 0.0);
                excluded = true;
            }
        }
        if !excluded {
            self.light_path_starts = None;
            return true;
        }
        let share: f64 = weights.iter().sum();
        let distribution = Distribution::new(&weights);
        let any = distribution.is_some();
        self.light_path_starts = Some(LightPathStarts {
            distribution,
            share,
        });
        any
    }

    /// The probability that a light subpath starts at all: the share of the
    /// power of the emitters where light subpaths start. A light subpath is
    /// drawn as if from every emitter by power, and dropped when it would
    /// start on another; the caller draws that event, so that a dropped
    /// subpath costs one random number.
    pub fn light_path_share(&self) -> f64 {
        match &self.light_path_starts {
            Some(starts) => starts.share,
            None => 1.0,
        }
    }

    /// The distribution light subpaths pick emitters by (given that one
    /// starts), and the factor from its probabilities to those of picking an
    /// emitter by power among all.
    fn light_path_distribution(&self) -> Option<(&Distribution, f64)> {
        match &self.light_path_starts {
            Some(starts) => Some((starts.distribution.as_ref()?, starts.share)),
            None => Some((self.distribution.as_ref()?, 1.0)),
        }
    }

    /// Picks an emitter with `select` (among those where light subpaths
    /// start; the density includes [`Emitters::light_path_share`]), a point
    /// on it with `u_point` and, for two-sided emitters, a side with
    /// `u_side`; `viewpoint` (the camera) chooses the cap of a cut sphere.
    pub fn sample_emission_point(
        &self,
        viewpoint: &Point3,
        time: f64,
        select: f64,
        u_point: [f64; 2],
        u_side: f64,
    ) -> Option<EmissionPoint> {
        let (distribution, share) = self.light_path_distribution()?;
        self.emission_point_of(
            distribution,
            share,
            viewpoint,
            time,
            select,
            u_point,
            u_side,
        )
    }

    /// [`Emitters::sample_emission_point`] over every emitter by power,
    /// whatever light subpaths are restricted to: where the photons of
    /// photon mapping leave from. The luminance of `pi emission / density`
    /// (a photon's power) is [`Emitters::photon_power_unit`], twice that
    /// for two-sided emitters.
    pub fn sample_photon_origin(
        &self,
        viewpoint: &Point3,
        time: f64,
        select: f64,
        u_point: [f64; 2],
        u_side: f64,
    ) -> Option<EmissionPoint> {
        let distribution = self.distribution.as_ref()?;
        self.emission_point_of(distribution, 1.0, viewpoint, time, select, u_point, u_side)
    }

    /// `pi` times the sum of the emitters' weights (emission luminance x
    /// reachable area): the luminance of one photon's power from a
    /// one-sided emitter, a scale for sums of photon powers (0 without
    /// emitters).
    pub fn photon_power_unit(&self) -> f64 {
        PI * self.total_weight
    }

    #[allow(clippy::too_many_arguments)]
    fn emission_point_of(
        &self,
        distribution: &Distribution,
        share: f64,
        viewpoint: &Point3,
        time: f64,
        select: f64,
        u_point: [f64; 2],
        u_side: f64,
    ) -> Option<EmissionPoint> {
        let (index, probability) = distribution.sample(select);
        let probability = probability * share;
        let emitter = &self.entries[index];
        let (point, normal, area_density, sides) =
            emission_point(emitter, viewpoint, time, u_point, u_side)?;
        let density = probability * area_density / sides;
        (density > 0.0 && density.is_finite()).then_some(EmissionPoint {
            point,
            normal,
            emission: emitter.emission,
            density,
            probability,
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
        let Some((index, _)) = self.entry_of(hit) else {
            return 0.0;
        };
        let Some((distribution, share)) = self.light_path_distribution() else {
            return 0.0;
        };
        let probability = distribution.pmf(index) * share;
        if probability <= 0.0 {
            return 0.0;
        }
        let emitter = &self.entries[index];
        match emitter.sphere() {
            Some(sphere) => {
                let center = sphere.center_at(time);
                let outward = (hit.point - center) / sphere.radius;
                if outward.dot(direction) <= 0.0 {
                    return 0.0;
                }
                let (cap, area) = sphere_region(emitter, sphere, viewpoint);
                match cap {
                    Some(cap) if !cap.contains(&outward) => 0.0,
                    _ => probability / area,
                }
            }
            None => {
                let area = emitter.area();
                if area > 0.0 {
                    probability / area * 0.5
                } else {
                    0.0
                }
            }
        }
    }
}

/// The solid angle `emitter` subtends from `reference`, near enough to tell a
/// small light from a sky-sized one: a sphere by its cone (a cut sphere by
/// its cap, taken flat), a planar emitter by area times cosine over the
/// squared distance of its centre.
fn solid_angle(emitter: &Emitter, reference: &Point3) -> f64 {
    let flat = |area: f64, centre: Point3, normal: Vec3| {
        let offset = reference - centre;
        let distance = offset.norm();
        if distance <= 0.0 {
            return 2.0 * PI;
        }
        let cosine = normal.dot(&offset).abs() / (normal.norm() * distance);
        let solid_angle = area * cosine / (distance * distance);
        if solid_angle.is_finite() {
            solid_angle.min(2.0 * PI)
        } else {
            0.0
        }
    };
    let Some(sphere) = emitter.sphere() else {
        return match emitter.flat_frame() {
            Some((centre, normal)) => flat(emitter.area(), centre, normal),
            None => 0.0,
        };
    };
    let (center, radius) = (sphere.center_at(0.5), sphere.radius);
    if let Some((_, cap)) = emitter.cap(reference) {
        let rim_radius2 = radius * radius * (1.0 - cap.min_cos * cap.min_cos);
        let rim_centre = center + cap.axis * (radius * cap.min_cos);
        return flat(PI * rim_radius2, rim_centre, cap.axis);
    }
    let distance2 = (center - reference).norm_squared();
    if distance2 <= radius * radius {
        return 4.0 * PI;
    }
    2.0 * PI * (1.0 - (1.0 - radius * radius / distance2).sqrt())
}

/// Where light subpaths leave a sphere from: the cap on the viewpoint's side
/// of its cuts (`Some`), or the whole sphere; and that region's area.
fn sphere_region(emitter: &Emitter, sphere: &Sphere, viewpoint: &Point3) -> (Option<Cap>, f64) {
    match emitter.cap(viewpoint) {
        Some((_, cap)) => (Some(cap), cap.area(sphere.radius)),
        None => (None, sphere.area()),
    }
}

/// A point of `emitter` for light to leave: `(point, unit normal of the
/// side emitted into, area density, number of sides)`. `u_side` picks the
/// side of a two-sided shape.
fn emission_point(
    emitter: &Emitter,
    viewpoint: &Point3,
    time: f64,
    u: [f64; 2],
    u_side: f64,
) -> Option<(Point3, Vec3, f64, f64)> {
    if let Some(sphere) = emitter.sphere() {
        let center = sphere.center_at(time);
        let (cap, area) = sphere_region(emitter, sphere, viewpoint);
        let normal = match cap {
            Some(cap) => cap.sample(u),
            None => uniform_sphere(u),
        };
        return Some((center + normal * sphere.radius, normal, 1.0 / area, 1.0));
    }
    let area = emitter.area();
    if !(area > 0.0 && area.is_finite()) {
        return None;
    }
    let (point, normal) = emitter.sample_area(time, u)?;
    let normal = if u_side < 0.5 { normal } else { -normal };
    Some((point, normal, 1.0 / area, 2.0))
}
