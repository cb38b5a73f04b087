//! Dispersion: a prism bends each wavelength as Snell's law with the
//! Cauchy index says, and splitting paths to one channel or wavelength
//! leaves the expected image of a glass without dispersion unchanged.

use pathtracer::bsdf::{Bsdf, DielectricFresnel, GlassChoice, LobeSet, Rules};
use pathtracer::color::Color;
use pathtracer::integrator::{CameraSample, Integrator, Splats};
use pathtracer::look::Look;
use pathtracer::math::{Ray, Vec3};
use pathtracer::render_scene::lobes::lobe_set;
use pathtracer::render_scene::{RenderScene, SceneSettings};
use pathtracer::rng::Rng;
use pathtracer::sampler::Sampler;
use pathtracer::scene::model::{Material, Object, Scene};
use pathtracer::spectral::{Dispersion, LAMBDA_MAX, LAMBDA_MIN, PathSpectrum};

const RULES: Rules = Rules {
    fresnel: DielectricFresnel::Exact,
    glass: GlassChoice::Fresnel,
};

/// Cambrian's bunny glass.
const CAUCHY: Dispersion = Dispersion::Cauchy {
    a: 2.385,
    b: 0.0117,
};

fn glass(dispersion: Option<Dispersion>) -> Material {
    Material {
        diffuse: 0.0,
        refract: 1.0,
        ior: 1.5,
        dispersion,
        ..Material::default()
    }
}

/// A path split at `nm` (the split's `u` for that wavelength).
fn split_at(nm: f64) -> PathSpectrum {
    let mut spectrum = PathSpectrum::Rgb;
    let mut throughput = Color::WHITE;
    let u = (nm - LAMBDA_MIN) / (LAMBDA_MAX - LAMBDA_MIN);
    spectrum.split(&CAUCHY, u, &mut throughput);
    spectrum
}

/// The refracted direction of `d` through the surface of normal `normal`
/// (the side `d` comes from), entering (`entering`) or leaving the glass,
/// by the BSDF at the path's index.
fn refract(set: &LobeSet, d: Vec3, normal: Vec3, entering: bool, spectrum: &PathSpectrum) -> Vec3 {
    let wo = -d;
    let bsdf = Bsdf::new(set, Color::WHITE, &normal, entering, normal.dot(&wo), RULES);
    let dispersion = bsdf.dispersion().expect("a dispersive glass");
    let set = bsdf.set().with_ior(dispersion.ior(spectrum));
    let bsdf = bsdf.with_set(&set);
    // uc near 1 takes the refraction (reflection has probability R).
    let sample = bsdf
        .sample(&wo, 1.0 - 1e-9, [0.5, 0.5])
        .expect("a direction");
    assert!(sample.is_delta());
    sample.wi
}

fn sin_between(a: &Vec3, b: &Vec3) -> f64 {
    a.cross(b).norm()
}

#[test]
fn a_prism_bends_each_wavelength_by_snells_law_with_the_cauchy_index() {
    let set = lobe_set(&glass(Some(CAUCHY)), Default::default());
    // A 30 degree prism, apex up, in the xy plane; outward face normals.
    // (Cambrian's glass has an index near 2.4: at 60 degrees the light
    // would be reflected inside.)
    let apex = 30f64.to_radians();
    let left = Vec3::new(-(apex / 2.0).cos(), (apex / 2.0).sin(), 0.0);
    let right = Vec3::new((apex / 2.0).cos(), (apex / 2.0).sin(), 0.0);
    // 40 degrees from the left face's normal, upwards.
    let incoming = Vec3::new(25f64.to_radians().cos(), 25f64.to_radians().sin(), 0.0);
    let theta_in = sin_between(&incoming, &left).asin();
    let mut deviations = Vec::new();
    for nm in [400.0, 450.0, 500.0, 550.0, 600.0, 650.0, 700.0] {
        let spectrum = split_at(nm);
        let n = Dispersion::cauchy(2.385, 0.0117, nm);
        assert!((n - (2.385 + 0.0117e6 / (nm * nm))).abs() < 1e-12);
        let inside = refract(&set, incoming, left, true, &spectrum);
        // Snell at the first face: sin θ = n sin θ'.
        let (sin_in, sin_inside) = (sin_between(&incoming, &left), sin_between(&inside, &left));
        assert!((sin_in - n * sin_inside).abs() < 1e-12, "{nm} nm");
        let out = refract(&set, inside, -right, false, &spectrum);
        assert!((n * sin_between(&inside, &right) - sin_between(&out, &right)).abs() < 1e-12);
        assert!(out.z.abs() < 1e-12 && (out.norm() - 1.0).abs() < 1e-12);
        // The prism's deviation from the closed form of the two refractions.
        let theta_inside = (theta_in.sin() / n).asin();
        let theta_exit = (n * (apex - theta_inside).sin()).asin();
        let expected = theta_in + theta_exit - apex;
        let deviation = incoming.dot(&out).clamp(-1.0, 1.0).acos();
        assert!(
            (deviation - expected).abs() < 1e-9,
            "{nm} nm: {deviation} vs {expected}"
        );
        deviations.push(deviation);
    }
    // Shorter wavelengths bend more, by a visible amount over the spectrum.
    assert!(deviations.windows(2).all(|w| w[0] > w[1]), "{deviations:?}");
    assert!(
        deviations[0] - deviations[6] > 1f64.to_radians(),
        "{deviations:?}"
    );
}

