//! Degenerate shapes (issue 12): a scene triangle whose corners are on one
//! line, a rectangle (any of its forms) with a zero or parallel edge, and
//! the triangles without area of an OBJ mesh were accepted without a word.
//! Each is now left out with a warning at its block (a mesh's counted in
//! one warning per file), and an image with them, as lights, has no NaN.

mod common;

use std::path::Path;

use pathtracer::integrator::Integrator;
use pathtracer::look::Look;
use pathtracer::render::RenderSettings;
use pathtracer::sampler::SamplerKind;
use pathtracer::scene::model::Scene;
use pathtracer::scene::{LoadOptions, build, parse};

/// A camera, a diffuse floor and an emitting material 1 for the shapes.
const HEAD: &str = "PerspectiveCamera { center 0 0 10 direction 0 0 -1 up 0 1 0 angle 40 \
                    width 8 height 8 }\nMaterials { numMaterials 2 Material { color 0.8 0.8 0.8 } \
                    Material { color 0 0 0 emission 5 5 5 } }\n";

fn load(text: &str, options: &LoadOptions) -> Scene {
    let file = Path::new("degenerate.txt");
    let document = parse(text, file).expect("parses");
    build(&document, file, options).expect("builds")
}

fn leaves(scene: &Scene) -> usize {
    let mut count = 0;
    scene.root.for_each_leaf(&mut |_| count += 1);
    count
}

/// Every pixel of a tiny render is finite and no sample was dropped.
fn assert_renders_finite(scene: &Scene) {
    let settings = RenderSettings {
        width: 8,
        height: 8,
        spp: 4,
        seed: 7,
        threads: Some(1),
        integrator: Integrator::Path,
        max_depth: 8,
        sampler: SamplerKind::Sobol,
        progress: false,
        progress_every: None,
        clamp: None,
        light_paths: true,
        look: Look::detect(scene).0,
        dispersion: None,
    };
    let (image, stats) = common::render_scene(scene, &settings).expect("renders");
    assert_eq!(stats.dropped, 0);
    assert!(
        image
            .pixels
            .iter()
            .all(|p| p.r.is_finite() && p.g.is_finite() && p.b.is_finite())
    );
}

/// `shape` alone on line 4 of a scene, with the floor: it warns at its
/// block (line 4, column 2), is left out, and the image is finite.
fn assert_left_out_with_a_warning(shape: &str) {
    let text = format!(
        "{HEAD}Group {{ MaterialIndex 1\n {shape}\n MaterialIndex 0 Plane {{ normal 0 0 1 offset -1 }} }}\n"
    );
    let scene = load(&text, &LoadOptions::default());
    let warnings: Vec<String> = scene.warnings.iter().map(|w| w.to_string()).collect();
    assert!(
        warnings
            .iter()
            .any(|w| w.starts_with("degenerate.txt:4:2: ") && w.contains("no area")),
        "{shape}: {warnings:?}"
    );
    assert_eq!(leaves(&scene), 1, "{shape}: only the floor is left");
    assert_renders_finite(&scene);
    let strict = LoadOptions {
        strict: true,
        ..LoadOptions::default()
    };
    let document = parse(&text, Path::new("degenerate.txt")).expect("parses");
    assert!(build(&document, Path::new("degenerate.txt"), &strict).is_err());
}

#[test]
fn a_triangle_with_its_corners_on_one_line_was_accepted_silently() {
    for shape in [
        "Triangle { vertex0 0 0 0 vertex1 1 0 0 vertex2 2 0 0 }",
        "Triangle { vertex0 1 1 1 vertex1 1 1 1 vertex2 1 1 1 }",
        "Triangle { vertex0 0 0 0 vertex1 1e300 0 0 vertex2 0 1e300 0 }",
    ] {
        assert_left_out_with_a_warning(shape);
    }
}

#[test]
fn a_rectangle_with_a_zero_or_parallel_edge_was_accepted_silently() {
    for shape in [
        "Quad { origin 0 0 0 u 1 0 0 v 2 0 0 }",
        "Quad { origin 0 0 0 u 0 0 0 v 0 1 0 }",
        "Rectangle { point 0 0 0 x 0 0 0 y 0 1 0 }",
        "Rectangle { x0 0 y0 0 x1 0 y1 1 k 0 }",
        "Rectangle { center 0 0 0 dirLen 1 0 0 dirWid 0 1 0 len 0 wid 1 }",
        "Rectangle { center 0 0 0 dirLen 1 0 0 dirWid 2 0 0 len 1 wid 1 }",
        "XYRectangle { points 0 0 0 1 offset 0 }",
        "FinitePlane { normal 0 0 1 offset 0 size 0 1 }",
    ] {
        assert_left_out_with_a_warning(shape);
    }
}

#[test]
fn shapes_with_area_do_not_warn() {
    let text = format!(
        "{HEAD}Group {{ MaterialIndex 1\n Triangle {{ vertex0 0 0 0 vertex1 1e-6 0 0 vertex2 0 1e-6 0 }}\n \
         Quad {{ origin 0 0 0 u 1 0 0 v 1 1e-9 0 }} }}\n"
    );
    let scene = load(&text, &LoadOptions::default());
    assert!(scene.warnings.is_empty(), "{:?}", scene.warnings);
    assert_eq!(leaves(&scene), 2);
}

#[test]
fn flat_obj_triangles_were_accepted_silently_and_warn_once_per_file() {
    let dir = std::env::temp_dir().join(format!("pathtracer-degenerate-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let mesh = dir.join("flat.obj");
    // One good triangle, two on a line, one with a repeated corner.
    std::fs::write(
        &mesh,
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nf 1 2 3\nf 1 2 4\nf 2 1 4\nf 1 1 3\n",
    )
    .expect("write");
    let text = format!(
        "{HEAD}Group {{ MaterialIndex 1\n TriangleMesh {{ obj_file {} }}\n \
         TriangleMesh {{ obj_file {} }} }}\n",
        mesh.display(),
        mesh.display()
    );
    let scene = load(&text, &LoadOptions::default());
    let warnings: Vec<String> = scene.warnings.iter().map(|w| w.to_string()).collect();
    assert_eq!(warnings.len(), 1, "{warnings:?}");
    assert!(
        warnings[0].starts_with("degenerate.txt:4:")
            && warnings[0].contains("flat.obj")
            && warnings[0].contains("3 of 4 triangles have no area"),
        "{warnings:?}"
    );
    let mut triangles = Vec::new();
    scene.root.for_each_leaf(&mut |leaf| {
        if let pathtracer::scene::model::Object::Mesh { mesh, .. } = leaf {
            triangles.push(mesh.triangles.len());
        }
    });
    assert_eq!(triangles, [1, 1]);
    assert_renders_finite(&scene);
}
