//! Options shared by the subcommands, and scene loading with its warnings.

/// `println!` that ignores a closed standard output (e.g. `| head`): the
/// command's files are written whatever happens to its report.
macro_rules! say {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        let _ = writeln!(std::io::stdout(), $($arg)*);
    }};
}

pub mod check;
pub mod compare;
pub mod completions;
pub mod converge;
pub mod debug_sample;
mod encoding;
pub mod examples;
pub mod job;
pub mod lookalike;
pub mod merge;
pub mod render;
pub mod sidecar;
pub mod view;

use std::path::{Path, PathBuf};

use clap::Args;

use pathtracer::allocation::check_available;
use pathtracer::film::Film;
use pathtracer::integrator::Integrator;
use pathtracer::integrator::sppm::PhotonSettings;
use pathtracer::limits::{MAX_IMAGE_SIDE, MAX_PATH_DEPTH, MemoryBudget};
use pathtracer::look::Look;
use pathtracer::render::RenderSettings;
use pathtracer::render_scene::RenderScene;
use pathtracer::sampler::SamplerKind;
use pathtracer::scene::model::{Dialect, Scene};
use pathtracer::scene::{LoadOptions, MissingAssets, load_scene};
use pathtracer::spectral::Dispersion;

pub use encoding::{EncodingOptions, linear_output_hint};

#[derive(Args, Clone)]
pub struct SceneOptions {
    /// Directory that relative mesh and texture paths resolve against first.
    #[arg(long)]
    pub base: Option<PathBuf>,
    /// Read the file as this dialect instead of detecting it.
    #[arg(long, value_parser = parse_dialect)]
    pub dialect: Option<Dialect>,
    /// Treat warnings (unknown fields, count mismatches, ...) as errors.
    #[arg(long)]
    pub strict: bool,
    /// A texture or mesh file that is not found: `error` (the default) or
    /// `placeholder` (a magenta and grey checker for a colour texture, a
    /// mesh or normal/height map left out; each with a warning).
    #[arg(long, default_value = "error", value_parser = parse_missing_assets)]
    pub missing_assets: MissingAssets,
    /// Memory an image's film and buffers, and a decoded texture, may take:
    /// bytes or a size with a binary unit (`8G`, `512M`); default 4G.
    #[arg(long, value_parser = parse_memory_budget)]
    pub max_memory: Option<MemoryBudget>,
    /// Give every refractive material one index per RGB channel: `yuzc19`
    /// (that renderer's `dispersion` command-line flag: 1.6473, 1.6527,
    /// 1.6726) or three indices `R,G,B`. Each path is split to one channel
    /// at the first such glass it meets.
    #[arg(long, value_parser = parse_dispersion)]
    pub dispersion: Option<Dispersion>,
}

impl SceneOptions {
    pub fn load_options(&self) -> LoadOptions {
        LoadOptions {
            base: self.base.clone(),
            dialect: self.dialect,
            strict: self.strict,
            missing_assets: self.missing_assets,
            memory_budget: self.memory_budget(),
        }
    }

    /// `--max-memory`, or the default budget.
    pub fn memory_budget(&self) -> MemoryBudget {
        self.max_memory.unwrap_or_default()
    }
}

fn parse_memory_budget(text: &str) -> Result<MemoryBudget, String> {
    MemoryBudget::parse(text)
}

