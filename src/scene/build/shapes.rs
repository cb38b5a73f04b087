//! Leaf shapes: spheres (static and moving), planes, triangles, rectangles, disks.

use crate::math::{Point3, Vec3, orthonormal_basis};
use crate::scene::ast::{Block, Item};
use crate::scene::build::{Context, Cursor};
use crate::scene::error::{Location, SceneError};
use crate::scene::model::Object;

/// The `key numbers*` fields of a shape block, with where each one was written.
pub struct Fields<'a> {
    block: &'a Block,
    location: Location,
    entries: Vec<Entry<'a>>,
}

/// One `key numbers*` field.
struct Entry<'a> {
    key: &'a str,
    numbers: Vec<f64>,
    /// Where the numbers end, and the item there (`None` at the closing brace).
    after: Location,
    next: Option<&'a Item>,
    /// Where the key is.
    at: Location,
}

impl<'a> Fields<'a> {
    /// Reads every field; keys not in `known` are skipped with a warning.
    pub fn read(
        context: &mut Context,
        block: &'a Block,
        location: Location,
        known: &[&str],
    ) -> Result<Self, SceneError> {
        let mut entries = Vec::new();
        let mut cursor = Cursor::of(block);
        while let Some(item) = cursor.next() {
            match item.word() {
                Some(key) if known.contains(&key) => {
                    let numbers = cursor.take_numbers();
                    entries.push(Entry {
                        key,
                        numbers,
                        after: cursor.here(),
                        next: cursor.peek(),
                        at: item.location,
                    });
                }
                Some(key) => context.skip_field(&mut cursor, key, item.location, &block.name)?,
                None => context.skip_item(item, &block.name)?,
            }
        }
        Ok(Fields {
            block,
            location,
            entries,
        })
    }

    pub fn has(&self, key: &str) -> bool {
        self.entries.iter().any(|entry| entry.key == key)
    }

    fn last(&self, key: &str) -> Option<&Entry<'a>> {
        self.entries.iter().rev().find(|entry| entry.key == key)
    }

    /// The numbers of the last `key` field, at least `count` of them, all finite.
    fn numbers(&self, context: &Context, key: &str, count: usize) -> Result<&[f64], SceneError> {
        let Some(entry) = self.last(key) else {
            return Err(context.error(self.location, format!("{} needs '{key}'", self.block.name)));
        };
        let numbers = &entry.numbers;
        match numbers.get(..count) {
            Some(values) if values.iter().all(|v| v.is_finite()) => Ok(values),
            Some(_) => {
                Err(context.error(entry.after, format!("a number after '{key}' is too large")))
            }
            None => {
                let next = entry.next.map_or_else(|| "'}'".to_string(), Item::describe);
                let found = match numbers.len() {
                    0 => next,
                    n => format!("{n} then {next}"),
                };
                let finite = match entry.next {
                    Some(item) if item.is_non_finite_word() => "finite ",
                    _ => "",
                };
                let expected = match count {
                    1 => format!("a {finite}number"),
                    n => format!("{n} {finite}numbers"),
                };
                Err(context.error(
                    entry.after,
                    format!("expected {expected} after '{key}', found {found}"),
                ))
            }
        }
    }

    /// The `radius` of a round shape: zero (no surface) and negative radii
    /// (their size is used) are read with a warning at the field.
    fn radius(&self, context: &mut Context) -> Result<f64, SceneError> {
        let radius = self.number(context, "radius")?;
        let at = self.last("radius").map_or(self.location, |entry| entry.at);
        let shape = &self.block.name;
        if radius == 0.0 {
            context.warn(
                at,
                format!("a {shape} of radius 0 has no surface: it is left out"),
            )?;
        } else if radius < 0.0 {
            context.warn(
                at,
                format!(
                    "negative radius {radius}: the {shape} of radius {} is used",
                    -radius
                ),
            )?;
        }
        Ok(radius.abs())
    }

    pub fn number(&self, context: &Context, key: &str) -> Result<f64, SceneError> {
        Ok(self
            .numbers(context, key, 1)?
            .first()
            .copied()
            .unwrap_or(0.0))
    }

    pub fn vec3(&self, context: &Context, key: &str) -> Result<Vec3, SceneError> {
        let v = self.numbers(context, key, 3)?;
        Ok(Vec3::new(v[0], v[1], v[2]))
    }

    pub fn vec3_or(&self, context: &Context, key: &str, default: Vec3) -> Result<Vec3, SceneError> {
        if self.has(key) {
            self.vec3(context, key)
        } else {
            Ok(default)
        }
    }

    /// Warns about each of `keys` that the block has: read, not rendered.
    fn not_rendered(
        &self,
        context: &mut Context,
        keys: &[&str],
        why: &str,
    ) -> Result<(), SceneError> {
        for entry in &self.entries {
            if keys.contains(&entry.key) {
                context.not_rendered(entry.at, entry.key, why)?;
            }
        }
        Ok(())
    }

    fn nonzero(&self, context: &Context, key: &str) -> Result<Vec3, SceneError> {
        let v = self.vec3(context, key)?;
        if v.norm() < 1e-300 {
            return Err(context.error(self.location, format!("'{key}' must not be zero")));
        }
        Ok(v)
    }
}

