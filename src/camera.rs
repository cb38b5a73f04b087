//! The camera of the original renderer: smallpt image plane, a canvas distance
//! that lets the eye sit behind a wall, and an optional thin lens.

use crate::math::{Point3, Ray, Vec3};
use crate::scene::model::{CameraDesc, FovAxis};

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
    right: Vec3,
    true_up: Vec3,
    canvas_distance: f64,
    focus_distance: f64,
    lens_radius: f64,
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
            right,
            true_up,
            canvas_distance: desc.canvas_distance,
            focus_distance: desc.focus_distance,
            lens_radius: desc.lens_radius,
            width,
            height,
        }
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
        let (a, b) = concentric_disk(lens);
        let eye = self.center + (self.true_up * a + self.right * b) * self.lens_radius;
        let new_direction = (focus - eye).normalize();
        let along = new_direction.dot(&self.direction).max(1e-12);
        let origin = eye + new_direction * (self.canvas_distance / along);
        Ray::new(origin, new_direction, time)
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

/// Shirley and Chiu's concentric map from the unit square to the unit disk
/// (uniform density; the original's squared-uniform lens was not).
pub fn concentric_disk(square: [f64; 2]) -> (f64, f64) {
    let a = 2.0 * square[0] - 1.0;
    let b = 2.0 * square[1] - 1.0;
    if a == 0.0 && b == 0.0 {
        return (0.0, 0.0);
    }
    let (radius, theta) = if a.abs() > b.abs() {
        (a, std::f64::consts::FRAC_PI_4 * (b / a))
    } else {
        (
            b,
            std::f64::consts::FRAC_PI_2 - std::f64::consts::FRAC_PI_4 * (a / b),
        )
    };
    (radius * theta.cos(), radius * theta.sin())
}

#[cfg(test)]
mod tests {
    use super::*;

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
