//! The looks, one const row each: the conventions of each renderer, from
//! its facts in `../shared/docs/looks.md`.

use super::{
    DispersionSensor, Integrator, LobeChoice, Look, Miss, MtlReading, OutputCurve, PixelSampling,
    PointLights, RayOrigins, Roulette, TextureFrames, TextureRows,
};
use crate::bsdf::DielectricFresnel;
use crate::geometry::{RevolutionTest, SphereTest};
use crate::sampler::SamplerKind;
use crate::scene::model::{FovAxis, LensShape};

/// Scattering vertices that stand for "no limit": Russian roulette ends
/// paths long before.
pub(super) const UNLIMITED: u32 = 64;

impl Look {
    pub const ORIGINAL: Look = Look {
        name: "original",
        renderer: "the ported renderer",
        integrator: Integrator::Path,
        max_depth: 5,
        miss: Miss::CameraBackground,
        point_lights: PointLights::WithoutEmitters,
        phong_lobes: true,
        fresnel: DielectricFresnel::Schlick,
        pixels: PixelSampling::Tent,
        one_sided_planes: false,
        planes_accept_zero: false,
        single_precision_hits: false,
        diffuse_about_modelled_normal: false,
        texture_times_color: false,
        texture_rows: TextureRows::Up,
        fov_axis: None,
        texture_frames: TextureFrames::Shapes,
        ray_origins: RayOrigins::Offset,
        osb_glossy: false,
        lens_shape: None,
        dispersion_sensor: DispersionSensor::Spectral,
        sphere_test: SphereTest::Robust,
        cambrian_rectangles: false,
        revolutions_about_z: false,
        revolution_test: RevolutionTest::Robust,
        photons: None,
        output: OutputCurve::Framework,
        emitters_reflect: true,
        lobe_choice: LobeChoice::Weights,
        every_hit_enters: false,
        framework_obj_reading: false,
        normals_as_stored: false,
        mtl_reading: MtlReading::Ignored,
        face_normals: false,
        single_precision_planes: false,
        roulette: Roulette::Never,
        sampler: SamplerKind::Sobol,
    };

    pub const PHYSICAL: Look = Look {
        name: "physical",
        renderer: "this project's physically based rendering",
        miss: Miss::Weighted,
        fresnel: DielectricFresnel::Exact,
        ..Look::ORIGINAL
    };

    pub const PA1: Look = Look {
        name: "pa1",
        renderer: "the course framework's ray caster",
        integrator: Integrator::RayCast,
        max_depth: 1,
        miss: Miss::CameraBackground,
        pixels: PixelSampling::Centre,
        ..Look::ORIGINAL
    };

    pub const HAN: Look = Look {
        name: "han",
        renderer: "hanna0911/image-renderer (the framework's ray caster through pixel corners)",
        pixels: PixelSampling::Corner,
        // Its Phong term uses the triangle's own normal, from its winding
        // (`hanna0911/image-renderer:include/triangle.hpp`,
        // `include/material.hpp`), and its meshes are made by the framework's
        // OBJ loader: the Lucy statue of `scene12_lucyangle` renders as
        // triangles joining unrelated vertices.
        normals_as_stored: true,
        framework_obj_reading: true,
        ..Look::PA1
    };

    pub const JEF: Look = Look {
        name: "jef",
        renderer: "jefflyy/CG_2022spring (Whitted with shadow rays)",
        integrator: Integrator::Whitted,
        max_depth: 5,
        point_lights: PointLights::Always,
        pixels: PixelSampling::Corner,
        // Its RevSurface turns the profile about z
        // (`jefflyy/CG_2022spring:include/revsurface.hpp`).
        revolutions_about_z: true,
        // Its Newton on the profile parameter, each step times the
        // parameter (`jefflyy/CG_2022spring:include/revsurface.hpp`).
        revolution_test: RevolutionTest::Jefflyy,
        ..Look::PA1
    };

