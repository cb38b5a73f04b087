//! The camera block, read as a key -> value map with every dialect's synonyms.

use crate::math::{Point3, Vec3};
use crate::medium::Mist;
use crate::scene::ast::Block;
use crate::scene::build::{Context, Cursor};
use crate::scene::error::{Location, SceneError};
use crate::scene::model::{CameraDesc, Dialect, FovAxis, LensShape};

/// Largest accepted `width * height`.
pub const MAX_PIXELS: u64 = 1 << 28;

const DEFAULT_SIZE: u32 = 512;

/// What a camera block holds.
pub struct CameraBlock {
    pub camera: CameraDesc,
    /// Cambrian's `mist` with where it was written (the builder turns it
    /// into the scene's medium, see [`Mist`]).
    pub mist: Option<(Mist, Location)>,
    /// Where Cambrian's `dispersion` flag was written (the builder keeps the
    /// materials' `cauchy` coefficients only with it).
    pub dispersion: Option<Location>,
}

/// The camera block.
pub fn build_camera(
    context: &mut Context,
    block: &Block,
    location: Location,
) -> Result<CameraBlock, SceneError> {
    let name = block.name.as_str();
    let mut center = Point3::zeros();
    let mut direction = Vec3::new(0.0, 0.0, -1.0);
    let mut up = Vec3::new(0.0, 1.0, 0.0);
    let mut up_at = location;
    let mut look_from: Option<Point3> = None;
    let mut look_at: Option<Point3> = None;
    let mut width: Option<(f64, Location)> = None;
    let mut height: Option<(f64, Location)> = None;
    let mut angle = None;
    let mut canvas_distance = 0.0;
    let mut focus = None;
    let mut lens_radius = 0.0;
    let mut defocus_angle = None;
    let mut mist = None;
    let mut dispersion = None;
    let mut cursor = Cursor::of(block);
    while let Some(item) = cursor.next() {
        let Some(key) = item.word() else {
            context.skip_item(item, name)?;
            continue;
        };
        match key {
            "center" => center = cursor.vec3(context, key)?,
            "direction" => direction = cursor.vec3(context, key)?,
            "up" => {
                up_at = item.location;
                up = cursor.vec3(context, key)?;
            }
            "lookFrom" => look_from = Some(cursor.vec3(context, key)?),
            "lookAt" => look_at = Some(cursor.vec3(context, key)?),
            "width" | "height" => {
                let at = cursor.here();
                let size = Some((cursor.integer(context, key)? as f64, at));
                if key == "width" {
                    width = size;
                } else {
                    height = size;
                }
            }
            "angle" => angle = Some(cursor.number(context, key)?),
            "canvasDistance" => canvas_distance = cursor.number(context, key)?,
            "focalLength" | "focal" | "focus" | "focus_distance" | "focusDist"
            | "focusDistance" | "focal_length" | "depth" | "dist" => {
                let mut distance = cursor.number(context, key)?;
                if name == "DepthCamera" && key == "focalLength" {
                    distance += 1.0;
                }
                focus = Some(distance);
            }
            "aperture" | "aperture_size" | "lens_radius" | "len_radius" | "field"
            | "interfereRatio" => {
                let mut radius = cursor.number(context, key)?;
                if context.dialect == Dialect::Cambrian && key == "aperture_size" {
                    // Cambrian moves the eye within a cube of this side
                    // (`src/main.cpp`, `shift`): half of it either way.
                    radius *= 0.5;
                }
                lens_radius = if radius >= 99990.0 {
                    0.0
                } else {
                    radius.max(0.0)
                };
            }
            "defocusAngle" => defocus_angle = Some(cursor.number(context, key)?),
            "time0" | "time1" | "tStart" | "tEnd" | "start" | "end" => {
                cursor.take_numbers();
                context.not_rendered(
                    item.location,
                    key,
                    "the shutter is open over the whole motion of moving spheres",
                )?;
            }
            "mist" => mist = Some((read_mist(context, &mut cursor)?, item.location)),
            "dispersion" => {
                if !cursor.take_numbers().is_empty() {
                    context.not_rendered(
                        item.location,
                        "the numbers after 'dispersion'",
                        "it is a flag",
                    )?;
                }
                dispersion = Some(item.location);
            }
            "lookat" => {
                cursor.take_numbers();
                context.not_rendered(
                    item.location,
                    key,
                    "the direction decides (emj ignores it too)",
                )?;
            }
            _ => context.skip_field(&mut cursor, key, item.location, name)?,
        }
    }
    if matches!(name, "OrthographicCamera" | "FisheyeCamera") {
        context.not_rendered(location, name, "rendered as a perspective camera")?;
    }
    if let (Some(from), Some(at)) = (look_from, look_at) {
        center = from;
        direction = at - from;
    } else if let Some(from) = look_from {
        center = from;
    }
    if direction.norm() < 1e-12 || !direction.iter().all(|v| v.is_finite()) {
        return Err(context.error(location, "the camera direction is zero".into()));
    }
    // The camera then takes any perpendicular as up (`Camera::new`).
    let sideways = direction
        .normalize()
        .cross(&up.try_normalize(0.0).unwrap_or_default());
    if sideways.norm().is_nan() || sideways.norm() < 1e-9 {
        context.warn(
            up_at,
            format!(
                "camera up ({}, {}, {}) is zero or along the view direction: the image's up is \
                 an arbitrary perpendicular",
                up.x, up.y, up.z
            ),
        )?;
    }
    let focus_distance = focus.unwrap_or(1.0);
    // osb's DepthCamera: `aperture` is the lens diameter, its radius drawn
    // uniformly (looks.md).
    let lens_shape = if name == "DepthCamera" {
        lens_radius *= 0.5;
        LensShape::DiskUniformRadius
    } else {
        LensShape::Disk
    };
    if let Some(theta) = defocus_angle {
        lens_radius = focus_distance * (theta.to_radians() / 2.0).tan().abs();
    }
    let size = |context: &mut Context, value: Option<(f64, Location)>, what: &str| match value {
        None => Ok(None),
        Some((v, at)) if v >= 1.0 && v <= MAX_PIXELS as f64 => Ok(Some((v as u32, at))),
        Some((v, at)) => Err(context.error(at, format!("camera {what} {v} is out of range"))),
    };
    let width = size(context, width, "width")?;
    let height = size(context, height, "height")?;
    let (width, height) = match (width, height) {
        (Some((w, at)), Some((h, _))) => {
            if u64::from(w) * u64::from(h) > MAX_PIXELS {
                return Err(context.error(at, format!("image size {w}x{h} is too large")));
            }
            (context.options.memory_budget)
                .check_image(u64::from(w), u64::from(h))
                .map_err(|e| context.error(at, e))?;
            (w, h)
        }
        (w, h) => {
            context.warn(
                location,
                format!("camera without width/height: using {DEFAULT_SIZE}x{DEFAULT_SIZE}"),
            )?;
            let w = w.map_or(DEFAULT_SIZE, |(w, _)| w.min(DEFAULT_SIZE * 8));
            let h = h.map_or(DEFAULT_SIZE, |(h, _)| h.min(DEFAULT_SIZE * 8));
            (w, h)
        }
    };
    let axis = match context.dialect {
        Dialect::Cyf | Dialect::Cambrian | Dialect::Cav => FovAxis::Horizontal,
        _ => FovAxis::Vertical,
    };
    let fov = match angle {
        Some(a) if a > 0.0 && a < 180.0 => Some((a, axis)),
        Some(a) => return Err(context.error(location, format!("camera angle {a} is out of range"))),
        None => None,
    };
    let camera = CameraDesc {
        center,
        direction,
        up,
        width,
        height,
        fov,
        canvas_distance,
        focus_distance,
        lens_radius,
        lens_shape,
    };
    Ok(CameraBlock {
        camera,
        mist,
        dispersion,
    })
}

