//! Materials of every dialect normalised to one `Material` (synonyms, §4 conflict rules).

use crate::bsdf::AngularWeights;
use crate::color::Color;
use crate::scene::ast::{Block, ItemKind};
use crate::scene::build::dispersion::read_cauchy;
use crate::scene::build::medium::build_medium;
use crate::scene::build::textures::{MapName, SurfaceMapRef};
use crate::scene::build::weights::{Fields, Kind, preset, resolve};
use crate::scene::build::{Context, Cursor};
use crate::scene::error::{Location, SceneError};
use crate::scene::model::{Dialect, Material};
use crate::spectral::Dispersion;
use crate::texture::uv_rule::UvRule;

/// A path written in the file, with where it was written.
#[derive(Clone, Debug, PartialEq)]
pub struct PathRef {
    pub path: String,
    pub location: Location,
}

/// A material before its images are loaded.
#[derive(Clone, Debug, PartialEq)]
pub struct MaterialSpec {
    pub material: Material,
    pub texture: Option<PathRef>,
    /// A surface map: a normal map or a height map, which the loader
    /// decides from the key that named it and the image.
    pub surface_map: Option<SurfaceMapRef>,
    /// Cambrian's `cauchy` and where it was written, until the camera
    /// says whether it is used (see `dispersion::resolve`).
    pub dispersion: Option<(Dispersion, Location)>,
}

impl MaterialSpec {
    pub fn new(material: Material) -> Self {
        MaterialSpec {
            material,
            texture: None,
            surface_map: None,
            dispersion: None,
        }
    }
}

/// Reads `Materials { numMaterials n <material>* }`.
pub fn build_materials(
    context: &mut Context,
    block: &Block,
) -> Result<Vec<MaterialSpec>, SceneError> {
    let mut specs = Vec::new();
    let mut expected = None;
    let mut cursor = Cursor::of(block);
    while let Some(item) = cursor.next() {
        if let Some(material) = item.block() {
            specs.push(build_material(context, material, item.location)?);
        } else if item.word() == Some("numMaterials") {
            expected = Some((cursor.integer(context, "numMaterials")?, item.location));
        } else if let Some(key) = item.word() {
            context.skip_field(&mut cursor, key, item.location, "Materials")?;
        } else {
            context.skip_item(item, "Materials")?;
        }
    }
    if let Some((n, at)) = expected
        && n != specs.len() as i64
    {
        let found = specs.len();
        context.warn(
            at,
            format!("numMaterials says {n} but {found} materials follow"),
        )?;
    }
    Ok(specs)
}

fn color3(cursor: &mut Cursor, context: &Context, key: &str) -> Result<Color, SceneError> {
    let v = cursor.vec3(context, key)?;
    Ok(Color::new(v.x, v.y, v.z))
}

fn path_after(cursor: &mut Cursor, context: &Context, key: &str) -> Result<PathRef, SceneError> {
    let location = cursor.here();
    let path = cursor.word(context, key)?.to_string();
    Ok(PathRef { path, location })
}

fn build_material(
    context: &mut Context,
    block: &Block,
    location: Location,
) -> Result<MaterialSpec, SceneError> {
    let name = block.name.as_str();
    let mut f = Fields::default();
    let mut interior = None;
    let mut interface = false;
    let mut dispersion = None;
    let mut cursor = Cursor::of(block);
    while let Some(item) = cursor.next() {
        let Some(key) = item.word() else {
            match item.block() {
                Some(medium) if medium.name == "Medium" => {
                    interior = Some(build_medium(context, medium)?);
                }
                Some(fresnel) if fresnel.name == "Fresnel" => {
                    f.angular = Some(read_fresnel(context, fresnel)?);
                }
                Some(other) if other.name == "translucency" => {
                    context.not_rendered(item.location, "translucency", "no subsurface light")?
                }
                _ => context.skip_item(item, name)?,
            }
            continue;
        };
        if key == "interface" {
            interface = true;
            continue;
        }
        if key == "cauchy" {
            read_cauchy(context, &mut cursor, &mut dispersion, item.location)?;
            continue;
        }
        read_field(context, &mut cursor, &mut f, key, item.location, name)?;
    }
    let mut spec = resolve(context, f, name, location)?;
    if interface && !spec.material.emission.is_black() {
        context.not_rendered(
            location,
            "emission",
            "an interface neither scatters nor emits",
        )?;
    }
    spec.material.interior = interior;
    spec.material.interface = interface;
    spec.dispersion = dispersion;
    Ok(spec)
}

