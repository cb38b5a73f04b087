//! The built scene: what the build stage produces and the renderer consumes.
//!
//! Every dialect is normalised into this one model. Positions are in world units,
//! colours are linear, materials are referred to by index.

use std::sync::Arc;

use crate::checker::Checker;
use crate::color::Color;
use crate::math::{Matrix, Point3, Vec3};
use crate::scene::error::Diagnostic;
use crate::texture::Texture;
use crate::uv_rule::UvRule;

/// A fully built scene.
#[derive(Clone, Debug)]
pub struct Scene {
    pub camera: CameraDesc,
    /// Radiance of camera rays that miss everything.
    pub background: Color,
    pub materials: Vec<Material>,
    /// Images referred to by materials (`Material::texture`, `Material::normal_map`).
    pub textures: Vec<Arc<Texture>>,
    pub lights: Vec<Light>,
    /// The object tree: groups and transforms over shapes.
    pub root: Object,
    pub dialect: Dialect,
    /// Non-fatal problems found while reading (unknown fields, count mismatches...).
    pub warnings: Vec<Diagnostic>,
    /// What reading the file cost (for `--stats`).
    pub load: LoadStats,
}

impl Scene {
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
            },
            background: Color::BLACK,
            materials,
            textures: Vec::new(),
            lights: Vec::new(),
            root,
            dialect: Dialect::Canonical,
            warnings: Vec::new(),
            load: LoadStats::default(),
        }
    }
}

/// Time spent in each phase of loading a scene, and what was loaded.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct LoadStats {
    pub parse_seconds: f64,
    pub mesh_seconds: f64,
    pub texture_seconds: f64,
    /// Distinct OBJ files read.
    pub meshes_loaded: usize,
    /// Distinct images decoded.
    pub textures_loaded: usize,
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
}

/// One normalised material: the weights of the original's three lobes
/// (`diffuse + specular + refract`, normally 1), what each of them is, and
/// the lobes that some dialects add on top (see `docs/materials.md` for the
/// table from dialect fields to these).
#[derive(Clone, Debug, PartialEq)]
pub struct Material {
    pub color: Color,
    pub emission: Color,
    pub diffuse: f64,
    pub specular: f64,
    pub refract: f64,
    pub ior: f64,
    /// Index into `Scene::textures`.
    pub texture: Option<usize>,
    /// Where `texture` is read: afb's rules from the world point (`Func`);
    /// `None`: at the shape's uv.
    pub uv_rule: Option<UvRule>,
    /// A procedural colour at the world point (rub's `checkerTexture`),
    /// instead of `texture` and `color`.
    pub checker: Option<Checker>,
    /// Index into `Scene::textures`: a tangent-space normal map.
    pub normal_map: Option<usize>,
    /// A greyscale height map (bump map).
    pub bump: Option<Bump>,
    /// GGX roughness `alpha` of the specular and refract lobes: 0 is a
    /// perfect mirror and smooth glass, larger is a rough conductor and a
    /// rough dielectric.
    pub roughness: f64,
    /// What the diffuse weight scatters by.
    pub diffuse_model: DiffuseModel,
    /// The Fresnel term of the specular weight (a conductor).
    pub conductor_fresnel: ConductorFresnel,
    /// A Phong lobe added on top of the weights (PA1 `specularColor` and
    /// `shininess`).
    pub phong: Option<Phong>,
    /// A GGX specular coat added on top of the weights (`glossy`, bow's
    /// `GlossyMaterial`).
    pub coat: Option<Coat>,
    /// Weights of the specular and refract lobes that depend on the angle of
    /// incidence (cav's `Fresnel { fbase fscale power }`); they replace
    /// `specular` and `refract`, and the diffuse weight is the rest.
    pub angular_weights: Option<AngularWeights>,
}