/// How to sample the image, shared by `render` and `converge`.
#[derive(Args, Clone)]
pub struct SamplingOptions {
    /// Seed of the random sequence: the same seed gives the same image.
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// Worker threads (default: one per core).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1024))]
    pub threads: Option<u32>,
    /// Seconds between progress lines when standard error is not a
    /// terminal, as in a batch log (default 5).
    #[arg(long, value_parser = parse_progress_every)]
    pub progress_every: Option<f64>,
    /// Image width, overriding the scene's camera.
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=MAX_IMAGE_SIDE as i64))]
    pub width: Option<u32>,
    /// Image height, overriding the scene's camera.
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=MAX_IMAGE_SIDE as i64))]
    pub height: Option<u32>,
    /// Sample values: `sobol` (Owen-scrambled Sobol') or `independent` (one
    /// random generator per pixel sample). Default: the look's (`sobol`;
    /// `independent` for `yjx`, whose clamped pixels depend on the noise
    /// of independent samples)
    #[arg(long, value_parser = parse_sampler)]
    pub sampler: Option<SamplerKind>,
    /// Estimator: `path` (next-event estimation with MIS), `original` (the
    /// original renderer's estimator, the same expected image), `raycast`
    /// (the course framework's ray casting) or `sppm` (stochastic
    /// progressive photon mapping: --spp passes, see --photons-per-pass).
    /// Default: the look's (path, or raycast for the pa1 look).
    #[arg(long, value_parser = parse_integrator)]
    pub integrator: Option<Integrator>,
    /// Scattering vertices before a path ends (default: the look's; the
    /// original: 5; at most 10000).
    #[arg(long, value_parser = parse_max_depth)]
    pub max_depth: Option<u32>,
    /// BIASED: scale every sample down to at most this luminance, trading
    /// energy for the absence of fireflies. Off by default.
    #[arg(long, value_parser = parse_positive)]
    pub clamp: Option<f64>,
    /// Path integrator without its strategies for caustics (light subpaths:
    /// light tracing and connections; split bounces at diffuse vertices seen
    /// through mirrors and glass): the same expected image, noisier; for
    /// comparisons.
    #[arg(long)]
    pub no_light_paths: bool,
    /// The conventions of the rendering: one coursework renderer's
    /// (`pa1`, `han`, `jef`, `emj`, `cambrian`, `wso`, `osb`, `ylc`, `yzc`,
    /// `cyy`, `cav`; by photon mapping `tsc`, `jms`, `alz-sppm`, `yzc-sppm`, `yao`),
    /// the ported renderer's
    /// (`original`) or this project's physically based one (`physical`).
    /// Default: the look of the renderer that wrote the scene, by its
    /// dialect and fingerprints.
    #[arg(long, value_parser = parse_look)]
    pub look: Option<Look>,
    #[command(flatten)]
    pub photons: PhotonOptions,
    #[command(flatten)]
    pub scene: SceneOptions,
}

/// The parameters of `--integrator sppm` (see docs/sppm.md).
#[derive(Args, Clone)]
pub struct PhotonOptions {
    /// sppm: photons traced per pass (default: one per pixel).
    #[arg(long, value_parser = clap::value_parser!(u64).range(1..=pathtracer::integrator::sppm::options::MAX_PHOTONS_PER_PASS))]
    pub photons_per_pass: Option<u64>,
    /// sppm: the gathering radius of every pixel before its first photons,
    /// in scene units (default: 1/200 of the diagonal of the box around
    /// what the camera sees in the first pass).
    #[arg(long, value_parser = parse_positive)]
    pub initial_radius: Option<f64>,
    /// sppm: the share of each pass's photons a pixel keeps, above 0 and at
    /// most 1 (Hachisuka and Jensen's alpha; default 0.7).
    #[arg(long, value_parser = parse_alpha)]
    pub alpha: Option<f64>,
}

impl PhotonOptions {
    pub fn settings(&self) -> PhotonSettings {
        let defaults = PhotonSettings::default();
        PhotonSettings {
            photons_per_pass: self.photons_per_pass,
            initial_radius: self.initial_radius,
            alpha: self.alpha.unwrap_or(defaults.alpha),
        }
    }

    /// Whether any of them was given.
    pub fn given(&self) -> bool {
        self.photons_per_pass.is_some() || self.initial_radius.is_some() || self.alpha.is_some()
    }
}

fn parse_alpha(text: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(alpha) if alpha > 0.0 && alpha <= 1.0 => Ok(alpha),
        _ => Err(format!("'{text}': expected a number above 0 and at most 1")),
    }
}

impl SamplingOptions {
    /// The look, and why it was chosen.
    pub fn look(&self, scene: &Scene) -> (Look, String) {
        match self.look {
            Some(look) => (look, "chosen by --look".to_string()),
            None => Look::detect(scene),
        }
    }

