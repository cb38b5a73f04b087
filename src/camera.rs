//! The camera of the original renderer: smallpt image plane, a canvas distance
//! that lets the eye sit behind a wall, and an optional thin lens.

use crate::geometry::surface_samples::concentric_disk;
use crate::math::{Point3, Ray, Vec3};
use crate::scene::model::{CameraDesc, FovAxis, LensShape};
use crate::trig::sin_cos_turns;

/// Image-plane scale of the original when no field of view is given:
/// a vertical field of view of 2 atan(0.5135 / 2) = 28.8 degrees.
pub const DEFAULT_PLANE_SCALE: f64 = 0.5135;

/// Lens radii below this are a pinhole (the original's threshold).
pub const MIN_LENS_RADIUS: f64 = 1e-4;

#[derive(Clone, Debug)]
pub struct Camera {
    center: Point3,
    direction: Vec3,
    /// Image-plane axes: offsets of a full image width and height.
    plane_x: Vec3,
    plane_y: Vec3,
    /// Their lengths: the image plane's extent at distance 1.
    span_x: f64,
    span_y: f64,
    right: Vec3,
    true_up: Vec3,
    canvas_distance: f64,
    focus_distance: f64,
    lens_radius: f64,
    lens_shape: LensShape,
    pub width: u32,
    pub height: u32,
}

impl Camera {
    /// Builds the camera for an image of `width` x `height` (which may differ
    /// from the scene's own size when the user overrides it).
    pub fn new(desc: &CameraDesc, width: u32, height: u32) -> Camera {
        let direction = normalize_or(desc.direction, Vec3::new(0.0, 0.0, -1.0));
        let mut up = normalize_or(desc.up, Vec3::new(0.0, 1.0, 0.0));
        if direction.cross(&up).norm() < 1e-9 {
            // Up parallel to the view direction: any perpendicular will do.
            up = crate::math::orthonormal_basis(&direction).0;
        }
        let right = direction.cross(&up).normalize();
        let true_up = right.cross(&direction);
        let aspect = width as f64 / height.max(1) as f64;
        let (span_x, span_y) = match desc.fov {
            None => (DEFAULT_PLANE_SCALE * aspect, DEFAULT_PLANE_SCALE),
            Some((degrees, FovAxis::Vertical)) => {
                let span = 2.0 * (degrees.to_radians() * 0.5).tan();
                (span * aspect, span)
            }
            Some((degrees, FovAxis::Horizontal)) => {
                let span = 2.0 * (degrees.to_radians() * 0.5).tan();
                (span, span / aspect)
            }
        };
        Camera {
            center: desc.center,
            direction,
            plane_x: right * span_x,
            plane_y: true_up * span_y,
            span_x,
            span_y,
            right,
            true_up,
            canvas_distance: desc.canvas_distance,
            focus_distance: desc.focus_distance,
            lens_radius: desc.lens_radius,
            lens_shape: desc.lens_shape,
            width,
            height,
        }
    }

    /// The lens point of the unit-square sample `lens`.
    #[inline]
    fn eye(&self, lens: [f64; 2]) -> Point3 {
        let (a, b) = lens_point(self.lens_shape, lens);
        self.center + (self.true_up * a + self.right * b) * self.lens_radius
    }

    /// Whether rays need lens samples (depth of field).
    pub fn has_lens(&self) -> bool {
        self.lens_radius >= MIN_LENS_RADIUS
    }

    /// The primary ray through film position (`film_x`, `film_y`) in pixels,
    /// y = 0 at the bottom edge. `lens` is a point of the unit square, used
    /// only with depth of field; `time` is the shutter time in [0, 1].
    pub fn ray(&self, film_x: f64, film_y: f64, lens: [f64; 2], time: f64) -> Ray {
        let d = self.plane_x * (film_x / self.width as f64 - 0.5)
            + self.plane_y * (film_y / self.height as f64 - 0.5)
            + self.direction;
        if !self.has_lens() {
            return Ray::new(self.center + d * self.canvas_distance, d.normalize(), time);
        }
        // Every unnormalised `d` has d . direction = 1: the points
        // center + d * s form planes, the focal plane at s = focus_distance.
        let focus = self.center + d * self.focus_distance;
        let eye = self.eye(lens);
        let new_direction = (focus - eye).normalize();
        let along = new_direction.dot(&self.direction).max(1e-12);
        let origin = eye + new_direction * (self.canvas_distance / along);
        Ray::new(origin, new_direction, time)
    }
}

