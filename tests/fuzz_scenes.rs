//! Deterministic mutation fuzzing: corrupted corpus scenes give errors, never
//! panics, and the ones that still build render (4x4 pixels, 1 spp, under
//! the scene's own look with its integrator and with the path integrator)
//! without a panic or a non-finite pixel.

mod common;

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::{Path, PathBuf};
use std::time::Instant;

use pathtracer::integrator::Integrator;
use pathtracer::look::Look;
use pathtracer::render::{RenderSettings, render};
use pathtracer::render_scene::RenderScene;
use pathtracer::rng::Rng;
use pathtracer::sampler::SamplerKind;
use pathtracer::scene::model::Scene;
use pathtracer::scene::{LoadOptions, build, parse};

const MUTANTS_PER_FILE: usize = 300;
/// Failures shown in full (the others are counted).
const SHOWN_FAILURES: usize = 5;
/// Scenes naming an asset bigger than this are built with their assets unreachable.
const MAX_ASSET_BYTES: u64 = 200_000;

const HUGE: [&str; 12] = [
    "1e308",
    "-1e308",
    "1e999",
    "4294967296",
    "99999999999",
    "-2147483649",
    "0",
    "-1",
    "1e-320",
    "nan",
    "inf",
    "1000000000",
];

fn below(rng: &mut Rng, n: usize) -> usize {
    if n == 0 {
        0
    } else {
        (rng.next_u32() as usize) % n
    }
}

/// Byte ranges of the whitespace-separated tokens.
fn tokens(text: &[u8]) -> Vec<(usize, usize)> {
    let mut out = Vec::new();
    let mut start = None;
    for (i, b) in text.iter().enumerate() {
        match (b.is_ascii_whitespace(), start) {
            (true, Some(s)) => {
                out.push((s, i));
                start = None;
            }
            (false, None) => start = Some(i),
            _ => {}
        }
    }
    if let Some(s) = start {
        out.push((s, text.len()));
    }
    out
}

fn mutate(rng: &mut Rng, text: &mut Vec<u8>) {
    let spans = tokens(text);
    let pick = |rng: &mut Rng| {
        spans
            .get(below(rng, spans.len()))
            .copied()
            .unwrap_or((0, 0))
    };
    match below(rng, 6) {
        0 => {
            let (s, e) = pick(rng);
            text.drain(s..e);
        }
        1 => {
            let (s, e) = pick(rng);
            let copy: Vec<u8> = text[s..e].to_vec();
            text.splice(e..e, [b" ".as_slice(), &copy].concat());
        }
        2 => {
            if !text.is_empty() {
                let at = below(rng, text.len());
                text[at] = rng.next_u32() as u8;
            }
        }
        3 => {
            let at = below(rng, text.len() + 1);
            let brace = [b"{", b"}", b"[", b"]"][below(rng, 4)];
            text.splice(at..at, brace.iter().copied());
        }
        4 => {
            let braces: Vec<usize> = (0..text.len())
                .filter(|&i| matches!(text[i], b'{' | b'}' | b'[' | b']'))
                .collect();
            if !braces.is_empty() {
                text.remove(braces[below(rng, braces.len())]);
            }
        }
        _ => {
            let numbers: Vec<(usize, usize)> = spans
                .iter()
                .copied()
                .filter(|&(s, e)| {
                    std::str::from_utf8(&text[s..e]).is_ok_and(|t| t.parse::<f64>().is_ok())
                })
                .collect();
            if !numbers.is_empty() {
                let (s, e) = numbers[below(rng, numbers.len())];
                let value = HUGE[below(rng, HUGE.len())];
                text.splice(s..e, value.bytes());
            }
        }
    }
}

/// True when every asset the scene names is small (or absent).
fn small_assets(text: &str, base: &Path) -> bool {
    text.split_whitespace()
        .filter(|w| w.contains('.') && w.contains('/'))
        .all(|w| std::fs::metadata(base.join(w)).map_or(true, |m| m.len() <= MAX_ASSET_BYTES))
}