    /// The options `render` runs with when none are given: clap's defaults
    /// above, parsed from an empty command line, so there is one source.
    pub fn defaults() -> Result<SamplingOptions, String> {
        #[derive(clap::Parser)]
        struct Bare {
            #[command(flatten)]
            sampling: SamplingOptions,
        }
        <Bare as clap::Parser>::try_parse_from(["pathtracer"])
            .map(|bare| bare.sampling)
            .map_err(|e| format!("default render options: {e}"))
    }

    pub fn settings(&self, scene: &Scene, spp: u32, progress: bool) -> RenderSettings {
        let (look, _) = self.look(scene);
        let integrator = self.integrator.unwrap_or(look.integrator);
        // Ray casting and tracing through fixed points of the pixels is
        // deterministic: one sample.
        let fixed_camera_rays = look
            .photons
            .and_then(|photons| photons.fixed_camera_rays)
            .filter(|_| integrator == Integrator::Sppm);
        let spp = if integrator.is_deterministic() && look.pixels.is_fixed() {
            1
        } else {
            fixed_camera_rays.unwrap_or(spp)
        };
        RenderSettings {
            width: self.width.unwrap_or(scene.camera.width),
            height: self.height.unwrap_or(scene.camera.height),
            spp,
            seed: self.seed,
            threads: self.threads.map(|t| t as usize),
            integrator,
            max_depth: self.max_depth.unwrap_or(look.max_depth),
            sampler: self.sampler.unwrap_or(look.sampler),
            progress,
            progress_every: self.progress_every,
            clamp: self.clamp,
            light_paths: !self.no_light_paths,
            look,
            dispersion: self.scene.dispersion,
        }
    }
}

impl SamplingOptions {
    /// A note when `settings` render another number of samples per pixel
    /// than the `asked`: a look that ray casts through pixel centres
    /// (PA1's) renders one, and yao-jz's photon mapper its 5 rounds of 8
    /// camera rays, whatever `--spp` says.
    pub fn spp_notice(&self, settings: &RenderSettings, asked: u32) -> Option<String> {
        let look = settings.look.name;
        let spp = settings.spp;
        if spp == asked {
            None
        } else if spp == 1 {
            Some(format!(
                "note: the {look} look casts one ray through each pixel centre, as the course \
                 framework did: 1 spp, not the {asked} asked (--look original path-traces it)"
            ))
        } else {
            Some(format!(
                "note: the {look} look traces {spp} camera rays per pixel, as its renderer \
                 always did, not the {asked} asked (--look original path-traces it)"
            ))
        }
    }
}

/// A finite number above 0 (`nan`, `inf`, 0 and negative numbers are refused).
pub(crate) fn parse_positive(text: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(value) if value.is_finite() && value > 0.0 => Ok(value),
        _ => Err(format!("'{text}': expected a finite number above 0")),
    }
}

fn parse_progress_every(text: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(seconds) if seconds.is_finite() && (0.1..=86_400.0).contains(&seconds) => Ok(seconds),
        _ => Err(format!(
            "'{text}': expected seconds between progress lines, from 0.1 to 86400"
        )),
    }
}

fn parse_max_depth(text: &str) -> Result<u32, String> {
    match text.trim().parse::<u64>() {
        Ok(depth) if depth <= MAX_PATH_DEPTH as u64 => Ok(depth as u32),
        Ok(depth) => Err(format!(
            "{depth} scattering vertices is more than the limit of {MAX_PATH_DEPTH} \
             (limits::MAX_PATH_DEPTH)"
        )),
        Err(_) => Err(format!(
            "'{text}' is not a whole number of scattering vertices"
        )),
    }
}

impl SamplingOptions {
    /// Checks the image size of `settings` against the memory budget
    /// before anything is allocated, naming `--width`/`--height` when they
    /// chose it (a scene's own size is checked, at its place, when the
    /// scene is built).
    /// The system is asked for the render's peak memory too (see
    /// [`pathtracer::allocation::check_available`]).
    pub fn check_size(&self, settings: &RenderSettings) -> Result<(), String> {
        let budget = self.scene.memory_budget();
        let (width, height) = (settings.width as u64, settings.height as u64);
        budget
            .check_image(width, height)
            .and_then(|()| {
                check_available(
                    MemoryBudget::image_bytes(width, height),
                    &format!("a {width}x{height} render"),
                )
            })
            .map_err(|error| match (self.width, self.height) {
                (None, None) => error,
                (Some(w), None) => format!("--width {w}: {error}"),
                (None, Some(h)) => format!("--height {h}: {error}"),
                (Some(w), Some(h)) => format!("--width {w} --height {h}: {error}"),
            })
    }

