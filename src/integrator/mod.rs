//! Estimators of the radiance arriving along a camera ray.

pub mod casters;
pub mod caustics;
pub mod lights;
pub mod original;
pub mod path;
pub mod raycast;
pub mod scatter;
pub mod split;
pub mod volpath;

use crate::bsdf::{LobeSet, lobe_sets};
use crate::camera::Camera;
use crate::color::Color;
use crate::lights::Emitters;
use crate::look::{DispersionSensor, Look, Miss};
use crate::math::Ray;
use crate::sampler::Sampler;
use crate::scene::model::{Light, Material, Scene};
use crate::world::World;

/// Which estimator renders the image.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Integrator {
    /// The original renderer's estimator (see docs/original-renderer.md).
    Original,
    /// The same expected image with next-event estimation and multiple
    /// importance sampling at diffuse vertices (see [`path`]).
    #[default]
    Path,
    /// The course framework's ray casting (see [`raycast`]): the PA1 look's
    /// estimator.
    RayCast,
}

impl Integrator {
    pub const ALL: [Integrator; 3] = [Integrator::Path, Integrator::Original, Integrator::RayCast];

    /// The command-line name.
    pub fn name(self) -> &'static str {
        match self {
            Integrator::Original => "original",
            Integrator::Path => "path",
            Integrator::RayCast => "raycast",
        }
    }

    /// Parses a command-line name, as returned by [`Integrator::name`].
    pub fn from_name(name: &str) -> Option<Integrator> {
        Integrator::ALL.into_iter().find(|i| i.name() == name)
    }

    /// The radiance along the camera ray `ray` of `sample`; light that the
    /// sample's light subpath (if any) sends to other pixels goes to `splats`.
    pub fn radiance(
        &self,
        view: &SceneView,
        ray: Ray,
        sample: &CameraSample,
        sampler: &mut Sampler,
        splats: &mut Splats,
    ) -> Color {
        match self {
            Integrator::Original => original::radiance(view, ray, sampler),
            Integrator::Path if view.media => volpath::radiance(view, ray, sampler),
            Integrator::Path => path::radiance(view, ray, sample, sampler, splats),
            Integrator::RayCast => raycast::radiance(view, ray),
        }
    }
}

/// What a render of `scene` leaves out because of its participating media,
/// one note each: the estimators other than `path` ignore media, the path
/// integrator's light subpaths are off in scenes with media.
pub fn media_notes(scene: &Scene, integrator: Integrator) -> Vec<String> {
    if !scene.has_media() {
        return Vec::new();
    }
    let mut notes = Vec::new();
    if integrator != Integrator::Path {
        let name = integrator.name();
        notes.push(format!(
            "the {name} estimator ignores participating media (Medium, mist): \
             '--integrator path' renders them"
        ));
        return notes;
    }
    notes.push(
        "participating media: light subpaths and split bounces (caustics) are off, \
         the path integrator samples lights and bounces only"
            .to_string(),
    );
    notes
}

/// What a render of `scene` with `integrator` says about its dispersive
/// materials: warnings where the estimator renders them with one index
/// (the original estimator, ray casting, and the path integrator of scenes
/// with media, which stays RGB), a note that the path integrator's light
/// subpaths are off.
pub fn dispersion_notes(scene: &Scene, integrator: Integrator) -> Vec<Notice> {
    if !scene.has_dispersion() {
        return Vec::new();
    }
    let single = "renders dispersive materials with one index for all wavelengths";
    let notice = match integrator {
        Integrator::Path if scene.has_media() => Notice::Warning(format!(
            "with participating media the path integrator {single} (spectral paths \
             are not traced through media)"
        )),
        Integrator::Path => Notice::Note(
            "dispersion: a path is split to one wavelength (or one RGB channel) at \
             the first dispersive glass it meets; light subpaths and split bounces \
             (caustics) are off"
                .to_string(),
        ),
        other => Notice::Warning(format!(
            "the {} estimator {single}: '--integrator path' renders the dispersion",
            other.name()
        )),
    };
    vec![notice]
}

/// A message about a render's settings, printed before it starts.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Notice {
    /// How something is rendered.
    Note(String),
    /// Something in the scene that is not rendered.
    Warning(String),
}

impl std::fmt::Display for Notice {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Notice::Note(text) => write!(f, "note: {text}"),
            Notice::Warning(text) => write!(f, "warning: {text}"),
        }
    }
}

/// Where a camera ray comes from: its pixel and lens sample (what light
/// tracing's MIS weights need to know of the camera's side).
#[derive(Clone, Copy, Debug, Default)]
pub struct CameraSample {
    pub pixel_x: usize,
    /// Row from the bottom of the image.
    pub pixel_y: usize,
    /// The unit-square lens sample of the ray (`[0.5, 0.5]` for a pinhole).
    pub lens: [f64; 2],
}

