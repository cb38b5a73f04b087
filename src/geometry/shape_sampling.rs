//! The emitter half of the shape contract: area, uniform points by area,
//! points seen from a reference point with their solid-angle density, and
//! the shape's extent along a direction, for the shapes that light
//! sampling picks (spheres, triangles, parallelograms, disks). Planes,
//! surfaces of revolution and whole meshes answer none (a mesh emits
//! triangle by triangle). A shape under a transform samples in world
//! space: [`Shape::to_world`] gives the transformed shape where one of the
//! same kind exists (a sphere under a similarity, a triangle, a
//! parallelogram); a disk samples in its own space and maps the point
//! through its transform (see `emitters::emitter`).

use std::f64::consts::PI;

use super::surface_samples::{ShapeSample, area_to_solid_angle, concentric_disk, from_area_sample};
use super::{Disk, Rectangle, Shape, Transform, Triangle};
use crate::math::{Point3, Vec3, orthonormal_basis, transform_point, transform_vector};

/// Relative tolerance of the similarity test for transformed spheres.
const SIMILARITY_TOLERANCE: f64 = 1e-9;

impl Triangle {
    pub fn area(&self) -> f64 {
        let [a, b, c] = self.vertices;
        0.5 * (b - a).cross(&(c - a)).norm()
    }

    /// A uniform point (square-root barycentrics) and the unit normal.
    pub fn sample_area(&self, u: [f64; 2]) -> (Point3, Vec3) {
        let [a, b, c] = self.vertices;
        let s = u[0].sqrt();
        let (b1, b2) = (s * (1.0 - u[1]), s * u[1]);
        let point = a * (1.0 - b1 - b2) + b * b1 + c * b2;
        (point, (b - a).cross(&(c - a)).normalize())
    }
}

impl Rectangle {
    pub fn area(&self) -> f64 {
        self.edge_u.cross(&self.edge_v).norm()
    }

    pub fn sample_area(&self, u: [f64; 2]) -> (Point3, Vec3) {
        (
            self.origin + self.edge_u * u[0] + self.edge_v * u[1],
            self.edge_u.cross(&self.edge_v).normalize(),
        )
    }
}

impl Disk {
    /// Its two radii, orthogonal, in the plane of the disk.
    fn axes(&self) -> (Vec3, Vec3) {
        let (e1, e2) = orthonormal_basis(&self.normal);
        (e1 * self.radius, e2 * self.radius)
    }

    /// The area of the disk under `transform` (an ellipse's, for a
    /// non-uniform scale).
    pub fn area_under(&self, transform: Option<&Transform>) -> f64 {
        let (axis_u, axis_v) = self.axes();
        let (axis_u, axis_v) = match transform {
            Some(t) => (
                transform_vector(&t.matrix, &axis_u),
                transform_vector(&t.matrix, &axis_v),
            ),
            None => (axis_u, axis_v),
        };
        PI * axis_u.cross(&axis_v).norm()
    }

    pub fn sample_area(&self, u: [f64; 2]) -> (Point3, Vec3) {
        let (axis_u, axis_v) = self.axes();
        let (x, y) = concentric_disk(u);
        (
            self.center + axis_u * x + axis_v * y,
            axis_u.cross(&axis_v).normalize(),
        )
    }
}

impl Shape {
    /// The same shape in world space under `transform`, where one of its
    /// kind exists: a sphere under a similarity, a triangle, a
    /// parallelogram; `None` otherwise (a disk, an ellipsoid, and the
    /// shapes that are not sampled).
    pub fn to_world(&self, transform: &Transform) -> Option<Shape> {
        let point = |p: &Point3| transform_point(&transform.matrix, p);
        let vector = |v: &Vec3| transform_vector(&transform.matrix, v);
        match self {
            Shape::Sphere(sphere) => {
                let scale = similarity_scale(transform)?;
                let mut world = *sphere;
                world.center = point(&sphere.center);
                world.motion = vector(&sphere.motion);
                world.radius = sphere.radius * scale;
                Some(Shape::Sphere(world))
            }
            Shape::Triangle(triangle) => Some(Shape::Triangle(Triangle::new(
                triangle.vertices.map(|p| point(&p)),
            ))),
            Shape::Rectangle(r) => {
                Rectangle::new(point(&r.origin), vector(&r.edge_u), vector(&r.edge_v))
                    .map(Shape::Rectangle)
            }
            _ => None,
        }
    }

    /// Whether light sampling can pick a point on it (see the module).
    pub fn is_sampled(&self) -> bool {
        matches!(
            self,
            Shape::Sphere(_) | Shape::Triangle(_) | Shape::Rectangle(_) | Shape::Disk(_)
        )
    }

