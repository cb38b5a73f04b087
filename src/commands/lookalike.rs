//! `pathtracer lookalike`: renders the scene of every pair in a pairs file
//! with the renderer's defaults, one pair after another, and writes ours,
//! theirs and the error map of each, `index.html`, `lookalike.csv` and the
//! summary (`pathtracer::pairs`).

use crate::commands::render_scene;
use std::collections::HashSet;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::{Path, PathBuf};
use std::time::Instant;

use clap::Args;

use pathtracer::image_io::{
    DisplayImage, PendingFile, commit_together, read_image_encoded, refuse_inputs, write_image,
};
use pathtracer::integrator::Integrator;
use pathtracer::look::Look;
use pathtracer::metrics::resample::box_resize;
use pathtracer::pairs::measure::measure;
use pathtracer::pairs::report::{Figures, Row, RunDescription, csv, html, summary};
use pathtracer::pairs::{Confidence, Pair, read_pairs, render_size};
use pathtracer::render::photon_passes;
use pathtracer::render::render;
use pathtracer::scene::{LoadOptions, load_scene};
use pathtracer::spectral::Dispersion;

use super::SamplingOptions;

#[derive(Args)]
pub struct LookalikeArgs {
    /// The pairs files: tab-separated folder, base, scene, render, pixels,
    /// ok|doubt; paths relative to each file's own directory. Several
    /// files are measured in one run and summed up file by file.
    #[arg(required = true)]
    pairs: Vec<PathBuf>,
    /// Width of our renders; the height follows the render's aspect ratio.
    #[arg(long, default_value_t = 160, value_parser = clap::value_parser!(u32).range(1..=4096))]
    width: u32,
    /// Samples per pixel of our renders.
    #[arg(long, default_value_t = 64, value_parser = clap::value_parser!(u32).range(1..))]
    spp: u32,
    /// Where the page, the CSV file and the images go.
    #[arg(long, default_value = "output/lookalike")]
    out: PathBuf,
    /// Which pairs: `ok` (those whose pairing is sure) or `all`.
    #[arg(long, default_value = "ok", value_parser = ["ok", "all"])]
    only: String,
    /// Render threads (default: one per core); pairs render one after another.
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1024))]
    jobs: Option<u32>,
    /// Render every pair with this look instead of the detected one (to
    /// see whether another renderer's conventions fit a folder better).
    #[arg(long, value_parser = super::parse_look)]
    look: Option<Look>,
    /// Only the pairs whose folder contains this text.
    #[arg(long)]
    folder: Option<String>,
}

pub fn run(args: &LookalikeArgs) -> Result<(), String> {
    // Each pair with the directory its paths start from and its file's name.
    let mut pairs: Vec<(Pair, PathBuf, String)> = Vec::new();
    for file in &args.pairs {
        let root = file.parent().map(Path::to_path_buf).unwrap_or_default();
        let source = file.file_name().map_or_else(
            || file.display().to_string(),
            |n| n.to_string_lossy().into_owned(),
        );
        pairs.extend(
            read_pairs(file)?
                .into_iter()
                .filter(|p| args.only == "all" || p.confidence == Confidence::Ok)
                .filter(|p| {
                    args.folder
                        .as_ref()
                        .is_none_or(|f| p.folder.contains(f.as_str()))
                })
                .map(|p| (p, root.clone(), source.clone())),
        );
    }
    let files: Vec<String> = args.pairs.iter().map(|f| f.display().to_string()).collect();
    if pairs.is_empty() {
        return Err(format!(
            "{}: no pair is selected by --only and --folder",
            files.join(", ")
        ));
    }
    // The page and the table are reserved before any pair is rendered.
    let mut csv_file = PendingFile::reserve(&args.out.join("lookalike.csv"))?;
    let index = args.out.join("index.html");
    let mut index_file = PendingFile::reserve(&index)?;
    let inputs: Vec<(&str, &Path)> = args
        .pairs
        .iter()
        .map(|f| ("the pairs file", f.as_path()))
        .collect();
    refuse_inputs(&[&csv_file, &index_file], &inputs)?;
    let images = args.out.join("images");
    std::fs::create_dir_all(&images)
        .map_err(|e| format!("{}: cannot create directory: {e}", images.display()))?;
    let mut sampling = SamplingOptions::defaults()?;
    sampling.threads = args.jobs;
    sampling.look = args.look;
    let started = Instant::now();
    let mut slugs = HashSet::new();
    let mut rows = Vec::with_capacity(pairs.len());
    for (index, (pair, root, source)) in pairs.iter().enumerate() {
        let mut slug = pair.slug();
        for n in 2.. {
            if slugs.insert(slug.clone()) {
                break;
            }
            slug = format!("{}-{n}", pair.slug());
        }
        pathtracer::stderr_line!(
            "[{}/{}] {}/{} against {}",
            index + 1,
            pairs.len(),
            pair.folder,
            pair.scene,
            pair.render
        );
        let job = PairJob {
            pair,
            root,
            source,
            images: &images,
            slug,
            sampling: &sampling,
            width: args.width as usize,
            spp: args.spp,
        };
        let row = catch_unwind(AssertUnwindSafe(|| job.run())).unwrap_or_else(|_| {
            job.failed(
                0.0,
                false,
                None,
                "panicked (see the message above)".to_string(),
            )
        });
        match &row.outcome {
            Ok(f) => pathtracer::stderr_line!(
                "        {}x{}, {:.1} s: lookalike mean {:.1}, p95 {:.1}, {}; flip {:.4}",
                f.width,
                f.height,
                row.seconds,
                f.mean,
                f.p95,
                if f.same { "same" } else { "different" },
                f.flip
            ),
            Err(error) => pathtracer::stderr_line!("        failed: {error}"),
        }
        rows.push(row);
    }
    let run = RunDescription {
        pairs_file: files.join(", "),
        width: args.width as usize,
        spp: args.spp,
        settings: format!(
            "integrator {}, sampler {}, look {}, max depth {}, seed {}",
            sampling.integrator.map_or("the look's", |i| i.name()),
            sampling.sampler.map_or("the look's", |s| s.name()),
            sampling.look.map_or("detected per scene", |l| l.name),
            sampling
                .max_depth
                .map_or("the look's".to_string(), |d| d.to_string()),
            sampling.seed
        ),
    };
    csv_file.write(csv(&rows).as_bytes())?;
    index_file.write(html(&rows, &run).as_bytes())?;
    commit_together(vec![csv_file, index_file])?;
    say!(
        "{} in {:.0} s; {}",
        summary(&rows),
        started.elapsed().as_secs_f64(),
        index.display()
    );
    Ok(())
}