    /// The film of `settings`, once its size is checked (see
    /// [`SamplingOptions::check_size`]).
    pub fn film(&self, settings: &RenderSettings) -> Result<Film, String> {
        self.check_size(settings)?;
        Film::try_new(settings.width as usize, settings.height as usize)
    }
}

pub(crate) fn parse_look(name: &str) -> Result<Look, String> {
    Look::from_name(name).ok_or_else(|| {
        let names: Vec<&str> = Look::ALL.iter().map(|l| l.name).collect();
        format!("unknown look '{name}' (one of: {})", names.join(", "))
    })
}

fn parse_sampler(name: &str) -> Result<SamplerKind, String> {
    SamplerKind::from_name(name).ok_or_else(|| {
        let names: Vec<&str> = SamplerKind::ALL.iter().map(|k| k.name()).collect();
        format!("unknown sampler '{name}' (one of: {})", names.join(", "))
    })
}

fn parse_integrator(name: &str) -> Result<Integrator, String> {
    Integrator::from_name(name).ok_or_else(|| {
        let names: Vec<&str> = Integrator::ALL.iter().map(|i| i.name()).collect();
        format!("unknown integrator '{name}' (one of: {})", names.join(", "))
    })
}

fn parse_missing_assets(name: &str) -> Result<MissingAssets, String> {
    MissingAssets::from_name(name).ok_or_else(|| {
        let names: Vec<&str> = MissingAssets::ALL.iter().map(|m| m.name()).collect();
        format!(
            "unknown --missing-assets '{name}' (one of: {})",
            names.join(", ")
        )
    })
}

fn parse_dialect(name: &str) -> Result<Dialect, String> {
    Dialect::from_name(name).ok_or_else(|| {
        let names: Vec<&str> = Dialect::ALL.iter().map(|d| d.name()).collect();
        format!("unknown dialect '{name}' (one of: {})", names.join(", "))
    })
}

/// Loads a scene for rendering, printing its warnings (fields that are
/// not rendered among them).
pub fn load_for_render(path: &Path, options: &SceneOptions) -> Result<Scene, String> {
    let scene = load_scene(path, &options.load_options()).map_err(|e| e.to_string())?;
    for warning in &scene.warnings {
        pathtracer::stderr_line!("warning: {warning}");
    }
    Ok(scene)
}

fn parse_dispersion(text: &str) -> Result<Dispersion, String> {
    if text == "yuzc19" {
        return Ok(Dispersion::YUZC19);
    }
    let indices: Vec<f64> = text
        .split(',')
        .map(|v| v.trim().parse::<f64>())
        .collect::<Result<_, _>>()
        .map_err(|_| format!("'{text}': expected 'yuzc19' or three indices R,G,B"))?;
    match indices[..] {
        [r, g, b]
            if [r, g, b]
                .iter()
                .all(|n| n.is_finite() && (1.0..=10.0).contains(n)) =>
        {
            Ok(Dispersion::Channels([r, g, b]))
        }
        _ => Err(format!(
            "'{text}': expected 'yuzc19' or three indices R,G,B from 1 to 10"
        )),
    }
}

/// The render-time scene of `scene` for `settings`, with what it says
/// about the render (see [`RenderScene::notices`]) printed.
pub fn render_scene(scene: Scene, settings: &RenderSettings) -> RenderScene {
    let scene = RenderScene::build(scene, &settings.scene());
    for notice in scene.notices(settings.integrator) {
        pathtracer::stderr_line!("{notice}");
    }
    scene
}

/// `output/<scene name><suffix>`.
pub fn default_output(scene: &Path, suffix: &str) -> PathBuf {
    let stem = scene
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| "render".to_string());
    Path::new("output").join(format!("{stem}{suffix}"))
}
