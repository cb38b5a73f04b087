//! Tests of the BSDF flags: the kinds of the lobes, of a set and of its
//! samples, the probability of a kind against sampling frequencies, and
//! the transport mode at a non-reciprocal surface.

use super::ConductorFresnel;
use super::conductor::Conductor;
use super::dielectric::Dielectric;
use super::fresnel::DielectricFresnel;
use super::lambert::Lambert;
use super::phong::Phong;
use super::{Bsdf, BsdfFlags, GlassChoice, Lobe, LobeSet, Rules, TransportMode};
use crate::color::Color;
use crate::math::Vec3;
use crate::rng::Rng;

const WHITE: Color = Color::new(1.0, 1.0, 1.0);

fn glass() -> Lobe {
    Lobe::Dielectric(Dielectric {
        tint: WHITE,
        eta_above: 1.0,
        eta_below: 1.5,
        fresnel: DielectricFresnel::Exact,
        choice: GlassChoice::Fresnel,
    })
}

fn mirror() -> Lobe {
    Lobe::Conductor(Conductor {
        tint: WHITE,
        alpha: 0.0,
        fresnel: ConductorFresnel::Constant,
    })
}

fn lambert() -> Lobe {
    Lobe::Lambert(Lambert { albedo: WHITE })
}

#[test]
fn every_lobe_says_what_kind_it_is() {
    let f = |lobe: Lobe| lobe.flags();
    use BsdfFlags as K;
    assert_eq!(f(lambert()), K::DIFFUSE | K::REFLECTION);
    assert_eq!(f(mirror()), K::SPECULAR | K::REFLECTION);
    assert_eq!(f(glass()), K::SPECULAR | K::REFLECTION | K::TRANSMISSION);
    let phong = Lobe::Phong(Phong {
        color: WHITE,
        exponent: 10.0,
    });
    assert_eq!(f(phong), K::GLOSSY | K::REFLECTION);
    let rough = Lobe::Conductor(Conductor {
        tint: WHITE,
        alpha: 0.3,
        fresnel: ConductorFresnel::Constant,
    });
    assert_eq!(f(rough), K::GLOSSY | K::REFLECTION);
    // A set: the union, and that of its continuous lobes.
    let mut set = LobeSet::default();
    set.push(lambert(), 0.5, true);
    set.push(glass(), 0.5, true);
    let bsdf = Bsdf::new(&set, WHITE, &Vec3::z(), true, 1.0, Rules::default());
    assert_eq!(
        bsdf.flags(),
        K::DIFFUSE | K::SPECULAR | K::REFLECTION | K::TRANSMISSION
    );
    assert!(bsdf.continuous_flags().is_diffuse_reflection_only());
    assert!(bsdf.diffuse_f().is_some());
}

/// Half Lambert, half glass: samples are diffuse reflections, specular
/// reflections (above) or specular transmissions (below) as their flags say,
/// and the continuous kinds come as often as `probability` says.
#[test]
fn samples_carry_the_kind_and_side_of_their_lobe() {
    let mut set = LobeSet::default();
    set.push(lambert(), 0.3, true);
    set.push(glass(), 0.7, true);
    let normal = Vec3::z();
    let wo = Vec3::new(0.6, 0.0, 0.8);
    let bsdf = Bsdf::new(&set, WHITE, &normal, true, wo.z, Rules::default());
    let mut rng = Rng::new(7, 8);
    let n = 200_000;
    let mut continuous = 0;
    for _ in 0..n {
        let u = [rng.next_f64(), rng.next_f64()];
        let Some(s) = bsdf.sample(&wo, rng.next_f64(), u) else {
            continue;
        };
        let above = s.wi.dot(&normal) > 0.0;
        if s.flags.intersects(BsdfFlags::CONTINUOUS) {
            continuous += 1;
            assert_eq!(s.flags, BsdfFlags::DIFFUSE_REFLECTION);
            assert!(!s.is_delta() && above);
        } else {
            assert!(s.is_delta());
            let side = if above {
                BsdfFlags::REFLECTION
            } else {
                BsdfFlags::TRANSMISSION
            };
            assert_eq!(s.flags, BsdfFlags::SPECULAR | side, "{:?}", s.wi);
        }
    }
    let frequency = continuous as f64 / n as f64;
    let probability = bsdf.probability(BsdfFlags::CONTINUOUS);
    let error = (probability * (1.0 - probability) / n as f64).sqrt();
    assert!(
        (frequency - probability).abs() < 5.0 * error,
        "{frequency} vs {probability}"
    );
    let specular = bsdf.probability(BsdfFlags::SPECULAR);
    assert!((specular + probability - 1.0).abs() < 1e-12);
}

/// On a non-reciprocal surface a delta direction that crosses it is marked
/// for radiance and refused for importance; one that stays is neither.
#[test]
fn importance_does_not_cross_a_non_reciprocal_surface() {
    let mut set = LobeSet::default();
    set.push(glass(), 1.0, true);
    let normal = Vec3::z();
    let wo = Vec3::new(0.0, 0.6, 0.8);
    let bsdf =
        Bsdf::new(&set, WHITE, &normal, true, wo.z, Rules::default()).on_nonreciprocal(&normal);
    // uc near 1: the refraction; near 0: the reflection.
    let crossing = bsdf
        .sample(&wo, 1.0 - 1e-9, [0.5, 0.5])
        .expect("a refraction");
    assert!(crossing.wi.z < 0.0);
    assert!(crossing.flags.contains(BsdfFlags::NONRECIPROCAL));
    let staying = bsdf.sample(&wo, 1e-9, [0.5, 0.5]).expect("a reflection");
    assert!(staying.wi.z > 0.0);
    assert!(!staying.flags.contains(BsdfFlags::NONRECIPROCAL));
    let importance = bsdf.transporting(TransportMode::Importance);
    assert!(importance.sample(&wo, 1.0 - 1e-9, [0.5, 0.5]).is_none());
    assert!(importance.sample(&wo, 1e-9, [0.5, 0.5]).is_some());
    // A reciprocal surface: nothing marked, nothing refused.
    let plain = Bsdf::new(&set, WHITE, &normal, true, wo.z, Rules::default())
        .transporting(TransportMode::Importance);
    let through = plain
        .sample(&wo, 1.0 - 1e-9, [0.5, 0.5])
        .expect("a refraction");
    assert!(!through.flags.contains(BsdfFlags::NONRECIPROCAL));
}
