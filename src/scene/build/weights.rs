//! Resolving the fields of one material into normalised weights, IOR and emission.

use crate::bsdf::AngularWeights;
use crate::color::Color;
use crate::scene::build::Context;
use crate::scene::build::lobes::add_lobes;
use crate::scene::build::material::{MaterialSpec, PathRef};
use crate::scene::build::textures::SurfaceMapRef;
use crate::scene::error::{Location, SceneError};
use crate::scene::model::{Dialect, Material};
use crate::texture::uv_rule::UvRule;

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Kind {
    Diffuse,
    Specular,
    Refract,
    Light,
}

impl Kind {
    pub fn weights(self) -> [f64; 3] {
        match self {
            Kind::Diffuse | Kind::Light => [1.0, 0.0, 0.0],
            Kind::Specular => [0.0, 1.0, 0.0],
            Kind::Refract => [0.0, 0.0, 1.0],
        }
    }

    pub fn from_block(name: &str) -> Option<Kind> {
        match name {
            "DiffuseMaterial" | "Lambert" | "Lambertian" | "GlossyMaterial" => Some(Kind::Diffuse),
            "MetalMaterial" | "Metal" | "ReflectiveMaterial" => Some(Kind::Specular),
            "DielecMaterial" | "Dielectric" | "RefractiveMaterial" => Some(Kind::Refract),
            "LightMaterial" | "Emissive" | "Light" => Some(Kind::Light),
            _ => None,
        }
    }
}

/// `prop <Name>` presets of tsc: (diffuse, specular, refract, IOR).
pub fn preset(name: &str) -> ([f64; 3], Option<f64>) {
    match name {
        "Matte" | "DiffLight" => ([1.0, 0.0, 0.0], None),
        "Mirror" | "Light" => ([0.0, 1.0, 0.0], None),
        "Glass" => ([0.0, 0.0, 1.0], Some(1.65)),
        "China" | "Photo" => ([0.8, 0.2, 0.0], None),
        "Apple" => ([0.99, 0.1, 0.0], None),
        "Marble" => ([0.9, 0.1, 0.0], None),
        "Cobble" => ([0.7, 0.3, 0.0], None),
        _ => ([0.0, 0.0, 0.0], None),
    }
}

/// Fields read from one material block, before resolution.
#[derive(Default)]
pub struct Fields {
    pub color: Option<Color>,
    pub diffuse_color: Option<Color>,
    pub specular_color: Option<Color>,
    pub emission: Option<Color>,
    pub emission_scale: Option<f64>,
    pub ior: Option<f64>,
    pub rates: [Option<f64>; 3],
    pub weights: Option<[f64; 3]>,
    pub yao: [Option<f64>; 3],
    pub yao_flag: Option<Kind>,
    pub per: [Option<f64>; 3],
    pub kind: Option<Kind>,
    pub reflective: Option<f64>,
    pub transmissive: Option<f64>,
    pub transmittance: Option<Color>,
    /// With where it was written (for the warning when it is not rendered).
    pub shininess: Option<(f64, Location)>,
    pub reflective_color: Option<Color>,
    pub fuzz: Option<f64>,
    pub roughness: Option<f64>,
    pub metallic: Option<(f64, Location)>,
    pub glossy: Option<bool>,
    pub cook_torrance: Option<(f64, f64)>,
    pub angular: Option<AngularWeights>,
    pub texture: Option<PathRef>,
    pub uv_rule: Option<UvRule>,
    pub texture_scale: Option<f64>,
    pub surface_map: Option<SurfaceMapRef>,
}

/// Clamps negative weights and scales them to sum to 1 (diffuse if they sum to 0).
fn normalise(weights: [f64; 3]) -> [f64; 3] {
    let w = weights.map(|x| if x.is_finite() { x.max(0.0) } else { 0.0 });
    let sum: f64 = w.iter().sum();
    if sum > 0.0 && sum.is_finite() {
        w.map(|x| x / sum)
    } else {
        [1.0, 0.0, 0.0]
    }
}

