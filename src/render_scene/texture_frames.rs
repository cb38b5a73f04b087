//! Cambrian's texture frames, written into the scene's images
//! (`../shared/docs/looks.md`, section cambrian-pathtracer;
//! Cambrian-yzt/PathTracer `include/sphere.hpp`, `include/plane.hpp`).
//!
//! | shape | Cambrian's texel (column, row from the image's bottom) | ours, with the image rewritten |
//! |---|---|---|
//! | sphere | longitude from -z (towards -x, then +z), latitude from -y, both scaled to `W - 1` and `H - 1` | our longitude starts a quarter turn later: the image is rolled left by `W / 4` columns |
//! | rectangle `point + s x + t y` | `(trunc(s k), trunc(t k))` with `k = min((W - 1) / abs(x), (H - 1) / abs(y))` texels per unit: the image is not stretched, one side is cut | the image cropped to `k abs(x)` columns from the left and `k abs(y)` rows from the bottom, then stretched as ours are |
//!
//! Its images are the course framework reader's
//! ([`crate::scene::model::Scene::framework_readings`]): a BMP whose pixels
//! do not start at byte 54 (`tex_world_map.bmp`'s start at 138) is read
//! from byte 54, 28 texels early.
//!
//! So the look keeps our shapes' uv and samples what Cambrian samples,
//! to within a texel. Each rewritten image is a new texture and each
//! material whose image changes a new material, so shapes of other kinds
//! or sizes sharing the original keep it.

use std::collections::HashMap;
use std::sync::Arc;

use crate::scene::model::{Object, Scene};
use crate::texture::Texture;

/// How a shape kind rewrites an image.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
enum Rewrite {
    /// Roll left by a quarter of the width (spheres).
    QuarterTurn,
    /// Keep this many columns from the left and rows from the bottom.
    Crop { columns: usize, rows: usize },
}

/// Rewrites the images of textured spheres and rectangles of `scene` so
/// that our uv read what Cambrian's renderer read (see the module docs).
pub fn apply_cambrian(scene: &mut Scene) {
    // Cambrian reads BMPs with the course framework's reader.
    for (&index, reading) in &scene.framework_readings {
        if let Some(texture) = scene.textures.get_mut(index) {
            *texture = Arc::clone(reading);
        }
    }
    let mut frames = Frames {
        textures: HashMap::new(),
        materials: HashMap::new(),
    };
    let mut root = std::mem::replace(&mut scene.root, Object::Group(Vec::new()));
    visit(&mut root, scene, &mut frames);
    scene.root = root;
}

struct Frames {
    /// (original texture, rewrite) -> new texture.
    textures: HashMap<(usize, Rewrite), usize>,
    /// (original material, rewrite) -> new material.
    materials: HashMap<(usize, Rewrite), usize>,
}

fn visit(object: &mut Object, scene: &mut Scene, frames: &mut Frames) {
    match object {
        Object::Group(children) => children
            .iter_mut()
            .for_each(|child| visit(child, scene, frames)),
        Object::Transform { child, .. } => visit(child, scene, frames),
        Object::Sphere { material, .. } => {
            *material = reframed(*material, scene, frames, |_| Some(Rewrite::QuarterTurn));
        }
        Object::Rectangle {
            edge_u,
            edge_v,
            material,
            ..
        } => {
            let (x, y) = (edge_u.norm(), edge_v.norm());
            *material = reframed(*material, scene, frames, |texture| {
                crop_of(texture.width, texture.height, x, y)
            });
        }
        _ => {}
    }
}