/// cav's `Fresnel { fbase b fscale s power p }`.
fn read_fresnel(context: &mut Context, block: &Block) -> Result<AngularWeights, SceneError> {
    let mut weights = AngularWeights {
        base: 0.0,
        scale: 0.0,
        power: 5.0,
    };
    let mut cursor = Cursor::of(block);
    while let Some(item) = cursor.next() {
        match item.word() {
            Some(key @ "fbase") => weights.base = cursor.number(context, key)?,
            Some(key @ "fscale") => weights.scale = cursor.number(context, key)?,
            Some(key @ "power") => weights.power = cursor.number(context, key)?,
            Some(key) => context.skip_field(&mut cursor, key, item.location, "Fresnel")?,
            None => context.skip_item(item, "Fresnel")?,
        }
    }
    Ok(weights)
}

fn read_field(
    context: &mut Context,
    cursor: &mut Cursor,
    f: &mut Fields,
    key: &str,
    location: Location,
    name: &str,
) -> Result<(), SceneError> {
    match key {
        "color" => f.color = Some(color3(cursor, context, key)?),
        "diffuseColor" | "attenuation" | "albedo" => {
            f.diffuse_color = Some(color3(cursor, context, key)?)
        }
        "transmittance" => f.transmittance = Some(color3(cursor, context, key)?),
        "specularColor" => f.specular_color = Some(color3(cursor, context, key)?),
        "shininess" | "exponent" => f.shininess = Some((cursor.number(context, key)?, location)),
        "reflectiveColor" => f.reflective_color = Some(color3(cursor, context, key)?),
        "emission" | "emissionColor" | "emissiveColor" | "Energy" | "luminance" | "lightColor" => {
            f.emission = Some(color3(cursor, context, key)?)
        }
        "boost" | "illumination" => f.emission_scale = Some(cursor.number(context, key)?),
        "refractiveIndex" | "refractive_index" | "refractive" | "refractionIndex"
        | "refractive_rate" | "ns" | "ir" => f.ior = Some(cursor.number(context, key)?),
        "refractRate" if context.dialect == Dialect::Rub => {
            f.ior = Some(cursor.number(context, key)?)
        }
        "diffusionRate" => f.rates[0] = Some(cursor.number(context, key)?),
        "specularRate" => f.rates[1] = Some(cursor.number(context, key)?),
        "refractRate" => f.rates[2] = Some(cursor.number(context, key)?),
        "diff" => f.yao[0] = Some(cursor.number(context, key)?),
        "refl" => f.yao[1] = Some(cursor.number(context, key)?),
        "refr" => f.yao[2] = Some(cursor.number(context, key)?),
        "DIFF" => f.yao_flag = Some(Kind::Diffuse),
        "SPEC" => f.yao_flag = Some(Kind::Specular),
        "REFR" => f.yao_flag = Some(Kind::Refract),
        "perDiffuse" => f.per[0] = Some(cursor.number(context, key)?),
        "perReflect" => f.per[1] = Some(cursor.number(context, key)?),
        "perRefract" => f.per[2] = Some(cursor.number(context, key)?),
        "fuzz" | "fuzziness" => f.fuzz = Some(cursor.number(context, key)?),
        "roughness" => f.roughness = Some(cursor.number(context, key)?),
        "metallic" => f.metallic = Some((cursor.number(context, key)?, location)),
        "glossy" => f.glossy = Some(cursor.number(context, key)? != 0.0),
        "cookTorrence" => {
            let alpha = cursor.number(context, key)?;
            let f0 = cursor.number(context, key)?;
            // rub's renderer ignores the third number.
            cursor.take_numbers();
            f.cook_torrance = Some((alpha, f0));
        }
        "reflective" => f.reflective = Some(cursor.number(context, key)?),
        "transmissive" => {
            f.transmissive = Some(cursor.number(context, key)?);
            if cursor.peek_number().is_some() {
                f.ior = Some(cursor.number(context, key)?);
            }
        }
        "type" => read_type(context, cursor, f, location)?,
        "prop" => {
            let (weights, ior) = preset(cursor.word(context, key)?);
            f.weights = Some(weights);
            f.ior = ior.or(f.ior);
        }
        "BRDF" => {
            let mut n = [0.0; 7];
            for slot in &mut n {
                *slot = cursor.number(context, key)?;
            }
            f.weights = Some([n[0], n[1], n[2]]);
            f.ior = Some(n[6]);
            if n[3..6].iter().any(|&v| v != 0.0) {
                context.not_rendered(
                    location,
                    "BRDF numbers 4 to 6",
                    "their meaning is unknown",
                )?;
            }
        }
        "texture" => read_texture(context, cursor, f, location)?,
        "Texture" | "texture_file" | "diffuseMap" => {
            f.texture = Some(path_after(cursor, context, key)?)
        }
        "bump" | "normal_file" | "bumpMap" | "normal" => {
            // The image decides between height and normal map at load, the
            // key only says which is assumed (see `textures`); a number after
            // the path is the height scale.
            let path = path_after(cursor, context, key)?;
            let named = match key {
                "bump" | "bumpMap" => MapName::Bump,
                _ => MapName::Normal,
            };
            let scale = cursor.take_numbers().first().copied().unwrap_or(1.0);
            f.surface_map = Some(SurfaceMapRef { path, named, scale });
        }
        "nTexture" => {
            // rub's normal-map descriptor file (see `descriptor`).
            let path = path_after(cursor, context, key)?;
            f.surface_map = Some(SurfaceMapRef {
                path,
                named: MapName::Normal,
                scale: 1.0,
            });
        }
        "specularMap" | "emissiveMap" | "opacityMap" => {
            cursor.word(context, key)?;
            context.not_rendered(location, key, "only colour, normal and bump maps are")?;
        }
        "dispersion" => {
            cursor.take_numbers();
            context.not_rendered(
                location,
                key,
                "a material's dispersion is given by 'cauchy A B'",
            )?;
        }
        "Func" => {
            let n = cursor.integer(context, key)?;
            f.uv_rule = UvRule::from_func(n);
            if f.uv_rule.is_none() && n != 0 {
                context.warn(
                    location,
                    format!(
                        "'Func {n}' is not one of afb's texture rules (1 to 7): the shape's uv"
                    ),
                )?;
            }
        }
        "textureScale" if context.dialect == Dialect::Cav => {
            f.texture_scale = Some(cursor.number(context, key)?)
        }
        "textureScale" | "textureLuminance" => {
            cursor.take_numbers();
            context.not_rendered(location, key, "this texture convention is not implemented")?;
        }
        "enableReflect" | "enableRefract" => {
            cursor.take_numbers();
            context.not_rendered(
                location,
                key,
                "the lobe weights decide (rub's renderer does not read it either)",
            )?;
        }
        "opacity" | "transparency" | "transparent" | "refractiveColor" | "transparentColor"
        | "ambientColor" => {
            cursor.take_numbers();
            context.not_rendered(location, key, "no such lobe")?;
        }
        _ => context.skip_field(cursor, key, location, name)?,
    }
    Ok(())
}

