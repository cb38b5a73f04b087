//! The conventions of the looks, checked on scenes whose pixels are known
//! in closed form: what a ray that misses brings back, and the course
//! framework's ray caster.

mod common;

use pathtracer::bsdf::phong::Phong;
use pathtracer::color::Color;
use pathtracer::integrator::Integrator;
use pathtracer::look::Look;
use pathtracer::math::Vec3;
use pathtracer::render::RenderSettings;
use pathtracer::sampler::SamplerKind;
use pathtracer::scene::model::{Light, Material, Object, Scene};

fn settings(look: Look, integrator: Integrator, spp: u32) -> RenderSettings {
    RenderSettings {
        width: 4,
        height: 4,
        spp,
        seed: 3,
        threads: None,
        integrator,
        max_depth: look.max_depth,
        sampler: SamplerKind::Independent,
        progress: false,
        progress_every: None,
        clamp: None,
        light_paths: true,
        look,
        dispersion: None,
    }
}

fn mean(scene: &Scene, settings: &RenderSettings) -> Color {
    let (image, _) = common::render_scene(scene, settings).expect("renders");
    let n = image.pixels.len() as f64;
    image.pixels.iter().fold(Color::BLACK, |sum, &c| sum + c) * (1.0 / n)
}

/// A diffuse floor of albedo 0.5 filling the view (the camera looks
/// straight down) under a uniform background of 0.8: every path leaves it
/// towards the open sky after one bounce.
fn floor_under_sky() -> Scene {
    let floor = Material {
        color: Color::gray(0.5),
        ..Material::default()
    };
    let root = Object::Plane {
        normal: Vec3::y(),
        offset: -1.0,
        material: 0,
    };
    let mut scene = common::scene_with(vec![floor], root);
    scene.camera.direction = Vec3::new(0.0, -1.0, 0.0);
    scene.camera.up = Vec3::z();
    scene.background = Color::gray(0.8);
    scene
}

#[test]
fn a_miss_brings_back_what_the_look_says() {
    // Films sum in fixed point: each sample is rounded to 2^-32, so a mean
    // is exact to half of that.
    let exact = 0.5 / (1u64 << pathtracer::fixed_sum::FRACTION_BITS) as f64;
    let scene = floor_under_sky();
    for integrator in [Integrator::Path, Integrator::Original] {
        let value = |look: Look| mean(&scene, &settings(look, integrator, 16)).r;
        // The original: the background only for camera rays.
        assert!(value(Look::ORIGINAL).abs() < 1e-12);
        assert!(value(Look::CAMBRIAN).abs() < 1e-12);
        // An environment light: albedo times the sky, exactly (the open
        // hemisphere integrates the cosine to 1 whatever the samples).
        assert!(
            (value(Look::PHYSICAL) - 0.4).abs() <= exact,
            "{}",
            value(Look::PHYSICAL)
        );
        // CaveSpiderLZJ's adds the background times the throughput too.
        assert!(
            (value(Look::CAV) - 0.4).abs() <= exact,
            "{}",
            value(Look::CAV)
        );
        // W-Solaris adds the sky raw on every miss: the floor glows with it.
        assert!(
            (value(Look::WSO) - 0.8).abs() <= exact,
            "{}",
            value(Look::WSO)
        );
    }
}

#[test]
fn the_pa1_look_casts_rays_with_the_framework_phong_term() {
    // A sphere straight ahead; the directional light shines along the
    // view, so the centre pixel sees n = l = v: kd + ks, unshadowed.
    let material = Material {
        color: Color::new(0.2, 0.4, 0.1),
        phong: Some(Phong {
            color: Color::gray(0.3),
            exponent: 20.0,
        }),
        ..Material::default()
    };
    let root = Object::Sphere {
        center: Vec3::new(0.0, 0.0, -5.0),
        radius: 1.0,
        motion: Vec3::zeros(),
        material: 0,
    };
    let mut scene = common::scene_with(vec![material], root);
    scene.camera.width = 3;
    scene.camera.height = 3;
    scene.lights = vec![Light::Directional {
        direction: Vec3::new(0.0, 0.0, -1.0),
        color: Color::gray(0.9),
    }];
    let mut s = settings(Look::PA1, Integrator::RayCast, 1);
    s.width = 3;
    s.height = 3;
    let (image, _) = common::render_scene(&scene, &s).expect("renders");
    let centre = image.pixels[4];
    let expected = (0.2 + 0.3) * 0.9;
    assert!((centre.r - expected).abs() < 1e-9, "{centre:?}");
    assert!((centre.g - (0.4 + 0.3) * 0.9).abs() < 1e-9);
}

