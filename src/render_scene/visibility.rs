//! Shadow rays: whether a point sees another, and the transmittance of the
//! media on the way. Every shadow ray of every integrator goes through
//! here, with one rule for where it stops ([`ShadowTarget::reach`]), so
//! that it does not find the target itself (an emitter's surface, the
//! vertex it connects to).

use crate::color::Color;
use crate::math::{Point3, Ray, Vec3, shadow_reach};
use crate::medium::Medium;
use crate::shading::RenderMaterial;

use super::RenderScene;

/// The fraction of the distance to its target that a shadow ray leaves
/// uncovered.
pub const SHADOW_SHORTENING: f64 = 1e-7;

/// The fraction of the distance to its target that a shadow ray covers.
pub const SHADOW_REACH: f64 = 1.0 - SHADOW_SHORTENING;

/// What a shadow ray aims at.
#[derive(Clone, Copy, Debug)]
pub enum ShadowTarget {
    /// A point on a surface (an emitter's, a light subpath's vertex): the
    /// ray stops short of it by [`SHADOW_SHORTENING`] of the distance from
    /// the ray's own origin and by the point's rounding (see
    /// [`shadow_reach`]), so that it does not find that surface, however far
    /// from the scene's origin it lies.
    Surface(Point3),
    /// A distance along the ray to something that is not a surface of the
    /// world (a PA1 light, the camera's canvas): [`SHADOW_REACH`] of it.
    Distance(f64),
}

impl ShadowTarget {
    /// How far along its direction a shadow ray from `origin` may look.
    #[inline]
    pub fn reach(self, origin: &Point3) -> f64 {
        match self {
            ShadowTarget::Surface(point) => shadow_reach(origin, &point, SHADOW_SHORTENING),
            ShadowTarget::Distance(distance) => distance * SHADOW_REACH,
        }
    }
}

/// Interfaces a ray (or a shadow ray) crosses between two vertices before
/// it is given up (it can only be reached by a degenerate geometry that
/// traps a ray between coincident surfaces).
pub const MAX_CROSSINGS: u32 = 256;

impl RenderScene {
    /// Whether nothing lies between `origin` (a ray origin already off its
    /// surface, see `Shading::spawn_origin`) and `target` along the unit
    /// `direction`, at shutter time `time`.
    #[inline]
    pub fn unoccluded(
        &self,
        origin: Point3,
        direction: Vec3,
        target: ShadowTarget,
        time: f64,
    ) -> bool {
        let shadow = Ray::new(origin, direction, time);
        !self.world.occluded(&shadow, 0.0, target.reach(&origin))
    }

    /// Transmittance from `origin` along the unit `direction` to `target`,
    /// starting in `medium`: the product of every medium's
    /// `e^(-sigma_t d)` across the interfaces on the way, black when
    /// another surface is in the way.
    pub fn transmittance<'s>(
        &'s self,
        origin: Point3,
        direction: Vec3,
        target: ShadowTarget,
        mut medium: Option<&'s Medium>,
        time: f64,
    ) -> Color {
        let mut seen = Color::WHITE;
        let mut ray = Ray::new(origin, direction, time);
        let mut remaining = target.reach(&origin);
        for _ in 0..=MAX_CROSSINGS {
            let Some(hit) = self.world.intersect(&ray, 0.0, remaining) else {
                if let Some(inside) = medium {
                    seen *= inside.transmittance(remaining);
                }
                return seen;
            };
            let material = self.material(hit.material);
            if !material.interface {
                return Color::BLACK;
            }
            if let Some(inside) = medium {
                seen *= inside.transmittance(hit.t);
                if seen.is_black() {
                    return Color::BLACK;
                }
            }
            let entering = hit.geometric_normal.dot(&direction) < 0.0;
            medium = self.medium_after(material, entering, medium);
            let next = hit.spawn_origin(&direction);
            remaining -= (next - ray.origin).dot(&direction);
            if remaining <= 0.0 {
                return seen;
            }
            ray = Ray::new(next, direction, time);
        }
        Color::BLACK
    }

    /// The medium a ray is in after crossing a surface of `material`
    /// (inwards when `entering`), coming from `current`.
    #[inline]
    pub fn medium_after<'s>(
        &'s self,
        material: &'s RenderMaterial,
        entering: bool,
        current: Option<&'s Medium>,
    ) -> Option<&'s Medium> {
        match (&material.interior, entering) {
            (None, _) => current,
            (Some(inside), true) => Some(inside),
            (Some(_), false) => self.medium(),
        }
    }
}
