//! `pathtracer view`: renders a scene progressively and serves the
//! converging picture to a browser on 127.0.0.1 (see `pathtracer::preview`);
//! when the scene file or a file it reads changes, the scene is built again
//! and the render restarts.

use std::path::PathBuf;
use std::sync::Arc;

use clap::Args;

use pathtracer::film::Film;
use pathtracer::image_io::{DisplayImage, check_writable, read_image};
use pathtracer::preview::board::Board;
use pathtracer::preview::passes::{Ended, render_passes};
use pathtracer::preview::server::{self, Served};
use pathtracer::preview::status::Status;
use pathtracer::preview::watch::Watch;
use pathtracer::preview::{compare, tev};
use pathtracer::render::{Progress, RenderSettings, Renderer};
use pathtracer::render_scene::RenderScene;

use super::{EncodingOptions, SamplingOptions, default_output, load_for_render, render_scene};

#[derive(Args)]
pub struct ViewArgs {
    /// The scene file to render and show (the PA grammar or one of its dialects).
    scene: PathBuf,
    /// Port to listen on, on 127.0.0.1 only (0, the default: a free port;
    /// the URL is printed).
    #[arg(long, default_value_t = 0)]
    port: u16,
    /// Samples per pixel to converge to; the picture sharpens pass after
    /// pass until then.
    #[arg(long, default_value_t = 1024, value_parser = clap::value_parser!(u32).range(1..))]
    spp: u32,
    /// Where the page's save button writes (.bmp, .png, .pfm or .exr);
    /// default output/<scene name>.bmp.
    #[arg(short, long)]
    output: Option<PathBuf>,
    /// Your own image of the scene (BMP, PNG, JPEG, TGA, PFM or EXR): shown
    /// beside ours, with the look-alike figures and the FLIP heat map,
    /// measured again as the render converges.
    #[arg(long, value_name = "IMAGE")]
    against: Option<PathBuf>,
    /// Also stream the film to the tev image viewer listening at
    /// HOST:PORT (tev's default: 127.0.0.1:14158).
    #[arg(long, value_name = "HOST:PORT")]
    display: Option<String>,
    /// Where the page's exposure, tone curve and gamma start.
    #[command(flatten)]
    encoding: EncodingOptions,
    #[command(flatten)]
    sampling: SamplingOptions,
}

/// A scene built for rendering, with what the page shows of it.
struct Prepared {
    scene: RenderScene,
    settings: RenderSettings,
    film: Film,
    warnings: Vec<String>,
    /// The scene file and every file it read.
    files: Vec<PathBuf>,
}

impl Prepared {
    fn load(args: &ViewArgs) -> Result<Prepared, String> {
        let scene = load_for_render(&args.scene, &args.sampling.scene)?;
        let warnings = scene.warnings.iter().map(|w| w.to_string()).collect();
        let files = std::iter::once(args.scene.clone())
            .chain(scene.load.assets.iter().cloned())
            .collect();
        let settings = args.sampling.settings(&scene, args.spp, false);
        if let Some(notice) = args.sampling.spp_notice(&settings, args.spp) {
            pathtracer::stderr_line!("{notice}");
        }
        let film = args.sampling.film(&settings)?;
        let scene = render_scene(scene, &settings);
        Ok(Prepared {
            scene,
            settings,
            film,
            warnings,
            files,
        })
    }

    /// Renders passes until the film is done or a watched file changes.
    fn render(
        &mut self,
        board: &Board,
        status: &mut Status,
        watch: &Watch,
    ) -> Result<Ended, String> {
        let renderer = Renderer::new(&self.scene, &self.settings, Progress::new(0, None))?;
        let spp = self.settings.spp;
        render_passes(&renderer, &mut self.film, spp, board, status, &|| {
            watch.changed()
        })
    }
}

pub fn run(args: &ViewArgs) -> Result<(), String> {
    let encoding = args.encoding.encoding();
    encoding.check()?;
    let output = args
        .output
        .clone()
        .unwrap_or_else(|| default_output(&args.scene, ".bmp"));
    check_writable(&output, 1, 1)?;
    // Theirs as 8-bit values: a file's own bytes, or for linear radiance
    // the bytes `render -o x.png` would write.
    let theirs = match &args.against {
        Some(path) => Some(DisplayImage::from_image(&read_image(path)?)),
        None => None,
    };
    let board = Arc::new(Board::default());
    if let (Some(theirs), Some(path)) = (theirs, &args.against) {
        compare::start(board.clone(), theirs, path.display().to_string())?;
    }
    if let Some(address) = &args.display {
        let name = format!("pathtracer view {}", args.scene.display());
        tev::start(board.clone(), tev::connect(address)?, name)?;
    }
    let mut status = Status {
        scene: args.scene.display().to_string(),
        exposure: encoding.exposure,
        tonemap: encoding.tonemap.name(),
        gamma: encoding.gamma,
        ..Status::default()
    };
    board.post(status.clone(), None);
    let served = Served {
        board: board.clone(),
        output,
    };
    let address = server::start(args.port, served)?;
    say!("view: http://{address}/ (Ctrl-C to stop)");
    // Until Ctrl-C: SIGINT or SIGTERM ends the process (see
    // `pathtracer::interrupt`); nothing is half written.
    let mut watch = Watch::new(vec![args.scene.clone()]);
    loop {
        watch.mark();
        let rendered = Prepared::load(args).and_then(|mut prepared| {
            watch.watch(prepared.files.clone());
            let inputs: Vec<PathBuf> = prepared
                .files
                .iter()
                .chain(&args.against)
                .cloned()
                .collect();
            board.set_inputs(&inputs);
            status.render += 1;
            status.width = prepared.settings.width;
            status.height = prepared.settings.height;
            status.error = None;
            status.warnings = std::mem::take(&mut prepared.warnings);
            status.done = false;
            board.post(status.clone(), None);
            prepared.render(&board, &mut status, &watch)
        });
        match rendered {
            Ok(Ended::Stopped) => continue,
            Ok(Ended::Done) => {}
            Err(message) => {
                pathtracer::stderr_line!("error: {message}");
                // The page keeps the last good image and shows why.
                status.error = Some(message);
                board.post(status.clone(), None);
            }
        }
        watch.wait();
    }
}