pub fn resolve(
    context: &mut Context,
    f: Fields,
    name: &str,
    location: Location,
) -> Result<MaterialSpec, SceneError> {
    let block_kind = Kind::from_block(name);
    let bow_tinted = matches!(name, "ReflectiveMaterial" | "RefractiveMaterial");
    let color = f
        .color
        .or(f.diffuse_color)
        .or(f.transmittance.filter(|_| bow_tinted))
        .unwrap_or(Color::WHITE);
    if f.transmittance.is_some() && !bow_tinted {
        context.not_rendered(
            location,
            "transmittance",
            "only bow's reflective and refractive materials have it",
        )?;
    }
    let specular_is_emission =
        context.dialect == Dialect::Rtiow && matches!(name, "LightMaterial" | "Material");
    let mut emission = f.emission.or(if specular_is_emission {
        f.specular_color
    } else {
        None
    });
    let kind = f.kind.or(block_kind);
    if kind == Some(Kind::Light) && emission.is_none() {
        emission = Some(color);
    }
    let emission = emission
        .unwrap_or(Color::BLACK)
        .map(|c| c * f.emission_scale.unwrap_or(1.0));
    let yao_weights = f.yao[0].is_some() || f.yao[1].is_some() || f.yao_flag.is_some();
    let mut ior = f.ior;
    if !yao_weights && let Some(r) = f.yao[2] {
        ior = Some(r);
    }
    let weights = if f.rates.iter().any(Option::is_some) {
        let s = f.rates[1].unwrap_or(0.0);
        let r = f.rates[2].unwrap_or(0.0);
        let d = f.rates[0].unwrap_or(1.0 - s - r);
        let sum = d + s + r;
        if (sum - 1.0).abs() > 1e-6 || d < -1e-6 || s < 0.0 || r < 0.0 {
            return Err(context.error(
                location,
                format!("material rates {d} + {s} + {r} must be non-negative and sum to 1"),
            ));
        }
        [d.max(0.0), s, r]
    } else if yao_weights {
        if f.yao.iter().any(Option::is_some) {
            normalise(f.yao.map(|w| w.unwrap_or(0.0)))
        } else {
            f.yao_flag.unwrap_or(Kind::Diffuse).weights()
        }
    } else if let Some(w) = f.weights {
        normalise(w)
    } else if context.dialect == Dialect::Rub {
        // rub draws one number against `perDiffuse`, then against
        // `perDiffuse + perReflect`, and refracts otherwise: `perRefract` is
        // never read, and a material without weights refracts.
        let d = f.per[0].unwrap_or(0.0).max(0.0);
        let s = f.per[1].unwrap_or(0.0).max(0.0);
        let d = d.min(1.0);
        let s = s.min(1.0 - d);
        [d, s, 1.0 - d - s]
    } else if f.per.iter().any(Option::is_some) {
        normalise(f.per.map(|w| w.unwrap_or(0.0)))
    } else if f.reflective.is_some() || f.transmissive.is_some() {
        let s = f.reflective.unwrap_or(0.0).max(0.0);
        let r = f.transmissive.unwrap_or(0.0).max(0.0);
        normalise([(1.0 - s - r).max(0.0), s, r])
    } else {
        kind.unwrap_or(Kind::Diffuse).weights()
    };
    let ior = match ior {
        Some(n) if n > 0.0 => n,
        Some(n) => {
            context.warn(
                location,
                format!("refractive index {n} is not positive; using 1.5"),
            )?;
            1.5
        }
        None => 1.5,
    };
    let mut material = Material {
        color,
        emission,
        boost: f.emission_scale.unwrap_or(1.0),
        diffuse: weights[0],
        specular: weights[1],
        refract: weights[2],
        ior,
        uv_rule: f.uv_rule,
        texture_scale: f.texture_scale.unwrap_or(1.0),
        ..Material::DEFAULT
    };
    add_lobes(context, &f, name, specular_is_emission, &mut material)?;
    Ok(MaterialSpec {
        material,
        texture: f.texture,
        surface_map: f.surface_map,
        dispersion: None,
    })
}
