//! The renderable world: the scene's object tree flattened into primitives,
//! with a BVH over the bounded ones when there are more than a few. Answers
//! the two ray queries of the integrators.

mod builder;
mod plain;
mod primitive;

use crate::accel::Bvh;
use crate::geometry::{Intersection, Shape, SphereTest};
use crate::math::{Aabb, Point3, Ray, Vec3, offset_origin};
use crate::scene::model::Scene;

use builder::Builder;
use plain::PlainShapes;
pub use primitive::Primitive;

/// How a hit's `uv` is meant to be read by a texture lookup.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum UvMapping {
    /// `uv` in [0, 1]: clamped lookup.
    Unit,
    /// `uv` in texels of a tiled texture (planes: 10 texels per world unit).
    Tiled,
}

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
        if self.leaves_from_point {
            return self.point;
        }
        offset_origin(&self.point, &self.geometric_normal, direction)
    }

    /// A ray leaving the hit in `direction` at shutter time `time`.
    pub fn spawn_ray(&self, direction: Vec3, time: f64) -> Ray {
        Ray::new(self.spawn_origin(&direction), direction, time)
    }
}

/// A look's conventions for how shapes meet rays (the exact ones by default).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ShapeRules {
    /// Planes are hit from the front only, so light passes them from behind.
    pub one_sided_planes: bool,
    pub sphere_test: SphereTest,
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
}

impl World {
    /// Flattens the object tree: nested transforms are composed (identities are
    /// dropped), each distinct mesh (`Arc` identity) gets one triangle BVH (and,
    /// when some instance is `smooth` and the file has no normals, one set of
    /// area-weighted vertex normals) shared by its instances, and a top-level
    /// BVH is built over the bounded primitives (unless they are few).
    /// Degenerate shapes (zero radius, zero normal, zero area, unusable profiles)
    /// are dropped.
    pub fn build(scene: &Scene) -> World {
        World::build_with(scene, ShapeRules::default())
    }

    /// [`World::build`] with a look's rules for how shapes meet rays.
    pub fn build_with(scene: &Scene, rules: ShapeRules) -> World {
        let mut builder = Builder::for_tree(&scene.root);
        builder.rules = rules;
        builder.visit(&scene.root, None);
        let mut world = World::from_primitives(builder.primitives);
        world.needs_uv = scene
            .materials
            .iter()
            .map(|m| m.texture.is_some() || m.normal_map.is_some() || m.bump.is_some())
            .collect();
        world
    }

