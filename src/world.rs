//! The renderable world: the scene's object tree flattened into primitives with
//! a BVH over the bounded ones. Answers the two ray queries of the integrators.

use std::collections::HashMap;
use std::sync::Arc;

use crate::accel::Bvh;
use crate::geometry::{
    Disk, Intersection, Mesh, Plane, Rectangle, Revolution, Shape, Sphere, SurfaceHit, Transform,
    Triangle,
};
use crate::math::{Aabb, Point3, Ray, Vec3, offset_origin};
use crate::scene::model::{Object, Scene};

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
    /// Unit tangent along increasing u (for normal maps).
    pub tangent: Vec3,
    pub uv: [f64; 2],
    pub uv_mapping: UvMapping,
    pub material: usize,
    /// Index of the primitive in the world (see [`World::primitive`]).
    pub primitive: usize,
    /// Element within the primitive (triangle of a mesh), else 0.
    pub element: u32,
}

impl WorldHit {
    /// Origin for a ray leaving the hit in `direction` (either side of the surface):
    /// the point offset along the geometric normal by [`offset_origin`]. Rays
    /// spawned from it do not re-hit this surface, even with `t_min = 0`.
    pub fn spawn_origin(&self, direction: &Vec3) -> Point3 {
        offset_origin(&self.point, &self.geometric_normal, direction)
    }

    /// A ray leaving the hit in `direction` at shutter time `time`.
    pub fn spawn_ray(&self, direction: Vec3, time: f64) -> Ray {
        Ray::new(self.spawn_origin(&direction), direction, time)
    }
}

/// One shape with its material and optional object-to-world transform.
#[derive(Clone, Debug)]
pub struct Primitive {
    pub shape: Shape,
    /// `None` for the identity.
    pub transform: Option<Box<Transform>>,
    pub material: usize,
}

impl Primitive {
    #[inline]
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Intersection> {
        match &self.transform {
            None => self.shape.intersect(ray, t_min, t_max),
            Some(transform) => self
                .shape
                .intersect(&transform.ray_to_object(ray), t_min, t_max),
        }
    }

    #[inline]
    pub fn occluded(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        match &self.transform {
            None => self.shape.occluded(ray, t_min, t_max),
            Some(transform) => self
                .shape
                .occluded(&transform.ray_to_object(ray), t_min, t_max),
        }
    }

    /// The world-space surface of a hit found by [`Primitive::intersect`]
    /// (uv and tangent only `with_uv`, see [`Shape::surface`]).
    pub fn surface(&self, ray: &Ray, hit: &Intersection, with_uv: bool) -> SurfaceHit {
        match &self.transform {
            None => self.shape.surface(ray, hit, with_uv),
            Some(transform) => {
                let local = self
                    .shape
                    .surface(&transform.ray_to_object(ray), hit, with_uv);
                transform.surface_to_world(&local)
            }
        }
    }

    /// World-space bounds; `None` when unbounded.
    pub fn bounds(&self) -> Option<Aabb> {
        let local = self.shape.bounds()?;
        Some(match &self.transform {
            None => local,
            Some(transform) => transform.bounds_to_world(&local),
        })
    }
}

/// The flattened scene geometry. Immutable after `build`, hence `Send + Sync`.
pub struct World {
    primitives: Vec<Primitive>,
    /// Indices of the bounded primitives, in BVH leaf order of `bvh`.
    bounded: Vec<u32>,
    /// Indices of the unbounded primitives (planes), tested linearly.
    unbounded: Vec<u32>,
    bvh: Bvh,
    /// Per material: whether a texture or normal map reads uv and tangents.
    /// Empty: compute them always.
    needs_uv: Vec<bool>,
}

impl World {
    /// Flattens the object tree: nested transforms are composed (identities are
    /// dropped), each distinct mesh (`Arc` identity) gets one triangle BVH shared by
    /// its instances, and a top-level BVH is built over the bounded primitives.
    /// Degenerate shapes (zero radius, zero normal, zero area, unusable profiles)
    /// are dropped.
    pub fn build(scene: &Scene) -> World {
        let mut builder = Builder::default();
        builder.visit(&scene.root, None);
        let mut world = World::from_primitives(builder.primitives);
        world.needs_uv = scene
            .materials
            .iter()
            .map(|m| m.texture.is_some() || m.normal_map.is_some())
            .collect();
        world
    }

