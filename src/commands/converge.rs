//! `pathtracer converge` (error against time for one scene) and
//! `pathtracer plot` (several such curves in one SVG).

use std::path::{Path, PathBuf};

use clap::Args;

use pathtracer::image_io::{
    Encoding, PendingFile, commit_together, encode_image, read_image, refuse_inputs,
    refuse_shared_outputs,
};
use pathtracer::integrator::Integrator;
use pathtracer::limits::{MAX_TABLE_BYTES, read_text_within};
use pathtracer::plot::{Series, check_plottable, log_log_svg};
use pathtracer::render::converge::{
    ConvergencePoint, Reach, converge_within, read_csv_series, time_to_reach, to_csv,
};
use pathtracer::render::photon_passes;
use pathtracer::render::render_within;

use super::{SamplingOptions, default_output, load_for_render, render_scene};

/// Seeds of references differ from the seeds of the runs they judge.
const REFERENCE_SEED_OFFSET: u64 = 0x5EED_F4EF;

#[derive(Args)]
pub struct ConvergeArgs {
    /// The scene file to render at 1, 2, 4, ... samples per pixel.
    scene: PathBuf,
    /// Reference image (PFM for linear radiance). Without one, a reference is
    /// first rendered at --reference-spp and saved next to the CSV, as
    /// <scene name>_reference.pfm (default output/<scene name>_reference.pfm).
    #[arg(long)]
    reference: Option<PathBuf>,
    /// Samples per pixel of the reference rendered when none is given.
    #[arg(long, default_value_t = 4096, value_parser = clap::value_parser!(u32).range(1..))]
    reference_spp: u32,
    /// The last stage's samples per pixel (stages: 1, 2, 4, ...).
    #[arg(long, default_value_t = 256, value_parser = clap::value_parser!(u32).range(1..))]
    max_spp: u32,
    /// CSV of (spp, seconds, rmse, rel_mse, ssim); default output/<scene>_converge.csv.
    #[arg(long)]
    csv: Option<PathBuf>,
    /// SVG plot of relative MSE against seconds; default output/<scene>_converge.svg.
    #[arg(long)]
    plot: Option<PathBuf>,
    /// Measure the error over this region only: x0,y0,x1,y1 (pixels,
    /// rows from the top, the end excluded).
    #[arg(long, value_parser = parse_region)]
    region: Option<[usize; 4]>,
    #[command(flatten)]
    sampling: SamplingOptions,
}

fn parse_region(text: &str) -> Result<[usize; 4], String> {
    let values: Vec<usize> = text
        .split(',')
        .map(|v| v.trim().parse::<usize>())
        .collect::<Result<_, _>>()
        .map_err(|_| format!("'{text}': expected x0,y0,x1,y1 in pixels"))?;
    match values[..] {
        [x0, y0, x1, y1] if x0 < x1 && y0 < y1 => Ok([x0, y0, x1, y1]),
        _ => Err(format!(
            "'{text}': expected x0,y0,x1,y1 with x0 < x1 and y0 < y1"
        )),
    }
}

