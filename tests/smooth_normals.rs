//! Smooth shading of meshes without `vn`: `smooth` interpolates area-weighted
//! vertex normals, which are unit, much closer to the true normal of a
//! tessellated sphere than its faces, and continuous across shared edges.

mod common;

use std::collections::HashMap;
use std::f64::consts::PI;
use std::path::Path;

use common::*;
use pathtracer::geometry::{Intersection, Mesh, Shape};
use pathtracer::math::{Point3, Ray, Vec3};
use pathtracer::rng::Rng;
use pathtracer::scene::LoadOptions;
use pathtracer::scene::model::Scene;
use pathtracer::world::World;

/// A UV sphere of radius 1 around the origin, as OBJ text without normals.
fn sphere_obj(stacks: usize, slices: usize) -> String {
    let mut text = String::from("# tessellated sphere, no vn\n");
    text += "v 0 1 0\n";
    for i in 1..stacks {
        let polar = PI * i as f64 / stacks as f64;
        for j in 0..slices {
            let azimuth = 2.0 * PI * j as f64 / slices as f64;
            let (x, y, z) = (
                polar.sin() * azimuth.cos(),
                polar.cos(),
                polar.sin() * azimuth.sin(),
            );
            text += &format!("v {x} {y} {z}\n");
        }
    }
    text += "v 0 -1 0\n";
    let ring = |i: usize, j: usize| 2 + (i - 1) * slices + j % slices;
    let bottom = 2 + (stacks - 1) * slices;
    for j in 0..slices {
        text += &format!("f 1 {} {}\n", ring(1, j + 1), ring(1, j));
        text += &format!(
            "f {bottom} {} {}\n",
            ring(stacks - 1, j),
            ring(stacks - 1, j + 1)
        );
    }
    for i in 1..stacks - 1 {
        for j in 0..slices {
            let (a, b) = (ring(i, j), ring(i, j + 1));
            let (c, d) = (ring(i + 1, j + 1), ring(i + 1, j));
            text += &format!("f {a} {b} {c}\nf {a} {c} {d}\n");
        }
    }
    text
}

