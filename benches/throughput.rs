//! Criterion benchmarks (release build, `make bench`): BVH build on the full
//! Stanford dragon, incoherent rays through it, ray-sphere and
//! revolution-surface intersections, and whole renders in samples per second
//! (smallpt and the three scenes of `scripts/curves.sh`).

use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::Duration;

mod common;

use common::{incoherent_rays, load_obj};
use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use pathtracer::geometry::{CurveKind, Profile};
use pathtracer::integrator::Integrator;
use pathtracer::look::Look;
use pathtracer::math::{Ray, Vec3};
use pathtracer::render::{RenderSettings, render};
use pathtracer::render_scene::{RenderScene, SceneSettings};
use pathtracer::sampler::SamplerKind;
use pathtracer::scene::model::{Material, Object, Scene};
use pathtracer::scene::{LoadOptions, load_scene};
use pathtracer::world::World;

fn shared(relative: &str) -> Option<PathBuf> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../shared")
        .join(relative);
    if path.exists() {
        Some(path)
    } else {
        eprintln!("skipped: ../shared not found ({})", path.display());
        None
    }
}

fn scene_with(root: Object) -> Scene {
    Scene::new(vec![Material::default()], root)
}

/// The render-time scene of `scene` in the original look.
fn built(scene: Scene) -> RenderScene {
    let settings = SceneSettings::defaults(&scene, Look::ORIGINAL);
    RenderScene::build(scene, &settings)
}

/// Closest hits of the incoherent ray set through `world`.
fn bench_rays(c: &mut Criterion, name: &str, world: &World) {
    bench_query(c, name, world, |r| {
        world.intersect(r, 0.0, f64::INFINITY).is_some()
    });
}

/// The rays of [`bench_rays`] as shadow rays: any hit, unbounded.
fn bench_any_hit(c: &mut Criterion, name: &str, world: &World) {
    bench_query(c, name, world, |r| world.occluded(r, 0.0, f64::INFINITY));
}

/// `query` over the incoherent ray set, in rays per second.
fn bench_query(c: &mut Criterion, name: &str, world: &World, query: impl Fn(&Ray) -> bool) {
    let rays = incoherent_rays(world, 100_000);
    let mut group = c.benchmark_group("rays");
    group.throughput(Throughput::Elements(rays.len() as u64));
    group.bench_function(name, |b| {
        b.iter(|| rays.iter().filter(|r| query(r)).count())
    });
    group.finish();
}

fn dragon(c: &mut Criterion) {
    let Some(path) = shared("reference/meshes/dragon_vrip.obj") else {
        return;
    };
    let mesh = Arc::new(load_obj(&path));
    let scene = scene_with(Object::Mesh {
        mesh,
        smooth: false,
        material: 0,
        face_materials: None,
        overridden_mtl: None,
    });
    let mut group = c.benchmark_group("bvh_build");
    group.sample_size(10);
    group.measurement_time(Duration::from_secs(20));
    group.bench_function("dragon_871k", |b| b.iter(|| built(scene.clone())));
    group.finish();
    let dragon = built(scene);
    bench_rays(c, "dragon_871k_incoherent", dragon.world());
    bench_any_hit(c, "dragon_871k_incoherent_any", dragon.world());
}

fn primitives(c: &mut Criterion) {
    let sphere = scene_with(Object::Sphere {
        center: Vec3::zeros(),
        radius: 1.0,
        motion: Vec3::zeros(),
        material: 0,
    });
    bench_rays(c, "sphere", built(sphere).world());
    let vase = scene_with(Object::Revolution {
        profile: Profile {
            kind: CurveKind::Bezier,
            controls: vec![
                [0.0, 0.0],
                [2.2, 0.0],
                [3.0, 1.5],
                [1.2, 3.0],
                [0.8, 4.0],
                [1.6, 5.0],
                [2.0, 5.6],
            ],
        },
        material: 0,
    });
    bench_rays(c, "revolution_bezier_vase", built(vase).world());
}

fn renders(c: &mut Criterion) {
    let mut scenes = vec![(
        "smallpt",
        PathBuf::from(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/testcases/smallpt.txt"
        )),
    )];
    // The three scenes of scripts/curves.sh, in the same (original) look.
    let curve_scenes = [
        (
            "sample_rec",
            "reference/cambrian-pathtracer/testcases/sample_rec.txt",
        ),
        ("spheres", "scenes/report_scene15_spheres.txt"),
        ("dragons", "scenes/report_scene11_dragons.txt"),
    ];
    for (name, relative) in curve_scenes {
        if let Some(path) = shared(relative) {
            scenes.push((name, path));
        }
    }
    let mut group = c.benchmark_group("render_samples");
    group.sample_size(10);
    group.measurement_time(Duration::from_secs(20));
    for (name, path) in scenes {
        let scene = load_scene(&path, &LoadOptions::default()).expect("bench scene loads");
        let mut scene_settings = SceneSettings::defaults(&scene, Look::ORIGINAL);
        (scene_settings.width, scene_settings.height) = (128, 96);
        let scene = RenderScene::build(scene, &scene_settings);
        for integrator in Integrator::ALL {
            let settings = RenderSettings {
                width: 128,
                height: 96,
                spp: 16,
                seed: 0,
                threads: None,
                integrator,
                max_depth: pathtracer::integrator::original::MAX_DEPTH,
                sampler: SamplerKind::Sobol,
                progress: false,
                progress_every: None,
                clamp: None,
                light_paths: true,
                look: Default::default(),
                dispersion: None,
            };
            let samples = settings.width as u64 * settings.height as u64 * settings.spp as u64;
            group.throughput(Throughput::Elements(samples));
            let id = BenchmarkId::new(name, integrator.name());
            group.bench_with_input(id, &settings, |b, s| {
                b.iter(|| render(&scene, s).expect("renders"))
            });
        }
    }
    group.finish();
}

criterion_group!(benches, primitives, dragon, renders);
criterion_main!(benches);
