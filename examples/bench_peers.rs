//! `make bench-peers`: the incoherent rays of the `rays/` benchmarks through
//! our BVH, obvhs (a compressed 8-wide BVH, f32 triangles) and Embree 3
//! (Debian's libembree3, f32), on one thread, in one run. Prints each one's
//! build time (wall, all threads), closest- and any-hit M rays/s by thread
//! CPU time, which a busy machine disturbs less (the median of `rounds`
//! rounds that alternate between the three, with the range), hit counts,
//! and our ratios to each peer.
//!
//! `cargo run --release --features peers --example bench_peers -- [mesh.obj] [rays] [rounds]`

#[path = "../benches/common/mod.rs"]
mod common;

use std::sync::Arc;
use std::time::{Duration, Instant};

use common::{incoherent_rays, load_obj, thread_cpu_seconds};
use glam::Vec3A;
use obvhs::BvhBuildParams;
use obvhs::cwbvh::builder::build_cwbvh_from_tris;
use obvhs::ray::RayHit;
use obvhs::triangle::Triangle;
use pathtracer::geometry::MeshData;
use pathtracer::look::Look;
use pathtracer::math::Ray;
use pathtracer::render_scene::{RenderScene, SceneSettings};
use pathtracer::scene::model::{Material, Object, Scene};

/// One renderer's answer to the two queries over a ray set.
trait Tracer {
    fn name(&self) -> &'static str;
    /// Rays with a hit.
    fn closest(&self, rays: &[Ray]) -> usize;
    fn any(&self, rays: &[Ray]) -> usize;
}

struct Ours(RenderScene);

impl Tracer for Ours {
    fn name(&self) -> &'static str {
        "ours"
    }
    fn closest(&self, rays: &[Ray]) -> usize {
        rays.iter()
            .filter(|r| self.0.world().intersect(r, 0.0, f64::INFINITY).is_some())
            .count()
    }
    fn any(&self, rays: &[Ray]) -> usize {
        rays.iter()
            .filter(|r| self.0.world().occluded(r, 0.0, f64::INFINITY))
            .count()
    }
}

/// obvhs's CWBVH with its triangles stored in leaf order.
struct Obvhs {
    bvh: obvhs::cwbvh::CwBvh,
    triangles: Vec<Triangle>,
}

fn obvhs_ray(ray: &Ray) -> obvhs::ray::Ray {
    let v = |p: [f64; 3]| Vec3A::new(p[0] as f32, p[1] as f32, p[2] as f32);
    obvhs::ray::Ray::new_inf(v(ray.origin.into()), v(ray.direction.into()))
}

impl Obvhs {
    fn build(mesh: &MeshData) -> Obvhs {
        let v = |i: u32| {
            let p = mesh.positions[i as usize];
            Vec3A::new(p.x as f32, p.y as f32, p.z as f32)
        };
        let triangles: Vec<Triangle> = mesh
            .triangles
            .iter()
            .map(|t| Triangle {
                v0: v(t[0]),
                v1: v(t[1]),
                v2: v(t[2]),
            })
            .collect();
        let bvh = build_cwbvh_from_tris(
            &triangles,
            BvhBuildParams::medium_build(),
            &mut Duration::default(),
        );
        let triangles = bvh
            .primitive_indices
            .iter()
            .map(|&i| triangles[i as usize])
            .collect();
        Obvhs { bvh, triangles }
    }
}

impl Tracer for Obvhs {
    fn name(&self) -> &'static str {
        "obvhs"
    }
    fn closest(&self, rays: &[Ray]) -> usize {
        rays.iter()
            .filter(|r| {
                let mut hit = RayHit::none();
                self.bvh.ray_traverse(obvhs_ray(r), &mut hit, |ray, i| {
                    self.triangles[i].intersect(ray)
                })
            })
            .count()
    }
    fn any(&self, rays: &[Ray]) -> usize {
        rays.iter()
            .filter(|r| {
                !self
                    .bvh
                    .ray_traverse_miss(obvhs_ray(r), |ray, i| self.triangles[i].intersect(ray))
            })
            .count()
    }
}

/// A committed Embree scene (it borrows its device and scene, which
/// `main` keeps alive).
struct Embree<'a>(embree::CommittedScene<'a>);

fn embree_ray(ray: &Ray) -> embree::Ray {
    let v = |p: [f64; 3]| cgmath::Vector3::new(p[0] as f32, p[1] as f32, p[2] as f32);
    embree::Ray::new(v(ray.origin.into()), v(ray.direction.into()))
}

fn embree_scene<'a>(device: &'a embree::Device, mesh: &MeshData) -> embree::Scene<'a> {
    let mut geometry =
        embree::TriangleMesh::unanimated(device, mesh.triangles.len(), mesh.positions.len());
    {
        let mut vertices = geometry.vertex_buffer.map();
        for (i, p) in mesh.positions.iter().enumerate() {
            vertices[i] = cgmath::Vector4::new(p.x as f32, p.y as f32, p.z as f32, 0.0);
        }
        let mut indices = geometry.index_buffer.map();
        for (i, t) in mesh.triangles.iter().enumerate() {
            indices[i] = cgmath::Vector3::new(t[0], t[1], t[2]);
        }
    }
    let mut geometry = embree::Geometry::Triangle(geometry);
    geometry.commit();
    let mut scene = embree::Scene::new(device);
    scene.attach_geometry(geometry);
    scene
}

