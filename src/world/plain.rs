//! The plain shapes of a world, tested inline in tight loops: untransformed
//! planes always, untransformed spheres when the world is small enough to go
//! without a BVH. The walls and balls of most course scenes are exactly these,
//! and a loop over a few of them costs less than the dispatch and box tests
//! of the general path.

use crate::geometry::{Intersection, Plane, Sphere, SphereTest};

use super::lanes::{Lanes, PlaneLanes, RayLanes, SphereLanes, groups};
use crate::math::Ray;

/// Shapes with the indices of their primitives in the world.
#[derive(Clone, Debug, Default)]
pub struct PlainShapes {
    planes: Vec<(Plane, u32)>,
    /// Planes of W-Solaris's and yangjunx21's single-precision tests, by
    /// their own `intersect`.
    other_planes: Vec<(Plane, u32)>,
    /// Spheres of the robust test.
    spheres: Vec<(Sphere, u32)>,
    /// Spheres of another test (a look's), by their own `intersect`.
    other_spheres: Vec<(Sphere, u32)>,
    /// `planes` and `spheres` in groups of four, tested a group at a time
    /// (see `lanes`); built by [`PlainShapes::pack`].
    plane_groups: Vec<PlaneLanes>,
    sphere_groups: Vec<SphereLanes>,
}

impl PlainShapes {
    pub fn push_plane(&mut self, plane: Plane, primitive: usize) {
        if plane.single_precision || plane.single_precision_two_sided {
            self.other_planes.push((plane, primitive as u32));
        } else {
            self.planes.push((plane, primitive as u32));
        }
    }

    pub fn push_sphere(&mut self, sphere: Sphere, primitive: usize) {
        if sphere.test == SphereTest::Robust {
            self.spheres.push((sphere, primitive as u32));
        } else {
            self.other_spheres.push((sphere, primitive as u32));
        }
    }

    /// Packs the planes and robust spheres pushed so far into their groups;
    /// the world calls it once all shapes are in.
    pub fn pack(&mut self) {
        self.plane_groups = groups(&self.planes, PlaneLanes::new);
        self.sphere_groups = groups(&self.spheres, SphereLanes::new);
    }

    /// Lowers `limit` to the nearest hit in `(t_min, limit)` and records it
    /// (primitive index, intersection) in `best`: the planes, then the
    /// other planes and spheres, then the robust spheres, each shape taking
    /// the hit only when strictly nearer.
    #[inline]
    pub fn nearest(
        &self,
        ray: &Ray,
        t_min: f64,
        limit: &mut f64,
        best: &mut Option<(usize, Intersection)>,
    ) {
        let lanes = RayLanes::new(ray);
        for group in &self.plane_groups {
            if let Some((index, t)) = group.nearest(&lanes, t_min, *limit) {
                *limit = t;
                *best = Some((index as usize, Intersection::new(t, 0.0, 0.0)));
            }
        }
        for (plane, index) in &self.other_planes {
            if let Some(hit) = plane.intersect(ray, t_min, *limit) {
                *limit = hit.t;
                *best = Some((*index as usize, hit));
            }
        }
        for (sphere, index) in &self.other_spheres {
            if let Some(hit) = sphere.intersect(ray, t_min, *limit) {
                *limit = hit.t;
                *best = Some((*index as usize, hit));
            }
        }
        for group in &self.sphere_groups {
            if let Some((index, t)) = group.nearest(&lanes, t_min, *limit) {
                *limit = t;
                *best = Some((index as usize, Intersection::new(t, 0.0, 0.0)));
            }
        }
    }