/// Where a world point appears on the film, seen from one lens point: what
/// light tracing needs to connect a vertex to the camera.
#[derive(Clone, Copy, Debug)]
pub struct Projection {
    /// Film position in pixels (`y` up from the bottom edge), as in
    /// [`Camera::ray`].
    pub film_x: f64,
    pub film_y: f64,
    /// The lens point (the eye) the ray starts from.
    pub eye: Point3,
    /// Unit direction from the eye to the point, and the distance.
    pub direction: Vec3,
    pub distance: f64,
    /// Distance from the eye to the canvas along `direction`: camera rays
    /// start there, so nothing nearer is seen.
    pub canvas: f64,
    /// Film area (square pixels) per solid angle at the eye in `direction`.
    pub film_per_steradian: f64,
}

impl Camera {
    /// The projection of `point` through the lens point of the unit-square
    /// sample `lens` (ignored without depth of field), as [`Camera::ray`]
    /// would trace it: the ray through the returned film position with the
    /// same `lens` sample heads for `point`. `None` behind the camera.
    pub fn project(&self, point: &Point3, lens: [f64; 2]) -> Option<Projection> {
        let eye = if self.has_lens() {
            self.eye(lens)
        } else {
            self.center
        };
        let offset = point - eye;
        let distance = offset.norm();
        let direction = offset / distance;
        let along = direction.dot(&self.direction);
        if !(distance > 0.0 && along > 1e-12) {
            return None;
        }
        // The unnormalised ray direction `d` (d . direction = 1) whose film
        // position is wanted: through the focal point on the lens's ray.
        let d = if self.has_lens() {
            let focus = eye + direction * (self.focus_distance / along);
            (focus - self.center) / self.focus_distance
        } else {
            direction / along
        };
        let film_x = (d.dot(&self.right) / self.span_x + 0.5) * self.width as f64;
        let film_y = (d.dot(&self.true_up) / self.span_y + 0.5) * self.height as f64;
        // Film pixels per unit area of the plane at distance 1, times that
        // area per solid angle (1 / cos^3).
        let film_per_steradian =
            self.width as f64 * self.height as f64 / (self.span_x * self.span_y * along.powi(3));
        Some(Projection {
            film_x,
            film_y,
            eye,
            direction,
            distance,
            canvas: self.canvas_distance / along,
            film_per_steradian,
        })
    }
}

fn normalize_or(v: Vec3, fallback: Vec3) -> Vec3 {
    let length = v.norm();
    if length > 0.0 && length.is_finite() {
        v / length
    } else {
        fallback
    }
}