    /// A world over already made primitives.
    pub fn from_primitives(primitives: Vec<Primitive>) -> World {
        let mut bounded = Vec::new();
        let mut unbounded = Vec::new();
        let mut boxes = Vec::new();
        for (index, primitive) in primitives.iter().enumerate() {
            if primitive.shape.is_bounded() {
                if let Some(b) = primitive.bounds() {
                    bounded.push(index as u32);
                    boxes.push(b);
                }
            } else {
                unbounded.push(index as u32);
            }
        }
        let bvh = Bvh::build(&boxes);
        World {
            primitives,
            bounded,
            unbounded,
            bvh,
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
        for &index in &self.unbounded {
            let index = index as usize;
            if let Some(hit) = self.primitives[index].intersect(ray, t_min, limit) {
                limit = hit.t;
                best = Some((index, hit));
            }
        }
        self.bvh.traverse(ray, t_min, limit, |slot, limit| {
            let index = self.bounded[slot] as usize;
            let hit = self.primitives[index].intersect(ray, t_min, limit)?;
            best = Some((index, hit));
            Some(hit.t)
        });
        let (index, hit) = best?;
        let primitive = &self.primitives[index];
        let with_uv = self
            .needs_uv
            .get(primitive.material)
            .copied()
            .unwrap_or(true);
        let surface = primitive.surface(ray, &hit, with_uv);
        debug_assert!(surface.point.iter().all(|c| c.is_finite()));
        Some(WorldHit {
            t: hit.t,
            point: surface.point,
            geometric_normal: surface.geometric_normal,
            shading_normal: surface.shading_normal,
            tangent: surface.tangent,
            uv: surface.uv,
            uv_mapping: surface.uv_mapping,
            material: primitive.material,
            primitive: index,
            element: hit.index,
        })
    }

    /// Whether anything lies on the ray with `t_min < t < t_max`.
    pub fn occluded(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        self.unbounded
            .iter()
            .any(|&index| self.primitives[index as usize].occluded(ray, t_min, t_max))
            || self.bvh.any(ray, t_min, t_max, |slot| {
                self.primitives[self.bounded[slot] as usize].occluded(ray, t_min, t_max)
            })
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
        self.bvh.bounds()
    }
}

#[derive(Default)]
struct Builder {
    primitives: Vec<Primitive>,
    /// One geometry mesh per distinct `MeshData` allocation.
    meshes: HashMap<*const crate::scene::model::MeshData, Arc<Mesh>>,
}

impl Builder {
    fn visit(&mut self, object: &Object, transform: Option<&Transform>) {
        let shape = match object {
            Object::Group(children) => {
                for child in children {
                    self.visit(child, transform);
                }
                return;
            }
            Object::Transform {
                matrix,
                inverse,
                child,
            } => {
                let local = Transform::new(*matrix, *inverse);
                let combined = match transform {
                    Some(parent) => parent.compose(&local),
                    None => local,
                };
                self.visit(child, Some(&combined));
                return;
            }
            Object::Sphere {
                center,
                radius,
                motion,
                ..
            } => (*radius != 0.0 && radius.is_finite())
                .then(|| Shape::Sphere(Sphere::new(*center, *radius, *motion))),
            Object::Plane { normal, offset, .. } => Plane::new(*normal, *offset).map(Shape::Plane),
            Object::Triangle { vertices, .. } => Some(Shape::Triangle(Triangle::new(*vertices))),
            Object::Rectangle {
                origin,
                edge_u,
                edge_v,
                ..
            } => Rectangle::new(*origin, *edge_u, *edge_v).map(Shape::Rectangle),
            Object::Disk {
                center,
                normal,
                radius,
                ..
            } => Disk::new(*center, *normal, *radius).map(Shape::Disk),
            Object::Mesh { mesh, smooth, .. } => {
                let shared = self
                    .meshes
                    .entry(Arc::as_ptr(mesh))
                    .or_insert_with(|| Arc::new(Mesh::new(Arc::clone(mesh))));
                Some(Shape::Mesh {
                    mesh: Arc::clone(shared),
                    smooth: *smooth,
                })
            }
            Object::Revolution { profile, .. } => {
                Revolution::new(profile).map(|r| Shape::Revolution(Arc::new(r)))
            }
        };
        let material = object.material().unwrap_or(0);
        if let Some(shape) = shape {
            let transform = transform
                .filter(|t| !t.is_identity())
                .map(|t| Box::new(t.clone()));
            self.primitives.push(Primitive {
                shape,
                transform,
                material,
            });
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::math::Matrix;
    use crate::scene::model::MeshData;

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

    #[test]
    fn world_is_send_and_sync() {
        fn check<T: Send + Sync>() {}
        check::<World>();
    }
}