#[test]
fn the_cav_look_takes_no_light_from_the_lights_block() {
    // The floor under a black sky, lit only by a point light: the original
    // (a scene without emitters) adds the light, CaveSpiderLZJ's does not.
    let mut scene = floor_under_sky();
    scene.background = Color::BLACK;
    scene.lights = vec![Light::Point {
        position: pathtracer::math::Point3::new(0.0, 3.0, 0.0),
        color: Color::gray(1.0),
    }];
    let value = |look: Look| mean(&scene, &settings(look, Integrator::Path, 4)).r;
    assert!(value(Look::ORIGINAL) > 0.1, "{}", value(Look::ORIGINAL));
    assert_eq!(value(Look::CAV), 0.0);
}

/// Camera looking down at a glass plane (y = 0) over a diffuse floor
/// (y = -0.5), under a small light: with one-sided planes light passes up
/// through the glass unrefracted but comes down refracted.
fn glass_over_floor() -> Scene {
    let floor = Material {
        color: Color::gray(0.8),
        ..Material::default()
    };
    let glass = Material {
        diffuse: 0.0,
        refract: 1.0,
        ior: 1.5,
        ..Material::default()
    };
    let light = Material {
        emission: Color::gray(4.0),
        ..Material::default()
    };
    let plane = |offset: f64, material: usize| Object::Plane {
        normal: Vec3::y(),
        offset,
        material,
    };
    let root = Object::Group(vec![
        plane(-0.5, 0),
        plane(0.0, 1),
        Object::Sphere {
            center: Vec3::new(0.3, 2.0, -0.5),
            radius: 0.4,
            motion: Vec3::zeros(),
            material: 2,
        },
    ]);
    let mut scene = common::scene_with(vec![floor, glass, light], root);
    scene.camera.center = Vec3::new(0.0, 3.0, 0.0);
    scene.camera.direction = Vec3::new(0.0, -1.0, 0.0);
    scene.camera.up = Vec3::z();
    scene
}

#[test]
fn one_sided_planes_give_the_path_integrator_the_original_estimators_image() {
    // The light subpaths that find caustics assume that visibility does not
    // depend on direction; the yzc look's one-sided planes break that (a
    // connection from the floor up to the camera would pass the glass that
    // the camera's ray is refracted by), so that look traces none.
    let scene = glass_over_floor();
    let average = |integrator: Integrator| {
        let mut s = settings(Look::YZC, integrator, 1024);
        (s.width, s.height) = (8, 8);
        let (image, _) = common::render_scene(&scene, &s).expect("renders");
        let n = image.pixels.len() as f64;
        image.pixels.iter().map(|c| c.r).sum::<f64>() / n
    };
    let (path, original) = (average(Integrator::Path), average(Integrator::Original));
    assert!(original > 0.1, "{original}");
    // (Traced from the light's side too, the floor gets 10% more.)
    assert!((path / original - 1.0).abs() < 0.03, "{path} {original}");
}

