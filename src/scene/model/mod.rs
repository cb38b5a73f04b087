//! The built scene: what the build stage produces and the renderer consumes.
//!
//! Every dialect is normalised into this one model. Positions are in world units,
//! colours are linear, materials are referred to by index.

use std::sync::Arc;

use crate::color::Color;
use crate::geometry::{MeshData, Profile};
use crate::math::{Matrix, Point3, Vec3};
use crate::medium::Medium;
use crate::scene::error::Diagnostic;
use crate::texture::Texture;

mod material;

pub use material::{Bump, Coat, DiffuseModel, Material};

/// A fully built scene.
#[derive(Clone, Debug)]
pub struct Scene {
    pub camera: CameraDesc,
    /// Radiance of camera rays that miss everything.
    pub background: Color,
    pub materials: Vec<Material>,
    /// Images referred to by materials (`Material::texture`, `Material::normal_map`).
    pub textures: Vec<Arc<Texture>>,
    /// How the course framework's BMP reader reads the textures whose
    /// reading differs from ours, by index into `textures` (see
    /// `scene::build::texture_file::framework_bmp_reading`): what the looks
    /// of renderers that keep that reader sample.
    pub framework_readings: std::collections::HashMap<usize, Arc<Texture>>,
    pub lights: Vec<Light>,
    /// The object tree: groups and transforms over shapes.
    pub root: Object,
    /// The medium that fills the scene outside the shapes with a medium of
    /// their own (a top-level `Medium` block, or the camera's `mist`).
    pub medium: Option<Medium>,
    pub dialect: Dialect,
    /// The scene file's path, as given (empty for scenes built in code).
    pub source: std::path::PathBuf,
    /// The file's distinct field and block names, sorted (what look
    /// detection reads, see `look::detect`).
    pub words: Vec<String>,
    /// Non-fatal problems found while reading (unknown fields, count mismatches...).
    pub warnings: Vec<Diagnostic>,
    /// What reading the file cost (for `--stats`).
    pub load: LoadStats,
}

impl Scene {
    /// Whether the file uses `word` as a field or block name.
    pub fn has_word(&self, word: &str) -> bool {
        self.words
            .binary_search_by(|kept| kept.as_str().cmp(word))
            .is_ok()
    }

    /// Whether light crosses a participating medium anywhere in the scene.
    pub fn has_media(&self) -> bool {
        self.medium.is_some() || self.materials.iter().any(|m| m.interior.is_some())
    }

    /// Whether some material's index depends on the wavelength (paths
    /// through it are split, see [`crate::spectral`]).
    pub fn has_dispersion(&self) -> bool {
        self.materials.iter().any(|m| m.dispersion.is_some())
    }

    /// A scene around `root`, for scenes built in code: a pinhole camera at
    /// the origin looking down -z (16x16, the original's field of view), a
    /// black background, no lights, the canonical dialect.
    pub fn new(materials: Vec<Material>, root: Object) -> Scene {
        Scene {
            camera: CameraDesc {
                center: Point3::zeros(),
                direction: Vec3::new(0.0, 0.0, -1.0),
                up: Vec3::new(0.0, 1.0, 0.0),
                width: 16,
                height: 16,
                fov: None,
                canvas_distance: 0.0,
                focus_distance: 1.0,
                lens_radius: 0.0,
                lens_shape: LensShape::Disk,
            },
            background: Color::BLACK,
            materials,
            textures: Vec::new(),
            framework_readings: std::collections::HashMap::new(),
            lights: Vec::new(),
            root,
            medium: None,
            dialect: Dialect::Canonical,
            source: std::path::PathBuf::new(),
            words: Vec::new(),
            warnings: Vec::new(),
            load: LoadStats::default(),
        }
    }
}

/// Time spent in each phase of loading a scene, and what was loaded.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct LoadStats {
    /// FNV-1a ([`fnv1a`](crate::scene::fnv1a)) of the scene file's bytes as
    /// read: what says that parts of a render are of the same scene.
    pub source_hash: u64,
    pub parse_seconds: f64,
    pub mesh_seconds: f64,
    pub texture_seconds: f64,
    /// Distinct OBJ files read.
    pub meshes_loaded: usize,
    /// Distinct images decoded.
    pub textures_loaded: usize,
    /// Files read besides the scene file (meshes, `.mtl` libraries,
    /// textures, texture descriptors), as resolved: outputs must not be one.
    pub assets: Vec<std::path::PathBuf>,
}

impl LoadStats {
    /// The files a render of this scene reads (`scene_file` and the assets),
    /// each with the words a message names it by: no output may replace one.
    pub fn inputs<'a>(
        &'a self,
        scene_file: &'a std::path::Path,
    ) -> Vec<(&'a str, &'a std::path::Path)> {
        std::iter::once(("the scene file", scene_file))
            .chain(
                self.assets
                    .iter()
                    .map(|asset| ("a file the scene reads", asset.as_path())),
            )
            .collect()
    }
}