/// `type`: 3 numbers = weights, 1 number = enum, a word = DIFF/SPEC/REFR.
fn read_type(
    context: &mut Context,
    cursor: &mut Cursor,
    f: &mut Fields,
    location: Location,
) -> Result<(), SceneError> {
    if let Some(ItemKind::Word(word)) = cursor.peek().map(|i| &i.kind) {
        f.kind = match &**word {
            "DIFF" => Some(Kind::Diffuse),
            "SPEC" => Some(Kind::Specular),
            "REFR" => Some(Kind::Refract),
            _ => {
                return context.warn(
                    location,
                    format!("unknown material type '{}'", crate::limits::shown(word)),
                );
            }
        };
        cursor.next();
        return Ok(());
    }
    let numbers = cursor.take_numbers();
    match numbers.as_slice() {
        [d, s, r] => f.weights = Some([*d, *s, *r]),
        [t] => {
            f.kind = match *t as i64 {
                0 => Some(Kind::Diffuse),
                1 => Some(Kind::Specular),
                2 => Some(Kind::Refract),
                3 => Some(Kind::Light),
                _ => return context.warn(location, format!("unknown material type {t}")),
            }
        }
        _ => context.warn(location, "'type' needs 1 or 3 numbers or a word".into())?,
    }
    Ok(())
}