/// One pair to render and measure.
struct PairJob<'a> {
    pair: &'a Pair,
    root: &'a Path,
    /// The name of the pairs file it comes from.
    source: &'a str,
    images: &'a Path,
    slug: String,
    sampling: &'a SamplingOptions,
    width: usize,
    spp: u32,
}

impl PairJob<'_> {
    fn image_path(&self, kind: &str) -> PathBuf {
        self.images.join(format!("{}.{kind}.png", self.slug))
    }

    fn failed(
        &self,
        seconds: f64,
        has_theirs: bool,
        scene: Option<(String, String)>,
        error: String,
    ) -> Row {
        let (dialect, look) = scene.unzip();
        Row {
            pair: self.pair.clone(),
            source: self.source.to_string(),
            slug: self.slug.clone(),
            dialect,
            look,
            seconds,
            has_theirs,
            outcome: Err(error),
        }
    }

    /// Reads theirs, renders ours, measures and writes the three images; any
    /// failure becomes the row's error.
    fn run(&self) -> Row {
        let started = Instant::now();
        let theirs = match read_image_encoded(&self.pair.render_path(self.root)) {
            Ok((image, _)) => DisplayImage::from_image(&image),
            Err(error) => return self.failed(0.0, false, None, error),
        };
        if (theirs.width, theirs.height) != self.pair.pixels {
            pathtracer::stderr_line!(
                "        warning: the render is {}x{}, the pairs file says {}x{}",
                theirs.width,
                theirs.height,
                self.pair.pixels.0,
                self.pair.pixels.1
            );
        }
        let (width, height) = render_size((theirs.width, theirs.height), self.width);
        let thumbnail = box_resize(&theirs, width, height).to_display();
        let has_theirs = match thumbnail.write(&self.image_path("theirs")) {
            Ok(()) => true,
            Err(error) => return self.failed(0.0, false, None, error),
        };
        let options = LoadOptions {
            base: Some(self.pair.base_path(self.root)),
            ..LoadOptions::default()
        };
        let scene = match load_scene(&self.pair.scene_path(self.root), &options) {
            Ok(scene) => scene,
            Err(error) => {
                let seconds = started.elapsed().as_secs_f64();
                return self.failed(seconds, has_theirs, None, format!("does not load: {error}"));
            }
        };
        let (look, _) = self.sampling.look(&scene);
        let dialect = Some((scene.dialect.name().to_string(), look.name.to_string()));
        if !scene.warnings.is_empty() {
            pathtracer::stderr_line!(
                "        {} warnings (pathtracer check lists them)",
                scene.warnings.len()
            );
        }
        let mut sampling = self.sampling.clone();
        sampling.width = Some(width as u32);
        sampling.height = Some(height as u32);
        if self.pair.command_line_dispersion() {
            sampling.scene.dispersion = Some(Dispersion::YUZC19);
        }
        let settings = sampling.settings(&scene, self.spp, true);
        let scene = render_scene(scene, &settings);
        // Photon mapping renders whole passes (`--spp` of them), not a film.
        let rendered = if settings.integrator == Integrator::Sppm {
            photon_passes::render(&scene, &settings, sampling.photons.settings(), false)
        } else {
            render(&scene, &settings)
        };
        let seconds = started.elapsed().as_secs_f64();
        let ours = match rendered {
            Ok((mut image, _)) => {
                // Ours as `render -o x.png` writes it: the look's curve.
                settings.look.output.apply(&mut image);
                image
            }
            Err(error) => return self.failed(seconds, has_theirs, dialect, error),
        };
        let written = write_image(&self.image_path("ours"), &ours, None).and_then(|()| {
            let measured = measure(&ours, &theirs)?;
            measured.error_map.write(&self.image_path("diff"))?;
            Ok(measured)
        });
        let measured = match written {
            Ok(measured) => measured,
            Err(error) => return self.failed(seconds, has_theirs, dialect, error),
        };
        let l = measured.lookalike;
        let (dialect, look) = dialect.unzip();
        Row {
            pair: self.pair.clone(),
            source: self.source.to_string(),
            slug: self.slug.clone(),
            dialect,
            look,
            seconds,
            has_theirs,
            outcome: Ok(Figures {
                mean: l.mean,
                p95: l.p95,
                same: l.same,
                flip: measured.flip,
                aspect_differs: l.aspect_differs,
                width,
                height,
            }),
        }
    }
}