    /// Surface area; 0 for the shapes that are not sampled.
    pub fn area(&self) -> f64 {
        match self {
            Shape::Sphere(s) => s.area(),
            Shape::Triangle(s) => s.area(),
            Shape::Rectangle(s) => s.area(),
            Shape::Disk(s) => s.area_under(None),
            _ => 0.0,
        }
    }

    /// A uniform point on the surface at shutter time `time`, and its unit
    /// normal; `None` for the shapes that are not sampled.
    pub fn sample_area(&self, time: f64, u: [f64; 2]) -> Option<(Point3, Vec3)> {
        match self {
            Shape::Sphere(s) => Some(s.sample_area(time, u)),
            Shape::Triangle(s) => Some(s.sample_area(u)),
            Shape::Rectangle(s) => Some(s.sample_area(u)),
            Shape::Disk(s) => Some(s.sample_area(u)),
            _ => None,
        }
    }

    /// A point on the shape for the uniform pair `u`, as seen from
    /// `reference` at shutter time `time`; `None` when the sample carries
    /// no density.
    pub fn sample(&self, reference: &Point3, time: f64, u: [f64; 2]) -> Option<ShapeSample> {
        match self {
            Shape::Sphere(s) => s.sample_from(reference, time, u),
            _ => {
                let (point, normal) = self.sample_area(time, u)?;
                from_area_sample(reference, &point, &normal, self.area())
            }
        }
    }

    /// The solid-angle density with which [`Shape::sample`] from
    /// `reference` produces `point` (a point on the shape with unit normal
    /// `normal`, first along its ray from `reference`).
    pub fn pdf(&self, reference: &Point3, time: f64, point: &Point3, normal: &Vec3) -> f64 {
        match self {
            Shape::Sphere(s) => s.pdf_from(reference, time, point, normal),
            _ => area_to_solid_angle(reference, point, normal, self.area()),
        }
    }

    /// The largest `direction . p` over the points `p` of the shape (`None`
    /// for a moving sphere, which sweeps a region over the shutter, and for
    /// the shapes that are not sampled).
    pub fn extent_along(&self, direction: &Vec3) -> Option<f64> {
        match self {
            Shape::Sphere(s) => {
                (s.motion == Vec3::zeros()).then(|| direction.dot(&s.center) + s.radius)
            }
            Shape::Triangle(t) => Some(
                t.vertices
                    .iter()
                    .map(|v| direction.dot(v))
                    .fold(f64::MIN, f64::max),
            ),
            Shape::Rectangle(r) => {
                let (u, v) = (direction.dot(&r.edge_u), direction.dot(&r.edge_v));
                Some(direction.dot(&r.origin) + u.max(0.0) + v.max(0.0))
            }
            Shape::Disk(d) => {
                let (axis_u, axis_v) = d.axes();
                let (u, v) = (direction.dot(&axis_u), direction.dot(&axis_v));
                Some(direction.dot(&d.center) + u.hypot(v))
            }
            _ => None,
        }
    }

    /// A point of the surface and a normal (not unit) that describe it as
    /// a flat light from afar: a triangle's centroid, a parallelogram's or
    /// disk's centre; `None` for the others.
    pub fn flat_frame(&self) -> Option<(Point3, Vec3)> {
        match self {
            Shape::Triangle(t) => {
                let [a, b, c] = t.vertices;
                Some(((a + b + c) / 3.0, (b - a).cross(&(c - a))))
            }
            Shape::Rectangle(r) => Some((
                r.origin + (r.edge_u + r.edge_v) * 0.5,
                r.edge_u.cross(&r.edge_v),
            )),
            Shape::Disk(d) => {
                let (axis_u, axis_v) = d.axes();
                Some((d.center, axis_u.cross(&axis_v)))
            }
            _ => None,
        }
    }
}

/// `s` when the linear part of `transform` is `s` times a rotation (or
/// reflection), else `None`.
fn similarity_scale(transform: &Transform) -> Option<f64> {
    let linear = transform.matrix.fixed_view::<3, 3>(0, 0).into_owned();
    let gram = linear.transpose() * linear;
    let scale_squared = gram.trace() / 3.0;
    if !(scale_squared > 0.0 && scale_squared.is_finite()) {
        return None;
    }
    let off = (gram - nalgebra::Matrix3::identity() * scale_squared).amax();
    (off <= SIMILARITY_TOLERANCE * scale_squared).then(|| scale_squared.sqrt())
}
