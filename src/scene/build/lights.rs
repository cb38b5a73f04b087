//! `Lights { ... }` and `DiskLights { ... }`: point, directional, disk and area lights.

use std::f64::consts::PI;

use crate::color::Color;
use crate::math::{Point3, Vec3};
use crate::scene::ast::Block;
use crate::scene::build::{Context, Cursor};
use crate::scene::error::SceneError;
use crate::scene::model::{Light, Material, Object};

pub fn build_lights(context: &mut Context, block: &Block) -> Result<Vec<Light>, SceneError> {
    let mut lights = Vec::new();
    let mut expected = None;
    let mut cursor = Cursor::of(block);
    while let Some(item) = cursor.next() {
        if let Some(key) = item.word() {
            match key {
                "numLights" | "numDiskLights" => {
                    expected = Some((cursor.integer(context, key)?, item.location))
                }
                _ => context.skip_field(&mut cursor, key, item.location, &block.name)?,
            }
            continue;
        }
        let Some(light) = item.block() else {
            context.skip_item(item, &block.name)?;
            continue;
        };
        match build_light(context, light)? {
            Some(l) => lights.push(l),
            None if matches!(light.name.as_str(), "SpotLight") => context.not_rendered(
                item.location,
                "SpotLight",
                "spot lights are not implemented",
            )?,
            None => context.warn(
                item.location,
                format!("unknown light '{}', skipped", light.name),
            )?,
        }
    }
    // Unknown or unsupported lights still count against numLights.
    let found = block.items.iter().filter(|i| i.block().is_some()).count();
    if let Some((n, at)) = expected
        && n != found as i64
    {
        context.warn(
            at,
            format!("{} says {n} but {found} lights follow", block.name),
        )?;
    }
    Ok(lights)
}

fn build_light(context: &mut Context, block: &Block) -> Result<Option<Light>, SceneError> {
    let kind = block.name.as_str();
    if !matches!(
        kind,
        "PointLight" | "DirectionalLight" | "DiskLight" | "AreaLight"
    ) {
        return Ok(None);
    }
    let mut position = Point3::zeros();
    let mut direction = Vec3::new(0.0, -1.0, 0.0);
    let mut color = Color::WHITE;
    let mut scale = 1.0;
    let mut radius = 1.0;
    let mut edge_u = Vec3::new(1.0, 0.0, 0.0);
    let mut edge_v = Vec3::new(0.0, 0.0, 1.0);
    let mut cursor = Cursor::of(block);
    while let Some(item) = cursor.next() {
        let Some(key) = item.word() else {
            context.skip_item(item, kind)?;
            continue;
        };
        match key {
            "position" | "center" | "corner" | "origin" => position = cursor.vec3(context, key)?,
            "direction" | "normal" => direction = cursor.vec3(context, key)?,
            "color" | "emission" | "intensity" => {
                let c = cursor.vec3(context, key)?;
                color = Color::new(c.x, c.y, c.z);
            }
            "brightness" | "power" => scale = cursor.number(context, key)?,
            "radius" => radius = cursor.number(context, key)?,
            "x" | "u" | "edge_u" | "edge1" => edge_u = cursor.vec3(context, key)?,
            "y" | "v" | "edge_v" | "edge2" => edge_v = cursor.vec3(context, key)?,
            "falloff" => {
                cursor.take_numbers();
                context.not_rendered(item.location, key, "PA1 lights have no falloff")?;
            }
            _ => context.skip_field(&mut cursor, key, item.location, kind)?,
        }
    }
    let color = color.map(|c| c * scale);
    Ok(Some(match kind {
        "PointLight" => Light::Point { position, color },
        "DirectionalLight" => Light::Directional { direction, color },
        "DiskLight" => Light::Disk {
            center: position,
            normal: direction,
            radius,
            color,
        },
        _ => Light::Area {
            corner: position,
            edge_u,
            edge_v,
            color,
        },
    }))
}

/// The disk and area lights of the coursework dialects as emitting geometry:
/// a black disk or parallelogram, so that both integrators find them by their
/// rays and the path integrator samples them. The light's `color` is read as
/// its radiant power (the coursework scenes give disks of radius 1.5 a colour
/// of 250): a Lambertian emitter of area A and power P has radiance
/// P / (pi A). Emission is two-sided, like every emitter of the original.
/// Material indices start at `first_material`.
pub fn emitting_geometry(lights: &[Light], first_material: usize) -> Vec<(Material, Object)> {
    let mut out = Vec::new();
    for light in lights {
        let material = first_material + out.len();
        let (color, object) = match light {
            Light::Disk {
                center,
                normal,
                radius,
                color,
            } => (
                *color / (PI * PI * radius * radius),
                Object::Disk {
                    center: *center,
                    normal: *normal,
                    radius: *radius,
                    material,
                },
            ),
            Light::Area {
                corner,
                edge_u,
                edge_v,
                color,
            } => (
                *color / (PI * edge_u.cross(edge_v).norm()),
                Object::Rectangle {
                    origin: *corner,
                    edge_u: *edge_u,
                    edge_v: *edge_v,
                    material,
                },
            ),
            Light::Point { .. } | Light::Directional { .. } => continue,
        };
        if !color.is_finite() {
            continue;
        }
        let emitter = Material {
            color: Color::BLACK,
            emission: color,
            ..Material::DEFAULT
        };
        out.push((emitter, object));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::build::build_text;

    #[test]
    fn disk_lights_become_emitting_disks_of_their_power() {
        let scene = build_text(
            "PerspectiveCamera { width 2 height 2 }\n\
             DiskLights { numDiskLights 1 DiskLight { position 0 4 0 direction 0 -1 0 color 10 20 30 radius 2 } }\n\
             Materials { numMaterials 1 Material { color 1 1 1 } }\n\
             Group { numObjects 1 MaterialIndex 0 Sphere { center 0 0 0 radius 1 } }",
        )
        .expect("builds");
        assert_eq!(scene.lights.len(), 1);
        assert_eq!(scene.materials.len(), 2);
        let emitter = &scene.materials[1];
        assert!(emitter.color.is_black());
        // Power P over pi * area: 10 / (pi * pi * 2^2).
        assert!((emitter.emission.r - 10.0 / (PI * PI * 4.0)).abs() < 1e-12);
        let mut disks = 0;
        scene.root.for_each_leaf(&mut |leaf| {
            if let Object::Disk {
                radius, material, ..
            } = leaf
            {
                assert_eq!((*radius, *material), (2.0, 1));
                disks += 1;
            }
        });
        assert_eq!(disks, 1);
    }
}
