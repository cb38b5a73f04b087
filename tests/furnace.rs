//! White-furnace tests: inside a closed emissive, diffuse sphere every path
//! sees the same radiance, so the estimator's mean is known exactly.

mod common;

use pathtracer::color::Color;
use pathtracer::integrator::{CameraSample, Integrator, Splats};
use pathtracer::math::{Ray, Vec3};
use pathtracer::rng::Rng;
use pathtracer::sampler::Sampler;
use pathtracer::scene::model::{Material, Object};

fn furnace_mean(integrator: Integrator, material: Material, paths: u64) -> (Color, f64) {
    let root = Object::Group(vec![Object::Sphere {
        center: Vec3::new(0.0, 0.0, 0.0),
        radius: 10.0,
        motion: Vec3::zeros(),
        material: 0,
    }]);
    let view = common::built(common::scene_with(vec![material], root));
    let mut sum = Color::BLACK;
    let mut sum_sq = 0.0;
    for i in 0..paths {
        let mut rng = Rng::for_sample(i, 0, 7);
        let d = Vec3::new(
            rng.next_f64() - 0.5,
            rng.next_f64() - 0.5,
            rng.next_f64() - 0.5,
        );
        let ray = Ray::new(Vec3::new(1.0, 2.0, -3.0), d.normalize(), 0.0);
        let mut sampler = Sampler::Independent(rng);
        let mut splats = Splats::default();
        let l = integrator.radiance(
            &view,
            ray,
            &CameraSample::default(),
            &mut sampler,
            &mut splats,
        );
        sum += l;
        sum_sq += l.r * l.r;
    }
    let n = paths as f64;
    let mean = sum / n;
    let variance = (sum_sq / n - mean.r * mean.r).max(0.0);
    (mean, (variance / n).sqrt())
}

/// Emission E seen through at most five scattering vertices of albedo a:
/// E (1 + a + a^2 + ... + a^5).
fn expected(emission: f64, albedo: f64) -> f64 {
    (0..=5).map(|k| emission * albedo.powi(k)).sum()
}

#[test]
fn diffuse_furnace_returns_the_geometric_series_of_its_albedo() {
    let material = Material {
        color: Color::gray(0.8),
        emission: Color::gray(1.0),
        ..Material::default()
    };
    let (mean, _) = furnace_mean(Integrator::Original, material, 2_000);
    // Every path has the same value: no variance at all.
    let want = expected(1.0, 0.8);
    assert!((mean.r - want).abs() < 1e-9, "{} vs {want}", mean.r);
    assert!((mean.g - want).abs() < 1e-9 && (mean.b - want).abs() < 1e-9);
}

#[test]
fn mixed_rates_furnace_is_unbiased() {
    // Diffuse and mirror lobes chosen at random: still every lobe returns to
    // the same wall, so the mean must be the series of the colour.
    let material = Material {
        color: Color::gray(0.6),
        emission: Color::gray(2.0),
        diffuse: 0.3,
        specular: 0.7,
        ..Material::default()
    };
    let (mean, _) = furnace_mean(Integrator::Original, material, 2_000);
    let want = expected(2.0, 0.6);
    assert!((mean.r - want).abs() < 1e-9, "{} vs {want}", mean.r);
}

#[test]
fn path_integrator_furnace_is_unbiased() {
    // Inside the emissive sphere, light samples land on the sphere itself
    // (area sampling from its own surface) and Russian roulette ends some
    // paths: no longer constant, but the same mean.
    for (diffuse, specular) in [(1.0, 0.0), (0.3, 0.7)] {
        let material = Material {
            color: Color::gray(0.7),
            emission: Color::gray(1.5),
            diffuse,
            specular,
            ..Material::default()
        };
        let (mean, error) = furnace_mean(Integrator::Path, material, 40_000);
        let want = expected(1.5, 0.7);
        assert!(
            (mean.r - want).abs() < 4.0 * error + 1e-9,
            "{} ± {error} vs {want}",
            mean.r
        );
        assert!(error < 0.01 * want, "{error}");
    }
}
