//! A small driver for profiling and instruction counts (perf, callgrind):
//! builds the world of one OBJ mesh, then traces the incoherent rays of
//! `benches/throughput.rs` through it, closest and any hit, and prints the
//! build time and M rays/s of each, by wall time and by this thread's CPU
//! time (which a busy machine disturbs less); with several rounds, each
//! round's figures and then the median and the range of the CPU-time ones.
//!
//! `cargo run --release --example dragon_rays -- [mesh.obj] [rays] [closest|any|both|build] [rounds]`

#[path = "../benches/common/mod.rs"]
mod common;

use std::sync::Arc;
use std::time::Instant;

use common::{incoherent_rays, load_obj, thread_cpu_seconds};

use pathtracer::look::Look;
use pathtracer::render_scene::{RenderScene, SceneSettings};
use pathtracer::scene::model::{Material, Object, Scene};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let path = args
        .get(1)
        .map_or("../shared/reference/meshes/dragon_vrip.obj", |s| s.as_str());
    let count: usize = args
        .get(2)
        .map_or(300_000, |s| s.parse().expect("ray count"));
    let mode = args.get(3).map_or("both", |s| s.as_str());
    let rounds: usize = args.get(4).map_or(1, |s| s.parse().expect("rounds"));
    let scene = Scene::new(
        vec![Material::default()],
        Object::Mesh {
            mesh: Arc::new(load_obj(std::path::Path::new(path))),
            smooth: false,
            material: 0,
            face_materials: None,
            overridden_mtl: None,
        },
    );
    let start = Instant::now();
    let settings = SceneSettings::defaults(&scene, Look::ORIGINAL);
    let scene = RenderScene::build(scene, &settings);
    let world = scene.world();
    println!("build: {:.3} s", start.elapsed().as_secs_f64());
    if mode == "build" {
        return;
    }
    let rays = incoherent_rays(world, count);
    let (mut closest, mut any) = (Vec::new(), Vec::new());
    for _ in 0..rounds {
        if mode != "any" {
            let (start, cpu) = (Instant::now(), thread_cpu_seconds());
            let hits = rays
                .iter()
                .filter(|r| world.intersect(r, 0.0, f64::INFINITY).is_some())
                .count();
            closest.extend(report("closest", count, hits, start, cpu));
        }
        if mode != "closest" {
            let (start, cpu) = (Instant::now(), thread_cpu_seconds());
            let hits = rays
                .iter()
                .filter(|r| world.occluded(r, 0.0, f64::INFINITY))
                .count();
            any.extend(report("any", count, hits, start, cpu));
        }
    }
    if rounds > 1 {
        for (query, rates) in [("closest", closest), ("any", any)] {
            if let Some(summary) = summary(rates) {
                println!("{query}: {summary} M rays/s by CPU time, median (range) of {rounds}");
            }
        }
    }
}

/// The median of `rates` and their range.
fn summary(mut rates: Vec<f64>) -> Option<String> {
    rates.sort_by(f64::total_cmp);
    let (low, high) = (rates.first()?, rates.last()?);
    Some(format!(
        "{:.3} ({low:.3}-{high:.3})",
        rates[rates.len() / 2]
    ))
}

/// Prints M rays/s by wall time and, where it can be read, by CPU time;
/// returns the latter.
fn report(query: &str, count: usize, hits: usize, start: Instant, cpu: Option<f64>) -> Option<f64> {
    let wall = count as f64 / start.elapsed().as_secs_f64() / 1e6;
    let rate = match (cpu, thread_cpu_seconds()) {
        (Some(a), Some(b)) => Some(count as f64 / (b - a) / 1e6),
        _ => None,
    };
    let cpu = rate.map_or(String::new(), |r| format!(", {r:.3} by CPU time"));
    println!("{query}: {wall:.3} M rays/s{cpu} ({hits} hits)");
    rate
}