/// Builds a shape block; `None` when the name is not a shape.
pub fn build_shape(
    context: &mut Context,
    block: &Block,
    location: Location,
    material: usize,
) -> Result<Option<Object>, SceneError> {
    let read =
        |context: &mut Context, known: &[&str]| Fields::read(context, block, location, known);
    let object = match block.name.as_str() {
        "Sphere" => {
            let f = read(
                context,
                &["center", "radius", "moveVector", "speed", "motion"],
            )?;
            let mut motion = Vec3::zeros();
            for key in ["moveVector", "speed", "motion"] {
                if f.has(key) {
                    motion = f.vec3_or(context, key, motion)?;
                    // osb's `speed` shifts the ray's origin by U speed at
                    // every test (looks.md): the sphere is seen at
                    // center - U speed.
                    if key == "speed" {
                        motion = -motion;
                    }
                }
            }
            Object::Sphere {
                center: f.vec3(context, "center")?,
                radius: f.radius(context)?,
                motion,
                material,
            }
        }
        "MovingSphere" | "MovingObj" => {
            let f = read(context, &["center0", "center1", "time0", "time1", "radius"])?;
            let shutter = "the motion spans the whole shutter";
            f.not_rendered(context, &["time0", "time1"], shutter)?;
            let start = f.vec3(context, "center0")?;
            Object::Sphere {
                center: start,
                radius: f.radius(context)?,
                motion: f.vec3(context, "center1")? - start,
                material,
            }
        }
        "MotionSphere" => {
            let f = read(
                context,
                &["origCenter", "center", "radius", "tStart", "tEnd"],
            )?;
            let shutter = "the motion spans the whole shutter";
            f.not_rendered(context, &["tStart", "tEnd"], shutter)?;
            let start = f.vec3(context, "origCenter")?;
            Object::Sphere {
                center: start,
                radius: f.radius(context)?,
                motion: f.vec3(context, "center")? - start,
                material,
            }
        }
        "Plane" => {
            let f = read(context, &["normal", "offset", "scale"])?;
            let tiling = "planes tile textures 10 times per unit";
            f.not_rendered(context, &["scale"], tiling)?;
            Object::Plane {
                normal: f.nonzero(context, "normal")?,
                offset: f.number(context, "offset")?,
                material,
            }
        }
        "FinitePlane" => {
            let f = read(context, &["normal", "offset", "size"])?;
            let normal = f.nonzero(context, "normal")?;
            let size = f.numbers(context, "size", 2)?;
            let (u, v) = orthonormal_basis(&normal.normalize());
            let center = normal * (f.number(context, "offset")? / normal.norm_squared());
            let (edge_u, edge_v) = (u * size[0], v * size[1]);
            Object::Rectangle {
                origin: center - edge_u / 2.0 - edge_v / 2.0,
                edge_u,
                edge_v,
                material,
            }
        }
        "Triangle" => {
            let f = read(context, &["vertex0", "vertex1", "vertex2"])?;
            Object::Triangle {
                vertices: [
                    f.vec3(context, "vertex0")?,
                    f.vec3(context, "vertex1")?,
                    f.vec3(context, "vertex2")?,
                ],
                material,
            }
        }
        "Quad" => {
            let f = read(context, &["origin", "u", "v"])?;
            Object::Rectangle {
                origin: f.vec3(context, "origin")?,
                edge_u: f.vec3(context, "u")?,
                edge_v: f.vec3(context, "v")?,
                material,
            }
        }
        "Rectangle" => rectangle(context, block, location, material)?,
        "XYRectangle" | "XZRectangle" | "YZRectangle" => {
            let f = read(context, &["points", "offset", "normal"])?;
            let p = f.numbers(context, "points", 4)?;
            let k = f.number(context, "offset")?;
            let sign = if f.has("normal") {
                f.number(context, "normal")?
            } else {
                1.0
            };
            let (origin, mut edge_u, mut edge_v) = match block.name.as_str() {
                "XYRectangle" => (
                    Point3::new(p[0], p[1], k),
                    Vec3::new(p[2] - p[0], 0.0, 0.0),
                    Vec3::new(0.0, p[3] - p[1], 0.0),
                ),
                "XZRectangle" => (
                    Point3::new(p[0], k, p[1]),
                    Vec3::new(p[2] - p[0], 0.0, 0.0),
                    Vec3::new(0.0, 0.0, p[3] - p[1]),
                ),
                _ => (
                    Point3::new(k, p[0], p[1]),
                    Vec3::new(0.0, p[2] - p[0], 0.0),
                    Vec3::new(0.0, 0.0, p[3] - p[1]),
                ),
            };
            let axis = match block.name.as_str() {
                "XYRectangle" => Vec3::z(),
                "XZRectangle" => Vec3::y(),
                _ => Vec3::x(),
            };
            if edge_u.cross(&edge_v).dot(&axis) * sign < 0.0 {
                std::mem::swap(&mut edge_u, &mut edge_v);
            }
            Object::Rectangle {
                origin,
                edge_u,
                edge_v,
                material,
            }
        }
        "Disk" => {
            let f = read(context, &["center", "normal", "radius"])?;
            Object::Disk {
                center: f.vec3(context, "center")?,
                normal: f.nonzero(context, "normal")?,
                radius: f.radius(context)?,
                material,
            }
        }
        _ => return Ok(None),
    };
    Ok(Some(object))
}