/// `mist e s b`: two survival rates per unit length in (0, 1] and the
/// direction bias (rendered as Cambrian renders them, see [`Mist`]).
fn read_mist(context: &mut Context, cursor: &mut Cursor) -> Result<Mist, SceneError> {
    let mut numbers = [0.0; 3];
    for (slot, what) in numbers.iter_mut().zip(["survival", "scatter survival"]) {
        let at = cursor.here();
        *slot = cursor.number(context, "mist")?;
        if !(*slot > 0.0 && *slot <= 1.0) {
            return Err(context.error(
                at,
                format!("the mist's {what} rate must be in (0, 1], found {slot}"),
            ));
        }
    }
    numbers[2] = cursor.number(context, "mist")?;
    Ok(Mist {
        survival: numbers[0],
        scatter_survival: numbers[1],
        bias: numbers[2],
    })
}

#[cfg(test)]
mod tests {
    use crate::scene::LoadOptions;
    use crate::scene::build::build;
    use crate::scene::model::{Dialect, FovAxis, LensShape};
    use crate::scene::parse::parse;
    use std::path::Path;

    fn camera(text: &str) -> Result<crate::scene::model::CameraDesc, String> {
        let doc = parse(text, Path::new("t.txt")).map_err(|e| e.to_string())?;
        build(&doc, Path::new("t.txt"), &LoadOptions::default())
            .map(|s| s.camera)
            .map_err(|e| e.to_string())
    }