    pub const EMJ: Look = Look {
        name: "emj",
        renderer: "emily-jia/graphic_homework (Whitted without shadow rays)",
        integrator: Integrator::WhittedUnshadowed,
        // Its recursion counts bounces from 0 and stops at 5: six hits.
        max_depth: 6,
        point_lights: PointLights::Always,
        pixels: PixelSampling::Corner,
        // Its sphere uses the hit's distance as the ray's parameter
        // (`emily-jia/graphic_homework:include/sphere.hpp`).
        sphere_test: SphereTest::DistanceAsParameter,
        // Its OBJ loader gives faces their `.mtl` material whatever the
        // scene's `MaterialIndex`, and its triangles their face normal
        // (`emily-jia/graphic_homework:src/mesh.cpp`).
        mtl_reading: MtlReading::EmilyJia,
        face_normals: true,
        ..Look::PA1
    };

    pub const CAV: Look = Look {
        name: "cav",
        renderer: "CaveSpiderLZJ/PathTracingFinal",
        // Its tracer samples the lobes alone (no light samples), with its
        // hit normals as its code leaves them (`integrator::cav`).
        integrator: Integrator::Cav,
        // Its paths stop at the 9th hit, which adds its emission.
        max_depth: 8,
        miss: Miss::Weighted,
        point_lights: PointLights::Never,
        phong_lobes: false,
        // `src/main.cpp`: the camera's point is (x + u - 0.5, y + v - 0.5).
        pixels: PixelSampling::AboutCorner,
        texture_rows: TextureRows::Down,
        // Its spheres give the inward normal to a ray that starts inside,
        // its planes flip theirs towards the ray; its triangles keep their
        // winding normal (`CaveSpiderLZJ/PathTracingFinal:include/sphere.hpp`,
        // `plane.hpp`, `triangle.hpp` at `d730b9c`; `integrator::cav`).
        every_hit_enters: true,
        sphere_test: SphereTest::Cav,
        // Its surfaces of revolution are meshes of the profile
        // (`CaveSpiderLZJ/PathTracingFinal:include/revsurface.hpp`).
        revolution_test: RevolutionTest::CavMesh,
        texture_frames: TextureFrames::Cav,
        ..Look::ORIGINAL
    };

    pub const CAMBRIAN: Look = Look {
        name: "cambrian",
        renderer: "Cambrian-yzt/PathTracer",
        max_depth: UNLIMITED,
        miss: Miss::Black,
        point_lights: PointLights::Never,
        phong_lobes: false,
        texture_times_color: true,
        texture_frames: TextureFrames::Cambrian,
        dispersion_sensor: DispersionSensor::Cambrian,
        sphere_test: SphereTest::Cambrian,
        // `src/main.cpp`, `shift`: the eye moves within a cube whose side
        // is `aperture_size` (the dialect halves it into our half side).
        lens_shape: Some(LensShape::Square),
        // `include/plane.hpp`, class `Rectangle`: its back walls and floors.
        cambrian_rectangles: true,
        ..Look::ORIGINAL
    };

    pub const WSO: Look = Look {
        name: "wso",
        renderer: "W-Solaris/computer-graphics (the D3 family's path tracer)",
        integrator: Integrator::Original,
        ray_origins: RayOrigins::AtHitSinglePrecision,
        lens_shape: Some(LensShape::Square),
        max_depth: 14,
        miss: Miss::Unweighted,
        point_lights: PointLights::Never,
        phong_lobes: false,
        one_sided_planes: true,
        // `W-Solaris/computer-graphics:include/plane.hpp:29` (looks.md).
        planes_accept_zero: true,
        // It computes in `float`: `include/sphere.hpp`, `plane.hpp`,
        // `triangle.hpp` and `src/main.cpp:73` (the next ray's origin).
        single_precision_hits: true,
        // `src/main.cpp:82-88`: the cosine lobe about the hit's normal.
        diffuse_about_modelled_normal: true,
        ..Look::ORIGINAL
    };

