//! `Lights { ... }` and `DiskLights { ... }`: point, directional, disk and area lights.

use crate::color::Color;
use crate::math::{Point3, Vec3};
use crate::scene::ast::Block;
use crate::scene::build::{Context, Cursor};
use crate::scene::error::SceneError;
use crate::scene::model::Light;

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
            None if matches!(light.name.as_str(), "SpotLight") => {
                context.unsupported("spot lights are ignored")
            }
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
