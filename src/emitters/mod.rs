//! The emitter table of next-event estimation: every emissive primitive whose
//! shape can be sampled, one entry per shape (per triangle for meshes, with
//! the emission of the triangle's own material when the mesh has `.mtl`
//! materials), chosen in proportion to its power (emission luminance x area; for a
//! sphere cut by planes, the area of the cap on the camera's side).
//!
//! Sampled: spheres (under similarity transforms only; a non-uniformly scaled
//! sphere is an ellipsoid and is left to BSDF sampling), triangles,
//! rectangles, disks and mesh triangles, with any transform. Not sampled, so
//! reached by BSDF sampling alone (MIS weight 1): planes, surfaces of
//! revolution and the background. The coursework disk and area lights are
//! emitting disks and parallelograms in the world (the scene builder makes
//! them), so they are sampled like any other. The PA1 point and directional
//! lights are not in this table: both integrators add them in
//! `integrator::point_lights`. A static sphere light cut by infinite planes is
//! sampled on the cap on the shading point's side (`cut`). The same table
//! starts the light subpaths of caustics (`emission`).

pub mod cosine;
pub mod cut;
pub mod distribution;
pub mod emission;
pub mod emitter;

#[cfg(test)]
mod camera_side_tests;
#[cfg(test)]
mod cut_tests;
#[cfg(test)]
mod tests;

use crate::color::Color;
use crate::geometry::Shape;
use crate::math::{Point3, Vec3, transform_point};
use crate::scene::model::{CameraDesc, Scene};
use crate::world::{Primitive, World, WorldHit};

pub use cut::{CutPlane, Cuts};
pub use distribution::Distribution;
pub use emission::EmissionPoint;
pub use emitter::Emitter;

/// No entry for this primitive.
const NONE: u32 = u32::MAX;

/// A sampled light point as seen from a shading point.
#[derive(Clone, Copy, Debug)]
pub struct LightSample {
    pub point: Point3,
    /// Unit direction from the shading point to `point`.
    pub direction: Vec3,
    pub distance: f64,
    pub emission: Color,
    /// Density in solid angle, including the probability of picking the emitter.
    pub pdf: f64,
    /// The table entry sampled (see [`Emitters::entry_of`]).
    pub entry: usize,
}

/// The emitters of a world and the distribution they are picked by.
#[derive(Clone, Debug, Default)]
pub struct Emitters {
    entries: Vec<Emitter>,
    distribution: Option<Distribution>,
    /// Per world primitive: its first entry, or `NONE`. A mesh's triangle `k`
    /// is entry `first + k`.
    first_entry: Vec<u32>,
    /// Light subpaths start only on some emitters (see
    /// [`Emitters::restrict_light_paths`]): the distribution over those, by
    /// power, and their share of the power. `None`: on every emitter.
    light_path_starts: Option<LightPathStarts>,
    /// The sum of the entries' weights (emission luminance x reachable
    /// area): with `pi`, the luminance of the power a photon carries (see
    /// [`Emitters::sample_photon_origin`]).
    total_weight: f64,
}

#[derive(Clone, Debug)]
struct LightPathStarts {
    /// Over all entries, zero for those where no light subpath starts.
    distribution: Option<Distribution>,
    /// The share of the total power of the entries where they start.
    share: f64,
}

impl Emitters {
    pub fn build(scene: &Scene, world: &World) -> Emitters {
        let mut entries = Vec::new();
        let mut first_entry = vec![NONE; world.primitives().len()];
        let planes: Vec<CutPlane> = world.primitives().iter().filter_map(world_plane).collect();
        let emission = |material: usize| {
            scene
                .materials
                .get(material)
                .map_or(Color::BLACK, |m| m.emission)
        };
        for (index, primitive) in world.primitives().iter().enumerate() {
            if primitive.materials().all(|m| emission(m).is_black()) {
                continue;
            }
            // Shapes come one per element (a mesh's triangle k is the k-th),
            // each with the emission of its own material.
            let start = entries.len();
            push_entries(primitive, &planes, &emission, &mut entries);
            if entries.len() > start {
                first_entry[index] = start as u32;
            }
        }
        // The power that shadow rays from the camera's side of the planes
        // can reach: smallpt's ceiling light would otherwise take the light
        // samples of a small sphere beside it for the 600-radius sphere it
        // is, and a light behind a wall would take its share for nothing.
        // (Only efficiency: an emitter left out is found by the bounces.)
        // The camera's side is the canvas's, where its rays start: smallpt's
        // eye is behind the box's front wall.
        let camera = canvas_centre(&scene.camera);
        let weights: Vec<f64> = entries
            .iter()
            .map(|e| e.emission.luminance().max(0.0) * e.reachable_area(&camera, &planes))
            .collect();
        let distribution = Distribution::new(&weights);
        let total_weight = weights.iter().filter(|w| w.is_finite() && **w > 0.0).sum();
        Emitters {
            entries,
            distribution,
            first_entry,
            light_path_starts: None,
            total_weight,
        }
    }

