//! Looks: the conventions by which a renderer turns a scene into pixels,
//! as data, one row per renderer (`../shared/docs/looks.md` has the facts
//! each row comes from, with their source lines). A look is chosen for each
//! scene by the fingerprints its renderer's files carry ([`detect`], one
//! table row per renderer), or by `--look NAME`; the render summary and
//! `check` say which and the fingerprint found.
//!
//! | look | renderer | estimator | depth | a ray that misses | PA1 lights | Phong lobes | glass |
//! |---|---|---|---|---|---|---|---|
//! | `original` | the ported renderer (canonical dialect) | path tracing | 5 | background for camera rays | when the scene has no emitter | yes | Schlick |
//! | `physical` | this project's physically based rendering | path tracing | 5 | background, weighted, at every depth | when the scene has no emitter | yes | exact Fresnel |
//! | `pa1` | the course framework's ray caster (Achazwl, aliezlo `rc`, Cambrian's first renders) | ray casting: Phong per light, no shadows, pixel centres | 1 | background | always | the framework's | none |
//! | `cambrian` | Cambrian-yzt/PathTracer | path tracing | unlimited (roulette) | black | never | no | Schlick; its sphere test (frosted glass balls); texels times the colour, its texture frames, its dispersion (one wavelength per camera sample times its colour); its rectangles, which lose the hits that round off their plane; a square lens |
//! | `wso` | W-Solaris (and aliezlo's `pt`), the D3 family's path tracer | path tracing by BSDF sampling, rays leaving from the hit itself; spheres, planes and triangles met in f32 by its tests, diffuse bounces about the modelled normal (`alz-pt` keeps the f64 ones) | 15 hits | background, unweighted, at every depth | never | no | Schlick; planes one-sided and hit at distance 0 too; square lens |
//! | `osb` | one-step-beh1nd | path tracing | unlimited (roulette) | black | never | no | reflect with 0.25 + R/2, unweighted; osb's `glossy` weight |
//! | `ylc` | ylc2001 | path tracing | unlimited (roulette) | background, unweighted | never | no | Schlick |
//! | `yzc` | yuzc19 | path tracing | 11 | background, weighted | never | no | Schlick; horizontal `angle`; square lens |
//! | `cyy` | Chenyu-Yang-2000 | path tracing | 5 | background for camera rays | always, next to the area lights | yes | Schlick |
//!
//! "Unlimited" depths are 64 scattering vertices: Russian roulette ends
//! paths long before, as it did in those renderers, without bias.

use crate::bsdf::DielectricFresnel;
use crate::bsdf::LookLobes;
use crate::geometry::{RevolutionTest, SphereTest};
use crate::sampler::SamplerKind;
use crate::scene::model::{CameraDesc, FovAxis, LensShape, Scene};
use crate::world::ShapeRules;

pub mod detect;
mod integrator;
mod material_rules;
mod output;
mod photons;
mod rows;
mod summary;
pub use integrator::Integrator;
pub use material_rules::{LobeChoice, MtlReading};
pub use output::OutputCurve;
pub use photons::{PhotonLook, PhotonMethod, SeenEmission};
pub use summary::summary;

/// How a look renders dispersive glass.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DispersionSensor {
    /// Spectral transport read by a sensor (`spectral`): the physical image.
    Spectral,
    /// Cambrian's: one wavelength per camera sample, the sample's RGB
    /// radiance times Cambrian's colour of it (`spectral::cambrian`).
    Cambrian,
}

/// Where a ray that leaves a surface starts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RayOrigins {
    /// Off the surface along the geometric normal, so that the ray cannot
    /// find the surface it leaves (ours).
    Offset,
    /// At the hit point itself, with no distance kept (W-Solaris's: a ray
    /// leaving a sphere or a triangle finds the same surface again at
    /// distance ~0 about half the time, by rounding, and scatters there
    /// again; inside an emitting mirror sphere it collects the emission at
    /// every bounce).
    AtHit,
    /// At the hit point computed in single precision, `origin + direction
    /// t` in f32 (W-Solaris's, with its single-precision tests: see
    /// [`Look::single_precision_hits`]; yangjunx21's, with its
    /// single-precision planes: see [`Look::single_precision_planes`]).
    AtHitSinglePrecision,
}

