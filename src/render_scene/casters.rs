//! Whether a ray can find a mirror or glass object at all: a test against
//! balls around them and their planes, much cheaper than the world's.
//!
//! A light subpath's first ray and a split bounce's probe (see `split`)
//! count only when the first surface they find is a mirror or glass; most
//! find a diffuse one, and end. When the ray misses every caster's ball and
//! plane, that is certain without tracing it, and the ray is skipped: the
//! image is the same, with fewer world queries.

use crate::emitters::Emitters;
use crate::geometry::Shape;
use crate::math::{Aabb, Point3, Ray, Vec3};
use crate::scene::model::Scene;
use crate::world::{Primitive, World};

/// Beyond this many bounded casters, one ball holds them all.
const MAX_BALLS: usize = 16;

/// Relative margin of a caster's ball, so that rounding never misses it.
const MARGIN: f64 = 1e-6;

/// The mirror and glass objects of a scene, as balls and planes.
#[derive(Clone, Debug)]
pub struct Casters {
    balls: Vec<(Point3, f64)>,
    planes: Vec<(Vec3, f64)>,
    /// A caster with neither (a transformed plane): every ray may find it.
    anywhere: bool,
}

impl Default for Casters {
    /// Unknown casters: every ray may find one.
    fn default() -> Casters {
        Casters {
            balls: Vec::new(),
            planes: Vec::new(),
            anywhere: true,
        }
    }
}

impl Casters {
    /// The casters of `world`: its primitives with a mirror or smooth glass.
    pub fn of(scene: &Scene, world: &World) -> Casters {
        let mut casters = Casters {
            balls: Vec::new(),
            planes: Vec::new(),
            anywhere: false,
        };
        for primitive in specular_primitives(scene, world) {
            match (&primitive.shape, &primitive.transform) {
                (Shape::Sphere(s), None) if s.motion == Vec3::zeros() => {
                    casters.balls.push((s.center, s.radius));
                }
                (Shape::Plane(p), None) => casters.planes.push((p.normal, p.offset)),
                _ => match primitive.bounds().filter(Aabb::is_valid) {
                    Some(b) => casters.balls.push(around(&b)),
                    None => casters.anywhere = true,
                },
            }
        }
        if casters.balls.len() > MAX_BALLS {
            let bounds = casters.balls.iter().fold(Aabb::empty(), |acc, &(c, r)| {
                let r = Vec3::repeat(r);
                acc.include_point(c - r).include_point(c + r)
            });
            casters.balls = vec![around(&bounds)];
        }
        for (_, radius) in &mut casters.balls {
            *radius *= 1.0 + MARGIN;
        }
        casters
    }

    /// Whether `ray` may find a caster ahead of its origin (`false`: it
    /// cannot).
    #[inline]
    pub fn may_hit(&self, ray: &Ray) -> bool {
        self.anywhere
            || self.planes.iter().any(|(normal, offset)| {
                // Ahead: the origin's side of the plane is left along the ray.
                let towards = normal.dot(&ray.direction);
                let side = normal.dot(&ray.origin) - offset;
                towards * side <= 0.0 && towards != 0.0 || side == 0.0
            })
            || {
                let a = ray.direction.norm_squared();
                self.balls.iter().any(|&(center, radius)| {
                    let to_center = center - ray.origin;
                    let along = to_center.dot(&ray.direction);
                    let distance2 = to_center.norm_squared();
                    let radius2 = radius * radius;
                    // Inside, or ahead and passing within the radius.
                    distance2 <= radius2 || along > 0.0 && distance2 - along * along / a <= radius2
                })
            }
    }
}

/// Whether light subpaths can add anything to a scene: it needs mirror or
/// glass to go through and emitters small enough, as seen from the mirrors
/// and glass, for the path tracer to miss them (see
/// [`Emitters::restrict_light_paths`], which this calls with the centre of
/// the bounded mirror and glass objects, or the camera).
pub fn prepare_light_paths(scene: &Scene, world: &World, emitters: &mut Emitters) -> bool {
    let casters: Vec<_> = specular_primitives(scene, world).collect();
    if casters.is_empty() || emitters.is_empty() {
        return false;
    }
    let bounds = casters
        .iter()
        .filter_map(|primitive| primitive.bounds())
        .filter(Aabb::is_valid)
        .fold(Aabb::empty(), |acc, b| acc.union(&b));
    let reference = if bounds.is_empty() {
        scene.camera.center
    } else {
        bounds.centroid()
    };
    emitters.restrict_light_paths(&reference)
}

