//! The closed set of shapes, dispatched by `match` (no trait objects per ray).

use std::sync::Arc;

use super::{
    CavRevolution, Disk, Intersection, Mesh, Plane, Rectangle, Revolution, SeededRevolution,
    Sphere, SurfaceHit, Triangle,
};
use crate::math::{Aabb, Ray};

#[derive(Clone, Debug)]
pub enum Shape {
    Sphere(Sphere),
    Plane(Plane),
    Triangle(Triangle),
    Rectangle(Rectangle),
    Disk(Disk),
    /// Shared by every instance of the same mesh data.
    Mesh {
        mesh: Arc<Mesh>,
        smooth: bool,
    },
    Revolution(Arc<Revolution>),
    /// A look's surface of revolution found from its tessellation (yao-jz's).
    SeededRevolution(Arc<SeededRevolution>),
    /// CaveSpiderLZJ's surface of revolution: its mesh, then its steps.
    CavRevolution(Arc<CavRevolution>),
}

impl Shape {
    #[inline]
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Intersection> {
        match self {
            Shape::Sphere(s) => s.intersect(ray, t_min, t_max),
            Shape::Plane(s) => s.intersect(ray, t_min, t_max),
            Shape::Triangle(s) => s.intersect(ray, t_min, t_max),
            Shape::Rectangle(s) => s.intersect(ray, t_min, t_max),
            Shape::Disk(s) => s.intersect(ray, t_min, t_max),
            Shape::Mesh { mesh, .. } => mesh.intersect(ray, t_min, t_max),
            Shape::Revolution(s) => s.intersect(ray, t_min, t_max),
            Shape::SeededRevolution(s) => s.intersect(ray, t_min, t_max),
            Shape::CavRevolution(s) => s.intersect(ray, t_min, t_max),
        }
    }

    /// Whether anything of the shape lies on the ray within `(t_min, t_max)`.
    #[inline]
    pub fn occluded(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        match self {
            Shape::Mesh { mesh, .. } => mesh.occluded(ray, t_min, t_max),
            _ => self.intersect(ray, t_min, t_max).is_some(),
        }
    }

    /// The surface at a hit. `with_uv: false` lets a shape skip texture
    /// coordinates and derivatives that nothing will read (a sphere's uv costs an
    /// atan2 and an asin); they are then zero.
    pub fn surface(&self, ray: &Ray, hit: &Intersection, with_uv: bool) -> SurfaceHit {
        match self {
            Shape::Sphere(s) if !with_uv => s.surface_without_uv(ray, hit),
            Shape::Sphere(s) => s.surface(ray, hit),
            Shape::Plane(s) => s.surface(ray, hit),
            Shape::Triangle(s) => s.surface(ray, hit),
            Shape::Rectangle(s) => s.surface(ray, hit),
            Shape::Disk(s) => s.surface(ray, hit),
            Shape::Mesh { mesh, smooth } => mesh.surface(ray, hit, *smooth),
            Shape::Revolution(s) => s.surface(ray, hit),
            Shape::SeededRevolution(s) => s.surface(ray, hit),
            Shape::CavRevolution(s) => s.surface(ray, hit),
        }
    }

    /// Object-space bounds; `None` for unbounded shapes (planes) and empty meshes.
    pub fn bounds(&self) -> Option<Aabb> {
        match self {
            Shape::Sphere(s) => Some(s.bounds()),
            Shape::Plane(_) => None,
            Shape::Triangle(s) => Some(s.bounds()),
            Shape::Rectangle(s) => Some(s.bounds()),
            Shape::Disk(s) => Some(s.bounds()),
            Shape::Mesh { mesh, .. } => mesh.bounds(),
            Shape::Revolution(s) => Some(s.bounds()),
            Shape::SeededRevolution(s) => s.bounds(),
            Shape::CavRevolution(s) => s.bounds(),
        }
    }

    pub fn is_bounded(&self) -> bool {
        !matches!(self, Shape::Plane(_))
    }
}
