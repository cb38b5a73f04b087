//! The `.json` sidecar of an HDR image (`.pfm`, `.exr`): HDR images are
//! measurements, so beside each one, rendered or merged, is how it was made
//! and how an 8-bit output would have encoded it.

use std::path::{Path, PathBuf};

use pathtracer::image_io::Encoding;
use pathtracer::render::job::JobHeader;
use pathtracer::side_files::side_file_path;

/// `IMAGE.json`, cut to a name that fits (see [`side_file_path`]).
pub fn sidecar_path(image: &Path) -> PathBuf {
    side_file_path(image, ".json")
}

/// What the image holds, besides the render's settings.
pub struct Made {
    /// Samples per pixel, on average, and in all.
    pub spp: f64,
    pub samples: u64,
    /// The spp the render asked for.
    pub spp_asked: u32,
    /// Every pixel has every sample asked for.
    pub complete: bool,
    /// Seconds of rendering (`None` for a merge: the parts' times are theirs).
    pub seconds: Option<f64>,
    /// Films merged into it (`None` for a render).
    pub parts: Option<usize>,
}

/// The sidecar's text, one JSON object on a line.
pub fn sidecar_json(header: &JobHeader, made: &Made, encoding: &Encoding) -> String {
    let mut fields: Vec<(&str, String)> = vec![
        ("scene", format!("{:?}", header.scene)),
        ("width", header.width.to_string()),
        ("height", header.height.to_string()),
        ("spp", made.spp.to_string()),
        ("spp_asked", made.spp_asked.to_string()),
        ("complete", made.complete.to_string()),
        ("samples", made.samples.to_string()),
    ];
    if let Some(seconds) = made.seconds {
        fields.push(("seconds", format!("{seconds:.6}")));
    }
    if let Some(parts) = made.parts {
        fields.push(("parts", parts.to_string()));
    }
    let text = |value: &str| format!("{value:?}");
    let clamp = match header.clamp.as_str() {
        "none" => "null".to_string(),
        value => value.to_string(),
    };
    fields.extend([
        ("seed", header.seed.to_string()),
        ("integrator", text(&header.integrator)),
        ("sampler", text(&header.sampler)),
        ("max_depth", header.max_depth.to_string()),
        ("clamp", clamp),
        ("light_paths", header.light_paths.to_string()),
        ("look", text(&header.look)),
        (
            "gamma",
            encoding.gamma.map_or("null".to_string(), |g| g.to_string()),
        ),
        ("exposure", encoding.exposure.to_string()),
        ("tonemap", text(encoding.tonemap.name())),
    ]);
    let body: Vec<String> = fields
        .iter()
        .map(|(name, value)| format!("\"{name}\": {value}"))
        .collect();
    format!("{{{}}}\n", body.join(", "))
}