/// Which family of the PA grammar a file was written in (see docs/scene-format.md).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dialect {
    /// The project's own grammar (diffusionRate / specularRate / refractRate).
    Canonical,
    /// The unmodified course framework (diffuseColor / specularColor / shininess).
    Pa1,
    /// `type d s r`, `refr` as IOR, `emission`, DiskLights (jms, alz, wso, ylc, ...).
    TypeVector,
    /// Material kinds with `attenuation`; specularColor is emission (shu, cui, re2).
    Rtiow,
    /// `prop` presets (tsc).
    Prop,
    /// rub.
    Rub,
    /// `type 0/1/2`, `Energy` (afb).
    SmallptInt,
    /// cyf.
    Cyf,
    /// dst.
    Dst,
    /// cav.
    Cav,
    /// jef (`reflective`, `transmissive`).
    Jef,
    /// yao (`emissionColor`, `diff`/`refl`/`refr` weights).
    Yao,
    /// cyy.
    Cyy,
    /// piu.
    Piu,
    /// bow.
    Bow,
    /// The Cambrian coursework renderer (`type DIFF|SPEC|REFR`, `refractive_rate`).
    Cambrian,
}

impl Dialect {
    pub const ALL: [Dialect; 16] = [
        Dialect::Canonical,
        Dialect::Pa1,
        Dialect::TypeVector,
        Dialect::Rtiow,
        Dialect::Prop,
        Dialect::Rub,
        Dialect::SmallptInt,
        Dialect::Cyf,
        Dialect::Dst,
        Dialect::Cav,
        Dialect::Jef,
        Dialect::Yao,
        Dialect::Cyy,
        Dialect::Piu,
        Dialect::Bow,
        Dialect::Cambrian,
    ];

    pub fn name(&self) -> &'static str {
        match self {
            Dialect::Canonical => "canonical",
            Dialect::Pa1 => "pa1",
            Dialect::TypeVector => "type-vector",
            Dialect::Rtiow => "rtiow",
            Dialect::Prop => "prop",
            Dialect::Rub => "rub",
            Dialect::SmallptInt => "smallpt-int",
            Dialect::Cyf => "cyf",
            Dialect::Dst => "dst",
            Dialect::Cav => "cav",
            Dialect::Jef => "jef",
            Dialect::Yao => "yao",
            Dialect::Cyy => "cyy",
            Dialect::Piu => "piu",
            Dialect::Bow => "bow",
            Dialect::Cambrian => "cambrian",
        }
    }

    pub fn from_name(name: &str) -> Option<Dialect> {
        Dialect::ALL.iter().copied().find(|d| d.name() == name)
    }
}

/// Which image axis an `angle` field of view spans.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FovAxis {
    Vertical,
    Horizontal,
}

#[derive(Clone, Debug, PartialEq)]
pub struct CameraDesc {
    pub center: Point3,
    /// Not necessarily normalised; the camera normalises it.
    pub direction: Vec3,
    pub up: Vec3,
    pub width: u32,
    pub height: u32,
    /// Field of view in degrees and the axis it spans; `None`: the original's
    /// fixed 0.5135 image-plane scale (28.8 degrees vertical).
    pub fov: Option<(f64, FovAxis)>,
    /// Rays start this far along the primary direction (default 0).
    pub canvas_distance: f64,
    /// Distance of the plane in focus (only used with a lens).
    pub focus_distance: f64,
    /// Lens radius; depth of field is on when it is at least 1e-4.
    pub lens_radius: f64,
    /// How lens points are spread over the lens.
    pub lens_shape: LensShape,
}

/// How a camera spreads its lens points (`lens_radius` is the disk's radius
/// or the square's half side).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum LensShape {
    /// Uniform over the disk (a thin lens).
    #[default]
    Disk,
    /// Over the disk with the radius uniform, so points crowd the centre
    /// (osb's `DepthCamera`).
    DiskUniformRadius,
    /// Uniform over the square (yuzc19's and W-Solaris's cameras).
    Square,
}

/// Lights of the PA1 and coursework dialects (besides emissive materials).
#[derive(Clone, Debug, PartialEq)]
pub enum Light {
    /// Radiant intensity `color` from a point.
    Point { position: Point3, color: Color },
    /// Irradiance `color` arriving along `direction`.
    Directional { direction: Vec3, color: Color },
    /// A point light that shines towards `direction` (unit): radiant
    /// intensity `color * max(0, cos)^exponent`, the cosine of the angle
    /// between `direction` and the way to the lit point (cyy's `SpotLight`).
    Spot {
        position: Point3,
        direction: Vec3,
        color: Color,
        exponent: f64,
    },
    /// A disk facing `normal` of radiant power `color` (the scene builder
    /// makes it emitting geometry).
    Disk {
        center: Point3,
        normal: Vec3,
        radius: f64,
        color: Color,
    },
    /// A parallelogram `corner + s*edge_u + t*edge_v` emitting radiance
    /// `color` (the scene builder makes it emitting geometry).
    Area {
        corner: Point3,
        edge_u: Vec3,
        edge_v: Vec3,
        color: Color,
    },
}