/// The three incompatible `Rectangle` forms, told apart by their first field.
fn rectangle(
    context: &mut Context,
    block: &Block,
    location: Location,
    material: usize,
) -> Result<Object, SceneError> {
    let first = block.items.iter().find_map(|i| i.word()).unwrap_or("point");
    match first {
        "x0" | "y0" | "x1" | "y1" | "k" | "n" | "d" => {
            let f = Fields::read(
                context,
                block,
                location,
                &["x0", "y0", "x1", "y1", "n", "d", "k"],
            )?;
            let (x0, y0) = (f.number(context, "x0")?, f.number(context, "y0")?);
            let (x1, y1) = (f.number(context, "x1")?, f.number(context, "y1")?);
            let z = if f.has("d") {
                f.number(context, "d")?
            } else {
                f.number(context, "k")?
            };
            Ok(Object::Rectangle {
                origin: Point3::new(x0, y0, z),
                edge_u: Vec3::new(x1 - x0, 0.0, 0.0),
                edge_v: Vec3::new(0.0, y1 - y0, 0.0),
                material,
            })
        }
        "center" | "dirLen" | "dirWid" | "len" | "wid" => {
            let f = Fields::read(
                context,
                block,
                location,
                &["center", "dirLen", "dirWid", "len", "wid"],
            )?;
            let along = f.nonzero(context, "dirLen")?.normalize() * f.number(context, "len")?;
            let across = f.nonzero(context, "dirWid")?.normalize() * f.number(context, "wid")?;
            Ok(Object::Rectangle {
                origin: f.vec3(context, "center")? - along / 2.0 - across / 2.0,
                edge_u: along,
                edge_v: across,
                material,
            })
        }
        _ => {
            let f = Fields::read(context, block, location, &["point", "x", "y"])?;
            Ok(Object::Rectangle {
                origin: f.vec3(context, "point")?,
                edge_u: f.vec3(context, "x")?,
                edge_v: f.vec3(context, "y")?,
                material,
            })
        }
    }
}