/// A scene with one `TriangleMesh` of `obj` (written to a fresh folder) with
/// the mesh block's extra `fields`.
fn mesh_scene(name: &str, obj: &str, fields: &str) -> Scene {
    let dir = std::env::temp_dir().join(format!("pt-smooth-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    std::fs::write(dir.join("sphere.obj"), obj).expect("write obj");
    let text = format!(
        "PerspectiveCamera {{ width 2 height 2 }}\nMaterials {{ Material {{ }} }}\n\
         Group {{ TriangleMesh {{ {fields} obj_file sphere.obj }} }}\n"
    );
    let file = dir.join("scene.txt");
    std::fs::write(&file, text).expect("write scene");
    let options = LoadOptions {
        base: Some(dir.clone()),
        ..LoadOptions::default()
    };
    pathtracer::scene::load_scene(&file, &options).expect("loads")
}

fn the_mesh(world: &World) -> (&Mesh, bool) {
    world
        .primitives()
        .iter()
        .find_map(|p| match &p.shape {
            Shape::Mesh { mesh, smooth } => Some((mesh.as_ref(), *smooth)),
            _ => None,
        })
        .expect("a mesh")
}

/// Mean angle to the true sphere normal of the shading and of the geometric
/// normal at random hits.
fn mean_errors(world: &World, rng: &mut Rng) -> (f64, f64) {
    let (mut shading, mut face, mut hits) = (0.0, 0.0, 0);
    for _ in 0..3000 {
        let origin = random_unit(rng) * 4.0;
        let target = random_unit(rng) * 0.5;
        let ray = Ray::new(origin, target - origin, 0.0);
        let Some(hit) = world.intersect(&ray, 0.0, f64::INFINITY) else {
            continue;
        };
        let truth = (hit.point - Point3::zeros()).normalize();
        shading += hit.shading_normal.angle(&truth);
        face += hit.geometric_normal.angle(&truth);
        hits += 1;
    }
    assert!(hits > 1000, "{hits}");
    (shading / hits as f64, face / hits as f64)
}

#[test]
fn smooth_sphere_mesh_without_vn_gets_close_unit_continuous_normals() {
    let scene = built(mesh_scene("smooth", &sphere_obj(12, 24), "smooth"));
    let world = scene.world();
    let (mesh, smooth) = the_mesh(world);
    assert!(smooth);
    assert!(mesh.data.normals.is_none(), "the file has no vn");
    let normals = mesh.computed_normals().expect("computed at build");
    assert_eq!(normals.len(), mesh.data.positions.len());
    for (n, p) in normals.iter().zip(&mesh.data.positions) {
        assert!((n.norm() - 1.0).abs() < 1e-12, "{n:?}");
        // Close to the radial direction (the quads' diagonals make the
        // neighbourhoods a little asymmetric): within half the 15-degree
        // spacing of the rings.
        assert!(n.angle(&(p - Point3::zeros())) < 0.13, "{n:?} at {p:?}");
    }

    let (shading, face) = mean_errors(world, &mut Rng::new(4, 9));
    println!("mean angle to the true normal: interpolated {shading:.5}, faces {face:.5}");
    // Measured: 0.013 against 0.091 rad (12 x 24 sphere).
    assert!(
        shading < 0.25 * face,
        "interpolated {shading}, faces {face}"
    );

    // Continuity: a point of an edge has the same shading normal in both
    // triangles that share it.
    let triangles = &mesh.data.triangles;
    let mut edges: HashMap<(u32, u32), Vec<usize>> = HashMap::new();
    for (index, t) in triangles.iter().enumerate() {
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            edges.entry((a.min(b), a.max(b))).or_default().push(index);
        }
    }
    let ray = Ray::new(Point3::zeros(), Vec3::z(), 0.0);
    let mut shared = 0;
    for (&(a, b), faces) in &edges {
        let [first, second] = faces.as_slice() else {
            panic!("a closed sphere: every edge has two faces");
        };
        for s in [0.1, 0.5, 0.77] {
            let normal_in = |face: usize| {
                let mut weights = [0.0; 3];
                for (k, &vertex) in triangles[face].iter().enumerate() {
                    weights[k] = if vertex == a {
                        1.0 - s
                    } else if vertex == b {
                        s
                    } else {
                        0.0
                    };
                }
                let hit = Intersection {
                    t: 1.0,
                    u: weights[1],
                    v: weights[2],
                    index: face as u32,
                    // Not where the mesh keeps it: surface looks it up.
                    slot: 0,
                };
                mesh.surface(&ray, &hit, true).shading_normal
            };
            let (n1, n2) = (normal_in(*first), normal_in(*second));
            assert!((n1 - n2).norm() < 1e-12, "edge {a}-{b}: {n1:?} vs {n2:?}");
        }
        shared += 1;
    }
    assert_eq!(shared, triangles.len() * 3 / 2);
}

#[test]
fn without_smooth_and_vn_triangles_are_flat_and_vn_is_always_used() {
    let obj = sphere_obj(8, 16);
    let flat = built(mesh_scene("flat", &obj, ""));
    assert!(the_mesh(flat.world()).0.computed_normals().is_none());
    let (shading, face) = mean_errors(flat.world(), &mut Rng::new(5, 1));
    assert_eq!(shading, face, "flat shading is the face normal");

    // The same sphere with exact vn, not `smooth`: interpolated anyway.
    let mut with_vn = String::new();
    let mut vertices = 0;
    for line in obj.lines() {
        if let Some(rest) = line.strip_prefix("v ") {
            with_vn += &format!("{line}\nvn {rest}\n");
            vertices += 1;
        } else if let Some(rest) = line.strip_prefix("f ") {
            let face: Vec<String> = rest.split(' ').map(|i| format!("{i}//{i}")).collect();
            with_vn += &format!("f {}\n", face.join(" "));
        } else {
            with_vn += &format!("{line}\n");
        }
    }
    let scene = built(mesh_scene("vn", &with_vn, ""));
    let world = scene.world();
    let (mesh, smooth) = the_mesh(world);
    assert!(!smooth && mesh.computed_normals().is_none());
    assert_eq!(mesh.data.normals.as_ref().map(Vec::len), Some(vertices));
    let (shading, face) = mean_errors(world, &mut Rng::new(5, 2));
    assert!(
        shading < 0.1 * face,
        "vn interpolated: {shading} vs faces {face}"
    );
}

#[test]
fn cambrian_smooth_bunny_without_vn_is_smooth() {
    let Some(file) = shared_file("reference/cambrian-pathtracer/testcases/bunny_and_wineglass.txt")
    else {
        return;
    };
    let base = file.parent().and_then(Path::parent).map(Path::to_path_buf);
    let options = LoadOptions {
        base,
        ..LoadOptions::default()
    };
    let scene = built(pathtracer::scene::load_scene(&file, &options).expect("loads"));
    let world = scene.world();
    let smooth: Vec<&Mesh> = world
        .primitives()
        .iter()
        .filter_map(|p| match &p.shape {
            Shape::Mesh { mesh, smooth: true } => Some(mesh.as_ref()),
            _ => None,
        })
        .collect();
    assert_eq!(smooth.len(), 1, "bunny_1k is the smooth mesh");
    assert!(smooth[0].data.normals.is_none());
    let normals = smooth[0].computed_normals().expect("computed");
    let unit = normals
        .iter()
        .filter(|n| (n.norm() - 1.0).abs() < 1e-9)
        .count();
    println!("bunny_1k: {unit} of {} vertex normals unit", normals.len());
    assert!(unit * 100 >= normals.len() * 99);
}
