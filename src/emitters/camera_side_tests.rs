//! The camera's side of the planes, from which light sampling weighs the
//! emitters, is its canvas's: smallpt's eye sits behind the box's front
//! wall, its rays start inside the box.

use super::tests::built;
use super::*;
use crate::scene::model::{Material, Object};

/// A box's front wall at z = 170 between smallpt's eye (z = 295.6, canvas
/// 140 ahead) and a small sphere light inside the box.
fn smallpt_like(canvas_distance: f64) -> Scene {
    let light = Material {
        color: Color::BLACK,
        emission: Color::gray(20.0),
        ..Material::default()
    };
    let root = Object::Group(vec![
        Object::Plane {
            normal: Vec3::z(),
            offset: 170.0,
            material: 0,
        },
        Object::Sphere {
            center: Point3::new(50.0, 64.0, 90.0),
            radius: 12.0,
            motion: Vec3::zeros(),
            material: 1,
        },
    ]);
    let mut scene = Scene::new(vec![Material::default(), light], root);
    scene.camera.center = Point3::new(50.0, 52.0, 295.6);
    scene.camera.direction = Vec3::new(0.0, -0.042612, -1.0);
    scene.camera.canvas_distance = canvas_distance;
    scene
}

#[test]
fn a_light_in_the_box_is_sampled_when_the_eye_is_behind_its_front_wall() {
    // The canvas (z about 155.7) is inside the box: the light is on the
    // camera's side. (Taken from the eye, it was behind the wall and never
    // sampled: crosscheck.txt lost light sampling and light subpaths.)
    let inside_box = built(&smallpt_like(140.0));
    let emitters = inside_box.emitters();
    assert!(!emitters.is_empty());
    let inside = Point3::new(50.0, 10.0, 100.0);
    let sample = emitters.sample(&inside, 0.0, 0.5, [0.3, 0.7]);
    assert!(sample.is_some_and(|s| s.pdf > 0.0));
    // A canvas that does not reach the wall leaves the light behind it.
    assert!(built(&smallpt_like(100.0)).emitters().is_empty());
}
