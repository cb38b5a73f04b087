//! Infinite planes that cut a sphere light.
//!
//! Scene files often sink a big sphere light into the ceiling plane (smallpt's
//! radius-600 light, the coursework's radius-30 one), so that only a shallow
//! cap hangs below it. From a point on one side of an opaque infinite plane,
//! no point of the sphere on the other side can be reached: the segment would
//! cross the plane, which a ray always hits first. Sampling only the cap on
//! the reference point's side is therefore unbiased, and when the cap is
//! small it wastes far fewer shadow rays than sampling the whole cone the
//! sphere subtends. The choice of cap depends on the reference point alone,
//! so that the density of a light sample and the density MIS asks for at a
//! BSDF-sampled hit are the same function.

use std::f64::consts::PI;

use crate::math::{Point3, Vec3, orthonormal_basis};
use crate::trig::sin_cos_turns;

/// Planes kept per sphere (the deepest cuts: the smallest caps).
pub const MAX_CUTS: usize = 2;

/// A reference point closer to a cutting plane than this fraction of the
/// sphere's radius is on neither side: that plane is not used for it.
const PLANE_MARGIN: f64 = 1e-6;

/// A cut is kept only when its cap is smaller than this fraction of the
/// sphere (`1 - min_cos` below `2 * MAX_CAP_FRACTION`); larger caps are left
/// to cone sampling.
const MAX_CAP_FRACTION: f64 = 0.5;

/// An oriented plane `normal . p = offset`, `normal` of unit length.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CutPlane {
    pub normal: Vec3,
    pub offset: f64,
    /// Hit only by rays travelling against `normal` (a look's one-sided
    /// planes): opaque seen from the side `normal` points to, and no cut
    /// at all from behind, where light passes through it.
    pub one_sided: bool,
}

/// The planes that cut one sphere, at most [`MAX_CUTS`].
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Cuts {
    planes: [Option<CutPlane>; MAX_CUTS],
}

/// The part of a sphere of unit directions `w` from its centre with
/// `axis . w >= min_cos`.
#[derive(Clone, Copy, Debug)]
pub struct Cap {
    pub axis: Vec3,
    pub min_cos: f64,
}

impl Cuts {
    /// No cuts: the whole sphere is sampled.
    pub const NONE: Cuts = Cuts {
        planes: [None; MAX_CUTS],
    };

    /// The planes among `planes` that cut the sphere, the deepest first.
    pub fn new(center: &Point3, radius: f64, planes: &[CutPlane]) -> Cuts {
        let mut cutting: Vec<(f64, CutPlane)> = planes
            .iter()
            .filter_map(|plane| {
                let height = (plane.normal.dot(center) - plane.offset).abs();
                (height < radius).then_some((height, *plane))
            })
            .collect();
        // A plane far from the centre cuts off the smallest cap.
        cutting.sort_by(|a, b| b.0.total_cmp(&a.0));
        let mut cuts = Cuts::NONE;
        for (slot, (_, plane)) in cuts.planes.iter_mut().zip(cutting) {
            *slot = Some(plane);
        }
        cuts
    }

    pub fn is_empty(&self) -> bool {
        self.planes[0].is_none()
    }

    /// The smallest cap of the sphere that holds every point reachable from
    /// `reference`, when one of the cuts gives a cap below
    /// [`MAX_CAP_FRACTION`] of the sphere.
    #[inline]
    pub fn cap(&self, center: &Point3, radius: f64, reference: &Point3) -> Option<Cap> {
        let mut best: Option<Cap> = None;
        for plane in self.planes.iter().flatten() {
            let side = plane.normal.dot(reference) - plane.offset;
            if side.abs() <= PLANE_MARGIN * radius || (plane.one_sided && side < 0.0) {
                continue;
            }
            let axis = if side > 0.0 {
                plane.normal
            } else {
                -plane.normal
            };
            // Points c + r w with axis . (c + r w) >= axis-side offset.
            let centre_height = axis.dot(center) - axis.dot(&(plane.normal * plane.offset));
            let min_cos = -centre_height / radius;
            if 1.0 - min_cos >= 2.0 * MAX_CAP_FRACTION {
                continue;
            }
            if best.is_none_or(|cap| min_cos > cap.min_cos) {
                best = Some(Cap { axis, min_cos });
            }
        }
        best
    }
}