/// A glass ball (material 0) in a diffuse enclosure (material 1) lit by a
/// small emitting sphere (material 2).
fn glass_scene(glass: Material, wall: Color) -> Scene {
    let sphere = |center: Vec3, radius: f64, material: usize| Object::Sphere {
        center,
        radius,
        motion: Vec3::zeros(),
        material,
    };
    let wall = Material {
        color: wall,
        ..Material::default()
    };
    let lamp = Material {
        color: Color::BLACK,
        emission: Color::gray(8.0),
        ..Material::default()
    };
    let unused = self::glass(Some(Dispersion::Channels([1.3, 1.5, 1.7])));
    Scene::new(
        vec![glass, wall, lamp, unused],
        Object::Group(vec![
            sphere(Vec3::zeros(), 1.0, 0),
            sphere(Vec3::zeros(), 8.0, 1),
            sphere(Vec3::new(0.0, 4.0, -2.0), 0.7, 2),
        ]),
    )
}

/// Per channel the mean radiance of `paths` camera paths from (0, 0, 3)
/// aimed at random points of the ball, with its standard error; and the
/// radiances themselves.
fn radiance_samples(scene: &Scene, paths: u64) -> ([(f64, f64); 3], Vec<Color>) {
    // Both kinds of scene by the same estimator (light subpaths are off
    // in dispersive scenes).
    let settings = SceneSettings {
        light_paths: false,
        ..SceneSettings::defaults(scene, Look::PHYSICAL)
    };
    let view = RenderScene::build(scene.clone(), &settings);
    let origin = Vec3::new(0.0, 0.0, 3.0);
    let mut samples = Vec::new();
    for i in 0..paths {
        let mut rng = Rng::for_sample(i, 0, 5);
        let target = Vec3::new(rng.next_f64(), rng.next_f64(), rng.next_f64()) * 1.2
            - Vec3::new(0.6, 0.6, 0.6);
        let ray = Ray::new(origin, (target - origin).normalize(), 0.0);
        let mut sampler = Sampler::Independent(rng);
        samples.push(Integrator::Path.radiance(
            &view,
            ray,
            &CameraSample::default(),
            &mut sampler,
            &mut Splats::default(),
        ));
    }
    let n = paths as f64;
    let stats = std::array::from_fn(|k| {
        let values = samples.iter().map(|c| [c.r, c.g, c.b][k]);
        let mean = values.clone().sum::<f64>() / n;
        let variance = values.map(|v| (v - mean) * (v - mean)).sum::<f64>() / (n - 1.0);
        (mean, (variance / n).sqrt())
    });
    (stats, samples)
}

fn assert_same_mean(a: [(f64, f64); 3], b: [(f64, f64); 3], what: &str) {
    for k in 0..3 {
        let ((ma, ea), (mb, eb)) = (a[k], b[k]);
        let error = (ea * ea + eb * eb).sqrt();
        assert!(
            (ma - mb).abs() <= 4.0 * error,
            "{what}: channel {k}: {ma} +- {ea} vs {mb} +- {eb}"
        );
        assert!(
            error < 0.015 * ma,
            "{what}: too noisy to tell: {error} of {ma}"
        );
    }
}

#[test]
fn a_channel_split_with_equal_indices_renders_the_plain_glass_mean() {
    let wall = Color::new(0.8, 0.5, 0.3);
    let (plain, _) = radiance_samples(&glass_scene(glass(None), wall), 120_000);
    let equal = Some(Dispersion::Channels([1.5; 3]));
    let (split, _) = radiance_samples(&glass_scene(glass(equal), wall), 120_000);
    assert_same_mean(plain, split, "channels");
}

