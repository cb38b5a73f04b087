//! Prints the sensor of spectral paths (`spectral::basis::sensor`, the dual
//! basis `c̃` that turns a wavelength's radiance into RGB) on a grid over
//! the wavelengths a path can be given, for scripts that need our weights
//! (`scripts/crosscheck_dispersion.py` integrates Mitsuba's renders at
//! fixed indices with them).
//!
//! `cargo run --release --example spectral_sensor -- [step_nm]` prints
//! `# lambda_min lambda_max` and then `nm r g b` lines from `LAMBDA_MIN`
//! to `LAMBDA_MAX` (both included), `step_nm` apart (default 0.5).

use pathtracer::spectral::basis::sensor;
use pathtracer::spectral::{LAMBDA_MAX, LAMBDA_MIN};

fn main() {
    let step: f64 = match std::env::args().nth(1).map(|s| s.parse::<f64>()) {
        None => 0.5,
        Some(Ok(step)) if step > 0.0 && step.is_finite() => step,
        Some(_) => {
            eprintln!("usage: spectral_sensor [step_nm > 0]");
            std::process::exit(2);
        }
    };
    let intervals = ((LAMBDA_MAX - LAMBDA_MIN) / step).round().max(1.0) as usize;
    println!("# {LAMBDA_MIN} {LAMBDA_MAX}");
    for i in 0..=intervals {
        let nm = LAMBDA_MIN + (LAMBDA_MAX - LAMBDA_MIN) * i as f64 / intervals as f64;
        let c = sensor(nm);
        println!("{nm:.6} {:.12e} {:.12e} {:.12e}", c.r, c.g, c.b);
    }
}