impl Cap {
    /// Area of the cap on a sphere of radius `radius`.
    pub fn area(&self, radius: f64) -> f64 {
        2.0 * PI * radius * radius * (1.0 - self.min_cos)
    }

    /// A uniform unit direction of the cap (uniform in area: the height along
    /// the axis is uniform).
    pub fn sample(&self, u: [f64; 2]) -> Vec3 {
        let z = 1.0 - u[0] * (1.0 - self.min_cos);
        let r = (1.0 - z * z).max(0.0).sqrt();
        let (sin, cos) = sin_cos_turns(u[1]);
        let (t, b) = orthonormal_basis(&self.axis);
        t * (r * cos) + b * (r * sin) + self.axis * z
    }

    /// Whether the unit direction `w` from the centre lies in the cap.
    pub fn contains(&self, w: &Vec3) -> bool {
        self.axis.dot(w) >= self.min_cos - 1e-9
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ceiling(height: f64) -> CutPlane {
        CutPlane {
            normal: Vec3::y(),
            offset: height,
            one_sided: false,
        }
    }

    #[test]
    fn keeps_only_cutting_planes_deepest_first() {
        let center = Point3::new(0.0, 10.0, 0.0);
        let planes = [
            ceiling(20.0), // misses
            ceiling(9.0),  // shallow cut
            ceiling(1.0),  // deep cut: smallest cap below
            CutPlane {
                normal: Vec3::x(),
                offset: 0.5,
                one_sided: false,
            },
        ];
        let cuts = Cuts::new(&center, 9.5, &planes);
        assert_eq!(cuts.planes[0], Some(ceiling(1.0)));
        assert_eq!(cuts.planes[1], Some(ceiling(9.0)));
        assert!(Cuts::new(&center, 9.5, &planes[..1]).is_empty());
    }

    #[test]
    fn cap_is_on_the_reference_side_and_skips_points_on_the_plane() {
        let center = Point3::new(0.0, 10.0, 0.0);
        let cuts = Cuts::new(&center, 2.0, &[ceiling(8.5)]);
        let below = cuts.cap(&center, 2.0, &Point3::new(3.0, 0.0, 1.0)).unwrap();
        assert_eq!(below.axis, -Vec3::y());
        // The cap below reaches 0.5 under the plane: height 0.5 of radius 2.
        assert!((below.min_cos - 0.75).abs() < 1e-12);
        assert!((below.area(2.0) - 2.0 * PI * 2.0 * 0.5).abs() < 1e-12);
        // Above the plane the reachable part is most of the sphere: no cap.
        assert!(
            cuts.cap(&center, 2.0, &Point3::new(0.0, 20.0, 0.0))
                .is_none()
        );
        assert!(
            cuts.cap(&center, 2.0, &Point3::new(5.0, 8.5, 0.0))
                .is_none()
        );
    }

    #[test]
    fn cap_samples_lie_in_the_cap_with_uniform_height() {
        let cap = Cap {
            axis: Vec3::new(1.0, 2.0, -0.5).normalize(),
            min_cos: 0.6,
        };
        let n = 4000;
        let mut mean_height = 0.0;
        for i in 0..n {
            let u = [(i as f64 + 0.5) / n as f64, (i * 37 % n) as f64 / n as f64];
            let w = cap.sample(u);
            assert!((w.norm() - 1.0).abs() < 1e-12);
            assert!(cap.contains(&w));
            mean_height += cap.axis.dot(&w) / n as f64;
        }
        assert!((mean_height - 0.8).abs() < 1e-3, "{mean_height}");
    }
}
