//! The renderable world: the scene's object tree flattened into primitives,
//! with a BVH over the bounded ones when there are more than a few. Answers
//! the two ray queries of the integrators.

mod builder;
mod lanes;
mod plain;
mod primitive;

use crate::accel::Bvh;
use crate::geometry::{Intersection, RevolutionTest, Shape, SphereTest, UvMapping};
use crate::math::{Aabb, Point3, Ray, Vec3, offset_origin};
use crate::scene::model::Scene;

use builder::Builder;
use plain::PlainShapes;
pub use primitive::Primitive;

/// A ray's nearest hit, in world space.
#[derive(Clone, Copy, Debug)]
pub struct WorldHit {
    pub t: f64,
    pub point: Point3,
    /// Unit normal of the surface as modelled (outward for closed shapes); not
    /// flipped towards the ray.
    pub geometric_normal: Vec3,
    /// Unit interpolated normal (meshes with normals), else the geometric one.
    pub shading_normal: Vec3,
    /// Partial derivatives of `point` with respect to `uv` (not normalised;
    /// per texel for [`UvMapping::Tiled`]), for normal and bump maps.
    pub dpdu: Vec3,
    pub dpdv: Vec3,
    pub uv: [f64; 2],
    pub uv_mapping: UvMapping,
    /// The material of the primitive, or of the triangle for meshes with
    /// `.mtl` materials ([`Primitive::material_of`]).
    pub material: usize,
    /// Index of the primitive in the world (see [`World::primitive`]).
    pub primitive: usize,
    /// Element within the primitive (triangle of a mesh), else 0.
    pub element: u32,
    /// Whether rays leave from `point` itself rather than off the surface
    /// (a sphere under Cambrian's test, [`SphereTest::Cambrian`]).
    pub leaves_from_point: bool,
}

impl WorldHit {
    /// Origin for a ray leaving the hit in `direction` (either side of the surface):
    /// the point offset along the geometric normal by [`offset_origin`]. Rays
    /// spawned from it do not re-hit this surface, even with `t_min = 0`
    /// (unless the hit `leaves_from_point`: then the point itself).
    pub fn spawn_origin(&self, direction: &Vec3) -> Point3 {
        spawn_origin(
            &self.point,
            &self.geometric_normal,
            self.leaves_from_point,
            direction,
        )
    }

    /// A ray leaving the hit in `direction` at shutter time `time`.
    pub fn spawn_ray(&self, direction: Vec3, time: f64) -> Ray {
        Ray::new(self.spawn_origin(&direction), direction, time)
    }
}

/// Origin of a ray leaving a surface point in `direction`: `point` pushed
/// off along the geometric normal `geometric` by [`offset_origin`], or
/// `point` itself where the hit `leaves_from_point` (see
/// [`WorldHit::leaves_from_point`]).
#[inline]
pub fn spawn_origin(
    point: &Point3,
    geometric: &Vec3,
    leaves_from_point: bool,
    direction: &Vec3,
) -> Point3 {
    if leaves_from_point {
        return *point;
    }
    offset_origin(point, geometric, direction)
}

/// A look's conventions for how shapes meet rays (the exact ones by default).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ShapeRules {
    /// Planes are hit from the front only, so light passes them from behind.
    pub one_sided_planes: bool,
    /// Planes are hit at distance 0 too (see [`crate::geometry::Plane::accepts_zero`]).
    pub planes_accept_zero: bool,
    pub sphere_test: SphereTest,
    /// Surfaces of revolution turn their profile's (x, y) about the **z**
    /// axis, the profile's y becoming z (jefflyy's), instead of about y.
    pub revolutions_about_z: bool,
    /// Spheres, planes and triangles (meshes' too) are tested by
    /// W-Solaris's tests in single precision
    /// ([`crate::geometry::single_precision`]), whatever `sphere_test` and
    /// the plane rules say.
    pub single_precision: bool,
    pub revolution_test: RevolutionTest,
    /// Meshes are made of their OBJ file's framework reading, when it has
    /// one (see `MeshData::framework_reading`).
    pub framework_obj_reading: bool,
    /// Mesh triangles shade with their face normal, the file's `vn` and
    /// `smooth` unused.
    pub face_normals: bool,
    /// Planes take cav's uv frame (see [`crate::geometry::Plane::with_cav_frame`]).
    pub cav_plane_frames: bool,
    /// Planes are met in single precision (see `Plane::intersect`).
    pub single_precision_planes: bool,
    /// Rectangles are met by Cambrian's test
    /// ([`crate::geometry::cambrian_rectangle`]).
    pub cambrian_rectangles: bool,
}