/// How the original integrator ends paths by chance.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Roulette {
    /// Never: paths end at the look's depth.
    Never,
    /// yangjunx21's, from the 6th hit on: a path goes on when a uniform
    /// draw from [-1, 1] is below `p`, the largest channel of the hit's
    /// colour, and its throughput is then divided by `p`. It goes on with
    /// probability (1 + p) / 2, not `p`, so each such hit brightens the
    /// expected image by (1 + p) / (2 p).
    SignedUniform,
}

/// What a ray that hits nothing brings back.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Miss {
    /// The background for camera rays, black after a bounce (the original).
    CameraBackground,
    /// The background at every depth, times the path's throughput (an
    /// environment light).
    Weighted,
    /// The background at every depth, *not* times the throughput (W-Solaris
    /// and its family add it raw: diffuse objects glow with it).
    Unweighted,
    /// Black at every depth, camera rays included.
    Black,
}

/// When the point and directional lights of a scene are added.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PointLights {
    /// Only in scenes without emissive materials (the PA1 scenes).
    WithoutEmitters,
    /// Never: light comes from emissive materials only.
    Never,
    /// Always, next to the emitters (cyy's renderer adds every light).
    Always,
}

/// Where in a pixel camera rays go.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PixelSampling {
    /// The original's 2x2 sub-pixels with tent filters.
    Tent,
    /// One ray through the pixel centre.
    Centre,
    /// One ray through the pixel's corner, its integer coordinate (the
    /// renderers that pass `(x, y)` to the framework's camera without
    /// adding 0.5: hanna0911, emily-jia, jefflyy).
    Corner,
    /// A point drawn uniformly within half a pixel of the pixel's corner,
    /// its integer coordinate (cav's: it adds a uniform number in
    /// [-0.5, 0.5) to each integer coordinate), so its image lies half a
    /// pixel away from the centred filters'.
    AboutCorner,
}

impl PixelSampling {
    /// Whether every camera ray of a pixel goes through the same point.
    pub fn is_fixed(self) -> bool {
        matches!(self, PixelSampling::Centre | PixelSampling::Corner)
    }
}

/// Which image row a texture coordinate v reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TextureRows {
    /// Row (1 - v) h: v = 0 is the bottom of the image (the original's).
    Up,
    /// Row v h: v = 0 is the top (yuzc19's, which does not flip).
    Down,
}

/// How a textured shape's uv reach its image.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TextureFrames {
    /// Our shapes' uv, the image stretched over them.
    Shapes,
    /// Cambrian's: sphere longitudes from -z and rectangles that cut the
    /// image instead of stretching it (see [`crate::render_scene::texture_frames`]).
    Cambrian,
    /// cav's: planes take their uv frame from the normal as cav's do, and
    /// a texel is read at the coordinates times the material's
    /// `textureScale`, wrapped (see [`crate::shading::cav_texel`]).
    Cav,
}