/// Cambrian's columns and rows for a `width` x `height` image on a
/// rectangle with sides `x` and `y`; `None` when nothing is cut.
fn crop_of(width: usize, height: usize, x: f64, y: f64) -> Option<Rewrite> {
    if width < 2 || height < 2 || !(x > 0.0 && y > 0.0) {
        return None;
    }
    let per_unit = ((width - 1) as f64 / x).min((height - 1) as f64 / y);
    let keep = |texels: f64, size: usize| ((texels.round() as usize).max(1)).min(size);
    let columns = keep(per_unit * x, width);
    let rows = keep(per_unit * y, height);
    // Cambrian reaches texel W - 1 where we reach W: one texel is no cut.
    let cut = |kept: usize, size: usize| kept + 1 < size;
    (cut(columns, width) || cut(rows, height)).then_some(Rewrite::Crop { columns, rows })
}

/// The material to use instead of `material` on a shape whose images
/// `rewrite_for` rewrites (`material` itself when it has no image or
/// nothing changes).
fn reframed(
    material: usize,
    scene: &mut Scene,
    frames: &mut Frames,
    rewrite_for: impl Fn(&Texture) -> Option<Rewrite>,
) -> usize {
    let Some(original) = scene.materials.get(material) else {
        return material;
    };
    let Some(texture) = original.texture.or(original.normal_map) else {
        return material;
    };
    let Some(rewrite) = scene.textures.get(texture).and_then(|t| rewrite_for(t)) else {
        return material;
    };
    if let Some(&done) = frames.materials.get(&(material, rewrite)) {
        return done;
    }
    let mut changed = original.clone();
    changed.texture = changed
        .texture
        .map(|t| rewritten(t, rewrite, scene, frames));
    changed.normal_map = changed
        .normal_map
        .map(|t| rewritten(t, rewrite, scene, frames));
    scene.materials.push(changed);
    let index = scene.materials.len() - 1;
    frames.materials.insert((material, rewrite), index);
    index
}

fn rewritten(texture: usize, rewrite: Rewrite, scene: &mut Scene, frames: &mut Frames) -> usize {
    if let Some(&done) = frames.textures.get(&(texture, rewrite)) {
        return done;
    }
    let Some(image) = scene.textures.get(texture) else {
        return texture;
    };
    let image = match rewrite {
        Rewrite::QuarterTurn => rolled_left(image, image.width / 4),
        Rewrite::Crop { columns, rows } => cropped(image, columns, rows),
    };
    scene.textures.push(Arc::new(image));
    let index = scene.textures.len() - 1;
    frames.textures.insert((texture, rewrite), index);
    index
}

/// Column `i` of the result is column `(i + shift) mod W` of `image`.
fn rolled_left(image: &Texture, shift: usize) -> Texture {
    let width = image.width;
    let texels = (0..image.texels.len())
        .map(|k| {
            let (row, column) = (k / width, k % width);
            image.texels[row * width + (column + shift) % width]
        })
        .collect();
    Texture {
        texels,
        ..image.clone()
    }
}