/// The box a linear primitive is culled by (see `World::linear_boxes`):
/// its world bounds grown by a millionth of their size and distance from
/// the origin, far more than the rounding of a slab test.
fn culling_box(primitive: &Primitive) -> Option<Aabb> {
    if !matches!(
        primitive.shape,
        Shape::Mesh { .. }
            | Shape::Revolution(_)
            | Shape::SeededRevolution(_)
            | Shape::CavRevolution(_)
    ) {
        return None;
    }
    let bounds = primitive.bounds().filter(Aabb::is_valid)?;
    let scale = bounds
        .min
        .iter()
        .chain(bounds.max.iter())
        .fold(1.0f64, |m, c| m.max(c.abs()));
    Some(bounds.expanded(1e-6 * scale))
}

/// Whether `ray` misses the culling box of a linear primitive (none: never)
/// within `(t_min, t_max)`; the ray's inverse direction is computed on the
/// first box a query meets, and kept for the next.
#[inline]
fn culled(
    culling: &Option<Aabb>,
    ray: &Ray,
    inverse_direction: &mut Option<Vec3>,
    t_min: f64,
    t_max: f64,
) -> bool {
    culling.as_ref().is_some_and(|b| {
        let inverse = inverse_direction.get_or_insert_with(|| ray.direction.map(|d| 1.0 / d));
        b.clip(&ray.origin, inverse, t_min, t_max).is_none()
    })
}

/// Worlds with at most this many bounded primitives go without a BVH: their
/// primitives are tested one after another (spheres inline), which is cheaper
/// than the box tests that would cull them.
const LINEAR_LIMIT: usize = 8;

/// The flattened scene geometry. Immutable after `build`, hence `Send + Sync`.
pub struct World {
    primitives: Vec<Primitive>,
    /// Untransformed planes, and untransformed spheres of a world without
    /// BVH: tested first, inline.
    plain: PlainShapes,
    /// Other primitives tested one by one (transformed planes; in a world
    /// without BVH, every bounded primitive that is not plain).
    linear: Vec<u32>,
    /// Per entry of `linear`: the world box (slightly grown) of a mesh or a
    /// surface of revolution, whose own test costs far more than a box
    /// test of the untransformed ray; `None` for the others.
    linear_boxes: Vec<Option<Aabb>>,
    /// Primitives in the BVH, in the slot order of `bvh` (empty in a world
    /// without BVH).
    bounded: Vec<u32>,
    bvh: Bvh,
    /// Bounds of the bounded primitives.
    bounds: Aabb,
    /// Per material: whether a texture, normal or bump map reads uv and the
    /// surface derivatives.
    /// Empty: compute them always.
    needs_uv: Vec<bool>,
    /// Surfaces of revolution built exact where the look asked for cav's
    /// tessellation, past [`crate::limits::MAX_CAV_TESSELLATION_TRIANGLES`].
    cav_revolutions_exact: usize,
}

impl World {
    /// Flattens the object tree: nested transforms are composed (identities are
    /// dropped), each distinct mesh (`Arc` identity) gets one triangle BVH (and,
    /// when some instance is `smooth` and the file has no normals, one set of
    /// area-weighted vertex normals) shared by its instances, and a top-level
    /// BVH is built over the bounded primitives (unless they are few).
    /// Degenerate shapes (zero radius, zero normal, zero area, unusable profiles)
    /// are dropped. `rules` are the look's for how shapes meet rays. (The
    /// render-time scene builds its world here: see `RenderScene::build`.)
    pub(crate) fn build(scene: &Scene, rules: ShapeRules) -> World {
        let mut builder = Builder::for_tree(&scene.root);
        builder.rules = rules;
        builder.visit(&scene.root, None);
        let cav_revolutions_exact = builder.cav_exact_instead;
        let mut world = World::from_primitives(builder.primitives);
        world.cav_revolutions_exact = cav_revolutions_exact;
        world.needs_uv = scene
            .materials
            .iter()
            .map(|m| m.texture.is_some() || m.normal_map.is_some() || m.bump.is_some())
            .collect();
        world
    }