    /// Whether light sampling can pick every emitting surface of `world`:
    /// each primitive with an emissive material is in the table, and every
    /// entry that emits has a positive probability. Then a light sample
    /// alone estimates all the light a vertex receives directly, and the
    /// BSDF's own bounce is needed only for the rest of the path.
    pub fn cover(&self, scene: &Scene, world: &World) -> bool {
        let emits = |material: usize| {
            scene
                .materials
                .get(material)
                .is_some_and(|m| !m.emission.is_black())
        };
        let listed = world
            .primitives()
            .iter()
            .enumerate()
            .all(|(index, primitive)| {
                !primitive.materials().any(emits) || self.first_entry.get(index) != Some(&NONE)
            });
        let picked = self.entries.iter().enumerate().all(|(index, entry)| {
            entry.emission.is_black()
                || self
                    .distribution
                    .as_ref()
                    .is_some_and(|d| d.pmf(index) > 0.0)
        });
        listed && picked
    }

    /// Whether light sampling has nothing to pick.
    /// Every entry: one per emitting shape (a mesh's triangle each).
    pub fn entries(&self) -> &[Emitter] {
        &self.entries
    }

    pub fn is_empty(&self) -> bool {
        self.distribution.is_none()
    }

    pub fn len(&self) -> usize {
        self.entries.len()
    }

    /// Picks an emitter with `select` and a point on it with `u`, as seen from
    /// `reference` at shutter time `time`.
    #[inline]
    pub fn sample(
        &self,
        reference: &Point3,
        time: f64,
        select: f64,
        u: [f64; 2],
    ) -> Option<LightSample> {
        let (index, probability) = self.distribution.as_ref()?.sample(select);
        let emitter = &self.entries[index];
        let sample = emitter.sample(reference, time, u)?;
        Some(LightSample {
            point: sample.point,
            direction: sample.direction,
            distance: sample.distance,
            emission: emitter.emission,
            pdf: sample.pdf * probability,
            entry: index,
        })
    }

    /// The density (solid angle, with the pick probability) with which
    /// [`Emitters::sample`] from `reference` gives the point of `hit`; 0 for
    /// everything light sampling never produces.
    pub fn pdf(&self, reference: &Point3, time: f64, hit: &WorldHit) -> f64 {
        let Some((index, probability)) = self.entry_of(hit) else {
            return 0.0;
        };
        let emitter = &self.entries[index];
        probability * emitter.pdf(reference, time, &hit.point, &hit.geometric_normal)
    }

    /// The entry of the emitter that `hit` is on and its pick probability;
    /// `None` when light sampling never picks it.
    pub fn entry_of(&self, hit: &WorldHit) -> Option<(usize, f64)> {
        let distribution = self.distribution.as_ref()?;
        let first = self.first_entry.get(hit.primitive).copied().unwrap_or(NONE);
        if first == NONE {
            return None;
        }
        let index = first as usize + hit.element as usize;
        let probability = distribution.pmf(index);
        (probability > 0.0).then_some((index, probability))
    }
}

/// The world-space plane of a plane primitive.
fn world_plane(primitive: &Primitive) -> Option<CutPlane> {
    let Shape::Plane(plane) = &primitive.shape else {
        return None;
    };
    let (normal, offset) = match primitive.transform.as_deref() {
        None => (plane.normal, plane.offset),
        Some(t) => {
            // n . p = d with p = A^-1 (q - t): (A^-T n) . q = d + (A^-T n) . t.
            let normal = t.normal_matrix * plane.normal;
            let translation = Vec3::new(t.matrix[(0, 3)], t.matrix[(1, 3)], t.matrix[(2, 3)]);
            (normal, plane.offset + normal.dot(&translation))
        }
    };
    let length = normal.norm();
    (length > 0.0 && length.is_finite() && offset.is_finite()).then(|| CutPlane {
        normal: normal / length,
        offset: offset / length,
        one_sided: plane.one_sided,
    })
}

/// The entries of a primitive (none when it cannot be sampled; one per
/// triangle of a mesh, each with its own material's emission); `planes`
/// are the world's infinite planes, which may cut spheres.
fn push_entries(
    primitive: &Primitive,
    planes: &[CutPlane],
    emission: &dyn Fn(usize) -> Color,
    entries: &mut Vec<Emitter>,
) {
    let transform = primitive.transform.as_deref();
    let Shape::Mesh { mesh, .. } = &primitive.shape else {
        let emission = emission(primitive.material_of(0));
        entries.extend(Emitter::new(&primitive.shape, transform, planes, emission));
        return;
    };
    // One entry per triangle, invalid ones included (with zero area), so
    // that triangle k of the mesh is entry first + k.
    let point = |p: &Point3| match transform {
        Some(t) => transform_point(&t.matrix, p),
        None => *p,
    };
    let positions = &mesh.data.positions;
    for (element, triangle) in mesh.data.triangles.iter().enumerate() {
        let vertex = |i: u32| positions.get(i as usize).map(point);
        let vertices = match (
            vertex(triangle[0]),
            vertex(triangle[1]),
            vertex(triangle[2]),
        ) {
            (Some(a), Some(b), Some(c)) => [a, b, c],
            _ => [Point3::zeros(); 3],
        };
        let emission = emission(primitive.material_of(element as u32));
        entries.push(Emitter::triangle(vertices, emission));
    }
}

/// Where the camera's rays start on its axis: the centre of its canvas
/// (the eye when the canvas distance is 0).
fn canvas_centre(camera: &CameraDesc) -> Point3 {
    match camera.direction.try_normalize(0.0) {
        Some(direction) => camera.center + direction * camera.canvas_distance,
        None => camera.center,
    }
}
