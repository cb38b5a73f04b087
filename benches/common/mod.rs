//! What the benchmarks and `examples/dragon_rays.rs` share: an OBJ mesh as
//! plain data, and the incoherent ray set of the `rays/` benchmarks.

use std::path::Path;

use pathtracer::geometry::MeshData;
use pathtracer::math::{Ray, Vec3};
use pathtracer::rng::Rng;
use pathtracer::world::World;

pub fn load_obj(path: &Path) -> MeshData {
    let options = tobj::LoadOptions {
        triangulate: true,
        single_index: true,
        ..Default::default()
    };
    let (models, _) = tobj::load_obj(path, &options).expect("reference mesh loads");
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

/// Rays from random points on a sphere around the world towards random
/// points inside its bounds: incoherent, and most of them hit.
pub fn incoherent_rays(world: &World, count: usize) -> Vec<Ray> {
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

/// CPU time of the calling thread in seconds (Linux's
/// `/proc/thread-self/schedstat`), `None` where it cannot be read: unlike
/// wall time it leaves out the time other processes of a busy machine
/// hold the core.
#[allow(dead_code)] // used by the examples, not by the criterion benches
pub fn thread_cpu_seconds() -> Option<f64> {
    let text = std::fs::read_to_string("/proc/thread-self/schedstat").ok()?;
    let nanoseconds: f64 = text.split_whitespace().next()?.parse().ok()?;
    Some(nanoseconds * 1e-9)
}