    /// A world over already made primitives.
    pub(crate) fn from_primitives(primitives: Vec<Primitive>) -> World {
        let mut plain = PlainShapes::default();
        let mut linear = Vec::new();
        let mut bounded = Vec::new();
        let mut boxes = Vec::new();
        for (index, primitive) in primitives.iter().enumerate() {
            match (&primitive.shape, &primitive.transform) {
                (Shape::Plane(plane), None) => plain.push_plane(*plane, index),
                (Shape::Plane(_), Some(_)) => linear.push(index as u32),
                _ => {
                    if let Some(b) = primitive.bounds().filter(Aabb::is_valid) {
                        bounded.push(index as u32);
                        boxes.push(b);
                    }
                }
            }
        }
        let bounds = boxes.iter().fold(Aabb::empty(), |acc, b| acc.union(b));
        let mut bvh = Bvh::default();
        if bounded.len() <= LINEAR_LIMIT {
            for index in bounded.drain(..) {
                let primitive = &primitives[index as usize];
                match (&primitive.shape, &primitive.transform) {
                    (Shape::Sphere(sphere), None) => plain.push_sphere(*sphere, index as usize),
                    _ => linear.push(index),
                }
            }
        } else {
            bvh = Bvh::build(&boxes);
        }
        plain.pack();
        let linear_boxes = linear
            .iter()
            .map(|&index| culling_box(&primitives[index as usize]))
            .collect();
        World {
            primitives,
            plain,
            linear,
            linear_boxes,
            bounded,
            bvh,
            bounds,
            needs_uv: Vec::new(),
            cav_revolutions_exact: 0,
        }
    }

    /// How many surfaces of revolution are exact where the look asked for
    /// cav's tessellation (see [`crate::limits::MAX_CAV_TESSELLATION_TRIANGLES`]).
    pub fn cav_revolutions_exact(&self) -> usize {
        self.cav_revolutions_exact
    }

    pub fn primitives(&self) -> &[Primitive] {
        &self.primitives
    }

    pub fn primitive(&self, index: usize) -> &Primitive {
        &self.primitives[index]
    }

    /// The nearest hit with `t_min < t < t_max`.
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<WorldHit> {
        let mut best: Option<(usize, Intersection)> = None;
        let mut limit = t_max;
        self.plain.nearest(ray, t_min, &mut limit, &mut best);
        if !self.linear.is_empty() {
            let mut inverse_direction = None;
            for (&index, culling) in self.linear.iter().zip(&self.linear_boxes) {
                if culled(culling, ray, &mut inverse_direction, t_min, limit) {
                    continue;
                }
                let index = index as usize;
                if let Some(hit) = self.primitives[index].intersect(ray, t_min, limit) {
                    limit = hit.t;
                    best = Some((index, hit));
                }
            }
        }
        if !self.bounded.is_empty() {
            self.bvh.traverse(ray, t_min, limit, |slot, limit| {
                let index = self.bounded[slot] as usize;
                let hit = self.primitives[index].intersect(ray, t_min, limit)?;
                best = Some((index, hit));
                Some(hit.t)
            });
        }
        let (index, hit) = best?;
        let primitive = &self.primitives[index];
        let material = primitive.material_of(hit.index);
        let with_uv = self.needs_uv.get(material).copied().unwrap_or(true);
        let surface = primitive.surface(ray, &hit, with_uv);
        debug_assert!(surface.point.iter().all(|c| c.is_finite()));
        Some(WorldHit {
            t: hit.t,
            point: surface.point,
            geometric_normal: surface.geometric_normal,
            shading_normal: surface.shading_normal,
            dpdu: surface.dpdu,
            dpdv: surface.dpdv,
            uv: surface.uv,
            uv_mapping: surface.uv_mapping,
            material,
            primitive: index,
            element: hit.index,
            leaves_from_point: primitive.leaves_from_point(),
        })
    }

    /// Whether anything lies on the ray with `t_min < t < t_max`.
    pub fn occluded(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        self.plain.any(ray, t_min, t_max)
            || !self.linear.is_empty() && {
                let mut inverse_direction = None;
                self.linear
                    .iter()
                    .zip(&self.linear_boxes)
                    .any(|(&index, culling)| {
                        !culled(culling, ray, &mut inverse_direction, t_min, t_max)
                            && self.primitives[index as usize].occluded(ray, t_min, t_max)
                    })
            }
            || (!self.bounded.is_empty()
                && self.bvh.any(ray, t_min, t_max, |slot| {
                    self.primitives[self.bounded[slot] as usize].occluded(ray, t_min, t_max)
                }))
    }

    /// Triangles of all mesh instances (an instanced mesh counts each time).
    pub fn triangle_count(&self) -> usize {
        self.primitives
            .iter()
            .map(|p| match &p.shape {
                Shape::Mesh { mesh, .. } => mesh.triangle_count(),
                _ => 0,
            })
            .sum()
    }

    /// Bounds of the bounded primitives (planes excluded).
    pub fn bounds(&self) -> Aabb {
        self.bounds
    }
}

#[cfg(test)]
mod tests;
