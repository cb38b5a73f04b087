//! `pathtracer compare` (image error metrics against a reference) and
//! `pathtracer convert` (an image to another format, e.g. PFM to BMP).

use std::path::PathBuf;

use clap::Args;

use pathtracer::image_io::{
    Encoding, PendingFile, check_writable, encode_image, is_hdr, read_image, read_image_encoded,
    refuse_inputs,
};
use pathtracer::metrics::flip::DEFAULT_PIXELS_PER_DEGREE;
use pathtracer::metrics::report::{Encoded, evaluate};

use super::EncodingOptions;

#[derive(Args)]
pub struct CompareArgs {
    /// The image under test (BMP, PNG, PFM or EXR).
    image: PathBuf,
    /// The reference image.
    reference: PathBuf,
    /// Print JSON instead of text.
    #[arg(long)]
    json: bool,
    /// FLIP's viewing conditions in pixels per degree of visual angle
    /// (default 67: a 0.7 m wide 3840-pixel monitor seen from 0.7 m).
    #[arg(long, default_value_t = DEFAULT_PIXELS_PER_DEGREE, value_parser = parse_ppd)]
    ppd: f64,
    /// Write the per-pixel error map (FLIP, or the largest channel
    /// difference for linear images) in the magma colour map (.png or .bmp).
    #[arg(long, value_name = "HEAT.png")]
    diff: Option<PathBuf>,
}

pub fn run(args: &CompareArgs) -> Result<(), String> {
    let mut diff_file = match &args.diff {
        Some(diff) => {
            check_writable(diff, 1, 1)?;
            let file = PendingFile::reserve(diff)?;
            let inputs = [
                ("the image", args.image.as_path()),
                ("the reference", args.reference.as_path()),
            ];
            refuse_inputs(&[&file], &inputs)?;
            Some(file)
        }
        None => None,
    };
    let (test, test_encoding) = read_image_encoded(&args.image)?;
    let (reference, reference_encoding) = read_image_encoded(&args.reference)?;
    let evaluation = evaluate(
        Encoded {
            image: &test,
            encoding: test_encoding,
        },
        Encoded {
            image: &reference,
            encoding: reference_encoding,
        },
        args.ppd,
    )?;
    if let Some(mut diff) = diff_file.take() {
        let map = evaluation.error_map.as_ref().ok_or_else(|| {
            format!(
                "--diff needs images of the same size ({}x{} against a {}x{} reference)",
                test.width, test.height, reference.width, reference.height
            )
        })?;
        let heat = map.to_magma().to_image();
        diff.write(&encode_image(diff.path(), &heat, &Encoding::gamma(None))?)?;
        diff.commit()?;
    }
    if args.json {
        say!("{}", evaluation.report.to_json());
    } else {
        say!("{}", evaluation.report);
    }
    Ok(())
}

/// Pixels per degree FLIP is defined for: far below and above any screen
/// (about 20 to 200); at 1e-300 its filters degenerate to NaN.
const PPD_RANGE: std::ops::RangeInclusive<f64> = 0.1..=1000.0;

fn parse_ppd(text: &str) -> Result<f64, String> {
    match text.parse::<f64>() {
        Ok(ppd) if PPD_RANGE.contains(&ppd) => Ok(ppd),
        _ => Err(format!(
            "'{text}': expected pixels per degree from {} to {}",
            PPD_RANGE.start(),
            PPD_RANGE.end()
        )),
    }
}

#[derive(Args)]
pub struct ConvertArgs {
    /// The image to read (BMP, PNG or PFM).
    input: PathBuf,
    /// The image to write (.bmp, .png, .pfm or .exr).
    output: PathBuf,
    /// Gamma, exposure and tone curve for 8-bit output, as `render`'s.
    #[command(flatten)]
    encoding: EncodingOptions,
}

pub fn convert(args: &ConvertArgs) -> Result<(), String> {
    let encoding = args.encoding.encoding();
    encoding.check()?;
    if is_hdr(&args.output) && encoding != Encoding::default() {
        pathtracer::stderr_line!(
            "warning: --gamma, --exposure and --tonemap apply to 8-bit outputs; {} stays linear",
            args.output.display()
        );
    }
    check_writable(&args.output, 1, 1)?;
    let mut output = PendingFile::reserve(&args.output)?;
    refuse_inputs(&[&output], &[("the input", args.input.as_path())])?;
    let image = read_image(&args.input)?;
    output.write(&encode_image(&args.output, &image, &encoding)?)?;
    output.commit()
}
