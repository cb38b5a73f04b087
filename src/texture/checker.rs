//! A procedural colour texture evaluated at the world hit point: rub's
//! `checkerTexture` (1rubbishyuan/path_tracing, `include/texture.hpp`).

use crate::color::Color;
use crate::math::Point3;

/// Cubes of side `1 / scale` in world space, coloured `even` where
/// `floor(s x) + floor(s y) + floor(s z)` is even and `odd` elsewhere.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Checker {
    pub scale: f64,
    pub even: Color,
    pub odd: Color,
}

impl Checker {
    /// The colour at `point` (world space). A coordinate that is not finite
    /// counts as even.
    pub fn color_at(&self, point: &Point3) -> Color {
        let cell = |c: f64| {
            let f = (self.scale * c).floor();
            if f.is_finite() {
                f.rem_euclid(2.0)
            } else {
                0.0
            }
        };
        let parity = (cell(point.x) + cell(point.y) + cell(point.z)).rem_euclid(2.0);
        if parity == 0.0 { self.even } else { self.odd }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const RED: Color = Color::new(1.0, 0.0, 0.0);
    const BLUE: Color = Color::new(0.0, 0.0, 1.0);

    fn checker(scale: f64) -> Checker {
        Checker {
            scale,
            even: RED,
            odd: BLUE,
        }
    }

    #[test]
    fn neighbouring_cells_alternate_along_every_axis_and_negative_cells_count() {
        let c = checker(2.0);
        // Cell (0, 0, 0) is even; a step of 1/2 along any axis flips it.
        let origin = Point3::new(0.1, 0.1, 0.1);
        assert_eq!(c.color_at(&origin), RED);
        for axis in 0..3 {
            for step in [0.5, -0.5, 1.5] {
                let mut p = origin;
                p[axis] += step;
                assert_eq!(c.color_at(&p), BLUE, "axis {axis}, step {step}");
                p[axis] += 0.5;
                assert_eq!(c.color_at(&p), RED, "axis {axis}, step {step} + 0.5");
            }
        }
        // floor(-0.2) = -1: odd, as rub's floor (not truncation).
        assert_eq!(c.color_at(&Point3::new(-0.1, 0.1, 0.1)), BLUE);
        assert_eq!(c.color_at(&Point3::new(-0.1, -0.1, 0.1)), RED);
    }

    #[test]
    fn scale_sets_the_cell_size_and_zero_is_one_colour() {
        let p = Point3::new(0.3, 0.0, 0.0);
        assert_eq!(checker(1.0).color_at(&p), RED);
        assert_eq!(checker(4.0).color_at(&p), BLUE);
        for x in [-7.3, 0.0, 12.9] {
            assert_eq!(checker(0.0).color_at(&Point3::new(x, x, -x)), RED);
        }
        assert_eq!(
            checker(1.0).color_at(&Point3::new(f64::NAN, 0.5, 1e300)),
            RED
        );
    }
}