impl Material {
    /// White, fully diffuse, not emitting, IOR 1.5.
    pub const DEFAULT: Material = Material {
        color: Color::WHITE,
        emission: Color::BLACK,
        diffuse: 1.0,
        specular: 0.0,
        refract: 0.0,
        ior: 1.5,
        texture: None,
        uv_rule: None,
        checker: None,
        normal_map: None,
        bump: None,
        roughness: 0.0,
        diffuse_model: DiffuseModel::Lambert,
        conductor_fresnel: ConductorFresnel::Constant,
        phong: None,
        coat: None,
        angular_weights: None,
    };

    /// Whether some lobe of the material is a perfect mirror or smooth glass
    /// (what light subpaths for caustics go through).
    pub fn has_delta_lobe(&self) -> bool {
        let smooth = self.roughness < MIN_ROUGHNESS;
        (smooth && (self.specular > 0.0 || self.refract > 0.0 || self.angular_weights.is_some()))
            || self.coat.is_some_and(|c| c.alpha < MIN_ROUGHNESS)
    }
}

impl Default for Material {
    fn default() -> Self {
        Material::DEFAULT
    }
}

/// Below this GGX `alpha`, a microfacet lobe is treated as perfectly smooth
/// (a delta lobe): its distribution is too narrow to evaluate in floating point.
pub const MIN_ROUGHNESS: f64 = 1e-3;

/// A height map: the grey value `g` of the texture (in [0, 1]) lifts the
/// surface along its normal by `scale * (2 g - 1)` world units.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bump {
    /// Index into `Scene::textures`.
    pub texture: usize,
    pub scale: f64,
}

/// What the diffuse weight of a material scatters by.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum DiffuseModel {
    /// Lambert: `color / pi`.
    Lambert,
    /// rub's Cook-Torrance (`cookTorrence a F0 x`): GGX with `alpha`, a
    /// Schlick Fresnel term from the scalar `f0`, and the Schlick-Smith
    /// shadowing with `k = (alpha + 1)^2 / 8`, times the colour.
    CookTorrance { alpha: f64, f0: f64 },
}

/// The Fresnel term of a conductor.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ConductorFresnel {
    /// The colour itself at every angle (the coursework metals, and
    /// Mitsuba's conductor of material `none`).
    Constant,
    /// Schlick's approximation from the colour as the reflectance at normal
    /// incidence.
    Schlick,
}

/// A Phong lobe, energy-normalised: `color (n + 2) / (2 pi) cos^n(alpha)`,
/// alpha the angle between the reflected direction and the light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Phong {
    pub color: Color,
    pub exponent: f64,
}

/// A conductor lobe added on top of the weights, with its own colour: a
/// GGX coat (`alpha`), or a mirror at `alpha` 0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Coat {
    pub alpha: f64,
    /// Reflectance (constant Fresnel) or reflectance at normal incidence (Schlick).
    pub color: Color,
    pub fresnel: ConductorFresnel,
}

/// cav's angle-dependent weights: reflection `base + scale (1 - cos)^power`
/// from outside (inside a dielectric the term is scaled up so that it reaches
/// `base + scale` at the critical angle; beyond it everything reflects),
/// refraction `base + scale` minus that, diffuse the rest.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AngularWeights {
    pub base: f64,
    pub scale: f64,
    pub power: f64,
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

/// Profile curve of a surface of revolution, in the xy plane, swept about y.
#[derive(Clone, Debug, PartialEq)]
pub struct Profile {
    pub kind: CurveKind,
    /// Control points (x, y); z of the file is dropped.
    pub controls: Vec<[f64; 2]>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CurveKind {
    /// One Bezier curve of degree `controls.len() - 1`.
    Bezier,
    /// A uniform cubic B-spline (clamped to the range where it is defined).
    Bspline,
}

/// Triangle mesh data as loaded from an OBJ file (object space).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MeshData {
    pub positions: Vec<Point3>,
    /// Per-vertex normals (same length as `positions`) when the file has them.
    pub normals: Option<Vec<Vec3>>,
    /// Per-vertex texture coordinates when the file has them.
    pub uvs: Option<Vec<[f64; 2]>>,
    pub triangles: Vec<[u32; 3]>,
}

/// In `Object::Mesh::face_materials`: the triangle has the mesh's own material.
pub const OWN_MATERIAL: u32 = u32::MAX;

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
}
