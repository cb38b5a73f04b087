//! emily-jia's OBJ meshes (the `emj` look): faces after `usemtl` take
//! their `.mtl` material as its reader leaves it, whatever `MaterialIndex`
//! the scene set, and triangles shade with their face normal, the file's
//! `vn` unused (`emily-jia/graphic_homework:src/mesh.cpp`).

mod common;

use common::{fresh_dir, render_text};
use pathtracer::look::{Look, MtlReading};

/// A camera at z = 5 looking down -z at 4x4 pixels, a grey scene material
/// (no specular) chosen by `MaterialIndex`, a white light along -z, on
/// black: the mirror rays of the look find nothing.
fn scene(mesh: &str) -> String {
    format!(
        "PerspectiveCamera {{ center 0 0 5 direction 0 0 -1 up 0 1 0 angle 30 width 4 height 4 }}\n\
         Lights {{ numLights 1 DirectionalLight {{ direction 0 0 -1 color 1 1 1 }} }}\n\
         Background {{ color 0 0 0 }}\n\
         Materials {{ numMaterials 1 PhongMaterial {{ diffuseColor 0.2 0.2 0.2 }} }}\n\
         Group {{ numObjects 1 MaterialIndex 0 TriangleMesh {{ obj_file {mesh} }} }}"
    )
}

/// A triangle filling the view in the plane z = 0, facing the camera, and
/// what follows its vertices (`vn`, `usemtl`) before its face line `face`.
fn write_mesh(name: &str, extra: &str, face: &str, mtl: Option<&str>) -> (String, String) {
    let dir = fresh_dir(name);
    let mut obj = String::new();
    if let Some(mtl) = mtl {
        std::fs::write(dir.join("mesh.mtl"), mtl).expect("writes the .mtl");
        obj.push_str("mtllib mesh.mtl\n");
    }
    obj.push_str(&format!("v -5 -5 0\nv 10 -5 0\nv -5 10 0\n{extra}{face}\n"));
    let path = dir.join("mesh.obj");
    std::fs::write(&path, obj).expect("writes the OBJ");
    let shown = path.to_str().expect("a UTF-8 path").to_string();
    (shown, dir.to_str().expect("a UTF-8 path").to_string())
}

/// The middle pixel's red, green and blue (`name`: the test's own
/// folder, as tests run at once).
fn middle(name: &str, text: &str, look: Look) -> [f64; 3] {
    let image = render_text(name, text, look, 1);
    let p = image.pixels[2 * 4 + 2];
    [p.r, p.g, p.b]
}

#[test]
fn emj_faces_take_the_mtl_material_as_its_reader_leaves_it() {
    // Their reader stores a material at the first word it does not know
    // (`Tf`, `illum`, ...), made of the values read so far: `second` is
    // stored at its `Tf`, with the `Kd` of `first` (blue), and its own
    // green goes to the name that `Tf 1 1 1` left, "1".
    let mtl = "newmtl first\nKd 0 0 1\nTf 1 1 1\nnewmtl second\nTf 1 1 1\nKd 0 1 0\nillum 2\n";
    let (mesh, dir) = write_mesh("emj-mtl", "usemtl second\n", "f 1 2 3", Some(mtl));
    let text = scene(&mesh);
    let theirs = middle("emj-mtl", &text, Look::EMJ);
    let scene_wins = Look {
        mtl_reading: MtlReading::Ignored,
        ..Look::EMJ
    };
    let ours = middle("emj-mtl", &text, scene_wins);
    std::fs::remove_dir_all(dir).ok();
    let near = |a: [f64; 3], b: [f64; 3]| a.iter().zip(b).all(|(a, b)| (a - b).abs() < 1e-6);
    assert!(
        near(theirs, [0.0, 0.0, 1.0]),
        "emj: blue, from `first`: {theirs:?}"
    );
    assert!(
        near(ours, [0.2; 3]),
        "MaterialIndex wins otherwise: {ours:?}"
    );
}

#[test]
fn emj_triangles_shade_with_their_face_normal() {
    // The file's vertex normals lean 60 degrees from the face's: shaded
    // with them the light along -z gives cos 60 = 1/2 of the face's.
    let lean = "vn 0.8660254 0 0.5\nvn 0.8660254 0 0.5\nvn 0.8660254 0 0.5\n";
    let (mesh, dir) = write_mesh("emj-vn", lean, "f 1//1 2//2 3//3", None);
    let text = scene(&mesh);
    let theirs = middle("emj-vn", &text, Look::EMJ);
    let with_vn = Look {
        face_normals: false,
        ..Look::EMJ
    };
    let ours = middle("emj-vn", &text, with_vn);
    std::fs::remove_dir_all(dir).ok();
    assert!((theirs[1] - 0.2).abs() < 1e-6, "face normal: {theirs:?}");
    assert!((ours[1] - 0.1).abs() < 1e-6, "vertex normals: {ours:?}");
}

#[test]
fn emj_weights_the_refracted_ray_by_the_mtl_index() {
    // A black face seen head-on on a background of 0.5: the "refracted" ray
    // of their tracer (`n cos_t + (d - (n.d) n) eta`, the normal facing the
    // camera) goes straight back to the background, weighted 1 - r with
    // Schlick's r of the two indices: ((1.5 - 1) / (1.5 + 1))^2 = 0.04 for
    // `Ni 1.5`, 0 for `Ni 1`.
    let pixel = |ni: &str| {
        let mtl = format!("newmtl glass\nNi {ni}\nKd 0 0 0\nillum 2\n");
        let (mesh, dir) = write_mesh("emj-ni", "usemtl glass\n", "f 1 2 3", Some(&mtl));
        let text = scene(&mesh).replace("color 0 0 0", "color 0.5 0.5 0.5");
        let red = middle("emj-ni", &text, Look::EMJ)[0];
        std::fs::remove_dir_all(dir).ok();
        red
    };
    let (glass, air) = (pixel("1.5"), pixel("1"));
    assert!((glass - 0.96 * 0.5).abs() < 1e-9, "Ni 1.5: {glass}");
    assert!((air - 0.5).abs() < 1e-9, "Ni 1: {air}");
}
