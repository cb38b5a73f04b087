//! The render-time scene: everything a render reads, built once by
//! [`RenderScene::build`] from a parsed scene and the settings of the
//! render (its look, depth, size, light subpaths, dispersion)
//! and immutable (hence `Sync`) after that. Every integrator, render, render
//! job, preview and test enters by it.
//!
//! The build applies `--dispersion` to the scene's glass, the look's
//! conventions that change the scene's data (texture rows and Cambrian's
//! texture frames) and those of its shapes (one-sided planes, Cambrian's
//! sphere test), flattens the object tree into the world, makes one render
//! material per scene material (lobes, colour, maps), the emitter table,
//! the camera of the film, and decides what the render's strategies can
//! use (PA1 lights, light subpaths, the mirror and glass casters). Shadow
//! rays go through [`RenderScene::unoccluded`] and
//! [`RenderScene::transmittance`], with one rule for where they stop.

use std::sync::Arc;

mod casters;
pub mod emily_jia_mtl;
pub mod lobes;
mod materials;
mod notices;
pub mod texture_frames;
mod visibility;

pub use casters::Casters;
pub use notices::Notice;
pub use visibility::{MAX_CROSSINGS, SHADOW_REACH, SHADOW_SHORTENING, ShadowTarget};

use crate::camera::{Camera, MIN_LENS_RADIUS};
use crate::color::Color;
use crate::emitters::Emitters;
use crate::look::{
    DispersionSensor, Integrator, Look, Miss, MtlReading, PixelSampling, PointLights,
    TextureFrames, TextureRows,
};
use crate::math::{Aabb, Point3, Ray};
use crate::medium::Medium;
use crate::sampler::Sampler;
use crate::scene::build::dispersion::apply_channels;
use crate::scene::model::{Light, Object, Scene};
use crate::shading::{RenderMaterial, Shading};
use crate::spectral::Dispersion;
use crate::subpixel::film_position;
use crate::world::{World, WorldHit};

/// The settings of a render that decide its render-time scene.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SceneSettings {
    /// The conventions of the rendering.
    pub look: Look,
    /// Image width and height (the film the camera's rays cover).
    pub width: u32,
    pub height: u32,
    /// Scattering vertices before a path ends.
    pub max_depth: u32,
    /// Whether the path integrator may use its strategies for caustics
    /// (light subpaths and split bounces) where the scene has any.
    pub light_paths: bool,
    /// Indices per RGB channel for every refractive material
    /// (`--dispersion`).
    pub dispersion: Option<Dispersion>,
}

impl SceneSettings {
    /// The settings a render of `scene` in `look` has when nothing else is
    /// asked: the look's depth, the scene's image size, light subpaths
    /// where they help, no `--dispersion`.
    pub fn defaults(scene: &Scene, look: Look) -> SceneSettings {
        SceneSettings {
            look,
            width: scene.camera.width,
            height: scene.camera.height,
            max_depth: look.max_depth,
            light_paths: true,
            dispersion: None,
        }
    }
}

/// Which sample dimensions a scene needs: a scene pays only for what it uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SamplingPlan {
    /// Lens samples (depth of field).
    pub lens: bool,
    /// Shutter-time samples (moving spheres).
    pub time: bool,
}

impl SamplingPlan {
    pub fn for_scene(scene: &Scene) -> SamplingPlan {
        SamplingPlan {
            lens: scene.camera.lens_radius >= MIN_LENS_RADIUS,
            time: has_motion(&scene.root),
        }
    }
}

fn has_motion(root: &Object) -> bool {
    let mut moving = false;
    root.for_each_leaf(&mut |leaf| {
        if let Object::Sphere { motion, .. } = leaf {
            moving |= motion.norm_squared() > 0.0;
        }
    });
    moving
}

/// A scene ready to render (see the module documentation).
pub struct RenderScene {
    /// The scene as the look reads it (the description; integrators read
    /// the render data below).
    scene: Scene,
    settings: SceneSettings,
    world: World,
    /// One per scene material.
    materials: Vec<RenderMaterial>,
    /// For a hit without a material.
    default_material: RenderMaterial,
    /// The emissive shapes that next-event estimation samples.
    emitters: Emitters,
    /// The point, spot and directional lights added by shadow rays (by the
    /// look's rule: see [`PointLights`]).
    direct_lights: Vec<Light>,
    camera: Camera,
    plan: SamplingPlan,
    /// Whether the path integrator traces light subpaths for caustics and
    /// splits the bounces of diffuse vertices seen through mirrors and
    /// glass (see `integrator::split`).
    light_paths: bool,
    /// The mirror and glass objects, for skipping the rays of light
    /// subpaths and split bounces that cannot find one.
    casters: Casters,
    /// Whether the scene has participating media.
    media: bool,
    /// Camera samples draw Cambrian's wavelength.
    cambrian_wavelengths: bool,
    /// Whether the path integrator's last vertex, when Lambert, takes its
    /// light sample alone (see `integrator::path`).
    light_sample_ends_paths: bool,
    /// What the build found not rendered.
    warnings: Vec<Notice>,
}

