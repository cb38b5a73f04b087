//! `pathtracer merge PART... -o IMAGE`: the films of render jobs added into
//! one image, after checking that they are parts of one render.

use std::path::PathBuf;

use clap::Args;

use pathtracer::film::Film;
use pathtracer::image_io::{
    PendingFile, check_writable, commit_together, encode_image, is_hdr, refuse_inputs,
    refuse_shared_outputs,
};
use pathtracer::render::film_file::{encode_film, read_film};
use pathtracer::render::job::{Crop, JobHeader, Part, check_parts};

use super::EncodingOptions;
use super::sidecar::{Made, sidecar_json, sidecar_path};

/// Missing regions listed before "and N more".
const MISSING_SHOWN: usize = 8;

#[derive(Args)]
pub struct MergeArgs {
    /// Film files written by `render --film`.
    #[arg(required = true)]
    parts: Vec<PathBuf>,
    /// Output image (.bmp, .png, .pfm or .exr).
    #[arg(short, long, required_unless_present = "film")]
    output: Option<PathBuf>,
    /// Also (or only) write the merged film, a part covering the whole
    /// image and every sample, for further merges.
    #[arg(long)]
    film: Option<PathBuf>,
    /// Merge even when samples are missing: each pixel is the mean of the
    /// samples it has.
    #[arg(long)]
    partial: bool,
    #[command(flatten)]
    encoding: EncodingOptions,
}

pub fn run(args: &MergeArgs) -> Result<(), String> {
    for path in args.output.iter().chain(&args.film) {
        check_writable(path, 1, 1)?;
    }
    let encoding = args.encoding.encoding();
    encoding.check()?;
    // Outputs are reserved before the parts are read, and none may be a part.
    let mut image_file = args
        .output
        .as_deref()
        .map(PendingFile::reserve)
        .transpose()?;
    let mut film_file = args.film.as_deref().map(PendingFile::reserve).transpose()?;
    let mut sidecar_file = args
        .output
        .as_deref()
        .filter(|path| is_hdr(path))
        .map(|path| PendingFile::reserve(&sidecar_path(path)))
        .transpose()?;
    let outputs: Vec<&PendingFile> = image_file
        .iter()
        .chain(&film_file)
        .chain(&sidecar_file)
        .collect();
    let inputs: Vec<(&str, &std::path::Path)> = args
        .parts
        .iter()
        .map(|part| ("a part to merge", part.as_path()))
        .collect();
    refuse_shared_outputs(&outputs)?;
    refuse_inputs(&outputs, &inputs)?;
    let names: Vec<String> = args.parts.iter().map(|p| p.display().to_string()).collect();
    // One film in memory besides the total: parts are added as they are read.
    let mut headers: Vec<JobHeader> = Vec::new();
    let mut total: Option<Film> = None;
    for (path, name) in args.parts.iter().zip(&names) {
        let (film, header) = read_film(path)?;
        if header.checkpoint {
            return Err(format!(
                "{name} is the checkpoint of an unfinished render (its pixels stopped at different samples): continue it with `render --resume`, it is not a part to merge"
            ));
        }
        if let Some(first) = headers.first() {
            check_parts(&[
                Part {
                    name: &names[0],
                    header: first,
                },
                Part {
                    name,
                    header: &header,
                },
            ])?;
        }
        match &mut total {
            Some(total) => total.add_film(&film).map_err(|e| format!("{name}: {e}"))?,
            None => total = Some(film),
        }
        headers.push(header);
    }
    let parts: Vec<Part> = names
        .iter()
        .zip(&headers)
        .map(|(name, header)| Part { name, header })
        .collect();
    let missing = check_parts(&parts)?;
    let total = total.ok_or("no film parts to merge")?;
    if !missing.is_empty() {
        let mut listed: Vec<String> = missing.iter().take(MISSING_SHOWN).cloned().collect();
        if missing.len() > MISSING_SHOWN {
            listed.push(format!("and {} more", missing.len() - MISSING_SHOWN));
        }
        if !args.partial || args.film.is_some() {
            return Err(format!(
                "the parts do not cover the image; missing (pixels x0,y0,x1,y1): {} (--partial merges them anyway into an image, not a film)",
                listed.join("; ")
            ));
        }
        pathtracer::stderr_line!("warning: partial merge, missing: {}", listed.join("; "));
    }
    let first = &headers[0];
    if let (Some(path), Some(file)) = (&args.film, &mut film_file) {
        let mut header = first.clone();
        header.crop = Crop::full(first.width, first.height);
        header.samples = 0..parts
            .iter()
            .map(|p| p.header.samples.end)
            .max()
            .unwrap_or(0);
        file.write(&encode_film(path, &total, &header)?)?;
    }
    let pixels = (first.width as u64 * first.height as u64).max(1);
    let spp_asked = parts
        .iter()
        .map(|p| p.header.samples.end)
        .max()
        .unwrap_or(0);
    if let (Some(path), Some(file)) = (&args.output, &mut image_file) {
        file.write(&encode_image(path, &total.to_image(), &encoding)?)?;
    }
    if let Some(sidecar) = &mut sidecar_file {
        let made = Made {
            spp: total.samples() as f64 / pixels as f64,
            samples: total.samples(),
            spp_asked,
            complete: missing.is_empty(),
            seconds: None,
            parts: Some(headers.len()),
        };
        sidecar.write(sidecar_json(first, &made, &encoding).as_bytes())?;
    }
    // The sidecar before its image, as `render` does.
    commit_together(
        film_file
            .into_iter()
            .chain(sidecar_file)
            .chain(image_file)
            .collect(),
    )?;
    let written: Vec<String> = args
        .output
        .iter()
        .chain(&args.film)
        .map(|p| p.display().to_string())
        .collect();
    say!(
        "{}: {} parts of {} (seed {}, look {}, {} integrator), {}x{}, {:.1} spp, {} light subpaths, {} NaN/Inf samples dropped, {} fireflies, {} saturated",
        written.join(", "),
        headers.len(),
        first.scene,
        first.seed,
        first.look,
        first.integrator,
        first.width,
        first.height,
        total.samples() as f64 / pixels as f64,
        total.light_paths,
        total.dropped(),
        total.fireflies(),
        total.saturated(),
    );
    if let Some(hint) = args
        .output
        .as_ref()
        .and_then(|output| super::linear_output_hint(output, &encoding))
    {
        say!("{hint}");
    }
    Ok(())
}
