//! `Lights { ... }` and `DiskLights { ... }`: point, directional, spot, disk and area lights.

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

/// One light block; `None` for an unknown kind. The fields each kind reads:
///
/// | kind | fields |
/// |---|---|
/// | `PointLight` | `position`, `color`, yao's `brightness` (a factor) |
/// | `DirectionalLight` | `direction`, `color` |
/// | `DiskLight` | `position`, `direction` (the normal), `color` (radiant power), `radius` |
/// | `AreaLight` (cyy) | `position` (a corner), `deltax`, `deltay` (the edges from it), `color` (radiance), `resolution` (not rendered) |
/// | `SpotLight` (cyy) | `position`, `color`, `direction`, `shininess` (the exponent of the cosine) |
///
/// cyy's renderer (`include/light.hpp`) spans the area light's points as
/// `position + s deltax + t deltay` with s and t in [0, 1], shows `color`
/// where a ray hits it (from either side), and lights a point with `color`
/// times the cosine at the light, without the area over the squared
/// distance (commented out there): `color` is read as the radiance. Its
/// `resolution` is the side of the grid of shadow rays of its ray tracer;
/// here the parallelogram is emitting geometry, sampled by area. Its spot
/// light is a point light times `max(0, cos)^shininess` of the angle
/// between `direction` and the way from the light to the point, with no
/// other cut-off and no distance falloff.
fn build_light(context: &mut Context, block: &Block) -> Result<Option<Light>, SceneError> {
    let kind = block.name.as_str();
    if !matches!(
        kind,
        "PointLight" | "DirectionalLight" | "DiskLight" | "AreaLight" | "SpotLight"
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
    let mut exponent = 0.0;
    let mut cursor = Cursor::of(block);
    while let Some(item) = cursor.next() {
        let Some(key) = item.word() else {
            context.skip_item(item, kind)?;
            continue;
        };
        match (kind, key) {
            (_, "position" | "center" | "corner" | "origin") => {
                position = cursor.vec3(context, key)?
            }
            (_, "direction" | "normal") => direction = cursor.vec3(context, key)?,
            (_, "color" | "emission" | "intensity") => {
                let c = cursor.vec3(context, key)?;
                color = Color::new(c.x, c.y, c.z);
            }
            (_, "brightness" | "power") => scale = cursor.number(context, key)?,
            ("DiskLight", "radius") => radius = cursor.number(context, key)?,
            ("AreaLight", "deltax") => edge_u = cursor.vec3(context, key)?,
            ("AreaLight", "deltay") => edge_v = cursor.vec3(context, key)?,
            ("AreaLight", "resolution") => {
                cursor.take_numbers();
                context.not_rendered(
                    item.location,
                    key,
                    "the area light is emitting geometry sampled by area, not a grid of shadow rays",
                )?;
            }
            ("SpotLight", "shininess") => {
                let at = cursor.here();
                exponent = cursor.number(context, key)?;
                if exponent < 0.0 {
                    context.warn(
                        at,
                        format!("a spot light's 'shininess' must not be negative, got {exponent}; using 0"),
                    )?;
                    exponent = 0.0;
                }
            }
            (_, "falloff") => {
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
        "SpotLight" => {
            let unit = direction.try_normalize(1e-12);
            if unit.is_none() {
                context.warn(
                    block.close,
                    "the SpotLight's direction is zero: it lights nothing".into(),
                )?;
            }
            Light::Spot {
                position,
                direction: unit.unwrap_or(Vec3::zeros()),
                color: if unit.is_some() { color } else { Color::BLACK },
                exponent,
            }
        }
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
/// rays and the path integrator samples them. A disk light's `color` is read
/// as its radiant power (the coursework scenes give disks of radius 1.5 a
/// colour of 250): a Lambertian emitter of area A and power P has radiance
/// P / (pi A). An area light's `color` is its radiance (see `build_light`).
/// Emission is two-sided, like every emitter of the original (cyy's area
/// light too is seen from both sides, though its shadow samples light only
/// the side of `deltax x deltay`). Material indices start at `first_material`.
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
                *color,
                Object::Rectangle {
                    origin: *corner,
                    edge_u: *edge_u,
                    edge_v: *edge_v,
                    material,
                },
            ),
            Light::Point { .. } | Light::Directional { .. } | Light::Spot { .. } => continue,
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

    #[test]
    fn cyy_area_lights_span_their_edges_from_the_corner_and_emit_their_colour() {
        let scene = build_text(
            "PerspectiveCamera { width 2 height 2 }\n\
             Lights { numLights 1\n\
             AreaLight { position 1 2 3 deltax 2 0 0 deltay 0 0 4 color 5 6 7\n\
             resolution 8 } }\n\
             Materials { numMaterials 1 Material { color 1 1 1 } }\n\
             Group { numObjects 1 MaterialIndex 0 Sphere { center 0 0 0 radius 1 } }",
        )
        .expect("builds");
        assert_eq!(
            scene.lights,
            vec![Light::Area {
                corner: Point3::new(1.0, 2.0, 3.0),
                edge_u: Vec3::new(2.0, 0.0, 0.0),
                edge_v: Vec3::new(0.0, 0.0, 4.0),
                color: Color::new(5.0, 6.0, 7.0),
            }]
        );
        // Radiance is the colour, whatever the area.
        assert_eq!(scene.materials[1].emission, Color::new(5.0, 6.0, 7.0));
        let mut rectangles = Vec::new();
        scene.root.for_each_leaf(&mut |leaf| {
            if let Object::Rectangle {
                origin,
                edge_u,
                edge_v,
                ..
            } = leaf
            {
                rectangles.push((*origin, *edge_u, *edge_v));
            }
        });
        assert_eq!(
            rectangles,
            vec![(
                Point3::new(1.0, 2.0, 3.0),
                Vec3::new(2.0, 0.0, 0.0),
                Vec3::new(0.0, 0.0, 4.0)
            )]
        );
        // `resolution` warns at its own line; nothing else does.
        assert_eq!(scene.warnings.len(), 1, "{:?}", scene.warnings);
        assert_eq!(scene.warnings[0].location.line, 4);
        assert!(
            scene.warnings[0]
                .message
                .contains("'resolution' is not rendered")
        );
    }

    #[test]
    fn cyy_spot_lights_keep_their_unit_direction_and_exponent() {
        let scene = build_text(
            "PerspectiveCamera { width 2 height 2 }\n\
             Lights { numLights 2\n\
             SpotLight { position 0 5 0 color 2 2 2 direction 0 -3 0 shininess 12 }\n\
             SpotLight { position 0 5 0 color 2 2 2 direction 0 0 0 shininess -1 } }\n\
             Group { numObjects 1 Sphere { center 0 0 0 radius 1 } }",
        )
        .expect("builds");
        assert_eq!(
            scene.lights[0],
            Light::Spot {
                position: Point3::new(0.0, 5.0, 0.0),
                direction: Vec3::new(0.0, -1.0, 0.0),
                color: Color::gray(2.0),
                exponent: 12.0,
            }
        );
        // A zero direction lights nothing, a negative exponent is 0: both warn
        // on the light's line.
        let Light::Spot {
            color, exponent, ..
        } = scene.lights[1]
        else {
            panic!("{:?}", scene.lights[1]);
        };
        assert_eq!((color, exponent), (Color::BLACK, 0.0));
        assert_eq!(scene.warnings.len(), 2, "{:?}", scene.warnings);
        assert!(scene.warnings.iter().all(|w| w.location.line == 4));
    }

    #[test]
    fn fields_of_other_kinds_are_not_dropped_silently() {
        let scene = build_text(
            "PerspectiveCamera { width 2 height 2 }\n\
             Lights { numLights 1 PointLight { position 0 1 0 color 1 1 1 shininess 3 deltax 1 0 0 } }",
        )
        .expect("builds");
        assert_eq!(scene.warnings.len(), 2, "{:?}", scene.warnings);
        assert!(
            scene
                .warnings
                .iter()
                .all(|w| w.message.contains("unknown field"))
        );
    }
}
