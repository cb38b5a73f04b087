//! Flat shapes without area: a triangle whose corners are on one line, a
//! rectangle with a zero edge or two parallel ones (and a scene triangle
//! or rectangle with coordinates so large that its area overflows).
//!
//! They have no surface to see or to emit from (the world already drops
//! such a rectangle silently), so the build leaves them out with a warning
//! at their block, and counts a mesh's in one warning per file. Zero and negative radii are `shapes::Fields::radius`'s,
//! a zero normal is an error (`shapes::Fields::nonzero`).

use crate::math::{Point3, Vec3};
use crate::scene::model::Object;

/// Whether the parallelogram of `edge_u` and `edge_v` has no usable area
/// (zero, or not finite): the rule of [`crate::geometry::Rectangle::new`].
pub fn no_area(edge_u: &Vec3, edge_v: &Vec3) -> bool {
    let area_squared = edge_u.cross(edge_v).norm_squared();
    !(area_squared > 0.0 && area_squared.is_finite())
}

/// Whether the triangle of corners `a`, `b`, `c` has no usable area.
pub fn triangle_without_area(a: &Point3, b: &Point3, c: &Point3) -> bool {
    no_area(&(b - a), &(c - a))
}

/// Why a built shape has no area (to follow "a Quad ..."), or `None`.
pub fn why_without_area(object: &Object) -> Option<&'static str> {
    match object {
        Object::Triangle {
            vertices: [a, b, c],
            ..
        } => triangle_without_area(a, b, c)
            .then_some("has no area (its corners are on one line, or too far apart)"),
        Object::Rectangle { edge_u, edge_v, .. } => {
            if edge_u.norm_squared() == 0.0 || edge_v.norm_squared() == 0.0 {
                Some("has no area (an edge of length 0)")
            } else if no_area(edge_u, edge_v) {
                Some("has no area (its edges are parallel, or too long)")
            } else {
                None
            }
        }
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn flat_triangles_and_rectangles_have_no_area_and_others_do() {
        let point = |x, y, z| Point3::new(x, y, z);
        let origin = point(0.0, 0.0, 0.0);
        assert!(triangle_without_area(
            &origin,
            &point(1.0, 0.0, 0.0),
            &point(2.0, 0.0, 0.0)
        ));
        assert!(triangle_without_area(&origin, &origin, &origin));
        assert!(triangle_without_area(
            &origin,
            &point(1e300, 0.0, 0.0),
            &point(0.0, 1e300, 0.0)
        ));
        assert!(!triangle_without_area(
            &origin,
            &point(1e-6, 0.0, 0.0),
            &point(0.0, 1e-6, 0.0)
        ));
        let rectangle = |edge_u, edge_v| Object::Rectangle {
            origin,
            edge_u,
            edge_v,
            material: 0,
        };
        let x = Vec3::x();
        assert!(why_without_area(&rectangle(x, Vec3::zeros())).is_some());
        assert!(why_without_area(&rectangle(x, 2.0 * x)).is_some());
        assert!(why_without_area(&rectangle(x, Vec3::y())).is_none());
    }
}
