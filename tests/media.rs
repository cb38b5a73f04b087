//! Participating media in the path integrator: white furnaces that a
//! non-absorbing medium must leave unchanged, and the transmittance of a
//! pure absorber seen along a ray and in an image.

use pathtracer::color::Color;
use pathtracer::integrator::{CameraSample, Integrator, Splats};
use pathtracer::look::Look;
use pathtracer::math::{Ray, Vec3};
use pathtracer::medium::{HenyeyGreenstein, Medium};
use pathtracer::render_scene::{RenderScene, SceneSettings};
use pathtracer::rng::Rng;
use pathtracer::sampler::Sampler;
use pathtracer::scene::model::{Material, Object, Scene};

/// `scene` in the physical look, with paths of `max_depth` vertices.
fn physical(scene: &Scene, max_depth: u32) -> RenderScene {
    let settings = SceneSettings {
        max_depth,
        ..SceneSettings::defaults(scene, Look::PHYSICAL)
    };
    RenderScene::build(scene.clone(), &settings)
}

/// The path integrator's radiance along `ray`, from a default camera sample.
fn path_radiance(view: &RenderScene, ray: Ray, sampler: &mut Sampler) -> Color {
    Integrator::Path.radiance(
        view,
        ray,
        &CameraSample::default(),
        sampler,
        &mut Splats::default(),
    )
}

fn sphere(center: Vec3, radius: f64, material: usize) -> Object {
    Object::Sphere {
        center,
        radius,
        motion: Vec3::zeros(),
        material,
    }
}

/// Scattering only (albedo 1 in every channel), a different extinction per
/// channel, forward scattering.
fn white_medium(scale: f64) -> Medium {
    Medium {
        sigma_a: Color::BLACK,
        sigma_s: Color::new(0.5, 1.0, 2.0) * scale,
        phase: HenyeyGreenstein { g: 0.3 },
        cambrian_mist: None,
    }
}

/// Per channel: the mean radiance of `paths` rays from `origin` in random
/// directions (towards random points of the unit ball when `aimed`), and
/// its standard error.
fn mean_radiance(scene: &Scene, origin: Vec3, aimed: bool, paths: u64) -> [(f64, f64); 3] {
    let view = physical(scene, 1000);
    assert!(view.media() && !view.light_paths());
    let mut sums = [0.0; 3];
    let mut squares = [0.0; 3];
    for i in 0..paths {
        let mut rng = Rng::for_sample(i, 0, 11);
        let z = 2.0 * rng.next_f64() - 1.0;
        let phi = 2.0 * std::f64::consts::PI * rng.next_f64();
        let r = (1.0 - z * z).max(0.0).sqrt();
        let mut d = Vec3::new(r * phi.cos(), r * phi.sin(), z);
        if aimed {
            d = (d * rng.next_f64().cbrt() - origin).normalize();
        }
        let mut sampler = Sampler::Independent(rng);
        let l = path_radiance(&view, Ray::new(origin, d, 0.0), &mut sampler);
        for (k, v) in [l.r, l.g, l.b].into_iter().enumerate() {
            sums[k] += v;
            squares[k] += v * v;
        }
    }
    let n = paths as f64;
    std::array::from_fn(|k| {
        let mean = sums[k] / n;
        let variance = (squares[k] / n - mean * mean).max(0.0);
        (mean, (variance / n).sqrt())
    })
}

/// Within 4 standard errors (and a floor of 1e-9 for zero-variance
/// estimates) of `want` in every channel.
fn assert_near(got: [(f64, f64); 3], want: f64, what: &str) {
    for (channel, (mean, error)) in got.into_iter().enumerate() {
        assert!(
            (mean - want).abs() <= 4.0 * error + 1e-9,
            "{what}: channel {channel} mean {mean} +- {error}, want {want}"
        );
    }
}

#[test]
fn a_scattering_ball_in_a_white_furnace_returns_the_background() {
    // An index-matched ball (an interface) of a non-absorbing medium under
    // a uniform environment of radiance 1: radiance is 1 everywhere, through
    // the ball too, whatever the path does in it (phase sampling, chromatic
    // free flights, roulette). Rays start outside and are aimed at it.
    let ball = Material {
        interface: true,
        interior: Some(white_medium(1.0)),
        ..Material::default()
    };
    let mut scene = Scene::new(
        vec![ball],
        Object::Group(vec![sphere(Vec3::zeros(), 1.0, 0)]),
    );
    scene.background = Color::gray(1.0);
    for origin in [Vec3::new(0.2, -0.3, 1.5), Vec3::new(0.0, 0.0, 3.0)] {
        let got = mean_radiance(&scene, origin, true, 20_000);
        assert_near(got, 1.0, "furnace ball");
        // Not trivially exact: the chromatic flights give paths different weights.
        assert!(got[2].1 > 1e-4, "{got:?}");
    }
}