#[test]
fn a_wavelength_split_without_dispersion_renders_the_plain_glass_mean() {
    // Grey materials: the spectral products equal the RGB ones.
    let wall = Color::gray(0.6);
    let (plain, _) = radiance_samples(&glass_scene(glass(None), wall), 120_000);
    let flat = Some(Dispersion::Cauchy { a: 1.5, b: 0.0 });
    let (split, _) = radiance_samples(&glass_scene(glass(flat), wall), 120_000);
    assert_same_mean(plain, split, "wavelengths");
}

#[test]
fn a_scene_whose_paths_meet_no_dispersive_glass_traces_exactly_as_without_one() {
    // The scene holds a dispersive material that no shape uses: every path
    // is traced bit for bit as in the same scene without it (no wavelength
    // drawn, no sample dimension spent).
    let wall = Color::new(0.8, 0.5, 0.3);
    let with_unused = glass_scene(glass(None), wall);
    let mut without = with_unused.clone();
    without.materials.truncate(3);
    assert!(with_unused.has_dispersion() && !without.has_dispersion());
    let (_, a) = radiance_samples(&with_unused, 2_000);
    let (_, b) = radiance_samples(&without, 2_000);
    assert!(a.iter().zip(&b).all(|(x, y)| x == y));
    // Whereas a dispersive glass that paths meet changes them.
    let dispersive = glass_scene(glass(Some(Dispersion::Channels([1.5; 3]))), wall);
    let (_, c) = radiance_samples(&dispersive, 2_000);
    assert!(a.iter().zip(&c).any(|(x, y)| x != y));
}

fn pathtracer(args: &[&str]) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_pathtracer"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("the binary runs")
}

/// A Cambrian scene with a Cauchy glass ball and the camera's flag, and
/// an output path, in a fresh directory.
fn cambrian_scene(name: &str) -> (std::path::PathBuf, std::path::PathBuf) {
    let dir = std::env::temp_dir().join(format!(
        "pathtracer-dispersion-{name}-{}",
        std::process::id()
    ));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("temp dir");
    let scene = dir.join("prism.txt");
    std::fs::write(
        &scene,
        "PerspectiveCamera { center 0 0 3 direction 0 0 -1 up 0 1 0 angle 35 width 8 height 8 dispersion }
Materials { numMaterials 3
  PhongMaterial { type REFR color 1 1 1 emission 0 0 0 refractive_rate 1.5 cauchy 1.5 0.02 }
  PhongMaterial { type DIFF color 0.8 0.8 0.8 emission 0 0 0 refractive_rate 1 }
  PhongMaterial { type DIFF color 0 0 0 emission 10 10 10 refractive_rate 1 }
}
Group { numObjects 3
  MaterialIndex 0 Sphere { center 0 0 0 radius 0.6 }
  MaterialIndex 1 Sphere { center 0 0 0 radius 6 }
  MaterialIndex 2 Sphere { center 0 3 0 radius 0.5 }
}
",
    )
    .expect("scene written");
    (scene, dir.join("out.pfm"))
}

#[test]
fn the_command_line_renders_dispersion_and_says_what_it_leaves_out() {
    let (scene, out) = cambrian_scene("cli");
    let (scene, out) = (scene.to_str().unwrap(), out.to_str().unwrap());
    let common = ["render", scene, "-o", out, "--spp", "4", "--quiet"];
    let run = pathtracer(&common);
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert!(run.status.success(), "{stderr}");
    assert!(stderr.contains("note: dispersion"), "{stderr}");
    assert!(!stderr.contains("not rendered"), "{stderr}");
    // The original estimator keeps one index, and says so.
    let run = pathtracer(&[&common[..], &["--integrator", "original"]].concat());
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert!(run.status.success(), "{stderr}");
    assert!(
        stderr.contains(
            "warning: the original estimator renders dispersive materials with one index"
        ),
        "{stderr}"
    );
    // yuzc19's flag, and indices that are not three numbers.
    let run = pathtracer(&[&common[..], &["--dispersion", "yuzc19"]].concat());
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let run = pathtracer(&[&common[..], &["--dispersion", "1.5,1.6"]].concat());
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert!(!run.status.success());
    assert!(
        stderr.contains("expected 'yuzc19' or three indices R,G,B"),
        "{stderr}"
    );
    let _ = std::fs::remove_dir_all(std::path::Path::new(out).parent().unwrap());
}
