//! hanna0911's look (the framework's ray caster): Phong shading with the
//! normal the shape stores, not turned toward the ray, and meshes made by
//! the course framework's OBJ loader, which reads `v/vt/vn` corners in
//! pairs (its `scene12_lucyangle` statue is a tangle of triangles).

mod common;

use common::{fresh_dir, mean, render_text};
use pathtracer::image_io::Image;
use pathtracer::look::Look;

/// A camera at z = 5 looking down -z at 8x8 pixels, a white diffuse
/// material without specular, and a light shining along -z (toward what
/// the camera sees), on black.
fn scene(objects: &str) -> String {
    format!(
        "PerspectiveCamera {{ center 0 0 5 direction 0 0 -1 up 0 1 0 angle 30 width 8 height 8 }}\n\
         Lights {{ numLights 1 DirectionalLight {{ direction 0 0 -1 color 1 1 1 }} }}\n\
         Background {{ color 0 0 0 }}\n\
         Materials {{ numMaterials 1 PhongMaterial {{ diffuseColor 1 1 1 specularColor 0 0 0 shininess 1 }} }}\n\
         Group {{ numObjects 1 MaterialIndex 0 {objects} }}"
    )
}

/// A triangle filling the view in the plane z = 0, its corners in the
/// order `corners`.
fn filling_triangle(corners: [&str; 3]) -> String {
    format!(
        "Triangle {{ vertex0 {} vertex1 {} vertex2 {} }}",
        corners[0], corners[1], corners[2]
    )
}

#[test]
fn a_triangle_wound_away_from_the_camera_gets_no_diffuse_light_in_han_only() {
    // (b - a) x (c - a) points along -z, away from the camera and the light.
    let away = scene(&filling_triangle(["-5 -5 0", "-5 10 0", "10 -5 0"]));
    let toward = scene(&filling_triangle(["-5 -5 0", "10 -5 0", "-5 10 0"]));
    for look in [Look::PA1, Look::HAN] {
        let lit = mean(&render_text("han-toward", &toward, look, 1));
        assert!((lit - 1.0).abs() < 1e-9, "{}: {lit}", look.name);
    }
    let pa1 = mean(&render_text("han-away", &away, Look::PA1, 1));
    assert!(
        (pa1 - 1.0).abs() < 1e-9,
        "pa1 turns the normal toward the ray: {pa1}"
    );
    let han = mean(&render_text("han-away", &away, Look::HAN, 1));
    assert_eq!(han, 0.0, "han keeps the normal the winding gives");
}

/// Lit pixels (of 8) in the middle two rows: on the left half and on the
/// right half of the image.
fn lit_halves(image: &Image) -> (usize, usize) {
    let lit = |x: usize| {
        (3..5)
            .filter(|&y| image.pixels[y * image.width + x].g > 0.5)
            .count()
    };
    ((0..4).map(lit).sum(), (4..8).map(lit).sum())
}

#[test]
fn han_reads_v_vt_vn_faces_in_pairs_as_the_framework_loader() {
    // One face: corners (1, 2, 3) by the standard reading, a triangle left
    // of x = 0; (1, 5, 6) by the framework's (the first, third and fifth
    // numbers of "1 1 5 2 6 2 3 3 3"), a triangle right of x = 0.
    let obj = "v 0 -3 0\nv -3 3 0\nv -0.2 3 0\nv 0 0 -50\nv 3 3 0\nv 0.2 3 0\n\
               vt 0 0\nvt 1 0\nvt 0 1\nvt 1 1\nvt 0.5 0\nvt 0 0.5\n\
               vn 0 0 1\nvn 0 0 1\nvn 0 0 1\nvn 0 0 1\nvn 0 0 1\nvn 0 0 1\n\
               f 1/1/5 2/6/2 3/3/3\n";
    let dir = fresh_dir("han-framework-obj");
    let path = dir.join("face.obj");
    std::fs::write(&path, obj).expect("writes the OBJ");
    let text = scene(&format!(
        "TriangleMesh {{ obj_file {} }}",
        path.to_str().expect("a UTF-8 path")
    ));
    let pa1 = lit_halves(&render_text("han-obj", &text, Look::PA1, 1));
    let han = lit_halves(&render_text("han-obj", &text, Look::HAN, 1));
    std::fs::remove_dir_all(&dir).ok();
    assert!(pa1.0 >= 4 && pa1.1 == 0, "pa1 reads (1, 2, 3): {pa1:?}");
    assert!(han.0 == 0 && han.1 >= 4, "han reads (1, 5, 6): {han:?}");
}