    /// A world over already made primitives.
    pub fn from_primitives(primitives: Vec<Primitive>) -> World {
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
        World {
            primitives,
            plain,
            linear,
            bounded,
            bvh,
            bounds,
            needs_uv: Vec::new(),
        }
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
        for &index in &self.linear {
            let index = index as usize;
            if let Some(hit) = self.primitives[index].intersect(ray, t_min, limit) {
                limit = hit.t;
                best = Some((index, hit));
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
            || self
                .linear
                .iter()
                .any(|&index| self.primitives[index as usize].occluded(ray, t_min, t_max))
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
mod tests {
    use super::*;

    use crate::math::Matrix;
    use std::sync::Arc;

    use crate::scene::model::{MeshData, Object};

    fn scene(root: Object) -> Scene {
        Scene::new(Vec::new(), root)
    }

    fn translate(offset: Vec3, child: Object) -> Object {
        let matrix = Matrix::new_translation(&offset);
        Object::Transform {
            matrix,
            inverse: Matrix::new_translation(&-offset),
            child: Box::new(child),
        }
    }

    #[test]
    fn build_composes_transforms_and_shares_meshes() {
        let data = Arc::new(MeshData {
            positions: vec![Point3::zeros(), Point3::x(), Point3::y()],
            normals: None,
            uvs: None,
            triangles: vec![[0, 1, 2]],
        });
        let mesh = |material| Object::Mesh {
            mesh: Arc::clone(&data),
            smooth: false,
            material,
            face_materials: None,
        };
        let root = Object::Group(vec![
            translate(
                Vec3::new(0.0, 0.0, -5.0),
                translate(Vec3::new(10.0, 0.0, 0.0), mesh(1)),
            ),
            translate(Vec3::zeros(), mesh(2)),
            Object::Sphere {
                center: Point3::zeros(),
                radius: 0.0,
                motion: Vec3::zeros(),
                material: 3,
            },
            Object::Plane {
                normal: Vec3::y(),
                offset: -1.0,
                material: 4,
            },
        ]);
        let world = World::build(&scene(root));
        // The zero-radius sphere is dropped; the identity transform is not stored.
        assert_eq!(world.primitives().len(), 3);
        assert!(world.primitive(1).transform.is_none());
        let (Shape::Mesh { mesh: a, .. }, Shape::Mesh { mesh: b, .. }) =
            (&world.primitive(0).shape, &world.primitive(1).shape)
        else {
            panic!("meshes expected");
        };
        assert!(Arc::ptr_eq(a, b), "one geometry mesh per MeshData");
        // Nested translations compose: the first instance sits at (10, 0, -5).
        let ray = Ray::new(Point3::new(10.25, 0.25, 0.0), -Vec3::z(), 0.0);
        let hit = world.intersect(&ray, 0.0, f64::INFINITY).unwrap();
        assert_eq!(hit.material, 1);
        assert!((hit.t - 5.0).abs() < 1e-12);
        assert!((hit.point - Point3::new(10.25, 0.25, -5.0)).norm() < 1e-12);
        let down = Ray::new(Point3::new(3.0, 0.0, 3.0), -Vec3::y(), 0.0);
        assert_eq!(
            world.intersect(&down, 0.0, f64::INFINITY).unwrap().material,
            4
        );
        assert!(world.occluded(&down, 0.0, 2.0));
        assert!(!world.occluded(&down, 0.0, 0.5));
        assert!((world.bounds().max.x - 11.0).abs() < 1e-12);
    }

    /// Spheres (some moving, some transformed), triangles and planes.
    fn random_primitives(rng: &mut crate::rng::Rng, count: usize) -> Vec<Primitive> {
        use crate::geometry::{Plane, Sphere, Triangle};
        let mut point = |scale: f64| {
            Vec3::new(rng.next_f64(), rng.next_f64(), rng.next_f64()) * scale
                - Vec3::repeat(scale / 2.0)
        };
        let mut primitives = Vec::new();
        for i in 0..count {
            let center = point(10.0);
            let (shape, transform) = match i % 4 {
                0 => (Shape::Sphere(Sphere::new(center, 1.0, Vec3::zeros())), None),
                1 => (Shape::Sphere(Sphere::new(center, 0.5, point(2.0))), None),
                2 => {
                    let matrix = Matrix::new_translation(&center) * Matrix::new_scaling(0.7);
                    let inverse = matrix.try_inverse().expect("invertible");
                    let sphere = Sphere::new(Point3::zeros(), 1.0, Vec3::zeros());
                    let transform = Box::new(crate::geometry::Transform::new(matrix, inverse));
                    (Shape::Sphere(sphere), Some(transform))
                }
                _ => {
                    let triangle =
                        Triangle::new([center, center + point(3.0), center + point(3.0)]);
                    (Shape::Triangle(triangle), None)
                }
            };
            primitives.push(Primitive {
                shape,
                transform,
                material: i,
                face_materials: None,
            });
        }
        for axis in 0..3 {
            let mut normal = Vec3::zeros();
            normal[axis] = 1.0;
            let plane = Plane::new(normal, 8.0).expect("valid plane");
            primitives.push(Primitive {
                shape: Shape::Plane(plane),
                transform: None,
                material: 100 + axis,
                face_materials: None,
            });
        }
        primitives
    }

    #[test]
    fn small_and_large_worlds_equal_brute_force() {
        let mut rng = crate::rng::Rng::new(11, 12);
        // 6 bounded primitives: tested linearly; 40: through the BVH.
        for count in [6, 40] {
            let world = World::from_primitives(random_primitives(&mut rng, count));
            assert_eq!(world.bounded.is_empty(), count <= LINEAR_LIMIT);
            let mut hits = 0;
            for _ in 0..3000 {
                let origin = Vec3::new(rng.next_f64(), rng.next_f64(), rng.next_f64()) * 12.0
                    - Vec3::repeat(6.0);
                let direction =
                    Vec3::new(rng.next_f64(), rng.next_f64(), rng.next_f64()) - Vec3::repeat(0.5);
                let ray = Ray::new(origin, direction.normalize(), rng.next_f64());
                let t_max = 4.0 + 20.0 * rng.next_f64();
                let brute = world
                    .primitives()
                    .iter()
                    .enumerate()
                    .filter_map(|(i, p)| p.intersect(&ray, 0.0, t_max).map(|hit| (i, hit.t)))
                    .min_by(|a, b| a.1.total_cmp(&b.1));
                let found = world.intersect(&ray, 0.0, t_max);
                assert_eq!(found.map(|h| h.primitive), brute.map(|b| b.0));
                if let (Some(hit), Some((_, t))) = (found, brute) {
                    assert!((hit.t - t).abs() <= 1e-9 * t.max(1.0));
                    hits += 1;
                }
                assert_eq!(world.occluded(&ray, 0.0, t_max), brute.is_some());
            }
            assert!(hits > 500, "{hits} hits of 3000");
        }
    }

    #[test]
    fn world_is_send_and_sync() {
        fn check<T: Send + Sync>() {}
        check::<World>();
    }
}
