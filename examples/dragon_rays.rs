//! A small driver for profiling and instruction counts (perf, callgrind):
//! builds the world of one OBJ mesh, then traces the incoherent rays of
//! `benches/throughput.rs` through it, closest and any hit, and prints the
//! build time and M rays/s of each.
//!
//! `cargo run --release --example dragon_rays -- [mesh.obj] [rays] [closest|any|both|build]`

use std::sync::Arc;
use std::time::Instant;

use pathtracer::math::{Ray, Vec3};
use pathtracer::rng::Rng;
use pathtracer::scene::model::{Material, MeshData, Object, Scene};
use pathtracer::world::World;

fn load_obj(path: &str) -> MeshData {
    let options = tobj::LoadOptions {
        triangulate: true,
        single_index: true,
        ..Default::default()
    };
    let (models, _) = tobj::load_obj(path, &options).expect("mesh loads");
    let mut mesh = MeshData::default();
    for model in models {
        let base = mesh.positions.len() as u32;
        let m = model.mesh;
        for p in m.positions.chunks_exact(3) {
            mesh.positions
                .push(Vec3::new(p[0] as f64, p[1] as f64, p[2] as f64));
        }
        for t in m.indices.chunks_exact(3) {
            mesh.triangles.push([base + t[0], base + t[1], base + t[2]]);
        }
    }
    mesh
}

/// The ray set of the `rays/` benchmarks.
fn incoherent_rays(world: &World, count: usize) -> Vec<Ray> {
    let bounds = world.bounds();
    let center = bounds.centroid();
    let radius = bounds.extent().norm();
    let mut rng = Rng::new(11, 13);
    (0..count)
        .map(|_| {
            let z = 2.0 * rng.next_f64() - 1.0;
            let phi = 2.0 * std::f64::consts::PI * rng.next_f64();
            let s = (1.0 - z * z).sqrt();
            let origin = center + Vec3::new(s * phi.cos(), s * phi.sin(), z) * radius;
            let e = bounds.extent();
            let target = bounds.min
                + Vec3::new(
                    e.x * rng.next_f64(),
                    e.y * rng.next_f64(),
                    e.z * rng.next_f64(),
                );
            Ray::new(origin, (target - origin).normalize(), 0.0)
        })
        .collect()
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let path = args
        .get(1)
        .map_or("../shared/reference/meshes/dragon_vrip.obj", |s| s.as_str());
    let count: usize = args
        .get(2)
        .map_or(300_000, |s| s.parse().expect("ray count"));
    let mode = args.get(3).map_or("both", |s| s.as_str());
    let scene = Scene::new(
        vec![Material::default()],
        Object::Mesh {
            mesh: Arc::new(load_obj(path)),
            smooth: false,
            material: 0,
            face_materials: None,
        },
    );
    let start = Instant::now();
    let world = World::build(&scene);
    println!("build: {:.3} s", start.elapsed().as_secs_f64());
    if mode == "build" {
        return;
    }
    let rays = incoherent_rays(&world, count);
    if mode != "any" {
        let start = Instant::now();
        let hits = rays
            .iter()
            .filter(|r| world.intersect(r, 0.0, f64::INFINITY).is_some())
            .count();
        let seconds = start.elapsed().as_secs_f64();
        println!(
            "closest: {:.3} M rays/s ({hits} hits)",
            count as f64 / seconds / 1e6
        );
    }
    if mode != "closest" {
        let start = Instant::now();
        let hits = rays
            .iter()
            .filter(|r| world.occluded(r, 0.0, f64::INFINITY))
            .count();
        let seconds = start.elapsed().as_secs_f64();
        println!(
            "any: {:.3} M rays/s ({hits} hits)",
            count as f64 / seconds / 1e6
        );
    }
}
