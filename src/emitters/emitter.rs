//! One entry of the emitter table: a shape that light sampling picks (see
//! the shape contract's emitter half, `geometry::shape_sampling`), in world
//! space, with its emission and, for a static sphere, the planes that cut
//! it (`cut`). A transformed shape is kept as the world-space shape of its
//! kind ([`Shape::to_world`]); a transformed disk, whose image is an
//! ellipse, samples in its own space and maps the point through its
//! transform (a uniform area density stays uniform under an affine map).

use super::cut::{Cap, CutPlane, Cuts};
use crate::color::Color;
use crate::geometry::surface_samples::{area_to_solid_angle, from_area_sample};
use crate::geometry::{Shape, ShapeSample, Sphere, Transform};
use crate::math::{Point3, Vec3, transform_point};

#[derive(Clone, Debug)]
pub struct Emitter {
    /// In world space, or in its own space under `transform`.
    shape: Shape,
    /// The map from the shape's space to world space (a transformed disk).
    transform: Option<Box<Transform>>,
    /// World-space area.
    area: f64,
    /// The world's planes that cut a static sphere.
    cuts: Cuts,
    pub emission: Color,
}

impl Emitter {
    /// The entry of `shape` (in its own space, under `transform`) emitting
    /// `emission`, cut by the world's `planes`; `None` for a shape that is
    /// not sampled (planes, surfaces of revolution, ellipsoids).
    pub fn new(
        shape: &Shape,
        transform: Option<&Transform>,
        planes: &[CutPlane],
        emission: Color,
    ) -> Option<Emitter> {
        if !shape.is_sampled() {
            return None;
        }
        let (shape, transform) = match transform {
            None => (shape.clone(), None),
            Some(t) => match shape.to_world(t) {
                Some(world) => (world, None),
                None if matches!(shape, Shape::Disk(_)) => {
                    (shape.clone(), Some(Box::new(t.clone())))
                }
                None => return None,
            },
        };
        let area = match (&shape, &transform) {
            (Shape::Disk(disk), Some(t)) => disk.area_under(Some(t)),
            _ => shape.area(),
        };
        let cuts = match &shape {
            Shape::Sphere(s) if s.motion == Vec3::zeros() => Cuts::new(&s.center, s.radius, planes),
            _ => Cuts::NONE,
        };
        Some(Emitter {
            shape,
            transform,
            area,
            cuts,
            emission,
        })
    }

    /// A triangle of a mesh, already in world space (degenerate ones too:
    /// triangle `k` of a mesh is its `k`-th entry).
    pub fn triangle(vertices: [Point3; 3], emission: Color) -> Emitter {
        let shape = Shape::Triangle(crate::geometry::Triangle::new(vertices));
        Emitter {
            area: shape.area(),
            shape,
            transform: None,
            cuts: Cuts::NONE,
            emission,
        }
    }

    /// World-space surface area.
    pub fn area(&self) -> f64 {
        self.area
    }

    /// The sphere, when the entry is one (in world space).
    pub(super) fn sphere(&self) -> Option<&Sphere> {
        match &self.shape {
            Shape::Sphere(s) => Some(s),
            _ => None,
        }
    }

    /// The cap of a cut sphere that `reference` can reach (see
    /// [`Cuts::cap`]), when the sphere is static and cut.
    pub(super) fn cap(&self, reference: &Point3) -> Option<(&Sphere, Cap)> {
        let sphere = self.sphere()?;
        if self.cuts.is_empty() {
            return None;
        }
        Some((
            sphere,
            self.cuts.cap(&sphere.center, sphere.radius, reference)?,
        ))
    }

    /// The area that shadow rays from `reference` can reach, past `planes`
    /// (infinite and opaque, as every plane is to a shadow ray): none when
    /// the shape lies wholly beyond one of them, a cut sphere's cap on that
    /// side (see [`Cuts::cap`]), else [`Emitter::area`].
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
        match self.cap(reference) {
            Some((sphere, cap)) => cap.area(sphere.radius),
            None => self.area,
        }
    }

    /// The largest `direction . p` over the points `p` of the entry.
    fn extent_along(&self, direction: &Vec3) -> Option<f64> {
        match &self.transform {
            None => self.shape.extent_along(direction),
            // In the shape's space, along the direction pulled back.
            Some(t) => {
                let local = t.matrix.fixed_view::<3, 3>(0, 0).transpose() * direction;
                let offset = direction.dot(&transform_point(&t.matrix, &Point3::zeros()));
                Some(self.shape.extent_along(&local)? + offset)
            }
        }
    }

    /// A uniform point on the surface at shutter time `time` (world space),
    /// and its unit normal.
    pub fn sample_area(&self, time: f64, u: [f64; 2]) -> Option<(Point3, Vec3)> {
        let (point, normal) = self.shape.sample_area(time, u)?;
        match &self.transform {
            None => Some((point, normal)),
            Some(t) => Some((
                transform_point(&t.matrix, &point),
                (t.normal_matrix * normal).try_normalize(0.0)?,
            )),
        }
    }

    /// A point on the entry for the uniform pair `u`, as seen from
    /// `reference` at shutter time `time`; `None` when the sample carries
    /// no density. A cut sphere is sampled on the cap `reference` reaches.
    pub fn sample(&self, reference: &Point3, time: f64, u: [f64; 2]) -> Option<ShapeSample> {
        if let Some((sphere, cap)) = self.cap(reference)
            && sphere.cone(time, reference).is_some()
        {
            let normal = cap.sample(u);
            let point = sphere.center + normal * sphere.radius;
            if normal.dot(&(reference - point)) <= 0.0 {
                // Facing away from `reference`: hidden by the sphere itself.
                return None;
            }
            return from_area_sample(reference, &point, &normal, cap.area(sphere.radius));
        }
        match &self.transform {
            None => self.shape.sample(reference, time, u),
            Some(_) => {
                let (point, normal) = self.sample_area(time, u)?;
                from_area_sample(reference, &point, &normal, self.area)
            }
        }
    }

    /// The solid-angle density with which [`Emitter::sample`] from
    /// `reference` produces `point` (a point on the entry with unit normal
    /// `normal`, first along its ray from `reference`).
    pub fn pdf(&self, reference: &Point3, time: f64, point: &Point3, normal: &Vec3) -> f64 {
        if let Some((sphere, cap)) = self.cap(reference)
            && sphere.cone(time, reference).is_some()
        {
            return if cap.contains(&((point - sphere.center) / sphere.radius)) {
                area_to_solid_angle(reference, point, normal, cap.area(sphere.radius))
            } else {
                0.0
            };
        }
        match &self.transform {
            None => self.shape.pdf(reference, time, point, normal),
            Some(_) => area_to_solid_angle(reference, point, normal, self.area),
        }
    }

    /// A point and a normal (not unit) that describe a planar entry as a
    /// flat light from afar (world space); `None` for spheres.
    pub(super) fn flat_frame(&self) -> Option<(Point3, Vec3)> {
        let (point, normal) = self.shape.flat_frame()?;
        match &self.transform {
            None => Some((point, normal)),
            Some(t) => Some((transform_point(&t.matrix, &point), t.normal_matrix * normal)),
        }
    }
}