/// What one camera sample's light subpath adds to the film (light tracing):
/// radiance for at most the 2x2 pixels around the film position it reaches,
/// as contributions to the film's light-tracing sums, and whether a light
/// subpath was traced at all (light tracing's estimate is the sum over
/// light subpaths divided by their number).
#[derive(Clone, Copy, Debug, Default)]
pub struct Splats {
    entries: [(usize, usize, Color); 4],
    len: usize,
    pub light_paths: u32,
}

impl Splats {
    /// Adds radiance to pixel (`x`, `y`), `y` from the bottom; beyond four
    /// entries (which one film position never needs) it is dropped.
    pub fn push(&mut self, x: usize, y: usize, value: Color) {
        if self.len < self.entries.len() {
            self.entries[self.len] = (x, y, value);
            self.len += 1;
        }
    }

    pub fn iter(&self) -> impl Iterator<Item = &(usize, usize, Color)> {
        self.entries[..self.len].iter()
    }
}

/// Everything an estimator reads: the built scene and its geometry.
pub struct SceneView<'a> {
    pub scene: &'a Scene,
    pub world: &'a World,
    /// The point and directional lights that are added by shadow rays:
    /// those of scenes without emissive materials (the PA1 scenes, lit only by
    /// such lights). Scenes with emitters are path traced from them alone, as
    /// the coursework path tracers did.
    pub direct_lights: &'a [Light],
    /// The emissive shapes that next-event estimation samples.
    pub emitters: Emitters,
    /// Scattering vertices before a path ends (the original: 5).
    pub max_depth: u32,
    /// Whether the path integrator traces light subpaths for caustics (the
    /// scene has mirror or glass and small enough emitters, and no media:
    /// see [`caustics::prepare`]); where they run, it also splits the
    /// bounces of diffuse vertices seen through mirrors and glass (see
    /// [`split`]): the scenes where caustics are rare and bright.
    pub light_paths: bool,
    /// The mirror and glass objects, for skipping the rays of light
    /// subpaths and split bounces that cannot find one.
    pub casters: casters::Casters,
    /// Whether the scene has participating media (the path integrator is
    /// then [`volpath`]).
    pub media: bool,
    /// The camera of the film being rendered, which light subpaths connect
    /// to (`None`: no light tracing, as for paths traced outside a render).
    pub camera: Option<Camera>,
    /// The conventions of the rendering.
    pub look: Look,
    /// The lobes of every material, made once.
    pub lobe_sets: Vec<LobeSet>,
    /// The lobes of the default material (for a hit without one).
    pub default_lobes: LobeSet,
    /// Camera samples draw Cambrian's wavelength (its look, in a scene
    /// with dispersion).
    pub cambrian_wavelengths: bool,
    /// Whether the path integrator's last vertex, when Lambert, takes its
    /// light sample alone and traces no bounce: light sampling covers every
    /// emitter, and a ray leaving the last vertex finds no background (see
    /// `path`).
    pub light_sample_ends_paths: bool,
}

impl<'a> SceneView<'a> {
    /// The view of `scene` in the original look.
    pub fn new(scene: &'a Scene, world: &'a World) -> SceneView<'a> {
        SceneView::with_look(scene, world, Look::default())
    }

    pub fn with_look(scene: &'a Scene, world: &'a World, look: Look) -> SceneView<'a> {
        let mut emitters = Emitters::build(scene, world);
        let emitters_cover = emitters.cover(scene, world);
        let media = scene.has_media();
        // One-sided planes make visibility depend on direction, which
        // light subpaths (traced from the light's side) cannot honour.
        // Light subpaths do not account for transmittance (see `volpath`).
        // Light subpaths carry RGB: they would cross dispersive glass
        // with one index (see `dispersion_notes`).
        let light_paths = !look.one_sided_planes
            && !media
            && !scene.has_dispersion()
            && caustics::prepare(scene, world, &mut emitters);
        SceneView {
            scene,
            world,
            direct_lights: lights::direct_lights(scene, look.point_lights),
            light_paths,
            casters: if light_paths {
                casters::Casters::of(scene, world)
            } else {
                casters::Casters::default()
            },
            media,
            emitters,
            max_depth: original::MAX_DEPTH,
            camera: None,
            look,
            lobe_sets: lobe_sets(&scene.materials, look.lobes()),
            default_lobes: LobeSet::from_material(&Material::DEFAULT, look.lobes()),
            cambrian_wavelengths: look.dispersion_sensor == DispersionSensor::Cambrian
                && scene.has_dispersion(),
            light_sample_ends_paths: emitters_cover
                && (scene.background.is_black()
                    || matches!(look.miss, Miss::Black | Miss::CameraBackground)),
        }
    }
}
