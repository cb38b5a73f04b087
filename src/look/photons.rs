//! The looks of the coursework renderers that render by photon mapping
//! (`../shared/docs/looks.md`): Tschal-rsa (`tsc`), JamesSand (`jms`),
//! aliezlo's `sppm` mode (`alz-sppm`) and yuzc19's `sppm` mode
//! (`yzc-sppm`), all of one structure (aliezlo's): a camera pass to the
//! first diffuse-chosen hit, photons of a fixed power per emitter, every
//! diffuse hit gathering `colour x photon power` within `r`, the
//! Hachisuka-Jensen shrink with alpha 0.7, pixel =
//! `flux / (pi r^2 photons rounds) + direct / rounds`.
//!
//! In this renderer's terms (see `integrator::sppm`): photons start with
//! `emission x power x pi / (E p)` (`E` emitters sharing the photons
//! equally, `p` the probability of picking the one it left, `pi` because a
//! Lambert visible point reflects `colour / pi`), from the emitter's
//! normal side only, and visible points gather them from their first hit
//! (direct light too: no light sample).

use super::{Integrator, Look, Miss, OutputCurve, PixelSampling, PointLights, RayOrigins};
use crate::geometry::RevolutionTest;
use crate::scene::model::FovAxis;

/// How a camera path adds an emitter it sees.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SeenEmission {
    /// Throughput x emission.
    Plain,
    /// Throughput x emission x the emitter's colour (JamesSand).
    TimesColor,
    /// Throughput x emission, each channel clamped to [0, 1] per sample
    /// (Tschal-rsa).
    Clamped,
}

/// Which photon-mapping method a renderer used.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PhotonMethod {
    /// Stochastic progressive photon mapping (`integrator::sppm`), in
    /// aliezlo's structure.
    Progressive,
    /// yao-jz's progressive photon mapping (`integrator::ppm`): every
    /// branch followed, cone-weighted gathering, rounds of 8 camera rays.
    Yao,
}

/// A photon-mapping renderer's conventions.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PhotonLook {
    pub method: PhotonMethod,
    /// A photon starts with the emission times this (times its emitter's
    /// share of the photons, see the module documentation); yao-jz's:
    /// the total brightness of a round's photons.
    pub power: f64,
    /// Photons per round (the default of `--photons-per-pass`).
    pub photons_per_pass: u64,
    /// The initial gathering radius (the default of `--initial-radius`).
    pub initial_radius: f64,
    pub alpha: f64,
    pub seen_emission: SeenEmission,
    /// The hits of a photon that can be gathered: Tschal-rsa's roulette
    /// from its 7th hit divides a surviving photon's power by its largest
    /// channel (emission x 1000 times the colours so far, thousands), so
    /// its later hits add almost nothing.
    pub photon_hits: u32,
    /// Camera rays per pixel that the renderer traces whatever it is
    /// asked (yao-jz's 5 rounds of 8: the rounds are fixed in its code);
    /// `None`: as many as `--spp` says.
    pub fixed_camera_rays: Option<u32>,
}

/// Looks are compared whole (a render-time scene is built for one); the
/// numbers here are constants, never NaN.
impl Eq for PhotonLook {}

/// The aliezlo structure's constants: photons x250, r^2 = 1e-4, alpha 0.7.
const ALIEZLO: PhotonLook = PhotonLook {
    method: PhotonMethod::Progressive,
    power: 250.0,
    photons_per_pass: 100_000,
    initial_radius: 0.01,
    alpha: 0.7,
    seen_emission: SeenEmission::Plain,
    photon_hits: u32::MAX,
    fixed_camera_rays: None,
};

impl Look {
    /// Tschal-rsa/rang-kardan: SPPM, photons x1000, 200,000 per round,
    /// r^2 = 0.1, emitters seen directly clamped per sample, sqrt output;
    /// a miss adds the background times the path's throughput (it keeps the
    /// last diffuse hit's, the same for paths without mirrors or glass).
    pub const TSC: Look = Look {
        name: "tsc",
        renderer: "Tschal-rsa/rang-kardan",
        integrator: Integrator::Sppm,
        max_depth: 20,
        photons: Some(PhotonLook {
            power: 1000.0,
            photons_per_pass: 200_000,
            initial_radius: 0.316_227_766_016_837_94,
            seen_emission: SeenEmission::Clamped,
            photon_hits: 6,
            ..ALIEZLO
        }),
        output: OutputCurve::SquareRoot,
        miss: Miss::Weighted,
        point_lights: PointLights::Never,
        phong_lobes: false,
        ..Look::ORIGINAL
    };

    /// JamesSand/ComputerGraphic2023: aliezlo's SPPM with a horizontal
    /// field of view, 1,000,000 photons per round, emitters seen as
    /// emission x colour.
    pub const JMS: Look = Look {
        name: "jms",
        renderer: "JamesSand/ComputerGraphic2023",
        fov_axis: Some(FovAxis::Horizontal),
        photons: Some(PhotonLook {
            photons_per_pass: 1_000_000,
            seen_emission: SeenEmission::TimesColor,
            ..ALIEZLO
        }),
        ..Look::ALZ_SPPM
    };

    /// aliezlo/dzy_gxgz_my's `sppm` mode: W-Solaris's geometry (one-sided
    /// planes, square lens), 100,000 photons x250 per round, 20 hits.
    pub const ALZ_SPPM: Look = Look {
        name: "alz-sppm",
        renderer: "aliezlo/dzy_gxgz_my (sppm)",
        integrator: Integrator::Sppm,
        max_depth: 20,
        photons: Some(ALIEZLO),
        // The photon passes use f64 shapes (W-Solaris's single-precision
        // tests are its path tracer's look alone).
        ray_origins: RayOrigins::AtHit,
        single_precision_hits: false,
        diffuse_about_modelled_normal: false,
        ..Look::WSO
    };

    /// yuzc19/Ray-tracing-engine's `sppm` mode (a command-line mode, so
    /// never detected): its path tracer's look with photons x200,
    /// 10,000,000 per round.
    pub const YZC_SPPM: Look = Look {
        name: "yzc-sppm",
        renderer: "yuzc19/Ray-tracing-engine (sppm)",
        integrator: Integrator::Sppm,
        max_depth: 20,
        photons: Some(PhotonLook {
            power: 200.0,
            photons_per_pass: 10_000_000,
            ..ALIEZLO
        }),
        ..Look::YZC
    };

    /// yao-jz/Computer-Graphics-THU's PPM (`src/main.cpp`): 5 rounds of 8
    /// camera rays per pixel (`--spp 40`) jittered about the pixel's
    /// corner, 100,000 photons per round from the point lights of total
    /// brightness 1800, radius 5 shrinking by 0.95 a round, 6 hits, black
    /// background; see `integrator::ppm`.
    pub const YAO: Look = Look {
        name: "yao",
        renderer: "yao-jz/Computer-Graphics-THU",
        integrator: Integrator::Sppm,
        max_depth: 6,
        photons: Some(PhotonLook {
            method: PhotonMethod::Yao,
            power: 1800.0,
            photons_per_pass: 100_000,
            initial_radius: 5.0,
            photon_hits: 6,
            fixed_camera_rays: Some(40),
            ..ALIEZLO
        }),
        miss: Miss::Black,
        point_lights: PointLights::Never,
        phong_lobes: false,
        pixels: PixelSampling::Corner,
        revolution_test: RevolutionTest::TessellationSeeded,
        ..Look::ORIGINAL
    };
}
