//! One shape of the world with its material and optional transform: the
//! object-space queries moved to world space.

use std::sync::Arc;

use crate::geometry::{Intersection, Shape, SphereTest, SurfaceHit, Transform};
use crate::math::{Aabb, Ray};
use crate::scene::model::OWN_MATERIAL;

/// One shape with its material and optional object-to-world transform.
#[derive(Clone, Debug)]
pub struct Primitive {
    pub shape: Shape,
    /// `None` for the identity.
    pub transform: Option<Box<Transform>>,
    pub material: usize,
    /// A mesh's per-triangle materials (from its `.mtl`; [`OWN_MATERIAL`]
    /// for `material`), indexed by the hit's element. `None`: `material`
    /// everywhere.
    pub face_materials: Option<Arc<[u32]>>,
}

impl Primitive {
    /// Whether rays leave this primitive's hits from the hit point itself
    /// (see [`WorldHit::leaves_from_point`](super::WorldHit)).
    #[inline]
    pub fn leaves_from_point(&self) -> bool {
        matches!(
            &self.shape,
            Shape::Sphere(sphere) if matches!(sphere.test, SphereTest::Cambrian | SphereTest::Cav)
        )
    }

    /// The material of element `element` (a mesh's triangle; 0 for other shapes).
    #[inline]
    pub fn material_of(&self, element: u32) -> usize {
        match self
            .face_materials
            .as_ref()
            .and_then(|faces| faces.get(element as usize))
        {
            Some(&m) if m != OWN_MATERIAL => m as usize,
            _ => self.material,
        }
    }

    /// Every material of the primitive (its own, and its triangles').
    pub fn materials(&self) -> impl Iterator<Item = usize> + '_ {
        let faces = self.face_materials.as_deref().unwrap_or(&[]);
        std::iter::once(self.material).chain(
            faces
                .iter()
                .filter(|&&m| m != OWN_MATERIAL)
                .map(|&m| m as usize),
        )
    }

    /// The hit of `ray` with `t_min < t < t_max`. A sphere under cav's test
    /// measures its `t` along the normalised direction (see
    /// [`cav_sphere::intersect`](crate::geometry::cav_sphere::intersect)); a
    /// transformed one is brought back to the ray's own units, as cav's
    /// transforms do.
    #[inline]
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Intersection> {
        match &self.transform {
            None => self.shape.intersect(ray, t_min, t_max),
            Some(transform) => match &self.shape {
                Shape::Sphere(sphere) if sphere.test == SphereTest::Cav => {
                    let local = transform.ray_to_object(ray);
                    let length = local.direction.norm();
                    let mut hit = self
                        .shape
                        .intersect(&local, t_min * length, t_max * length)?;
                    hit.t /= length;
                    Some(hit)
                }
                _ => self
                    .shape
                    .intersect(&transform.ray_to_object(ray), t_min, t_max),
            },
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
    /// (uv and surface derivatives only `with_uv`, see [`Shape::surface`]).
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
