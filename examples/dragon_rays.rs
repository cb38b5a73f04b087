//! A small driver for profiling and instruction counts (perf, callgrind):
//! builds the world of one OBJ mesh, then traces the incoherent rays of
//! `benches/throughput.rs` through it, closest and any hit, and prints the
//! build time and M rays/s of each, by wall time and by this thread's CPU
//! time (which a busy machine disturbs less).
//!
//! `cargo run --release --example dragon_rays -- [mesh.obj] [rays] [closest|any|both|build]`

#[path = "../benches/common/mod.rs"]
mod common;

use std::sync::Arc;
use std::time::Instant;

use common::{incoherent_rays, load_obj, thread_cpu_seconds};

use pathtracer::scene::model::{Material, Object, Scene};
use pathtracer::world::World;

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
            mesh: Arc::new(load_obj(std::path::Path::new(path))),
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
        let (start, cpu) = (Instant::now(), thread_cpu_seconds());
        let hits = rays
            .iter()
            .filter(|r| world.intersect(r, 0.0, f64::INFINITY).is_some())
            .count();
        report("closest", count, hits, start, cpu);
    }
    if mode != "closest" {
        let (start, cpu) = (Instant::now(), thread_cpu_seconds());
        let hits = rays
            .iter()
            .filter(|r| world.occluded(r, 0.0, f64::INFINITY))
            .count();
        report("any", count, hits, start, cpu);
    }
}

/// Prints M rays/s by wall time and, where it can be read, by CPU time.
fn report(query: &str, count: usize, hits: usize, start: Instant, cpu: Option<f64>) {
    let wall = count as f64 / start.elapsed().as_secs_f64() / 1e6;
    let cpu = match (cpu, thread_cpu_seconds()) {
        (Some(a), Some(b)) => format!(", {:.3} by CPU time", count as f64 / (b - a) / 1e6),
        _ => String::new(),
    };
    println!("{query}: {wall:.3} M rays/s{cpu} ({hits} hits)");
}