/// In `Object::Mesh::face_materials`: the triangle has the mesh's own material.
pub const OWN_MATERIAL: u32 = u32::MAX;

/// An OBJ's `.mtl` materials that the scene's `MaterialIndex` overrides,
/// kept as written for the looks whose renderer lets them win (`emj`).
#[derive(Clone, Debug, PartialEq)]
pub struct OverriddenMtl {
    /// The `.mtl` files the OBJ names, their text.
    pub libraries: Vec<String>,
    /// Per material of those files: its name and its library (an index
    /// into `libraries`; out of range when not known).
    pub materials: Vec<(String, usize)>,
    /// Per triangle: an index into `materials`, or [`OWN_MATERIAL`] (no
    /// `usemtl`).
    pub faces: Arc<[u32]>,
}

/// A node of the object tree.
#[derive(Clone, Debug)]
pub enum Object {
    Group(Vec<Object>),
    Transform {
        /// Object to world.
        matrix: Matrix,
        /// World to object.
        inverse: Matrix,
        child: Box<Object>,
    },
    Sphere {
        center: Point3,
        radius: f64,
        /// Displacement of the centre over the whole shutter interval (motion blur).
        motion: Vec3,
        material: usize,
    },
    /// Points `p` with `normal . p = offset`.
    Plane {
        normal: Vec3,
        offset: f64,
        material: usize,
    },
    Triangle {
        vertices: [Point3; 3],
        material: usize,
    },
    /// The parallelogram `origin + s*edge_u + t*edge_v`, s and t in [0, 1].
    Rectangle {
        origin: Point3,
        edge_u: Vec3,
        edge_v: Vec3,
        material: usize,
    },
    Disk {
        center: Point3,
        normal: Vec3,
        radius: f64,
        material: usize,
    },
    Mesh {
        mesh: Arc<MeshData>,
        /// Shade with interpolated normals even when the OBJ has no `vn`
        /// (area-weighted vertex normals are computed then); the file's own
        /// `vn` are interpolated either way.
        smooth: bool,
        material: usize,
        /// Per triangle (index into `MeshData::triangles`): the material of
        /// the OBJ's `.mtl` (an index into `Scene::materials`), or
        /// [`OWN_MATERIAL`] for `material`. `None`: every triangle has
        /// `material`.
        face_materials: Option<Arc<[u32]>>,
        /// The `.mtl` materials that `material` overrides, when it does.
        overridden_mtl: Option<Arc<OverriddenMtl>>,
    },
    Revolution {
        profile: Profile,
        material: usize,
    },
}

impl Object {
    /// The material of a leaf; `None` for groups and transforms.
    pub fn material(&self) -> Option<usize> {
        match self {
            Object::Sphere { material, .. }
            | Object::Plane { material, .. }
            | Object::Triangle { material, .. }
            | Object::Rectangle { material, .. }
            | Object::Disk { material, .. }
            | Object::Mesh { material, .. }
            | Object::Revolution { material, .. } => Some(*material),
            Object::Group(_) | Object::Transform { .. } => None,
        }
    }

    /// Every material a leaf shades with: its own and, for a mesh with
    /// `.mtl` materials, those of its triangles (repeats included).
    pub fn materials(&self) -> impl Iterator<Item = usize> + '_ {
        let faces = match self {
            Object::Mesh {
                face_materials: Some(faces),
                ..
            } => &faces[..],
            _ => &[],
        };
        self.material().into_iter().chain(
            faces
                .iter()
                .filter(|&&m| m != OWN_MATERIAL)
                .map(|&m| m as usize),
        )
    }

    /// Calls `visit` on every leaf (non-group, non-transform) node.
    pub fn for_each_leaf(&self, visit: &mut impl FnMut(&Object)) {
        match self {
            Object::Group(children) => children.iter().for_each(|c| c.for_each_leaf(visit)),
            Object::Transform { child, .. } => child.for_each_leaf(visit),
            leaf => visit(leaf),
        }
    }

    /// Calls `visit` on every leaf node, which it may change.
    pub fn for_each_leaf_mut(&mut self, visit: &mut impl FnMut(&mut Object)) {
        match self {
            Object::Group(children) => children.iter_mut().for_each(|c| c.for_each_leaf_mut(visit)),
            Object::Transform { child, .. } => child.for_each_leaf_mut(visit),
            leaf => visit(leaf),
        }
    }
}