/// One look's conventions.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Look {
    pub name: &'static str,
    /// Whose renderer it is.
    pub renderer: &'static str,
    /// The estimator that renders it (`--integrator` overrides it).
    pub integrator: Integrator,
    /// Scattering vertices before a path ends (`--max-depth` overrides it).
    pub max_depth: u32,
    pub miss: Miss,
    pub point_lights: PointLights,
    /// Whether PA1's `specularColor`/`shininess` become a Phong lobe of the
    /// path traced BSDF (most coursework path tracers ignore them).
    pub phong_lobes: bool,
    /// What dielectrics reflect.
    pub fresnel: DielectricFresnel,
    pub pixels: PixelSampling,
    /// Whether planes are hit from the front only (so that light passes
    /// through them from behind).
    pub one_sided_planes: bool,
    /// Whether planes are hit at distance 0 too (W-Solaris's accept
    /// `t >= 0`): with rays leaving from the hit itself, a ray refracted
    /// through a plane from a point that rounds exactly onto it meets the
    /// plane again at 0, hit after hit, until it is reflected away or its
    /// hits run out.
    pub planes_accept_zero: bool,
    /// Whether spheres, planes and triangles meet rays by W-Solaris's tests
    /// in single precision (`geometry::single_precision`): with rays leaving
    /// from the f32 hit point ([`RayOrigins::AtHitSinglePrecision`]), a ray
    /// finds the surface it leaves again about half the time, as in its
    /// renderer.
    pub single_precision_hits: bool,
    /// Whether diffuse bounces are cosine-weighted about the surface's
    /// normal as modelled (outward for a sphere, a triangle's own) rather
    /// than about the normal turned towards the ray (W-Solaris's: a ray
    /// that meets a surface from behind goes on through it).
    pub diffuse_about_modelled_normal: bool,
    /// Whether a texel is multiplied by the material's colour (Cambrian's
    /// `colour x texture`) instead of replacing it (the original's).
    pub texture_times_color: bool,
    pub texture_rows: TextureRows,
    /// The image axis an `angle` spans, when the renderer decides it rather
    /// than the dialect (yuzc19's is horizontal).
    pub fov_axis: Option<FovAxis>,
    pub texture_frames: TextureFrames,
    pub ray_origins: RayOrigins,
    /// Whether osb's `glossy` is its renderer's own weight (a GGX coat
    /// otherwise).
    pub osb_glossy: bool,
    /// The lens shape the renderer gives every camera (`None`: the scene's).
    pub lens_shape: Option<LensShape>,
    pub dispersion_sensor: DispersionSensor,
    /// How spheres meet rays (Cambrian's test for its glass balls).
    pub sphere_test: SphereTest,
    /// Whether rectangles meet rays by Cambrian's test, which loses the
    /// hits whose point does not round into the rectangle's box
    /// ([`crate::geometry::cambrian_rectangle`]).
    pub cambrian_rectangles: bool,
    /// Whether surfaces of revolution turn about z (jefflyy's: the
    /// profile's y becomes z) rather than about y.
    pub revolutions_about_z: bool,
    /// How surfaces of revolution meet rays (jefflyy's Newton, yao-jz's
    /// from a tessellation).
    pub revolution_test: RevolutionTest,
    /// A photon-mapping renderer's conventions (`photons`); `None`: this
    /// project's photon mapping, when `--integrator sppm` asks for it.
    pub photons: Option<PhotonLook>,
    /// What the renderer does to a pixel's average before its image writer
    /// (8-bit outputs, unless `--gamma`, `--exposure` or `--tonemap` say).
    pub output: OutputCurve,
    /// Whether an emitter's colour also reflects light (no: a hit on an
    /// emitter returns its emission and ends the path).
    pub emitters_reflect: bool,
    /// How a material's lobe is chosen from its written weights.
    pub lobe_choice: LobeChoice,
    /// Whether every hit counts as a ray entering its surface from outside
    /// (cav's shapes turn their normals towards the ray before its tracer
    /// asks which side the ray is on, so a ray leaving glass refracts as if
    /// entering it, bending towards the normal by 1/ior, and is never
    /// totally reflected).
    pub every_hit_enters: bool,
    /// Whether OBJ faces are read as the course framework's loader reads
    /// them (one flat triangle per face, `v/vt/vn` corners read in pairs:
    /// see `MeshData::framework_reading`).
    pub framework_obj_reading: bool,
    /// Whether ray casting shades with the normal as the shape stores it (a
    /// triangle's from its winding), not turned toward the ray: a face
    /// seen from behind gets no diffuse light (hanna0911's).
    pub normals_as_stored: bool,
    /// Whose reading of an OBJ's `.mtl` materials wins over the scene's
    /// `MaterialIndex` (none: the scene's material).
    pub mtl_reading: MtlReading,
    /// Whether mesh triangles shade with their face normal, the file's
    /// `vn` unused (emily-jia's).
    pub face_normals: bool,
    /// Whether planes are met in single precision (yangjunx21's `float`
    /// vectors): with rays leaving from the hit itself
    /// ([`RayOrigins::AtHitSinglePrecision`]), a bounce that rounded to the far side
    /// of a wall meets it again, from behind, and leaves through it.
    pub single_precision_planes: bool,
    /// How paths end by chance in the original integrator.
    pub roulette: Roulette,
    /// The sample values (`--sampler` overrides it). A renderer that clamps
    /// each pixel's average keeps less of a noisier pixel, so the noise of
    /// its independent draws is part of its image.
    pub sampler: SamplerKind,
}