/// A glass ball resting on a diffuse floor under a small light (as in
/// Cambrian's `sample_rec`), seen from the side: the caustic around its
/// foot comes through the ball.
fn glass_ball_on_floor() -> Scene {
    let mut scene = glass_over_floor();
    let Object::Group(objects) = &mut scene.root else {
        unreachable!("glass_over_floor is a group");
    };
    objects[0] = Object::Plane {
        normal: Vec3::y(),
        offset: 0.0,
        material: 0,
    };
    objects[1] = Object::Sphere {
        center: Vec3::new(0.0, 1.0, 0.0),
        radius: 1.0,
        motion: Vec3::zeros(),
        material: 1,
    };
    objects[2] = Object::Sphere {
        center: Vec3::new(0.0, 5.0, 0.0),
        radius: 0.3,
        motion: Vec3::zeros(),
        material: 2,
    };
    scene.materials[2].emission = Color::gray(100.0);
    scene.camera.center = Vec3::new(0.0, 1.5, 4.0);
    scene.camera.direction = Vec3::new(0.0, -1.5, -4.0);
    scene.camera.up = Vec3::y();
    scene
}

#[test]
fn cambrian_sphere_test_keeps_the_image_of_paths_traced_from_the_camera_alone() {
    // Cambrian's sphere test takes a glass ball's exit for an entry, so
    // light does not cross the ball the same way both ways: light subpaths
    // stop where they would cross such a sphere, and camera paths through
    // it count alone. (Without that stop this image comes out 12% dark.)
    let scene = glass_ball_on_floor();
    let average = |light_paths: bool| {
        let mut s = settings(Look::CAMBRIAN, Integrator::Path, 4096);
        (s.width, s.height, s.light_paths) = (8, 8, light_paths);
        let (image, _) = common::render_scene(&scene, &s).expect("renders");
        let n = image.pixels.len() as f64;
        image.pixels.iter().map(|c| c.r).sum::<f64>() / n
    };
    let (with_light_paths, camera_alone) = (average(true), average(false));
    assert!(camera_alone > 0.1, "{camera_alone}");
    assert!(
        (with_light_paths / camera_alone - 1.0).abs() < 0.03,
        "{with_light_paths} {camera_alone}"
    );
}

#[test]
fn wso_planes_keep_a_ray_that_leaves_from_a_point_on_them() {
    // W-Solaris's planes accept t >= 0 and its rays leave from the hit
    // itself: a camera ray refracted by a glass plane at y = -4 from a hit
    // point that rounds onto the plane meets it again at distance 0, hit
    // after hit, and never reaches the emitting floor under it.
    let mut scene = glass_over_floor();
    let Object::Group(objects) = &mut scene.root else {
        unreachable!("glass_over_floor is a group");
    };
    objects.truncate(2);
    objects[0] = Object::Plane {
        normal: Vec3::y(),
        offset: -4.5,
        material: 2,
    };
    objects[1] = Object::Plane {
        normal: Vec3::y(),
        offset: -4.0,
        material: 1,
    };
    scene.materials[2].emission = Color::gray(0.5);
    let red = |look: Look| mean(&scene, &settings(look, look.integrator, 64)).r;
    // In f64 (the plane's own rule) and in W-Solaris's float32 test.
    let in_f64 = Look {
        ray_origins: pathtracer::look::RayOrigins::AtHit,
        single_precision_hits: false,
        ..Look::WSO
    };
    let kept = red(in_f64);
    let kept_in_float32 = red(Look::WSO);
    let refracted_through = red(Look {
        planes_accept_zero: false,
        ..in_f64
    });
    // Through the glass the floor is 0.5 (its emission) times what the
    // glass does not reflect (Schlick: about 0.96); kept on the glass, a
    // path brings nothing.
    assert!(refracted_through > 0.45, "{refracted_through}");
    assert!(kept < 0.5 * refracted_through, "{kept} {refracted_through}");
    assert!(
        kept_in_float32 < 0.5 * refracted_through,
        "{kept_in_float32} {refracted_through}"
    );
}