impl Tracer for Embree<'_> {
    fn name(&self) -> &'static str {
        "embree"
    }
    fn closest(&self, rays: &[Ray]) -> usize {
        let mut context = embree::IntersectContext::incoherent();
        rays.iter()
            .filter(|r| {
                let mut hit = embree::RayHit::new(embree_ray(r));
                self.0.intersect(&mut context, &mut hit);
                hit.hit.hit()
            })
            .count()
    }
    fn any(&self, rays: &[Ray]) -> usize {
        let mut context = embree::IntersectContext::incoherent();
        rays.iter()
            .filter(|r| {
                let mut ray = embree_ray(r);
                self.0.occluded(&mut context, &mut ray);
                ray.tfar == f32::NEG_INFINITY
            })
            .count()
    }
}

/// Rays per second of each round, and the last hit count.
#[derive(Default)]
struct Rates {
    closest: Vec<f64>,
    any: Vec<f64>,
    hits: (usize, usize),
}

/// M rays/s of `query` by this thread's CPU time (wall time where that
/// cannot be read), and its hit count.
fn rate(rays: &[Ray], query: impl Fn(&[Ray]) -> usize) -> (f64, usize) {
    let (start, cpu) = (Instant::now(), thread_cpu_seconds());
    let hits = query(rays);
    let seconds = match (cpu, thread_cpu_seconds()) {
        (Some(a), Some(b)) => b - a,
        _ => start.elapsed().as_secs_f64(),
    };
    (rays.len() as f64 / seconds / 1e6, hits)
}

fn median(values: &[f64]) -> f64 {
    let mut v = values.to_vec();
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn range(values: &[f64]) -> String {
    let low = values.iter().copied().fold(f64::INFINITY, f64::min);
    let high = values.iter().copied().fold(0.0, f64::max);
    format!("{:.3} ({low:.3}-{high:.3})", median(values))
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let path = args
        .get(1)
        .map_or("../shared/reference/meshes/dragon_vrip.obj", |s| s.as_str());
    let count: usize = args
        .get(2)
        .map_or(300_000, |s| s.parse().expect("ray count"));
    let rounds: usize = args.get(3).map_or(3, |s| s.parse().expect("rounds"));
    let mesh = Arc::new(load_obj(std::path::Path::new(path)));
    println!(
        "{path}: {} triangles, {count} incoherent rays, {rounds} rounds, one thread (M rays/s by its CPU time)",
        mesh.triangles.len()
    );

    let scene = Scene::new(
        vec![Material::default()],
        Object::Mesh {
            mesh: Arc::clone(&mesh),
            smooth: false,
            material: 0,
            face_materials: None,
            overridden_mtl: None,
        },
    );
    let start = Instant::now();
    let settings = SceneSettings::defaults(&scene, Look::ORIGINAL);
    let ours = Ours(RenderScene::build(scene, &settings));
    let mut builds = vec![start.elapsed().as_secs_f64()];
    let start = Instant::now();
    let obvhs = Obvhs::build(&mesh);
    builds.push(start.elapsed().as_secs_f64());
    let device = embree::Device::new();
    let start = Instant::now();
    let embree_scene = embree_scene(&device, &mesh);
    let embree = Embree(embree_scene.commit());
    builds.push(start.elapsed().as_secs_f64());

    let rays = incoherent_rays(ours.0.world(), count);
    let tracers: [&dyn Tracer; 3] = [&ours, &obvhs, &embree];
    let mut rates: Vec<Rates> = tracers.iter().map(|_| Rates::default()).collect();
    for _ in 0..rounds {
        for (tracer, rates) in tracers.iter().zip(&mut rates) {
            let (closest, closest_hits) = rate(&rays, |r| tracer.closest(r));
            let (any, any_hits) = rate(&rays, |r| tracer.any(r));
            rates.closest.push(closest);
            rates.any.push(any);
            rates.hits = (closest_hits, any_hits);
        }
    }
    println!(
        "            build s   closest M rays/s      any M rays/s          hits (closest, any)"
    );
    for ((tracer, rates), build) in tracers.iter().zip(&rates).zip(&builds) {
        println!(
            "{:<10} {build:>7.3}   {:<21} {:<21} {:?}",
            tracer.name(),
            range(&rates.closest),
            range(&rates.any),
            rates.hits
        );
    }
    let (closest, any) = (median(&rates[0].closest), median(&rates[0].any));
    for (i, peer) in [(1, "obvhs"), (2, "embree")] {
        println!(
            "ours/{peer}: closest {:.2}x, any {:.2}x, build {:.2}x the time",
            closest / median(&rates[i].closest),
            any / median(&rates[i].any),
            builds[0] / builds[i]
        );
    }
}