/// Renders `scene` at 4x4 and 1 spp under its own look, with the look's
/// integrator and with the path integrator; an error names what went wrong.
fn render_tiny(scene: Scene) -> Result<(), String> {
    let (look, _) = Look::detect(&scene);
    let own = look.integrator;
    let mut built = None;
    let integrators: &[Integrator] = if own == Integrator::Path {
        &[Integrator::Path]
    } else {
        &[own, Integrator::Path]
    };
    for &integrator in integrators {
        let settings = RenderSettings {
            width: 4,
            height: 4,
            spp: 1,
            seed: 1,
            threads: Some(1),
            integrator,
            max_depth: look.max_depth,
            sampler: SamplerKind::Sobol,
            progress: false,
            progress_every: None,
            clamp: None,
            light_paths: true,
            look,
            dispersion: None,
        };
        // One render-time scene for both integrators.
        let scene =
            built.get_or_insert_with(|| RenderScene::build(scene.clone(), &settings.scene()));
        // A refusal is an answer; only panics and bad pixels are failures.
        let Ok((image, _)) = render(scene, &settings) else {
            continue;
        };
        if image.pixels.iter().any(|p| !p.is_finite()) {
            return Err(format!(
                "a non-finite pixel ({} look, {} integrator)",
                look.name,
                integrator.name()
            ));
        }
    }
    Ok(())
}

/// The message a caught panic carried.
fn panic_message(payload: &(dyn std::any::Any + Send)) -> String {
    payload
        .downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "(no message)".to_string())
}

#[test]
fn mutated_scenes_never_panic() {
    let Some(shared) = common::shared() else {
        return;
    };
    let empty = std::env::temp_dir().join(format!("pt-fuzz-empty-{}", std::process::id()));
    let _ = std::fs::create_dir_all(&empty);
    let started = Instant::now();
    let (mut total, mut built) = (0usize, 0usize);
    let mut failures: Vec<String> = Vec::new();
    for (index, (file, base)) in common::corpus(&shared).iter().enumerate() {
        let Ok(original) = std::fs::read(file) else {
            continue;
        };
        let text = String::from_utf8_lossy(&original);
        let (path, base): (PathBuf, PathBuf) = if small_assets(&text, base) {
            (file.clone(), base.clone())
        } else {
            (empty.join("scene.txt"), empty.clone())
        };
        let options = LoadOptions {
            base: Some(base),
            ..LoadOptions::default()
        };
        let mut rng = Rng::new(index as u64, 0xF022);
        for _ in 0..MUTANTS_PER_FILE {
            let mut bytes = original.clone();
            for _ in 0..=below(&mut rng, 3) {
                mutate(&mut rng, &mut bytes);
            }
            let mutant = String::from_utf8_lossy(&bytes).into_owned();
            let outcome = catch_unwind(AssertUnwindSafe(|| {
                parse(&mutant, &path).and_then(|doc| build(&doc, &path, &options))
            }));
            total += 1;
            let failure = match outcome {
                Err(payload) => Some(format!(
                    "panicked in parse or build: {}",
                    panic_message(&*payload)
                )),
                Ok(Err(_)) => None,
                Ok(Ok(scene)) => {
                    built += 1;
                    match catch_unwind(AssertUnwindSafe(|| render_tiny(scene))) {
                        Ok(Ok(())) => None,
                        Ok(Err(message)) => Some(message),
                        Err(payload) => Some(format!(
                            "panicked in the render: {}",
                            panic_message(&*payload)
                        )),
                    }
                }
            };
            if let Some(message) = failure {
                let saved = empty.join(format!("failing-mutant-{}.txt", failures.len()));
                let _ = std::fs::write(&saved, &bytes);
                failures.push(format!(
                    "a mutant of {} (saved to {}): {message}\n--- mutated scene ---\n{mutant}\n---",
                    file.display(),
                    saved.display()
                ));
            }
        }
    }
    println!(
        "{total} mutants ({built} still build and were rendered) in {:.1} s",
        started.elapsed().as_secs_f64()
    );
    assert!(total >= 10_000, "only {total} mutants");
    assert!(built >= 1_000, "only {built} mutants rendered");
    assert!(
        failures.is_empty(),
        "{} mutants failed; the first {}:\n{}",
        failures.len(),
        SHOWN_FAILURES.min(failures.len()),
        failures[..SHOWN_FAILURES.min(failures.len())].join("\n")
    );
}
