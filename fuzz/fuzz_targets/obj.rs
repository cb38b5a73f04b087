//! Fuzz target `obj`: any bytes as the OBJ file of a scene's `TriangleMesh`,
//! read as the scene build reads it (with `smooth` normals for inputs of odd
//! length), then rendered at 4x4 with 1 spp by every integrator through a
//! camera aimed at the mesh.
//!
//! Its `mtllib` libraries and their images resolve in the sandbox, which holds
//! only the input itself (`m.obj`): inputs with a line other than a face
//! (`f 1//2 ...`) that could name a file outside it (an absolute path, a `..`
//! next to a `/`, a backslash: `sandbox::names_stay_inside`) are skipped.

#![no_main]

use std::sync::OnceLock;

use libfuzzer_sys::{Corpus, fuzz_target};
use pathtracer::math::Vec3;
use pathtracer::scene::LoadOptions;
use pathtracer_fuzz::sandbox::{Sandbox, names_stay_inside};
use pathtracer_fuzz::{panics, tiny_render};

static SANDBOX: OnceLock<Sandbox> = OnceLock::new();

fn sandbox() -> &'static Sandbox {
    SANDBOX.get_or_init(|| Sandbox::enter("obj"))
}

/// True when no line but a face (`f 1/2/3 ...`) can name a file outside.
fn names_stay_inside_obj(data: &[u8]) -> bool {
    data.split(|&b| b == b'\n').all(|line| {
        let face = line
            .split(|b| b.is_ascii_whitespace())
            .find(|word| !word.is_empty())
            .is_some_and(|word| word == b"f");
        let slashes_allowed: Vec<u8> = if face {
            line.iter().copied().filter(|&b| b != b'/').collect()
        } else {
            line.to_vec()
        };
        names_stay_inside(&slashes_allowed)
    })
}

const SCENE: &str = "PerspectiveCamera { center 0 0 5 direction 0 0 -1 up 0 1 0 width 4 height 4 }
Lights { numLights 1 PointLight { position 3 3 3 color 1 1 1 } }
Background { color 0.2 0.2 0.2 }
Materials { numMaterials 1 Material { color 0.8 0.8 0.8 } }
Group { numObjects 1 MaterialIndex 0 TriangleMesh { obj_file m.obj SMOOTH } }
";

fuzz_target!(
    init: {
        panics::install();
        sandbox();
    },
    |data: &[u8]| -> Corpus {
        if !names_stay_inside_obj(data) {
            return Corpus::Reject;
        }
        let sandbox = sandbox();
        if !sandbox.write("m.obj", data) {
            return Corpus::Reject;
        }
        let text = SCENE.replace(" SMOOTH", if data.len() % 2 == 1 { " smooth" } else { "" });
        let file = sandbox.path("scene.txt");
        let options = LoadOptions {
            base: Some(sandbox.folder.clone()),
            ..LoadOptions::default()
        };
        panics::crash_on_panic(|| {
            let Some(mut scene) = tiny_render::build_text(&text, &file, &options) else {
                return;
            };
            let bounds = tiny_render::bounds(&scene);
            let extent = bounds.max - bounds.min;
            let centre = bounds.min + extent * 0.5;
            let size = extent.norm();
            if centre.iter().all(|c| c.is_finite()) && size.is_finite() && size > 0.0 {
                scene.camera.center = centre + Vec3::new(0.3, 0.4, 1.0) * size;
                scene.camera.direction = centre - scene.camera.center;
            }
            tiny_render::render_every_integrator(scene);
        });
        Corpus::Keep
    }
);