impl RenderScene {
    /// The render-time scene of `scene` under `settings`: the one way to
    /// make one.
    pub fn build(mut scene: Scene, settings: &SceneSettings) -> RenderScene {
        let mut warnings = Vec::new();
        if let Some(dispersion) = settings.dispersion {
            warnings.extend(apply_dispersion(&mut scene, dispersion));
        }
        let look = settings.look;
        adapt(&mut scene, &look);
        let world = World::build(&scene, look.shape_rules());
        if world.cav_revolutions_exact() > 0 {
            warnings.push(Notice::Warning(format!(
                "the {} look's tessellations of surfaces of revolution would pass {} \
                 triangles: {} of them rendered exact instead",
                look.name,
                crate::limits::MAX_CAV_TESSELLATION_TRIANGLES,
                world.cav_revolutions_exact()
            )));
        }
        let camera = Camera::new(
            &look.camera(&scene.camera),
            settings.width.max(1),
            settings.height.max(1),
        );
        let mut emitters = Emitters::build(&scene, &world);
        let emitters_cover = emitters.cover(&scene, &world);
        let media = scene.has_media();
        // One-sided planes make visibility depend on direction, which
        // light subpaths (traced from the light's side) cannot honour.
        // Light subpaths do not account for transmittance (see `volpath`).
        // Light subpaths carry RGB: they would cross dispersive glass
        // with one index (see `notices::dispersion_notes`).
        let caustics = !look.one_sided_planes
            && !media
            && !scene.has_dispersion()
            && casters::prepare_light_paths(&scene, &world, &mut emitters);
        let casters = if caustics {
            Casters::of(&scene, &world)
        } else {
            Casters::default()
        };
        RenderScene {
            materials: materials::render_materials(&scene, look),
            default_material: materials::default_material(look),
            direct_lights: direct_lights(&scene, look.point_lights).to_vec(),
            plan: SamplingPlan::for_scene(&scene),
            light_paths: caustics && settings.light_paths,
            casters,
            media,
            cambrian_wavelengths: look.dispersion_sensor == DispersionSensor::Cambrian
                && scene.has_dispersion(),
            light_sample_ends_paths: emitters_cover
                && (scene.background.is_black()
                    || matches!(look.miss, Miss::Black | Miss::CameraBackground)),
            emitters,
            camera,
            world,
            settings: *settings,
            warnings,
            scene,
        }
    }

    /// The settings it was built for.
    pub fn settings(&self) -> &SceneSettings {
        &self.settings
    }

    /// The scene description it was built from, as the look reads it
    /// (`--dispersion` applied).
    pub fn description(&self) -> &Scene {
        &self.scene
    }

    /// What a render of this scene with `integrator` says before it
    /// starts: what it does not render, and how it renders media and
    /// dispersion.
    pub fn notices(&self, integrator: Integrator) -> Vec<Notice> {
        let mut notices = self.warnings.clone();
        notices.extend(notices::media_notes(&self.scene, integrator));
        notices.extend(notices::dispersion_notes(&self.scene, integrator));
        notices
    }

    #[inline(always)]
    pub fn world(&self) -> &World {
        &self.world
    }

    #[inline(always)]
    pub fn look(&self) -> &Look {
        &self.settings.look
    }

    /// Scattering vertices before a path ends.
    #[inline(always)]
    pub fn max_depth(&self) -> u32 {
        self.settings.max_depth
    }

    /// The camera of the film being rendered.
    #[inline(always)]
    pub fn camera(&self) -> &Camera {
        &self.camera
    }

    pub fn plan(&self) -> SamplingPlan {
        self.plan
    }

    #[inline(always)]
    pub fn emitters(&self) -> &Emitters {
        &self.emitters
    }

    /// The PA1 point, spot and directional lights that shadow rays add.
    #[inline(always)]
    pub fn direct_lights(&self) -> &[Light] {
        &self.direct_lights
    }

    /// Every PA1 light of the scene (what ray casting shades with).
    pub fn lights(&self) -> &[Light] {
        &self.scene.lights
    }

    /// Radiance of rays that miss everything.
    #[inline(always)]
    pub fn background(&self) -> Color {
        self.scene.background
    }

    /// The medium outside every shape with one of its own.
    #[inline(always)]
    pub fn medium(&self) -> Option<&Medium> {
        self.scene.medium.as_ref()
    }

    /// Where the scene's camera is (the reference of light subpaths' starts).
    #[inline(always)]
    pub fn camera_center(&self) -> Point3 {
        self.scene.camera.center
    }

    /// Whether light subpaths and split bounces run.
    #[inline(always)]
    pub fn light_paths(&self) -> bool {
        self.light_paths
    }

    #[inline(always)]
    pub fn casters(&self) -> &Casters {
        &self.casters
    }

    /// Whether the scene has participating media (the path integrator is
    /// then `volpath`).
    #[inline(always)]
    pub fn media(&self) -> bool {
        self.media
    }