    pub const OSB: Look = Look {
        name: "osb",
        renderer: "one-step-beh1nd/THU2024Spring-CG-Final",
        max_depth: UNLIMITED,
        miss: Miss::Black,
        point_lights: PointLights::Never,
        phong_lobes: false,
        fresnel: DielectricFresnel::SmallptUnweighted,
        osb_glossy: true,
        ..Look::ORIGINAL
    };

    pub const YLC: Look = Look {
        name: "ylc",
        renderer: "ylc2001/Computational-Graphics-Final-Project",
        max_depth: UNLIMITED,
        miss: Miss::Unweighted,
        point_lights: PointLights::Never,
        phong_lobes: false,
        ..Look::ORIGINAL
    };

    pub const CYY: Look = Look {
        name: "cyy",
        renderer: "Chenyu-Yang-2000/PathTracing",
        point_lights: PointLights::Always,
        ..Look::ORIGINAL
    };

    pub const YZC: Look = Look {
        name: "yzc",
        renderer: "yuzc19/Ray-tracing-engine",
        fov_axis: Some(FovAxis::Horizontal),
        lens_shape: Some(LensShape::Square),
        max_depth: 11,
        miss: Miss::Weighted,
        point_lights: PointLights::Never,
        phong_lobes: false,
        one_sided_planes: true,
        texture_rows: TextureRows::Down,
        ..Look::ORIGINAL
    };

    /// yangjunx21/jt_lighting: smallpt's recursion with its misses black,
    /// emitters that end the path, lobes by exact weights (everything not
    /// wholly diffuse or wholly mirror is glass of index 1.5), and its
    /// output `clamp(c)^(1/2.2)` rounded to the nearest byte. Its `float`
    /// planes and rays leaving from the hit itself with `tmin` 0, its
    /// roulette and its single random generator (`src/main.cpp`,
    /// `include/plane.hpp`): its few-sample pixels are clamped averages, so
    /// their noise is part of the image and the estimator is its own.
    pub const YJX: Look = Look {
        name: "yjx",
        renderer: "yangjunx21/jt_lighting",
        integrator: Integrator::Original,
        ray_origins: RayOrigins::AtHitSinglePrecision,
        single_precision_planes: true,
        roulette: Roulette::SignedUniform,
        // One Mersenne Twister for every draw (`src/main.cpp`).
        sampler: SamplerKind::Independent,
        max_depth: UNLIMITED,
        miss: Miss::Black,
        point_lights: PointLights::Never,
        phong_lobes: false,
        output: OutputCurve::Gamma22Rounded,
        emitters_reflect: false,
        lobe_choice: LobeChoice::WholeWeights,
        ..Look::ORIGINAL
    };

    /// chen-yingfa/raytracer: "Ray Tracing in One Weekend" path tracing
    /// with a black background, emitters that end the path, and its output
    /// `sqrt(c)`.
    pub const CYF: Look = Look {
        name: "cyf",
        renderer: "chen-yingfa/raytracer",
        max_depth: UNLIMITED,
        miss: Miss::Black,
        point_lights: PointLights::Never,
        phong_lobes: false,
        output: OutputCurve::SquareRoot,
        emitters_reflect: false,
        ..Look::ORIGINAL
    };

    /// AfireBao/2022_Monte_Carlo_RayTracing: smallpt's recursion, misses
    /// black, no depth cap (roulette from the 6th hit), light from `Energy`
    /// only.
    pub const AFB: Look = Look {
        name: "afb",
        renderer: "AfireBao/2022_Monte_Carlo_RayTracing",
        max_depth: UNLIMITED,
        miss: Miss::Black,
        point_lights: PointLights::Never,
        phong_lobes: false,
        ..Look::ORIGINAL
    };

