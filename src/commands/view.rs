//! `pathtracer view`: renders a scene progressively and serves the
//! converging picture to a browser on 127.0.0.1 (see `pathtracer::preview`).

use std::path::PathBuf;
use std::sync::Arc;

use clap::Args;

use pathtracer::preview::board::Board;
use pathtracer::preview::passes::render_passes;
use pathtracer::preview::server;
use pathtracer::preview::status::Status;
use pathtracer::render::{Progress, Renderer};

use super::{EncodingOptions, SamplingOptions, load_for_render, render_scene};

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
    /// Where the page's exposure, tone curve and gamma start.
    #[command(flatten)]
    encoding: EncodingOptions,
    #[command(flatten)]
    sampling: SamplingOptions,
}

pub fn run(args: &ViewArgs) -> Result<(), String> {
    let encoding = args.encoding.encoding();
    encoding.check()?;
    let scene = load_for_render(&args.scene, &args.sampling.scene)?;
    let warnings: Vec<String> = scene.warnings.iter().map(|w| w.to_string()).collect();
    let settings = args.sampling.settings(&scene, args.spp, false);
    if let Some(notice) = args.sampling.spp_notice(&settings, args.spp) {
        pathtracer::stderr_line!("{notice}");
    }
    let mut film = args.sampling.film(&settings)?;
    let scene = render_scene(scene, &settings);
    let board = Arc::new(Board::default());
    let status = Status {
        scene: args.scene.display().to_string(),
        width: settings.width,
        height: settings.height,
        spp_target: settings.spp,
        render: 1,
        warnings,
        exposure: encoding.exposure,
        tonemap: encoding.tonemap.name(),
        gamma: encoding.gamma,
        ..Status::default()
    };
    board.post(status.clone(), None);
    let address = server::start(args.port, board.clone())?;
    say!("view: http://{address}/ (Ctrl-C to stop)");
    let renderer = Renderer::new(&scene, &settings, Progress::new(0, None))?;
    render_passes(&renderer, &mut film, settings.spp, &board, status, &|| {
        false
    })?;
    // Converged: the page stays served until Ctrl-C (SIGINT or SIGTERM
    // ends the process, see `pathtracer::interrupt`).
    loop {
        std::thread::park();
    }
}
