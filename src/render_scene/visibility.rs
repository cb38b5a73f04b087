//! Shadow rays: whether a point sees another, and the transmittance of the
//! media on the way. Every shadow ray of every integrator goes through
//! here, with one rule for where it stops: [`SHADOW_REACH`] of the way to
//! its target, so that it does not find the target itself (an emitter's
//! surface, the vertex it connects to).

use crate::color::Color;
use crate::math::{Point3, Ray, Vec3};
use crate::medium::Medium;
use crate::shading::RenderMaterial;

use super::RenderScene;

/// The fraction of the distance to its target that a shadow ray covers.
pub const SHADOW_REACH: f64 = 1.0 - 1e-7;

/// Interfaces a ray (or a shadow ray) crosses between two vertices before
/// it is given up (it can only be reached by a degenerate geometry that
/// traps a ray between coincident surfaces).
pub const MAX_CROSSINGS: u32 = 256;

impl RenderScene {
    /// Whether nothing lies between `origin` (a ray origin already off its
    /// surface, see `Shading::spawn_origin`) and the target `distance`
    /// away along the unit `direction`, at shutter time `time`.
    #[inline]
    pub fn unoccluded(&self, origin: Point3, direction: Vec3, distance: f64, time: f64) -> bool {
        let shadow = Ray::new(origin, direction, time);
        !self.world.occluded(&shadow, 0.0, distance * SHADOW_REACH)
    }

    /// Transmittance from `origin` along the unit `direction` to the target
    /// `distance` away, starting in `medium`: the product of every medium's
    /// `e^(-sigma_t d)` across the interfaces on the way, black when
    /// another surface is in the way.
    pub fn transmittance<'s>(
        &'s self,
        origin: Point3,
        direction: Vec3,
        distance: f64,
        mut medium: Option<&'s Medium>,
        time: f64,
    ) -> Color {
        let mut seen = Color::WHITE;
        let mut ray = Ray::new(origin, direction, time);
        let mut remaining = distance * SHADOW_REACH;
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