#[test]
fn cambrian_rectangles_lose_the_hits_that_round_off_their_plane() {
    // An emitting wall filling the view with nothing behind it. Cambrian's
    // rectangle keeps a hit only when the hit point's z rounds exactly to
    // the wall's: the camera rays that do not go through it and find
    // black, so the wall is darker in the cambrian look than it is.
    let light = Material {
        color: Color::BLACK,
        emission: Color::gray(1.0),
        ..Material::default()
    };
    let root = Object::Rectangle {
        origin: Vec3::new(-100.0, -100.0, 0.0),
        edge_u: Vec3::new(200.0, 0.0, 0.0),
        edge_v: Vec3::new(0.0, 200.0, 0.0),
        material: 0,
    };
    let mut scene = common::scene_with(vec![light], root);
    // As far as Cambrian's camera from its back wall in `focus_on_earth`.
    scene.camera.center = Vec3::new(0.3, 0.7, 295.1);
    let seen = |look: Look| mean(&scene, &settings(look, look.integrator, 64)).r;
    let solid = seen(Look {
        cambrian_rectangles: false,
        ..Look::CAMBRIAN
    });
    let cambrian = seen(Look::CAMBRIAN);
    assert!((solid - 1.0).abs() < 1e-9, "{solid}");
    assert!(cambrian > 0.6 && cambrian < 0.95, "{cambrian}");
}

#[test]
fn cambrian_eyes_fill_a_square_of_side_aperture_size() {
    use pathtracer::camera::Camera;
    use pathtracer::scene::LoadOptions;
    use pathtracer::scene::model::Dialect;
    let text = "PerspectiveCamera { center 0 0 0 direction 0 0 -1 up 0 1 0 angle 60 \
                width 4 height 4 focal_length 250 aperture_size 2 }";
    let options = LoadOptions {
        dialect: Some(Dialect::Cambrian),
        ..LoadOptions::default()
    };
    let file = std::path::Path::new("cambrian.txt");
    let document = pathtracer::scene::parse(text, file).expect("parses");
    let scene = pathtracer::scene::build(&document, file, &options).expect("builds");
    let camera = Camera::new(&Look::CAMBRIAN.camera(&scene.camera), 4, 4);
    // Corners of the unit square of lens samples reach the cube's edges,
    // one either way along right (x) and up (y), never beyond.
    for (lens, corner) in [([0.0, 0.0], (-1.0, -1.0)), ([1.0, 1.0], (1.0, 1.0))] {
        let eye = camera.ray(2.0, 2.0, lens, 0.0).origin;
        assert!((eye.x.abs() - 1.0).abs() < 1e-12 && (eye.y.abs() - 1.0).abs() < 1e-12);
        assert_eq!((eye.x.signum(), eye.y.signum()), corner, "{eye:?}");
    }
    for i in 0..64 {
        let lens = [(i % 8) as f64 / 8.0 + 0.01, (i / 8) as f64 / 8.0 + 0.01];
        let eye = camera.ray(1.0, 3.0, lens, 0.0).origin;
        assert!(eye.x.abs() <= 1.0 && eye.y.abs() <= 1.0 && eye.z == 0.0);
    }
}

#[test]
fn cambrian_reads_the_world_map_28_texels_early() {
    // `tex_world_map.bmp` has a 124-byte header (pixels at byte 138); the
    // course framework's reader starts at byte 54, so its texel in column
    // c shows our pixel c - 28 of the same row.
    use pathtracer::scene::LoadOptions;
    let Some(file) =
        common::shared_file("reference/cambrian-pathtracer/testcases/focus_on_earth.txt")
    else {
        return;
    };
    let base = file
        .parent()
        .and_then(std::path::Path::parent)
        .map(|p| p.to_path_buf());
    let options = LoadOptions {
        base,
        ..LoadOptions::default()
    };
    let scene = pathtracer::scene::load_scene(&file, &options).expect("loads");
    assert_eq!(scene.framework_readings.len(), 1, "only the world map");
    let (&index, framework) = scene.framework_readings.iter().next().expect("one");
    let ours = &scene.textures[index];
    assert_eq!((ours.width, ours.height), (1280, 640));
    for (row, column) in [(0, 28), (100, 500), (639, 1279), (320, 700)] {
        let k = row * 1280 + column;
        assert_eq!(framework.texels[k], ours.texels[k - 28], "{row} {column}");
    }
}