    #[test]
    fn keyed_in_any_order_with_synonyms() {
        let c = camera("PerspectiveCamera { height 30 aperture 0.5 width 40 focalLength 7 angle 45 center 1 2 3 direction 0 0 -1 up 0 1 0 }")
            .expect("builds");
        assert_eq!((c.width, c.height), (40, 30));
        assert_eq!(c.focus_distance, 7.0);
        assert_eq!(c.lens_radius, 0.5);
        assert_eq!(c.fov, Some((45.0, FovAxis::Vertical)));
    }

    #[test]
    fn lens_rules() {
        let c =
            camera("PerspectiveCamera { width 2 height 2 len_radius 99999 focus 3 }").expect("ok");
        assert_eq!(c.lens_radius, 0.0);
        let c = camera("PerspectiveCamera { width 2 height 2 defocusAngle 90 focusDist 2 }")
            .expect("ok");
        assert!((c.lens_radius - 2.0).abs() < 1e-9);
        let c = camera("DepthCamera { width 2 height 2 focalLength 2 aperture 10 }").expect("ok");
        assert_eq!(c.focus_distance, 3.0);
        // osb's aperture is the diameter, the radius drawn uniformly.
        assert_eq!(
            (c.lens_radius, c.lens_shape),
            (5.0, LensShape::DiskUniformRadius)
        );
        let c = camera("PerspectiveCamera { width 2 height 2 aperture 10 }").expect("ok");
        assert_eq!((c.lens_radius, c.lens_shape), (10.0, LensShape::Disk));
    }

    #[test]
    fn cambrian_aperture_size_is_the_side_of_its_eye_cube() {
        let text = "PerspectiveCamera { width 2 height 2 focal_length 250 aperture_size 2 }";
        let doc = parse(text, Path::new("t.txt")).expect("parses");
        let options = |dialect| LoadOptions {
            dialect,
            ..LoadOptions::default()
        };
        let cambrian = build(&doc, Path::new("t.txt"), &options(Some(Dialect::Cambrian)));
        assert_eq!(cambrian.expect("builds").camera.lens_radius, 1.0);
        let canonical = build(&doc, Path::new("t.txt"), &options(None));
        assert_eq!(canonical.expect("builds").camera.lens_radius, 2.0);
    }

    #[test]
    fn mist_becomes_the_scene_medium_and_its_rates_are_checked() {
        let text = "PerspectiveCamera { width 2 height 2 mist 0.998 0.9985 0.2 }";
        let doc = parse(text, Path::new("t.txt")).expect("parses");
        let scene = build(&doc, Path::new("t.txt"), &LoadOptions::default()).expect("builds");
        let medium = scene.medium.expect("mist medium");
        assert!((medium.sigma_a.r + 0.998f64.ln()).abs() < 1e-15);
        assert!((medium.sigma_s.b + 0.9985f64.ln()).abs() < 1e-15);
        let e = camera("PerspectiveCamera { width 2 height 2 mist 1.5 0.9 0 }").expect_err("rate");
        assert!(e.contains("t.txt:1:43") && e.contains("(0, 1]"), "{e}");
        let text = "Medium { sigmaS 1 1 1 }\nPerspectiveCamera { width 2 height 2 mist 0.5 0.5 0 }";
        let doc = parse(text, Path::new("t.txt")).expect("parses");
        let scene = build(&doc, Path::new("t.txt"), &LoadOptions::default()).expect("builds");
        assert_eq!(scene.medium.expect("block").sigma_a.r, 0.0);
        assert!(
            scene
                .warnings
                .iter()
                .any(|w| w.message.contains("replaces it"))
        );
    }

    #[test]
    fn sizes_are_checked() {
        assert!(camera("PerspectiveCamera { width 1000000000 height 1000000000 }").is_err());
        let e = camera("PerspectiveCamera {\n width\n}").expect_err("no number");
        assert!(e.contains("t.txt:3:1"), "{e}");
        let c = camera("PerspectiveCamera { center 0 0 0 }").expect("defaults");
        assert_eq!((c.width, c.height), (512, 512));
    }
}