    /// Whether camera samples draw Cambrian's wavelength (its look, in a
    /// scene with dispersion).
    #[inline(always)]
    pub fn cambrian_wavelengths(&self) -> bool {
        self.cambrian_wavelengths
    }

    /// Whether the path integrator's last vertex, when Lambert, takes its
    /// light sample alone and traces no bounce: light sampling covers every
    /// emitter, and a ray leaving the last vertex finds no background.
    #[inline(always)]
    pub fn light_sample_ends_paths(&self) -> bool {
        self.light_sample_ends_paths
    }

    /// The render material of material `index` (the default material's
    /// for a hit without one).
    #[inline(always)]
    pub fn material(&self, index: usize) -> &RenderMaterial {
        self.materials.get(index).unwrap_or(&self.default_material)
    }

    /// The nearest hit of `ray`.
    #[inline(always)]
    pub fn intersect(&self, ray: &Ray) -> Option<WorldHit> {
        self.world.intersect(ray, 0.0, f64::INFINITY)
    }

    /// `hit` of `ray`, seen from the ray.
    #[inline(always)]
    pub fn shade(&self, hit: &WorldHit, ray: &Ray) -> Shading<'_> {
        let mut at = Shading::new(self.material(hit.material), hit, ray);
        at.entering |= self.look().every_hit_enters;
        at
    }

    /// Bounds of the bounded shapes.
    pub fn bounds(&self) -> Aabb {
        self.world.bounds()
    }

    /// A camera ray through pixel (`x`, `y`), `y` from the bottom, and its
    /// lens sample: a position under the look's pixel filter (the 2x2
    /// sub-pixels' tent, see `subpixel`, the centre, the corner or a box
    /// about the corner), lens and time only
    /// where the scene needs them, drawn from `sampler` in that order.
    pub fn camera_ray(&self, x: usize, y: usize, sampler: &mut Sampler) -> (Ray, [f64; 2]) {
        let (film_x, film_y) = match self.look().pixels {
            PixelSampling::Tent => film_position(x, y, sampler.next_2d()),
            PixelSampling::Centre => (x as f64 + 0.5, y as f64 + 0.5),
            PixelSampling::Corner => (x as f64, y as f64),
            PixelSampling::AboutCorner => {
                let [u, v] = sampler.next_2d();
                (x as f64 + u - 0.5, y as f64 + v - 0.5)
            }
        };
        let lens = if self.plan.lens {
            sampler.next_2d()
        } else {
            [0.5, 0.5]
        };
        let time = if self.plan.time {
            sampler.next_f64()
        } else {
            0.0
        };
        (self.camera.ray(film_x, film_y, lens, time), lens)
    }
}

/// Gives the refractive materials of `scene` the indices of `dispersion`
/// (a warning when there are none). The scene's hash changes with them, so
/// that parts of renders with and without them do not merge.
fn apply_dispersion(scene: &mut Scene, dispersion: Dispersion) -> Option<Notice> {
    if apply_channels(&mut scene.materials, dispersion) == 0 {
        return Some(Notice::Warning(
            "'--dispersion' is not rendered: no material refracts".to_string(),
        ));
    }
    if let Dispersion::Channels(indices) = dispersion {
        let mut bytes = scene.load.source_hash.to_le_bytes().to_vec();
        bytes.extend(indices.iter().flat_map(|index| index.to_le_bytes()));
        scene.load.source_hash = crate::scene::fnv1a(&bytes);
    }
    None
}

/// Makes `scene` read as `look` reads it where that is a property of the
/// scene's data: textures upside down for [`TextureRows::Down`], rewritten
/// for [`TextureFrames::Cambrian`].
fn adapt(scene: &mut Scene, look: &Look) {
    if look.mtl_reading == MtlReading::EmilyJia {
        emily_jia_mtl::apply(scene);
    }
    scene
        .materials
        .iter_mut()
        .for_each(|material| look.adapt_material(material));
    if look.texture_frames == TextureFrames::Cambrian {
        crate::render_scene::texture_frames::apply_cambrian(scene);
    }
    if look.texture_rows == TextureRows::Down {
        scene
            .textures
            .iter_mut()
            .for_each(|texture| Arc::make_mut(texture).flip_rows());
    }
}

/// The lights that are added by shadow rays, by the look's rule: in scenes
/// without emitters (the PA1 scenes), always (cyy's renderer adds every
/// light), or never.
fn direct_lights(scene: &Scene, rule: PointLights) -> &[Light] {
    match rule {
        PointLights::Never => return &[],
        PointLights::Always => return &scene.lights,
        PointLights::WithoutEmitters => {}
    }
    let mut has_emitter = false;
    scene.root.for_each_leaf(&mut |leaf| {
        for m in leaf.materials().filter_map(|i| scene.materials.get(i)) {
            has_emitter |= !m.emission.is_black();
        }
    });
    if has_emitter { &[] } else { &scene.lights }
}