/// The `columns` leftmost columns of the `rows` bottom rows of `image`.
fn cropped(image: &Texture, columns: usize, rows: usize) -> Texture {
    let first_row = image.height - rows;
    let texels = (first_row..image.height)
        .flat_map(|row| {
            let start = row * image.width;
            image.texels[start..start + columns].iter().copied()
        })
        .collect();
    Texture {
        width: columns,
        height: rows,
        texels,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::color::Color;
    use crate::scene::build::build_text;

    /// A `width` x `height` image whose texel encodes its column and its
    /// row counted from the bottom.
    fn numbered(width: usize, height: usize) -> Texture {
        let texels = (0..width * height)
            .map(|k| {
                let (top_row, column) = (k / width, k % width);
                [column as f32, (height - 1 - top_row) as f32, 0.0]
            })
            .collect();
        Texture {
            width,
            height,
            texels,
        }
    }

    /// Column and row from the bottom of the texel read at (u, v).
    fn texel(texture: &Texture, u: f64, v: f64) -> (f64, f64) {
        let c: Color = texture.lookup(u, v);
        (c.r, c.g)
    }

    const SCENE: &str =
        "PerspectiveCamera { center 0 0 5 direction 0 0 -1 up 0 1 0 angle 30 width 4 height 4 }
Materials { PhongMaterial { type DIFF color 1 1 1 refractive_rate 1 } }
Group { MaterialIndex 0
  Rectangle { point 1 0 0 x 98 0 0 y 0 81.6 0 }
  Sphere { center 0 0 0 radius 1 }
  Rectangle { point 0 0 0 x 10 0 0 y 0 10 0 } }";

    fn scene_with(texture: Texture) -> Scene {
        let mut scene = build_text(SCENE).expect("builds");
        scene.textures.push(Arc::new(texture));
        scene.materials[0].texture = Some(scene.textures.len() - 1);
        scene
    }

    fn leaf_materials(scene: &Scene) -> Vec<usize> {
        let mut found = Vec::new();
        scene
            .root
            .for_each_leaf(&mut |leaf| found.extend(leaf.material()));
        found
    }

    #[test]
    fn the_framework_reading_of_a_bmp_replaces_ours() {
        // Ours reads column c of a row, the framework's reader (a longer
        // header read as pixels) column c - 1: the square rectangle (no
        // crop) then samples the framework's.
        let mut scene = scene_with(numbered(10, 10));
        let mut framework = numbered(10, 10);
        framework.texels.rotate_right(1);
        scene
            .framework_readings
            .insert(0, Arc::new(framework.clone()));
        apply_cambrian(&mut scene);
        let materials = leaf_materials(&scene);
        assert_eq!(materials[2], 0);
        let poster = &scene.textures[scene.materials[0].texture.unwrap()];
        assert_eq!(**poster, framework);
        assert_eq!(texel(poster, 0.55, 0.05), (4.0, 0.0));
    }

    #[test]
    fn a_rectangle_reads_cambrian_s_unstretched_texels() {
        let mut scene = scene_with(numbered(800, 800));
        apply_cambrian(&mut scene);
        let materials = leaf_materials(&scene);
        let poster = &scene.textures[scene.materials[materials[0]].texture.unwrap()];
        // Cambrian: k = min(799 / 98, 799 / 81.6) = 799 / 98 texels per
        // unit; at (s, t) the texel is (trunc(98 s k), trunc(81.6 t k)).
        let k = 799.0 / 98.0;
        for (s, t) in [(0.0, 0.0), (0.5, 0.5), (0.999, 0.999), (0.25, 0.9)] {
            let (column, row) = texel(poster, s, t);
            let (want_column, want_row) = ((98.0 * s * k).trunc(), (81.6 * t * k).trunc());
            assert!(
                (column - want_column).abs() <= 1.0,
                "{s} {t}: {column} {want_column}"
            );
            assert!((row - want_row).abs() <= 1.0, "{s} {t}: {row} {want_row}");
        }
        // The square rectangle fits the square image: its material is kept.
        assert_eq!(materials[2], 0);
    }

    #[test]
    fn a_sphere_reads_longitude_from_minus_z() {
        let mut scene = scene_with(numbered(64, 32));
        apply_cambrian(&mut scene);
        let materials = leaf_materials(&scene);
        let globe = &scene.textures[scene.materials[materials[1]].texture.unwrap()];
        // Our u at a direction w is 0.5 - atan2(w.z, w.x) / 2 pi; Cambrian's
        // longitude is 0 at -z, 90 degrees at -x, 180 at +z, 270 at +x.
        for (w, longitude) in [
            ((0.0f64, -1.0f64), 0.0),
            ((-1.0, 0.0), 90.0),
            ((0.0, 1.0), 180.0),
            ((1.0, 0.0), 270.0),
        ] {
            let (x, z) = w;
            let u = (0.5 - z.atan2(x) / (2.0 * std::f64::consts::PI)).rem_euclid(1.0);
            let (column, _) = texel(globe, u, 0.5);
            let want = longitude / 360.0 * 63.0;
            assert!((column - want).abs() <= 1.0, "{longitude}: {column} {want}");
        }
        // The rectangles' material is not the sphere's new one.
        assert_ne!(materials[0], materials[1]);
    }
}