/// A point of the lens of `shape` with radius (or half side) 1, from a
/// point of the unit square.
pub fn lens_point(shape: LensShape, square: [f64; 2]) -> (f64, f64) {
    match shape {
        LensShape::Disk => concentric_disk(square),
        LensShape::DiskUniformRadius => {
            let (sin, cos) = sin_cos_turns(square[0]);
            (square[1] * cos, square[1] * sin)
        }
        LensShape::Square => (2.0 * square[0] - 1.0, 2.0 * square[1] - 1.0),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lens_shapes_spread_points_as_their_renderers_do() {
        // Mean distance from the centre over a midpoint grid of the square:
        // 2/3 for the uniform disk, 1/2 for a uniform radius, and the square
        // reaches its corners.
        let n = 200;
        let mean = |shape: LensShape| {
            let mut total = 0.0;
            for i in 0..n {
                for j in 0..n {
                    let u = [(i as f64 + 0.5) / n as f64, (j as f64 + 0.5) / n as f64];
                    let (a, b) = lens_point(shape, u);
                    total += (a * a + b * b).sqrt();
                }
            }
            total / (n * n) as f64
        };
        assert!((mean(LensShape::Disk) - 2.0 / 3.0).abs() < 1e-3);
        assert!((mean(LensShape::DiskUniformRadius) - 0.5).abs() < 1e-3);
        assert_eq!(lens_point(LensShape::Square, [1.0, 0.0]), (1.0, -1.0));
        // The square's mean distance, (sqrt 2 + asinh 1) / 3.
        let square = (2f64.sqrt() + 1f64.asinh()) / 3.0;
        assert!((mean(LensShape::Square) - square).abs() < 1e-3);
    }

    fn smallpt_desc() -> CameraDesc {
        CameraDesc {
            center: Vec3::new(50.0, 52.0, 295.6),
            direction: Vec3::new(0.0, -0.042612, -1.0),
            up: Vec3::new(0.0, 1.0, 0.0),
            width: 1024,
            height: 768,
            fov: None,
            canvas_distance: 140.0,
            focus_distance: 1.0,
            lens_radius: 0.0,
            lens_shape: LensShape::Disk,
        }
    }

    #[test]
    fn matches_smallpt_image_plane() {
        let camera = Camera::new(&smallpt_desc(), 1024, 768);
        let dir = Vec3::new(0.0, -0.042612, -1.0).normalize();
        // smallpt: cx = (w * .5135 / h, 0, 0), cy = normalize(cx x dir) * .5135.
        let cx = Vec3::new(1024.0 * 0.5135 / 768.0, 0.0, 0.0);
        let cy = cx.cross(&dir).normalize() * 0.5135;
        let (fx, fy) = (300.25, 100.75);
        let d = cx * (fx / 1024.0 - 0.5) + cy * (fy / 768.0 - 0.5) + dir;
        let ray = camera.ray(fx, fy, [0.5, 0.5], 0.0);
        assert!((ray.direction - d.normalize()).norm() < 1e-12);
        assert!((ray.origin - (Vec3::new(50.0, 52.0, 295.6) + d * 140.0)).norm() < 1e-9);
    }

    #[test]
    fn projection_inverts_the_camera_ray_with_and_without_lens() {
        let mut desc = smallpt_desc();
        for lens_radius in [0.0, 3.0] {
            desc.lens_radius = lens_radius;
            desc.focus_distance = 200.0;
            let camera = Camera::new(&desc, 64, 48);
            for (fx, fy, lens) in [(10.0, 20.0, [0.1, 0.9]), (50.5, 3.25, [0.7, 0.2])] {
                let ray = camera.ray(fx, fy, lens, 0.0);
                let point = ray.at(170.0);
                let p = camera.project(&point, lens).expect("in front");
                assert!((p.film_x - fx).abs() < 1e-9 && (p.film_y - fy).abs() < 1e-9);
                assert!((p.direction - ray.direction).norm() < 1e-12);
                // The ray starts on the canvas, `canvas` from the eye.
                assert!((p.eye + p.direction * p.canvas - ray.origin).norm() < 1e-9);
            }
        }
    }

    #[test]
    fn film_per_steradian_matches_finite_differences() {
        let camera = Camera::new(&smallpt_desc(), 64, 48);
        let (fx, fy, h) = (40.0, 10.0, 1e-4);
        let d = |x: f64, y: f64| camera.ray(x, y, [0.5, 0.5], 0.0).direction;
        // Solid angle of a small film square: |dw/dx x dw/dy| h^2.
        let solid_angle = ((d(fx + h, fy) - d(fx, fy)).cross(&(d(fx, fy + h) - d(fx, fy)))).norm();
        let point = camera.ray(fx, fy, [0.5, 0.5], 0.0).at(100.0);
        let p = camera.project(&point, [0.5, 0.5]).unwrap();
        let expected = h * h / solid_angle;
        assert!(
            (p.film_per_steradian / expected - 1.0).abs() < 1e-3,
            "{} vs {expected}",
            p.film_per_steradian
        );
    }

    #[test]
    fn lens_rays_meet_at_the_focal_plane() {
        let mut desc = smallpt_desc();
        desc.lens_radius = 3.0;
        desc.focus_distance = 200.0;
        let camera = Camera::new(&desc, 64, 48);
        let pinhole = Camera::new(&smallpt_desc(), 64, 48);
        let reference = pinhole.ray(10.0, 20.0, [0.5, 0.5], 0.0);
        let dir = Vec3::new(0.0, -0.042612, -1.0).normalize();
        let along = reference.direction.dot(&dir);
        let focus = desc.center + reference.direction * (200.0 / along);
        for lens in [[0.1, 0.9], [0.7, 0.2], [0.99, 0.5]] {
            let ray = camera.ray(10.0, 20.0, lens, 0.0);
            // The ray passes through the focus point.
            let to_focus = focus - ray.origin;
            let cross = to_focus.cross(&ray.direction).norm();
            assert!(cross < 1e-6 * to_focus.norm(), "misses focus by {cross}");
            // and starts on the canvas plane.
            let depth = (ray.origin - desc.center).dot(&dir);
            assert!((depth - 140.0).abs() < 1e-9);
        }
    }

    #[test]
    fn concentric_disk_stays_in_the_disk_and_is_uniform() {
        let mut inside_half = 0;
        let n = 200;
        for i in 0..n {
            for j in 0..n {
                let (x, y) =
                    concentric_disk([(i as f64 + 0.5) / n as f64, (j as f64 + 0.5) / n as f64]);
                let r2 = x * x + y * y;
                assert!(r2 <= 1.0 + 1e-12);
                if r2 < 0.25 {
                    inside_half += 1;
                }
            }
        }
        // A disk of radius 1/2 holds a quarter of a uniform disk's area.
        let fraction = inside_half as f64 / (n * n) as f64;
        assert!((fraction - 0.25).abs() < 0.01, "{fraction}");
    }

    #[test]
    fn vertical_fov_spans_the_image_height() {
        let mut desc = smallpt_desc();
        desc.fov = Some((90.0, FovAxis::Vertical));
        desc.canvas_distance = 0.0;
        let camera = Camera::new(&desc, 100, 100);
        let top = camera.ray(50.0, 100.0, [0.5, 0.5], 0.0);
        let dir = desc.direction.normalize();
        let angle = top.direction.dot(&dir).acos().to_degrees();
        assert!((angle - 45.0).abs() < 1e-9, "{angle}");
    }
}