pub fn run(args: &ConvergeArgs) -> Result<(), String> {
    // Every output's temporary exists before the scene is read.
    let csv = args
        .csv
        .clone()
        .unwrap_or_else(|| default_output(&args.scene, "_converge.csv"));
    let svg = args
        .plot
        .clone()
        .unwrap_or_else(|| default_output(&args.scene, "_converge.svg"));
    let mut csv_file = PendingFile::reserve(&csv)?;
    let mut svg_file = PendingFile::reserve(&svg)?;
    let mut reference_file = match &args.reference {
        Some(_) => None,
        None => Some(PendingFile::reserve(&beside(
            &csv,
            &default_output(&args.scene, "_reference.pfm"),
        ))?),
    };
    let scene = load_for_render(&args.scene, &args.sampling.scene)?;
    let mut inputs = scene.load.inputs(&args.scene);
    if let Some(reference) = &args.reference {
        inputs.push(("the reference", reference.as_path()));
    }
    let outputs: Vec<&PendingFile> = [&csv_file, &svg_file]
        .into_iter()
        .chain(reference_file.as_ref())
        .collect();
    refuse_shared_outputs(&outputs)?;
    refuse_inputs(&outputs, &inputs)?;
    let settings = args.sampling.settings(&scene, args.max_spp, false);
    if let Some(notice) = args.sampling.spp_notice(&settings, args.max_spp) {
        pathtracer::stderr_line!("{notice}");
    }
    args.sampling.check_size(&settings)?;
    let budget = args.sampling.scene.memory_budget();
    let scene = render_scene(scene, &settings);
    let reference = match (&args.reference, reference_file.take()) {
        (Some(path), _) => read_image(path)?,
        (None, None) => return Err("converge: no reference to read or render".to_string()),
        (None, Some(mut file)) => {
            let path = file.path().to_path_buf();
            let mut reference_settings =
                args.sampling
                    .settings(scene.description(), args.reference_spp, true);
            reference_settings.seed = settings.seed.wrapping_add(REFERENCE_SEED_OFFSET);
            if reference_settings.integrator == Integrator::Sppm {
                // Photon mapping converges to the path integrator's image.
                reference_settings.integrator = Integrator::Path;
            }
            pathtracer::stderr_line!(
                "rendering a reference at {} spp into {}",
                args.reference_spp,
                path.display()
            );
            let (image, stats) = render_within(&scene, &reference_settings, budget)?;
            pathtracer::stderr_line!("reference took {:.1} s", stats.seconds);
            file.write(&encode_image(&path, &image, &Encoding::gamma(None))?)?;
            file.commit()?;
            image
        }
    };
    say!("spp  seconds  rmse  rel_mse  ssim");
    let report = |p: &ConvergencePoint| {
        say!(
            "{} {:.3} {:.6} {:.6e} {:.4}",
            p.spp,
            p.seconds,
            p.rmse,
            p.rel_mse,
            p.ssim
        )
    };
    let points = if settings.integrator == Integrator::Sppm {
        let photons = args.sampling.photons.settings();
        photon_passes::converge(
            &scene,
            &settings,
            photons,
            &reference,
            args.max_spp,
            args.region,
            report,
        )?
    } else {
        converge_within(
            &scene,
            &settings,
            &reference,
            args.max_spp,
            budget,
            args.region,
            report,
        )?
    };
    csv_file.write(to_csv(&points).as_bytes())?;
    let name = args
        .scene
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    let series = [Series {
        name: "pathtracer".into(),
        points: points.iter().map(|p| (p.seconds, p.rel_mse)).collect(),
    }];
    svg_file.write(log_log_svg(&name, "seconds", "relative MSE", &series).as_bytes())?;
    commit_together(vec![csv_file, svg_file])?;
    say!("wrote {} and {}", csv.display(), svg.display());
    Ok(())
}

/// `file`'s name in the folder of `neighbour`.
fn beside(neighbour: &Path, file: &Path) -> PathBuf {
    let name = file.file_name().unwrap_or_default();
    neighbour.with_file_name(name)
}

#[derive(Args)]
pub struct PlotArgs {
    /// CSV files with `seconds` and the plotted column; each is one curve,
    /// named `name=path` or by its file name.
    #[arg(required = true)]
    curves: Vec<String>,
    /// The SVG file to write.
    #[arg(short, long)]
    output: PathBuf,
    /// The plot's title (default: "COLUMN against seconds").
    #[arg(long)]
    title: Option<String>,
    /// The column plotted against seconds.
    #[arg(long, default_value = "rel_mse")]
    column: String,
    /// Also print when each curve first reaches this value of the column.
    #[arg(long)]
    time_to: Option<f64>,
}

pub fn plot(args: &PlotArgs) -> Result<(), String> {
    let mut output = PendingFile::reserve(&args.output)?;
    let mut series = Vec::new();
    for curve in &args.curves {
        let (name, path) = match curve.split_once('=') {
            Some((name, path)) => (name.to_string(), PathBuf::from(path)),
            None => {
                let path = PathBuf::from(curve);
                let name = path
                    .file_stem()
                    .map(|s| s.to_string_lossy().into_owned())
                    .unwrap_or_default();
                (name, path)
            }
        };
        refuse_inputs(&[&output], &[("a curve to plot", path.as_path())])?;
        let text = read_text_within(&path, MAX_TABLE_BYTES, "limits::MAX_TABLE_BYTES")
            .map_err(|e| format!("cannot read the curve: {e}"))?;
        let points =
            read_csv_series(&text, &args.column).map_err(|e| format!("{}: {e}", path.display()))?;
        if let Some(target) = args.time_to {
            let reach = match time_to_reach(&points, target) {
                Some(Reach::Measured(t)) => format!("{t:.3} s"),
                Some(Reach::Extrapolated(t)) => format!("{t:.3} s (extrapolated)"),
                None => "no data".to_string(),
            };
            say!("{name}: {} {target:.4e} reached at {reach}", args.column);
        }
        series.push(Series { name, points });
    }
    check_plottable(&series)?;
    let title = args
        .title
        .clone()
        .unwrap_or_else(|| format!("{} against seconds", args.column));
    let svg = log_log_svg(&title, "seconds", &args.column, &series);
    output.write(svg.as_bytes())?;
    output.commit()
}