#[test]
fn a_grey_scattering_ball_in_a_white_furnace_returns_the_background_exactly() {
    // With the same extinction in every channel, every weight of a path in
    // a non-absorbing medium is exactly 1 (a collision's albedo, a pass's
    // transmittance over its probability, the phase function over its
    // density, a Fresnel choice at a white glass over its probability):
    // each sample, not only the mean, returns the background. Behind an
    // interface and behind a glass boundary.
    let medium = Medium {
        sigma_a: Color::BLACK,
        sigma_s: Color::gray(1.5),
        phase: HenyeyGreenstein { g: -0.4 },
        cambrian_mist: None,
    };
    let interface = Material {
        interface: true,
        interior: Some(medium),
        ..Material::default()
    };
    let glass = Material {
        color: Color::WHITE,
        diffuse: 0.0,
        refract: 1.0,
        ior: 1.5,
        interior: Some(medium),
        ..Material::default()
    };
    for ball in [interface, glass] {
        let mut scene = Scene::new(
            vec![ball],
            Object::Group(vec![sphere(Vec3::zeros(), 1.0, 0)]),
        );
        scene.background = Color::gray(1.0);
        let view = physical(&scene, 1000);
        let origin = Vec3::new(0.1, 0.2, 3.0);
        for i in 0..5_000 {
            let mut rng = Rng::for_sample(i, 0, 13);
            let target =
                Vec3::new(rng.next_f64(), rng.next_f64(), 0.0) * 1.4 - Vec3::new(0.7, 0.7, 0.0);
            let ray = Ray::new(origin, (target - origin).normalize(), 0.0);
            let mut sampler = Sampler::Independent(rng);
            let l = path_radiance(&view, ray, &mut sampler);
            for v in [l.r, l.g, l.b] {
                assert!((v - 1.0).abs() < 1e-12, "sample {i}: {l:?}");
            }
        }
    }
}

#[test]
fn a_scattering_medium_inside_an_emitting_enclosure_returns_its_emission() {
    // A black sphere of emission 1 filled by a scene-wide non-absorbing
    // medium: radiance 1 everywhere. Light reaches medium vertices by light
    // samples (with transmittance) and by phase sampling, MIS-weighted: a
    // wrong weight or a missing transmittance moves the mean.
    let wall = Material {
        color: Color::BLACK,
        emission: Color::gray(1.0),
        ..Material::default()
    };
    let mut scene = Scene::new(
        vec![wall],
        Object::Group(vec![sphere(Vec3::zeros(), 10.0, 0)]),
    );
    scene.medium = Some(white_medium(0.1));
    let got = mean_radiance(&scene, Vec3::new(1.0, 2.0, -3.0), false, 20_000);
    assert_near(got, 1.0, "emitting enclosure");
    // With absorption the medium must darken it.
    scene.medium = Some(Medium {
        sigma_a: Color::gray(0.05),
        ..white_medium(0.1)
    });
    let got = mean_radiance(&scene, Vec3::new(1.0, 2.0, -3.0), false, 4_000);
    assert!(got.iter().all(|(mean, _)| *mean < 0.95), "{got:?}");
}

fn absorber_scene() -> Scene {
    let absorber = Material {
        interface: true,
        interior: Some(Medium {
            sigma_a: Color::new(0.25, 0.5, 1.0),
            sigma_s: Color::BLACK,
            phase: HenyeyGreenstein { g: 0.0 },
            cambrian_mist: None,
        }),
        ..Material::default()
    };
    let light = Material {
        color: Color::BLACK,
        emission: Color::gray(2.0),
        ..Material::default()
    };
    let root = Object::Group(vec![
        sphere(Vec3::zeros(), 1.0, 0),
        sphere(Vec3::new(0.0, 0.0, -20.0), 10.0, 1),
    ]);
    Scene::new(vec![absorber, light], root)
}

#[test]
fn an_emitter_through_a_pure_absorber_is_attenuated_by_exp_minus_sigma_t_d() {
    let view = physical(&absorber_scene(), 5);
    // Rays at height h cross a chord 2 sqrt(1 - h^2) of the ball.
    for h in [0.0, 0.5, 0.9] {
        let ray = Ray::new(Vec3::new(0.0, h, 5.0), Vec3::new(0.0, 0.0, -1.0), 0.0);
        let mut sampler = Sampler::Independent(Rng::for_sample(0, 0, 1));
        let l = path_radiance(&view, ray, &mut sampler);
        let d = 2.0 * (1.0 - h * h).sqrt();
        let want = [0.25, 0.5, 1.0].map(|sigma: f64| 2.0 * (-sigma * d).exp());
        for (got, want) in [l.r, l.g, l.b].into_iter().zip(want) {
            assert!((got - want).abs() < 1e-9, "h {h}: {got} vs {want}");
        }
    }
}