/// `texture`: an integer index, a path (an image, or rub's descriptor
/// `.txt`, read when textures load), or a path + 8 numbers.
fn read_texture(
    context: &mut Context,
    cursor: &mut Cursor,
    f: &mut Fields,
    location: Location,
) -> Result<(), SceneError> {
    if cursor.peek_number().is_some() {
        cursor.take_numbers();
        return context.not_rendered(location, "texture <index>", "texture tables are not read");
    }
    f.texture = Some(path_after(cursor, context, "texture")?);
    if !cursor.take_numbers().is_empty() {
        context.not_rendered(
            location,
            "the numbers after 'texture'",
            "planar texture mappings are not implemented",
        )?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::LoadOptions;
    use crate::scene::build::build;
    use crate::scene::parse::parse;
    use std::path::Path;

    fn materials(body: &str) -> Result<Vec<Material>, String> {
        let text = format!("PerspectiveCamera {{ width 2 height 2 }}\nMaterials {{\n{body}\n}}");
        let doc = parse(&text, Path::new("t.txt")).map_err(|e| e.to_string())?;
        build(&doc, Path::new("t.txt"), &LoadOptions::default())
            .map(|s| s.materials)
            .map_err(|e| e.to_string())
    }

    fn weights(m: &Material) -> [f64; 3] {
        [m.diffuse, m.specular, m.refract]
    }

    #[test]
    fn canonical_rates() {
        let m = materials("Material { specularRate 0.3 refractRate 0.2 refractiveIndex 1.3 }")
            .expect("ok");
        assert!((m[0].diffuse - 0.5).abs() < 1e-12);
        assert_eq!(m[0].ior, 1.3);
        let e = materials("Material { diffusionRate 0.5 specularRate 0.3 }").expect_err("sum");
        assert!(e.contains("t.txt:3:1"), "{e}");
        let m = materials("Material { color 0 0 0 emission 12 12 12 }").expect("ok");
        assert_eq!(weights(&m[0]), [1.0, 0.0, 0.0]);
        assert_eq!(m[0].emission, Color::gray(12.0));
    }

    #[test]
    fn dialect_conflicts() {
        let m = materials("Material { type 1 1 0 refr 1.3 diffuseColor 1 0 0 }").expect("ok");
        assert_eq!(weights(&m[0]), [0.5, 0.5, 0.0]);
        assert_eq!(m[0].ior, 1.3);
        assert_eq!(m[0].color, Color::new(1.0, 0.0, 0.0));
        let m = materials("Material { diff 0 refl 0 refr 1 emissionColor 1 1 1 }").expect("ok");
        assert_eq!(weights(&m[0]), [0.0, 0.0, 1.0]);
        assert_eq!(m[0].ior, 1.5);
        let m = materials("PhongMaterial { type REFR refractive_rate 1.4 }").expect("ok");
        assert_eq!(weights(&m[0]), [0.0, 0.0, 1.0]);
        let m = materials("Material { attenuation 1 1 1 specularColor 4 4 4 type 3 }").expect("ok");
        assert_eq!(m[0].emission, Color::gray(4.0));
        let m = materials("Material { diffuseColor 1 1 1 specularColor 1 1 1 shininess 20}")
            .expect("ok");
        assert_eq!(m[0].emission, Color::BLACK);
        assert_eq!(weights(&m[0]), [1.0, 0.0, 0.0]);
    }

    #[test]
    fn count_mismatch_is_a_warning_and_unknown_keys_are_skipped() {
        let text = "PerspectiveCamera { width 2 height 2 }\nMaterials { numMaterials 3\n Material { wobble 1 2 color 1 0 0 } }";
        let doc = parse(text, Path::new("t.txt")).expect("parses");
        let scene = build(&doc, Path::new("t.txt"), &LoadOptions::default()).expect("builds");
        assert_eq!(scene.warnings.len(), 2);
        assert_eq!(
            scene.warnings[0].location,
            Location {
                line: 3,
                column: 13
            }
        );
        assert_eq!(scene.materials[0].color, Color::new(1.0, 0.0, 0.0));
        let strict = LoadOptions {
            strict: true,
            ..LoadOptions::default()
        };
        assert!(build(&doc, Path::new("t.txt"), &strict).is_err());
    }
}
