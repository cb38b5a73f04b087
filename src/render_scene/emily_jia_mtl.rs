//! emily-jia's reading of an OBJ's `.mtl` materials, for the `emj` look
//! (`emily-jia/graphic_homework:src/mesh.cpp`, `include/material.hpp`;
//! facts in `../shared/docs/looks.md`).
//!
//! Its OBJ loader gives every face after a `usemtl` that `.mtl` material,
//! whatever `MaterialIndex` the scene set (a name it does not know leaves
//! the scene's). Its `.mtl` reader keeps one set of current values (`Kd`,
//! `Ks`, `Ns`, `Ni`, ...) and, on a `newmtl` line, stores a material made
//! of them under the name read *before*, then reads the new name. It knows
//! the words `newmtl Ns Ni Ka Kd Ks map_Kd d Tr TF KE #` exactly as
//! written; any other first word, an empty line included, is taken for
//! `newmtl` too, its next word (if any) becoming the current name. In a
//! typical exporter's file (`Tf`, `illum`, `Ke`, blank lines) a material
//! therefore ends up with the colours of the material *before* it, and the
//! last one with its own. A line not ended by a newline is not read.
//!
//! The material is theirs `Material(Kd, Ks, Ns, Tr, Ni, Tf)`: diffuse
//! colour `Kd`, specular colour `Ks` with exponent `Ns`, index of
//! refraction `Ni` (transparency and transmitted colour are not rendered by
//! it). Values never read are 0. The materials of the scene file itself
//! have index 1: its parser sets none.

use std::collections::HashMap;
use std::sync::Arc;

use crate::bsdf::phong::Phong;
use crate::color::Color;
use crate::scene::model::{Material, OWN_MATERIAL, Object, OverriddenMtl, Scene};

/// The current values of their reader.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct Values {
    kd: [f64; 3],
    ks: [f64; 3],
    ns: f64,
    ni: f64,
}

impl Values {
    fn material(&self) -> Material {
        let color = |c: [f64; 3]| Color::new(c[0], c[1], c[2]);
        let specular = color(self.ks);
        Material {
            color: color(self.kd),
            phong: (!specular.is_black()).then_some(Phong {
                color: specular,
                exponent: self.ns,
            }),
            ior: self.ni,
            ..Material::DEFAULT
        }
    }
}

/// The materials of one `.mtl` text by name, as their reader leaves them.
fn read_library(text: &str) -> HashMap<String, Values> {
    let mut materials = HashMap::new();
    let mut current = Values::default();
    let mut name = String::new();
    // Their loop stops at the end of the file before using a line that no
    // newline ends.
    for line in text.split_inclusive('\n').filter(|l| l.ends_with('\n')) {
        let mut words = line.split_ascii_whitespace();
        let first = words.next().unwrap_or("");
        let mut number = || {
            words
                .next()
                .and_then(|w| w.parse::<f64>().ok())
                .unwrap_or(0.0)
        };
        match first {
            "Ns" => current.ns = number(),
            "Ni" => current.ni = number(),
            "Kd" => current.kd = [number(), number(), number()],
            "Ks" => current.ks = [number(), number(), number()],
            // Read and not rendered (or, for `map_Kd`, never loaded).
            "Ka" | "map_Kd" | "d" | "Tr" | "TF" | "KE" | "#" => {}
            _ => {
                materials.insert(name.clone(), current);
                if let Some(next) = words.next() {
                    name = next.to_string();
                }
            }
        }
    }
    materials
}

/// The scene's materials as emily-jia's renderer has them: those of the
/// scene file at index 1 (its parser sets none), and every mesh whose
/// `.mtl` materials a `MaterialIndex` overrides given its face materials as
/// its loader assigns them, the materials appended to the scene's (once
/// per OBJ file).
pub fn apply(scene: &mut Scene) {
    for material in &mut scene.materials {
        material.ior = 1.0;
    }
    let mut done: HashMap<*const OverriddenMtl, Arc<[u32]>> = HashMap::new();
    let materials = &mut scene.materials;
    scene.root.for_each_leaf_mut(&mut |leaf| {
        if let Object::Mesh {
            face_materials,
            overridden_mtl: Some(overridden),
            ..
        } = leaf
        {
            let faces = done
                .entry(Arc::as_ptr(overridden))
                .or_insert_with(|| face_materials_of(overridden, materials));
            *face_materials = Some(Arc::clone(faces));
        }
    });
}

/// Per triangle, the scene material emily-jia's loader gives it (those of
/// the `.mtl` appended to `materials`), or [`OWN_MATERIAL`].
fn face_materials_of(overridden: &OverriddenMtl, materials: &mut Vec<Material>) -> Arc<[u32]> {
    let libraries: Vec<HashMap<String, Values>> = overridden
        .libraries
        .iter()
        .map(|text| read_library(text))
        .collect();
    let indices: Vec<u32> = overridden
        .materials
        .iter()
        .map(|(name, library)| {
            let Some(values) = libraries.get(*library).and_then(|l| l.get(name)) else {
                return OWN_MATERIAL;
            };
            let Ok(index) = u32::try_from(materials.len()) else {
                return OWN_MATERIAL;
            };
            materials.push(values.material());
            index.min(OWN_MATERIAL - 1)
        })
        .collect();
    overridden
        .faces
        .iter()
        .map(|&face| indices.get(face as usize).copied().unwrap_or(OWN_MATERIAL))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_material_takes_the_colours_read_before_its_next_unknown_word() {
        // An exporter's file: `Tf`, `illum`, `Ke` and the blank line are
        // not words their reader knows, so each stores the current values
        // under the current name, then takes its own next word for a name.
        let block = |name: &str, ns: u8, kd: &str| {
            format!(
                "newmtl {name}\r\n\tNs {ns}\r\n\tNi 1.5\r\n\tTf 1 1 1\r\n\tillum 2\r\n\
                 \tKd {kd}\r\n\tKe 0 0 0\r\n\r\n"
            )
        };
        let text = block("a", 10, "0.5 0.25 0") + &block("b", 20, "1 1 1");
        let materials = read_library(&text);
        // `a` is stored at its `Tf`, before its `Kd` is read.
        assert_eq!((materials["a"].kd, materials["a"].ns), ([0.0; 3], 10.0));
        // `b` too: with `a`'s colour and its own `Ns` and `Ni`.
        let b = materials["b"];
        assert_eq!((b.kd, b.ns, b.ni), ([0.5, 0.25, 0.0], 20.0, 1.5));
        // `b`'s own colour goes to the name `illum` left: "2".
        assert_eq!(materials["2"].kd, [1.0; 3]);
        let unterminated = read_library("newmtl a\nKd 1 1 1\nnewmtl b");
        assert!(unterminated.contains_key("") && !unterminated.contains_key("a"));
    }
}