    /// Whether any shape lies on the ray within `(t_min, t_max)`: the
    /// spheres first, which block shadow rays far more often than planes.
    #[inline]
    pub fn any(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        let lanes = RayLanes::new(ray);
        self.sphere_groups
            .iter()
            .any(|group| group.any(&lanes, t_min, t_max))
            || self
                .plane_groups
                .iter()
                .any(|group| group.any(&lanes, t_min, t_max))
            || self
                .other_planes
                .iter()
                .any(|(plane, _)| plane.intersect(ray, t_min, t_max).is_some())
            || self
                .other_spheres
                .iter()
                .any(|(sphere, _)| sphere.intersect(ray, t_min, t_max).is_some())
            || self
                .other_planes
                .iter()
                .any(|(plane, _)| plane.intersect(ray, t_min, t_max).is_some())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::{Point3, Vec3};
    use crate::rng::Rng;

    /// The scalar loop the groups replace: every shape's own test in
    /// order, each hit taken only when strictly nearer.
    fn nearest_one_by_one(
        shapes: &PlainShapes,
        ray: &Ray,
        t_min: f64,
        t_max: f64,
    ) -> Option<(usize, f64)> {
        let mut best = None;
        let mut limit = t_max;
        for (plane, index) in &shapes.planes {
            if let Some(hit) = plane.intersect(ray, t_min, limit) {
                limit = hit.t;
                best = Some((*index as usize, hit.t));
            }
        }
        for (sphere, index) in &shapes.spheres {
            if let Some(hit) = sphere.intersect(ray, t_min, limit) {
                limit = hit.t;
                best = Some((*index as usize, hit.t));
            }
        }
        best
    }

    #[test]
    fn groups_find_the_same_hit_as_the_shapes_own_tests() {
        let mut rng = Rng::new(3, 4);
        let mut random = move |scale: f64| {
            Vec3::new(rng.next_f64(), rng.next_f64(), rng.next_f64()) * scale
                - Vec3::repeat(scale / 2.0)
        };
        let (mut hits, mut rays) = (0, 0);
        for scene in 0..200 {
            let mut shapes = PlainShapes::default();
            let mut index = 0;
            // 0 to 6 planes and 0 to 9 spheres: empty, partial and full groups.
            for _ in 0..scene % 7 {
                let mut plane = Plane::new(random(2.0), random(6.0).x).unwrap();
                plane.one_sided = scene % 3 == 0;
                plane.accepts_zero = scene % 4 < 2;
                shapes.push_plane(plane, index);
                index += 1;
            }
            for _ in 0..scene % 10 {
                let sphere = Sphere::new(random(6.0), 0.1 + random(2.0).x.abs(), random(1.0));
                shapes.push_sphere(sphere, index);
                index += 1;
            }
            shapes.pack();
            for k in 0..100 {
                let origin: Point3 = random(8.0);
                let direction = if k % 10 == 0 {
                    Vec3::zeros()
                } else {
                    random(2.0)
                };
                let ray = Ray::new(origin, direction, 0.7);
                let t_min = if k % 3 == 0 { -0.5 } else { 0.0 };
                let t_max = if k % 4 == 0 { 3.0 } else { f64::INFINITY };
                let expected = nearest_one_by_one(&shapes, &ray, t_min, t_max);
                let mut limit = t_max;
                let mut best = None;
                shapes.nearest(&ray, t_min, &mut limit, &mut best);
                let got = best.map(|(index, hit)| (index, hit.t));
                // Planes to the bit; spheres within rounding (`Sphere::intersect`
                // orders the robust quadratic's operations a little differently).
                match (got, expected) {
                    (Some((i, t)), Some((j, u))) if i == j => {
                        let exact = i < scene % 7;
                        assert!(
                            if exact {
                                t.to_bits() == u.to_bits()
                            } else {
                                (t - u).abs() <= 1e-9 * u.abs().max(1.0)
                            },
                            "{t} vs {u} for shape {i}, {ray:?} in scene {scene}"
                        );
                    }
                    (None, None) => {}
                    other => panic!("{other:?} for {ray:?} in scene {scene}"),
                }
                assert_eq!(shapes.any(&ray, t_min, t_max), expected.is_some());
                hits += usize::from(expected.is_some());
                rays += 1;
            }
        }
        assert!(hits > rays / 4 && hits < rays * 9 / 10, "{hits} of {rays}");
    }

    #[test]
    fn groups_meet_a_plane_that_accepts_zero_from_a_point_on_it() {
        let ray = Ray::new(Point3::new(0.3, -4.0, 1.7), Vec3::new(0.2, -1.0, 0.1), 0.0);
        for accepts_zero in [false, true] {
            let mut shapes = PlainShapes::default();
            let mut plane = Plane::new(Vec3::y(), -4.0).unwrap();
            (plane.one_sided, plane.accepts_zero) = (true, accepts_zero);
            shapes.push_plane(plane, 0);
            shapes.pack();
            let (mut limit, mut best) = (f64::INFINITY, None);
            shapes.nearest(&ray, 0.0, &mut limit, &mut best);
            assert_eq!(
                best.map(|(index, hit)| (index, hit.t)),
                accepts_zero.then_some((0, 0.0))
            );
            assert_eq!(shapes.any(&ray, 0.0, f64::INFINITY), accepts_zero);
        }
    }
}