impl Look {
    /// The scene's camera as this look reads it.
    pub fn camera(&self, camera: &CameraDesc) -> CameraDesc {
        let mut camera = camera.clone();
        if let (Some(axis), Some((angle, _))) = (self.fov_axis, camera.fov) {
            camera.fov = Some((angle, axis));
        }
        if let Some(shape) = self.lens_shape {
            camera.lens_shape = shape;
        }
        camera
    }

    /// How this look's shapes meet rays.
    pub fn shape_rules(&self) -> ShapeRules {
        ShapeRules {
            one_sided_planes: self.one_sided_planes,
            planes_accept_zero: self.planes_accept_zero,
            sphere_test: self.sphere_test,
            revolutions_about_z: self.revolutions_about_z,
            single_precision: self.single_precision_hits,
            revolution_test: self.revolution_test,
            framework_obj_reading: self.framework_obj_reading,
            face_normals: self.face_normals,
            cav_plane_frames: self.texture_frames == TextureFrames::Cav,
            single_precision_planes: self.single_precision_planes,
            cambrian_rectangles: self.cambrian_rectangles,
        }
    }

    /// What this look decides about materials' lobes.
    pub fn lobes(&self) -> LookLobes {
        LookLobes {
            phong: self.phong_lobes,
            osb_glossy: self.osb_glossy,
        }
    }

    pub fn from_name(name: &str) -> Option<Look> {
        Look::ALL.into_iter().find(|look| look.name == name)
    }

    /// The look of the renderer that most likely wrote `scene`, and why
    /// (see [`detect`]).
    pub fn detect(scene: &Scene) -> (Look, String) {
        detect::detect(scene)
    }
}

impl Default for Look {
    fn default() -> Self {
        Look::ORIGINAL
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::build::build_text;

    fn look_of(text: &str) -> &'static str {
        let scene = build_text(text).expect("builds");
        Look::detect(&scene).0.name
    }

    const CAMERA: &str =
        "PerspectiveCamera { center 0 0 5 direction 0 0 -1 up 0 1 0 angle 30 width 4 height 4 }\n";

    #[test]
    fn every_look_has_a_name_of_its_own() {
        for look in Look::ALL {
            assert_eq!(Look::from_name(look.name), Some(look));
        }
        assert_eq!(Look::from_name("nope"), None);
    }

    #[test]
    fn looks_are_detected_by_dialect_and_fingerprints() {
        let pa1 = "Materials { Material { diffuseColor 1 0 0 specularColor 1 1 1 shininess 20 } }";
        assert_eq!(look_of(&format!("{CAMERA}{pa1}")), "pa1");
        let cambrian = "Materials { PhongMaterial { type DIFF color 1 1 1 refractive_rate 1 } }";
        assert_eq!(look_of(&format!("{CAMERA}{cambrian}")), "cambrian");
        let d3 = "Materials { Material { color 1 1 1 type 1 0 0 } }";
        assert_eq!(look_of(&format!("{CAMERA}{d3}")), "yzc");
        let osb = "Materials { Material { color 1 1 1 type 1 0 0 glossy 1 } }";
        assert_eq!(look_of(&format!("{CAMERA}{osb}")), "osb");
        let ylc =
            "DiskLights { numDiskLights 0 } Materials { Material { color 1 1 1 type 1 0 0 } }";
        assert_eq!(look_of(&format!("{CAMERA}{ylc}")), "ylc");
        let wso = "Materials { Material { color 1 1 1 type 1 0 0 bump texture/rope.jpg } }";
        assert_eq!(look_of(&format!("{CAMERA}{wso}")), "wso");
        let canonical = "Materials { Material { color 1 1 1 diffusionRate 1 } }";
        assert_eq!(look_of(&format!("{CAMERA}{canonical}")), "original");
    }
}
