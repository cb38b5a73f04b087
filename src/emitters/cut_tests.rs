//! Spheres cut by planes (see `cut`): light sampling picks and samples
//! the cap that shadow rays can reach, and its densities match the solid
//! angle in which the cap is the first hit.

use std::f64::consts::PI;

use super::tests::built;
use super::*;
use crate::color::Color;
use crate::geometry::surface_samples::uniform_sphere;
use crate::look::Look;
use crate::math::Ray;
use crate::render_scene::{RenderScene, SceneSettings};
use crate::rng::Rng;
use crate::scene::model::{Object, Scene};
use crate::world::World;

#[test]
fn sphere_cut_by_a_plane_is_sampled_on_the_reachable_cap() {
    use crate::scene::model::Material;
    let emissive = Material {
        emission: Color::gray(1.0),
        ..Material::default()
    };
    // A ceiling at y = 1 with a radius-1 light sunk into it: 0.2 hangs below.
    let root = Object::Group(vec![
        Object::Plane {
            normal: Vec3::y(),
            offset: 1.0,
            material: 0,
        },
        Object::Sphere {
            center: Point3::new(0.3, 1.8, -2.0),
            radius: 1.0,
            motion: Vec3::zeros(),
            material: 1,
        },
    ]);
    let scene = Scene::new(vec![Material::default(), emissive], root);
    let built = built(&scene);
    let (world, emitters) = (built.world(), built.emitters());
    let mut rng = Rng::new(11, 12);
    for reference in [Point3::new(0.0, -1.0, 0.0), Point3::new(2.5, 0.9, -1.0)] {
        // Every light sample reaches the light, with the density of its hit.
        let n = 20_000;
        let mut sampled = 0.0;
        for _ in 0..n {
            let u = [rng.next_f64(), rng.next_f64()];
            let Some(light) = emitters.sample(&reference, 0.0, rng.next_f64(), u) else {
                continue;
            };
            let ray = Ray::new(reference, light.direction, 0.0);
            let hit = world.intersect(&ray, 0.0, f64::INFINITY).unwrap();
            assert_eq!(hit.primitive, 1, "a cap sample behind the ceiling");
            assert!((hit.t - light.distance).abs() < 1e-9 * light.distance);
            let pdf = emitters.pdf(&reference, 0.0, &hit);
            assert!(
                (pdf - light.pdf).abs() < 1e-6 * light.pdf,
                "{pdf} vs {}",
                light.pdf
            );
            sampled += 1.0 / light.pdf / n as f64;
        }
        // ... and the samples cover the solid angle in which the light is seen.
        assert_covers_the_seen_light(world, reference, sampled, &mut rng);
    }
}

#[test]
fn a_one_sided_plane_cuts_nothing_seen_from_behind() {
    use crate::scene::model::Material;
    let emissive = Material {
        emission: Color::gray(1.0),
        ..Material::default()
    };
    // A ceiling at y = 1 facing down into the room, a light below it whose
    // top 0.2 pokes through.
    let root = Object::Group(vec![
        Object::Plane {
            normal: -Vec3::y(),
            offset: -1.0,
            material: 0,
        },
        Object::Sphere {
            center: Point3::new(0.3, 0.2, -2.0),
            radius: 1.0,
            motion: Vec3::zeros(),
            material: 1,
        },
    ]);
    let scene = Scene::new(vec![Material::default(), emissive], root);
    // yuzc19's look: its planes are one-sided.
    const { assert!(Look::YZC.one_sided_planes) };
    let built = RenderScene::build(scene.clone(), &SceneSettings::defaults(&scene, Look::YZC));
    let (world, emitters) = (built.world(), built.emitters());
    let mut rng = Rng::new(5, 6);
    // Above the ceiling every ray passes it: the whole sphere is in view,
    // not only the cap above the ceiling.
    let reference = Point3::new(0.5, 3.0, -1.5);
    let n = 20_000;
    let mut sampled = 0.0;
    for _ in 0..n {
        let u = [rng.next_f64(), rng.next_f64()];
        let light = emitters.sample(&reference, 0.0, 0.5, u).unwrap();
        let ray = Ray::new(reference, light.direction, 0.0);
        let hit = world.intersect(&ray, 0.0, f64::INFINITY).unwrap();
        assert_eq!(hit.primitive, 1);
        sampled += 1.0 / light.pdf / n as f64;
    }
    assert_covers_the_seen_light(world, reference, sampled, &mut rng);
}

#[test]
fn a_cut_sphere_is_picked_by_the_power_of_its_cap_on_the_cameras_side() {
    use crate::scene::model::Material;
    let light = |emission: f64| Material {
        emission: Color::gray(emission),
        ..Material::default()
    };
    // smallpt's ceiling light (radius 600, 0.27 below the ceiling at y = 1)
    // beside a small sphere light below it; the camera is at the origin.
    // (The pick probabilities only decide efficiency: a light never picked
    // is found by the bounces, with MIS weight 1.)
    let (radius, depth) = (600.0, 0.27);
    let root = Object::Group(vec![
        Object::Plane {
            normal: -Vec3::y(),
            offset: -1.0,
            material: 0,
        },
        Object::Sphere {
            center: Point3::new(0.0, 1.0 + radius - depth, -3.0),
            radius,
            motion: Vec3::zeros(),
            material: 1,
        },
        Object::Sphere {
            center: Point3::new(0.5, 0.0, -3.0),
            radius: 0.25,
            motion: Vec3::zeros(),
            material: 2,
        },
        // A wall at z = -10 and a big light behind it, which no shadow
        // ray from the camera's side reaches.
        Object::Plane {
            normal: Vec3::z(),
            offset: -10.0,
            material: 0,
        },
        Object::Sphere {
            center: Point3::new(0.0, 0.0, -20.0),
            radius: 9.9,
            motion: Vec3::zeros(),
            material: 2,
        },
    ]);
    let scene = Scene::new(vec![Material::default(), light(15.0), light(30.0)], root);
    let built = built(&scene);
    let emitters = built.emitters();
    let distribution = emitters.distribution.as_ref().unwrap();
    let cap = 2.0 * PI * radius * depth * 15.0;
    let small = 4.0 * PI * 0.25 * 0.25 * 30.0;
    let expected = small / (cap + small);
    assert!(
        (distribution.pmf(1) - expected).abs() < 1e-9,
        "{} vs {expected}",
        distribution.pmf(1)
    );
    assert_eq!(distribution.pmf(2), 0.0);
}

/// Asserts that light samples from `reference`, summing to `sampled` (their
/// `1 / pdf` over the count), cover the solid angle in which the light
/// (primitive 1) is the first hit, within 5%.
fn assert_covers_the_seen_light(world: &World, reference: Point3, sampled: f64, rng: &mut Rng) {
    let seen = seen_solid_angle(world, reference, 1, rng);
    assert!(
        (sampled - seen).abs() < 0.05 * seen,
        "{reference:?}: sampled {sampled} vs seen {seen}"
    );
}

/// The solid angle in which `primitive` is the first hit from `reference`,
/// by uniform directions (400k rays).
fn seen_solid_angle(world: &World, reference: Point3, primitive: usize, rng: &mut Rng) -> f64 {
    let m = 400_000;
    let seen = (0..m)
        .filter(|_| {
            let d = uniform_sphere([rng.next_f64(), rng.next_f64()]);
            let hit = world.intersect(&Ray::new(reference, d, 0.0), 0.0, f64::INFINITY);
            hit.is_some_and(|h| h.primitive == primitive)
        })
        .count();
    4.0 * PI * seen as f64 / m as f64
}