#[test]
fn an_image_of_an_emitter_through_an_absorbing_ball_has_its_transmittance() {
    // A narrow camera (0.5 degrees) at z = 5 sees the emitter through the
    // ball's centre: every pixel within 1e-3 of 2 exp(-2 sigma).
    let mut scene = absorber_scene();
    scene.camera.center = Vec3::new(0.0, 0.0, 5.0);
    scene.camera.width = 4;
    scene.camera.height = 4;
    scene.camera.fov = Some((0.5, pathtracer::scene::model::FovAxis::Vertical));
    let settings = pathtracer::render::RenderSettings {
        width: 4,
        height: 4,
        spp: 4,
        seed: 0,
        threads: Some(2),
        integrator: Integrator::Path,
        max_depth: 5,
        sampler: pathtracer::sampler::SamplerKind::Sobol,
        progress: false,
        progress_every: None,
        clamp: None,
        light_paths: true,
        look: Look::PHYSICAL,
        dispersion: None,
    };
    let scene = RenderScene::build(scene, &settings.scene());
    let (image, _) = pathtracer::render::render(&scene, &settings).expect("renders");
    let want = [0.25, 0.5, 1.0].map(|sigma: f64| 2.0 * (-2.0 * sigma).exp());
    for pixel in &image.pixels {
        for (got, want) in [pixel.r, pixel.g, pixel.b].into_iter().zip(want) {
            assert!((got - want).abs() < 1e-3 * want, "{got} vs {want}");
        }
    }
}

#[test]
fn light_subpaths_are_off_and_said_so_in_scenes_with_media() {
    // A glass ball under a small light: light subpaths run without media,
    // and are off (with a note) once a medium fills the scene.
    let glass = Material {
        color: Color::WHITE,
        diffuse: 0.0,
        refract: 1.0,
        ..Material::default()
    };
    let floor = Material::default();
    let light = Material {
        color: Color::BLACK,
        emission: Color::gray(10.0),
        ..Material::default()
    };
    let root = Object::Group(vec![
        sphere(Vec3::new(0.0, 0.0, -5.0), 1.0, 0),
        sphere(Vec3::new(0.0, -1001.0, -5.0), 1000.0, 1),
        sphere(Vec3::new(0.0, 5.0, -5.0), 0.2, 2),
    ]);
    let mut scene = Scene::new(vec![glass, floor, light], root);
    let view = physical(&scene, 5);
    assert!(view.light_paths());
    assert!(view.notices(Integrator::Path).is_empty());
    scene.medium = Some(white_medium(0.01));
    let view = physical(&scene, 5);
    assert!(view.media() && !view.light_paths());
    let notes = view.notices(Integrator::Path);
    assert!(notes[0].to_string().contains("light subpaths"), "{notes:?}");
    let notes = view.notices(Integrator::Original);
    assert!(
        notes[0].to_string().contains("original estimator ignores"),
        "{notes:?}"
    );
}

#[test]
fn a_directional_light_through_an_absorbing_ball_is_attenuated_twice() {
    // PA1 lighting (no emitters): a floor lit from straight above, seen
    // from above through an absorbing ball that also stands between the
    // floor point and the light: 0.5 (albedo) e^(-sigma 2) twice. A shadow
    // ray that stopped at the interface would give 0.
    let absorber = absorber_scene().materials[0].clone();
    let floor = Material {
        color: Color::gray(0.5),
        ..Material::default()
    };
    let root = Object::Group(vec![
        sphere(Vec3::new(0.0, 2.0, 0.0), 1.0, 0),
        Object::Plane {
            normal: Vec3::new(0.0, 1.0, 0.0),
            offset: 0.0,
            material: 1,
        },
    ]);
    let mut scene = Scene::new(vec![absorber, floor], root);
    scene
        .lights
        .push(pathtracer::scene::model::Light::Directional {
            direction: Vec3::new(0.0, -1.0, 0.0),
            color: Color::WHITE,
        });
    let view = physical(&scene, 5);
    assert!(!view.direct_lights().is_empty());
    let ray = Ray::new(Vec3::new(0.0, 5.0, 0.0), Vec3::new(0.0, -1.0, 0.0), 0.0);
    let mut sampler = Sampler::Independent(Rng::for_sample(0, 0, 2));
    let l = path_radiance(&view, ray, &mut sampler);
    let want = [0.25, 0.5, 1.0].map(|sigma: f64| 0.5 * (-4.0 * sigma).exp());
    for (got, want) in [l.r, l.g, l.b].into_iter().zip(want) {
        assert!((got - want).abs() < 1e-9, "{got} vs {want}");
    }
}
