//! afb's `Func N` texture selectors: where a material's image is read,
//! from the world hit point instead of the shape's uv
//! (AfireBao/2022_Monte_Carlo_RayTracing, `include/material.hpp`; its
//! scenes fit a [-2, 2] box).
//!
//! | `Func` | rule | a | b |
//! |---|---|---|---|
//! | 1, 6 ("background", "front") | [`UvRule::FrontXy`] | `(x + 2) / 4` | `(2 - y) / 4` |
//! | 2, 3 ("top", "bottom") | [`UvRule::TopXz`] | `(x + 2) / 4` | `(z + 2) / 4 - trunc(z + 2) / 4` |
//! | 4, 5 ("left", "right") | [`UvRule::SideYz`] | `(y + 2) / 4` | as for 2 |
//! | 7 (RevSurface) | [`UvRule::Revolution`] | the angle `atan2(-z, x)` in radians, in (-pi, pi] | `5 t - trunc(5 t)`, `t` the hit's ray distance |
//! | 0 (afb's default) or any other | none: the shape's own uv | | |
//!
//! `(x, y, z)` is the world hit point. For 2 to 5, `b` is `frac(z + 2) / 4`
//! for `z > -2`: only the top quarter of the image is read, repeating every
//! world unit along z. The texel is `(trunc(a w), trunc(b h))`, each
//! wrapped into the image by a double modulo (`((i % w) + w) % w`), row 0
//! the top of the file (no vertical flip); see
//! [`crate::texture::Texture::lookup_rows_down`].
//!
//! For 7 the angle is the surface of revolution's own, from its uv (the
//! angle about its axis in its object space, as afb's, for profiles on the
//! positive x side); on other shapes it is `2 pi u` of their uv, where
//! afb's value is whatever the last surface of revolution left on the
//! material. `t` is our ray's distance (unit directions); afb's camera rays
//! have a unit component along the view axis, so at the first hit its `t`
//! is the depth along that axis instead.

use std::f64::consts::PI;

use crate::math::Point3;

/// One of afb's texture-coordinate rules (see the module docs).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum UvRule {
    /// `Func` 1 and 6: the xy plane, y down.
    FrontXy,
    /// `Func` 2 and 3: x across, the fraction of z + 2 (over 4) down.
    TopXz,
    /// `Func` 4 and 5: y across, the fraction of z + 2 (over 4) down.
    SideYz,
    /// `Func` 7: the angle about a surface of revolution's axis across,
    /// the fraction of 5 times the ray distance down.
    Revolution,
}

impl UvRule {
    /// The rule of `Func n`; `None` for 0 (afb's default) and values afb
    /// does not define.
    pub fn from_func(n: i64) -> Option<UvRule> {
        match n {
            1 | 6 => Some(UvRule::FrontXy),
            2 | 3 => Some(UvRule::TopXz),
            4 | 5 => Some(UvRule::SideYz),
            7 => Some(UvRule::Revolution),
            _ => None,
        }
    }

    /// The image coordinates `(a, b)` (a across, b down from the top row,
    /// wrapped by the lookup) of a hit at `point`, `t` along its ray, with
    /// the shape's `uv`.
    pub fn coordinates(self, point: &Point3, t: f64, uv: [f64; 2]) -> [f64; 2] {
        let fraction_of_z = || (point.z + 2.0) / 4.0 - (point.z + 2.0).trunc() / 4.0;
        match self {
            UvRule::FrontXy => [(point.x + 2.0) / 4.0, (2.0 - point.y) / 4.0],
            UvRule::TopXz => [(point.x + 2.0) / 4.0, fraction_of_z()],
            UvRule::SideYz => [(point.y + 2.0) / 4.0, fraction_of_z()],
            UvRule::Revolution => {
                // Our angle is in [0, 2 pi); afb's atan2 is in (-pi, pi].
                let angle = uv[0] * 2.0 * PI;
                let angle = if angle > PI { angle - 2.0 * PI } else { angle };
                [angle, 5.0 * t - (5.0 * t).trunc()]
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn funcs_map_to_their_rules() {
        assert_eq!(UvRule::from_func(0), None);
        assert_eq!(UvRule::from_func(8), None);
        assert_eq!(UvRule::from_func(-1), None);
        assert_eq!(UvRule::from_func(1), UvRule::from_func(6));
        assert_eq!(UvRule::from_func(2), UvRule::from_func(3));
        assert_eq!(UvRule::from_func(4), UvRule::from_func(5));
        assert_eq!(UvRule::from_func(7), Some(UvRule::Revolution));
    }

    #[test]
    fn the_box_rules_span_the_unit_square_over_the_four_unit_box() {
        let uv = [0.3, 0.7];
        let at = |x, y, z| Point3::new(x, y, z);
        assert_eq!(
            UvRule::FrontXy.coordinates(&at(-2.0, 2.0, 9.0), 1.0, uv),
            [0.0, 0.0]
        );
        assert_eq!(
            UvRule::FrontXy.coordinates(&at(2.0, -2.0, 9.0), 1.0, uv),
            [1.0, 1.0]
        );
        assert_eq!(
            UvRule::FrontXy.coordinates(&at(0.0, 0.0, 0.0), 1.0, uv),
            [0.5, 0.5]
        );
        // b is a quarter of the fraction of z + 2: in [0, 0.25), period 1.
        for rule in [UvRule::TopXz, UvRule::SideYz] {
            for z in [-1.75, -0.75, 0.25, 1.25] {
                let [_, b] = rule.coordinates(&at(0.0, 0.0, z), 1.0, uv);
                assert!((b - 0.0625).abs() < 1e-15, "{rule:?} at z = {z}: {b}");
            }
        }
        assert_eq!(
            UvRule::TopXz.coordinates(&at(1.0, 5.0, 0.0), 1.0, uv)[0],
            0.75
        );
        assert_eq!(
            UvRule::SideYz.coordinates(&at(5.0, 1.0, 0.0), 1.0, uv)[0],
            0.75
        );
        // Below z = -2 the truncation goes towards zero: b is negative
        // (the lookup wraps it to the bottom rows).
        let [_, b] = UvRule::TopXz.coordinates(&at(0.0, 0.0, -2.5), 1.0, uv);
        assert!((b + 0.125).abs() < 1e-15, "{b}");
    }

    #[test]
    fn the_revolution_rule_takes_the_angle_in_radians_and_five_times_the_distance() {
        let point = Point3::zeros();
        // A quarter turn: pi / 2; three quarters: -pi / 2 (atan2's range).
        let [a, b] = UvRule::Revolution.coordinates(&point, 1.26, [0.25, 0.0]);
        assert!((a - PI / 2.0).abs() < 1e-15);
        assert!((b - 0.3).abs() < 1e-12, "frac(6.3) = {b}");
        let [a, _] = UvRule::Revolution.coordinates(&point, 1.0, [0.75, 0.0]);
        assert!((a + PI / 2.0).abs() < 1e-15);
        let [a, b] = UvRule::Revolution.coordinates(&point, 2.0, [0.5, 0.0]);
        assert_eq!((a, b), (PI, 0.0));
    }
}