    /// Bowen-Xu04/MiniRendererProj (its CPU path tracer with NEE, as its
    /// `run.bat` runs it): roulette from the first hit with no cap, a miss
    /// after a bounce adds the background unweighted, one fixed ray
    /// through the pixel centre, glass with no Fresnel split, and its
    /// output `c^0.6`.
    pub const BOW: Look = Look {
        name: "bow",
        renderer: "Bowen-Xu04/MiniRendererProj",
        max_depth: UNLIMITED,
        miss: Miss::Unweighted,
        point_lights: PointLights::Never,
        phong_lobes: false,
        fresnel: DielectricFresnel::None,
        pixels: PixelSampling::Centre,
        output: OutputCurve::Power06,
        ..Look::ORIGINAL
    };

    /// ShuoAndy/Graphic_Final_Project: "Ray Tracing in One Weekend" path
    /// tracing to depth 50 with no roulette, misses weighted, light from
    /// the materials' `specularColor` only, lights that do not scatter.
    pub const SHU: Look = Look {
        name: "shu",
        renderer: "ShuoAndy/Graphic_Final_Project",
        // Depth 50 returns the emission alone: 49 scatterings.
        max_depth: 49,
        miss: Miss::Weighted,
        point_lights: PointLights::Never,
        phong_lobes: false,
        emitters_reflect: false,
        ..Look::ORIGINAL
    };

    /// re2ikotr/thucg-render: "Ray Tracing in One Weekend" path tracing,
    /// the 10th hit adding its emission alone, no roulette, misses
    /// weighted, light from `specularColor` only, lights that do not
    /// scatter.
    pub const RE2: Look = Look {
        name: "re2",
        renderer: "re2ikotr/thucg-render",
        max_depth: 9,
        ..Look::SHU
    };

    /// aliezlo/dzy_gxgz_my's `pt` mode (a command-line mode, so never
    /// detected): W-Solaris's path tracer with 20 hits instead of 15.
    pub const ALZ_PT: Look = Look {
        name: "alz-pt",
        renderer: "aliezlo/dzy_gxgz_my (pt)",
        max_depth: 19,
        // W-Solaris's single precision is not measured against aliezlo's
        // renders (none is of `pt`): its images stay as they were.
        ray_origins: RayOrigins::AtHit,
        single_precision_hits: false,
        diffuse_about_modelled_normal: false,
        ..Look::WSO
    };

    /// 1rubbishyuan/path_tracing: its recursive estimator with ad-hoc
    /// factors (`integrator::rub`), light from `lightColor` materials only,
    /// misses that return the background at every depth, every sample
    /// through the integer pixel coordinate, and its output `sqrt(c)`.
    pub const RUB: Look = Look {
        name: "rub",
        renderer: "1rubbishyuan/path_tracing (its recursive estimator)",
        integrator: Integrator::Rub,
        max_depth: UNLIMITED,
        miss: Miss::Weighted,
        point_lights: PointLights::Never,
        phong_lobes: false,
        pixels: PixelSampling::Corner,
        output: OutputCurve::SquareRoot,
        emitters_reflect: false,
        ..Look::ORIGINAL
    };

    /// Every look, by name.
    pub const ALL: [Look; 26] = [
        Look::ORIGINAL,
        Look::PHYSICAL,
        Look::PA1,
        Look::CAMBRIAN,
        Look::WSO,
        Look::OSB,
        Look::YLC,
        Look::YZC,
        Look::CYY,
        Look::HAN,
        Look::JEF,
        Look::EMJ,
        Look::CAV,
        Look::TSC,
        Look::JMS,
        Look::ALZ_SPPM,
        Look::YZC_SPPM,
        Look::YAO,
        Look::YJX,
        Look::CYF,
        Look::AFB,
        Look::BOW,
        Look::SHU,
        Look::RE2,
        Look::ALZ_PT,
        Look::RUB,
    ];
}