/// The primitives of `world` with a material that has a delta lobe (a
/// mirror or smooth glass): the casters of caustics.
fn specular_primitives<'w>(
    scene: &'w Scene,
    world: &'w World,
) -> impl Iterator<Item = &'w Primitive> + 'w {
    world.primitives().iter().filter(|primitive| {
        primitive.materials().any(|material| {
            scene
                .materials
                .get(material)
                .is_some_and(|m| m.has_delta_lobe())
        })
    })
}

/// The ball around a box.
fn around(bounds: &Aabb) -> (Point3, f64) {
    (bounds.centroid(), bounds.extent().norm() / 2.0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::look::Look;
    use crate::render_scene::{RenderScene, SceneSettings};
    use crate::rng::Rng;
    use crate::scene::model::{Material, Object};

    /// A mirror ball, a glass box (a transformed sphere: its box's ball), a
    /// mirror floor plane and a diffuse ball.
    fn scene() -> Scene {
        let mirror = Material {
            diffuse: 0.0,
            specular: 1.0,
            ..Material::default()
        };
        let glass = Material {
            diffuse: 0.0,
            refract: 1.0,
            ..Material::default()
        };
        let sphere = |center: Point3, radius: f64, material: usize| Object::Sphere {
            center,
            radius,
            motion: Vec3::zeros(),
            material,
        };
        let squash = crate::math::Matrix::new_nonuniform_scaling(&Vec3::new(2.0, 0.5, 1.0));
        Scene::new(
            vec![Material::default(), mirror, glass],
            Object::Group(vec![
                sphere(Point3::new(0.0, 0.0, -5.0), 1.0, 1),
                Object::Transform {
                    matrix: squash,
                    inverse: squash.try_inverse().unwrap(),
                    child: Box::new(sphere(Point3::new(1.0, 4.0, -3.0), 0.5, 2)),
                },
                Object::Plane {
                    normal: Vec3::y(),
                    offset: -2.0,
                    material: 1,
                },
                sphere(Point3::new(-3.0, 1.0, -4.0), 1.0, 0),
            ]),
        )
    }

    #[test]
    fn a_ray_that_finds_a_caster_may_hit_one() {
        let scene = scene();
        let built = RenderScene::build(
            scene.clone(),
            &SceneSettings::defaults(&scene, Look::ORIGINAL),
        );
        let world = built.world();
        let casters = Casters::of(&scene, world);
        assert!(!casters.anywhere);
        assert_eq!((casters.balls.len(), casters.planes.len()), (2, 1));
        let mut rng = Rng::new(9, 10);
        let (mut skipped, count) = (0, 20_000);
        for _ in 0..count {
            let origin = Point3::new(
                rng.next_f64() * 8.0 - 4.0,
                rng.next_f64() * 6.0 - 1.9,
                rng.next_f64() * 8.0 - 8.0,
            );
            let direction = crate::emitters::cosine::cosine_hemisphere(
                &Vec3::new(0.0, 1.0, 0.0),
                [rng.next_f64(), rng.next_f64()],
            );
            let ray = Ray::new(origin, direction, 0.0);
            let found = world
                .intersect(&ray, 0.0, f64::INFINITY)
                .is_some_and(|hit| hit.material != 0);
            if !casters.may_hit(&ray) {
                assert!(!found, "{ray:?} finds a caster");
                skipped += 1;
            }
        }
        // Upward rays over the mirror floor: most miss the balls.
        assert!(skipped > count / 3, "{skipped}");
        // Downward rays above the floor find it.
        let down = Ray::new(Point3::new(5.0, 3.0, 9.0), Vec3::new(0.1, -1.0, 0.2), 0.0);
        assert!(casters.may_hit(&down));
    }
}
