//! Statistical tests of every lobe, as pbrt's and Mitsuba's suites run: the
//! directions `sample` produces are distributed as `pdf` says (chi-square
//! over a grid on the sphere), `pdf` integrates to 1, `sample`'s weight and
//! density are `eval / pdf` and `pdf`, `eval` is reciprocal, and a rough
//! conductor of reflectance 1 loses only what single scattering loses.

use std::f64::consts::PI;

use super::ConductorFresnel;
use super::conductor::Conductor;
use super::cook_torrance::CookTorrance;
use super::fresnel::DielectricFresnel;
use super::lambert::Lambert;
use super::lobe::Lobe;
use super::phong::Phong;
use super::rough_dielectric::RoughDielectric;
use super::{Bsdf, BsdfFlags, GlassChoice, Lobe as L, LobeSet, Rules};
use crate::color::Color;
use crate::math::Vec3;
use crate::rng::Rng;

const WHITE: Color = Color::WHITE;

fn conductor(alpha: f64) -> Lobe {
    L::Conductor(Conductor {
        tint: WHITE,
        alpha,
        fresnel: ConductorFresnel::Constant,
    })
}

fn rough_glass(alpha: f64, entering: bool, fresnel: DielectricFresnel) -> Lobe {
    let (eta_above, eta_below) = if entering { (1.0, 1.5) } else { (1.5, 1.0) };
    L::RoughDielectric(RoughDielectric {
        tint: WHITE,
        alpha,
        eta_above,
        eta_below,
        fresnel,
    })
}

/// Every continuous lobe, by name, at the roughnesses that matter.
fn lobes() -> Vec<(String, Lobe)> {
    let mut all = vec![("lambert".to_string(), L::Lambert(Lambert { albedo: WHITE }))];
    for n in [1.0, 12.0, 100.0] {
        all.push((
            format!("phong n={n}"),
            L::Phong(Phong {
                color: WHITE,
                exponent: n,
            }),
        ));
    }
    for alpha in [0.08, 0.3, 1.0] {
        all.push((format!("conductor alpha={alpha}"), conductor(alpha)));
    }
    for (alpha, entering, fresnel) in [
        (0.15, true, DielectricFresnel::Exact),
        (0.5, true, DielectricFresnel::Schlick),
        (0.3, false, DielectricFresnel::Exact),
        (0.7, false, DielectricFresnel::Schlick),
    ] {
        all.push((
            format!("rough dielectric alpha={alpha} entering={entering} {fresnel:?}"),
            rough_glass(alpha, entering, fresnel),
        ));
    }
    all.push((
        "cook-torrance".to_string(),
        L::CookTorrance(CookTorrance {
            color: WHITE,
            alpha: 0.4,
            f0: 0.3,
        }),
    ));
    all
}

/// Outgoing directions: near normal, 60 degrees, grazing.
fn outgoing() -> [Vec3; 3] {
    let at = |cos: f64, phi: f64| {
        let sin = (1.0 - cos * cos).sqrt();
        Vec3::new(sin * phi.cos(), sin * phi.sin(), cos)
    };
    [at(0.95, 0.3), at(0.5, 2.0), at(0.12, -1.0)]
}

fn direction(theta: f64, phi: f64) -> Vec3 {
    let (s, c) = theta.sin_cos();
    Vec3::new(s * phi.cos(), s * phi.sin(), c)
}

/// Midpoint quadrature of `f` over the whole sphere on a (theta, phi) grid.
fn sphere_integral(f: &dyn Fn(&Vec3) -> f64, n_theta: usize, n_phi: usize) -> f64 {
    let (dt, dp) = (PI / n_theta as f64, 2.0 * PI / n_phi as f64);
    let mut sum = 0.0;
    for i in 0..n_theta {
        let theta = (i as f64 + 0.5) * dt;
        let mut ring = 0.0;
        for j in 0..n_phi {
            ring += f(&direction(theta, (j as f64 + 0.5) * dp));
        }
        sum += ring * theta.sin();
    }
    sum * dt * dp
}

/// ln Gamma(x) for x > 0 (Lanczos, g = 7).
fn ln_gamma(x: f64) -> f64 {
    const C: [f64; 9] = [
        0.999_999_999_999_809_9,
        676.520_368_121_885_1,
        -1_259.139_216_722_402_8,
        771.323_428_777_653_1,
        -176.615_029_162_140_6,
        12.507_343_278_686_905,
        -0.138_571_095_265_720_12,
        9.984_369_578_019_572e-6,
        1.505_632_735_149_311_6e-7,
    ];
    let x = x - 1.0;
    let mut a = C[0];
    let t = x + 7.5;
    for (i, c) in C.iter().enumerate().skip(1) {
        a += c / (x + i as f64);
    }
    0.5 * (2.0 * PI).ln() + (x + 0.5) * t.ln() - t + a.ln()
}

/// The regularised upper incomplete gamma function Q(a, x).
fn gamma_q(a: f64, x: f64) -> f64 {
    if x <= 0.0 {
        return 1.0;
    }
    let prefix = (-x + a * x.ln() - ln_gamma(a)).exp();
    if x < a + 1.0 {
        // Series for P.
        let (mut term, mut sum, mut n) = (1.0 / a, 1.0 / a, a);
        for _ in 0..10_000 {
            n += 1.0;
            term *= x / n;
            sum += term;
            if term.abs() < sum.abs() * 1e-15 {
                break;
            }
        }
        1.0 - sum * prefix
    } else {
        // Continued fraction for Q (modified Lentz).
        let tiny = 1e-300;
        let mut b = x + 1.0 - a;
        let mut c = 1.0 / tiny;
        let mut d = 1.0 / b;
        let mut h = d;
        for i in 1..10_000 {
            let an = -(i as f64) * (i as f64 - a);
            b += 2.0;
            d = an * d + b;
            if d.abs() < tiny {
                d = tiny;
            }
            c = b + an / c;
            if c.abs() < tiny {
                c = tiny;
            }
            d = 1.0 / d;
            let delta = d * c;
            h *= delta;
            if (delta - 1.0).abs() < 1e-15 {
                break;
            }
        }
        prefix * h
    }
}

#[test]
fn the_chi_square_tail_is_right() {
    // Known values: Q(k/2, x/2) for chi-square with k dof.
    assert!((gamma_q(0.5, 3.841_458_82 / 2.0) - 0.05).abs() < 1e-6);
    assert!((gamma_q(5.0, 23.209_251 / 2.0) - 0.01).abs() < 1e-6);
    assert!((gamma_q(50.0, 124.342_113 / 2.0) - 0.05).abs() < 1e-5);
}

/// Chi-square test of the continuous samples of `sample` against `pdf`
/// (which may integrate to less than 1 when some samples are delta):
/// the p-value of the statistic over a 16 x 32 grid of the sphere, cells of
/// fewer than 5 expected samples pooled.
fn chi_square(
    sample: &dyn Fn(&mut Rng) -> Option<(Vec3, bool)>,
    pdf: &dyn Fn(&Vec3) -> f64,
    count: usize,
) -> f64 {
    let (n_theta, n_phi) = (16, 32);
    let mut observed = vec![0.0; n_theta * n_phi];
    let mut rng = Rng::new(11, 17);
    for _ in 0..count {
        if let Some((w, false)) = sample(&mut rng) {
            let theta = w.z.clamp(-1.0, 1.0).acos();
            let phi = w.y.atan2(w.x).rem_euclid(2.0 * PI);
            let i = ((theta / PI * n_theta as f64) as usize).min(n_theta - 1);
            let j = ((phi / (2.0 * PI) * n_phi as f64) as usize).min(n_phi - 1);
            observed[i * n_phi + j] += 1.0;
        }
    }
    // Expected counts by a 24 x 24 midpoint rule inside each cell.
    let sub = 24;
    let (dt, dp) = (PI / n_theta as f64, 2.0 * PI / n_phi as f64);
    let mut expected = vec![0.0; n_theta * n_phi];
    for i in 0..n_theta {
        for j in 0..n_phi {
            let mut sum = 0.0;
            for a in 0..sub {
                let theta = (i as f64 + (a as f64 + 0.5) / sub as f64) * dt;
                for b in 0..sub {
                    let phi = (j as f64 + (b as f64 + 0.5) / sub as f64) * dp;
                    sum += pdf(&direction(theta, phi)) * theta.sin();
                }
            }
            expected[i * n_phi + j] = sum * dt * dp / (sub * sub) as f64 * count as f64;
        }
    }
    let (mut chi2, mut cells) = (0.0, 0usize);
    let (mut pooled_observed, mut pooled_expected) = (0.0, 0.0);
    for (o, e) in observed.iter().zip(&expected) {
        if *e < 5.0 {
            pooled_observed += o;
            pooled_expected += e;
        } else {
            chi2 += (o - e) * (o - e) / e;
            cells += 1;
        }
    }
    if pooled_expected > 0.0 {
        chi2 += (pooled_observed - pooled_expected).powi(2) / pooled_expected.max(5.0);
        cells += 1;
    }
    gamma_q((cells.max(2) - 1) as f64 / 2.0, chi2 / 2.0)
}

/// Significance of each chi-square test, corrected for their number.
const SIGNIFICANCE: f64 = 0.01 / 60.0;

#[test]
fn sampled_directions_follow_the_pdf_of_every_lobe() {
    for (name, lobe) in lobes() {
        for wo in outgoing() {
            let p = chi_square(
                &|rng| {
                    let u = [rng.next_f64(), rng.next_f64()];
                    lobe.sample(&wo, rng.next_f64(), u).map(|s| (s.wi, s.delta))
                },
                &|wi| lobe.pdf(&wo, wi),
                200_000,
            );
            assert!(p > SIGNIFICANCE, "{name}, wo {wo:?}: p-value {p:e}");
        }
    }
}

#[test]
fn the_pdf_of_every_lobe_integrates_to_one() {
    for (name, lobe) in lobes() {
        for wo in outgoing() {
            let total = sphere_integral(&|wi| lobe.pdf(&wo, wi), 1400, 2800);
            assert!((total - 1.0).abs() < 1e-3, "{name}, wo {wo:?}: {total}");
        }
    }
}

#[test]
fn sample_weights_and_densities_are_eval_over_pdf() {
    let mut rng = Rng::new(5, 6);
    for (name, lobe) in lobes() {
        for wo in outgoing() {
            for _ in 0..2000 {
                let u = [rng.next_f64(), rng.next_f64()];
                let Some(s) = lobe.sample(&wo, rng.next_f64(), u) else {
                    continue;
                };
                assert!(!s.delta);
                assert!((s.wi.norm() - 1.0).abs() < 1e-9, "{name}");
                let pdf = lobe.pdf(&wo, &s.wi);
                assert!(
                    (s.pdf - pdf).abs() <= 1e-7 * pdf.max(1e-3),
                    "{name}: sample pdf {} vs pdf {pdf}",
                    s.pdf
                );
                let expected = lobe.eval(&wo, &s.wi) / pdf;
                let error = (s.weight.r - expected.r).abs();
                assert!(
                    error <= 1e-7 * expected.r.max(1.0),
                    "{name}: weight {:?} vs eval / pdf {expected:?}",
                    s.weight
                );
            }
        }
    }
}

fn random_direction(rng: &mut Rng, upper: bool) -> Vec3 {
    let z = rng.next_f64() * if upper { 1.0 } else { -1.0 };
    let phi = 2.0 * PI * rng.next_f64();
    let r = (1.0 - z * z).sqrt();
    Vec3::new(r * phi.cos(), r * phi.sin(), z)
}

#[test]
fn eval_is_reciprocal() {
    let mut rng = Rng::new(7, 8);
    let flip = |v: &Vec3| Vec3::new(v.x, v.y, -v.z);
    for (name, lobe) in lobes() {
        for _ in 0..2000 {
            let wo = random_direction(&mut rng, true);
            let wi = random_direction(&mut rng, true);
            let forward = lobe.eval(&wo, &wi).r / wi.z;
            let backward = lobe.eval(&wi, &wo).r / wo.z;
            assert!(
                (forward - backward).abs() <= 1e-9 * forward.abs().max(1e-6),
                "{name}: f(wo, wi) {forward} vs f(wi, wo) {backward}"
            );
        }
        // Transmission: the same boundary seen from the other side.
        if let L::RoughDielectric(d) = lobe {
            let other = RoughDielectric {
                eta_above: d.eta_below,
                eta_below: d.eta_above,
                ..d
            };
            for _ in 0..2000 {
                let wo = random_direction(&mut rng, true);
                let wi = random_direction(&mut rng, false);
                let forward = d.eval(&wo, &wi).r / -wi.z;
                let backward = other.eval(&flip(&wi), &flip(&wo)).r / wo.z;
                assert!(
                    (forward - backward).abs() <= 1e-9 * forward.abs().max(1e-6),
                    "{name}: transmission {forward} vs {backward}"
                );
            }
        }
    }
}

/// Directional albedo `integral eval(wo, wi) dwi` by quadrature of `eval`.
fn albedo_by_quadrature(lobe: &Lobe, wo: &Vec3) -> f64 {
    sphere_integral(&|wi| lobe.eval(wo, wi).r, 1400, 2800)
}

/// The same by the mean weight of samples: mean and standard error.
fn albedo_by_sampling(lobe: &Lobe, wo: &Vec3, count: usize) -> (f64, f64) {
    let mut rng = Rng::new(21, 22);
    let (mut sum, mut sum2) = (0.0, 0.0);
    for _ in 0..count {
        let u = [rng.next_f64(), rng.next_f64()];
        let w = lobe
            .sample(wo, rng.next_f64(), u)
            .map_or(0.0, |s| s.weight.r);
        sum += w;
        sum2 += w * w;
    }
    let mean = sum / count as f64;
    let variance = (sum2 / count as f64 - mean * mean).max(0.0);
    (mean, (variance / count as f64).sqrt())
}

/// The white furnace of a rough conductor of reflectance 1: the sampled
/// albedo equals the quadrature of `eval`, never exceeds 1, and loses what
/// single scattering loses. At normal incidence the albedo of GGX with
/// Smith masking has a closed form at `alpha = 1`, where `D = 1 / pi` and
/// `G1 = 2 cos / (1 + cos)`: `E = integral_0^1 c / (1 + c) dc = 1 - ln 2 =
/// 0.307` (a loss of 69%: the model has no multiple scattering, and GGX's
/// long tail sends 8% of reflections below the surface already at `alpha =
/// 0.3`). Measured (quadrature, `--nocapture`) at cos 0.95 / 0.5 / 0.12:
/// 0.992 / 0.980 / 0.887 at alpha 0.08, 0.873 / 0.818 / 0.836 at 0.3,
/// 0.315 / 0.409 / 0.548 at 1.
#[test]
fn white_furnace_of_a_rough_conductor() {
    let normal = Vec3::z();
    let (at_normal, error) = albedo_by_sampling(&conductor(1.0), &normal, 400_000);
    let known = 1.0 - 2.0_f64.ln();
    println!("alpha 1 at normal incidence: sampled {at_normal:.4} ± {error:.4}, known {known:.4}");
    assert!((at_normal - known).abs() <= 4.0 * error + 1e-4);
    assert!((albedo_by_quadrature(&conductor(1.0), &normal) - known).abs() < 1e-3);
    for alpha in [0.08, 0.3, 1.0] {
        let lobe = conductor(alpha);
        for wo in outgoing() {
            let exact = albedo_by_quadrature(&lobe, &wo);
            let (sampled, error) = albedo_by_sampling(&lobe, &wo, 400_000);
            println!(
                "alpha {alpha} cos {:.2}: quadrature {exact:.4}, sampled {sampled:.4} ± {error:.4}",
                wo.z
            );
            assert!((sampled - exact).abs() <= 4.0 * error + 1e-4);
            assert!(sampled <= 1.0 + 4.0 * error && exact <= 1.0 + 1e-3);
        }
    }
}

#[test]
fn a_mixture_samples_its_continuous_part_by_its_pdf() {
    let normal = Vec3::new(0.2, -0.3, 0.9).normalize();
    let mut set = LobeSet::default();
    let lambert = L::Lambert(Lambert {
        albedo: Color::new(0.5, 0.4, 0.3),
    });
    set.push(lambert, 0.5, false);
    set.push(conductor(0.0), 0.2, false);
    set.push(rough_glass(0.4, true, DielectricFresnel::Exact), 0.3, false);
    let phong = L::Phong(Phong {
        color: Color::gray(0.6),
        exponent: 20.0,
    });
    set.push(phong, 1.0, false);
    let local_wo = Vec3::new(0.3, 0.2, 0.6).normalize();
    let rules = Rules {
        fresnel: DielectricFresnel::Exact,
        glass: GlassChoice::Fresnel,
    };
    let bsdf = Bsdf::new(&set, Color::WHITE, &normal, true, local_wo.z, rules);
    let wo = bsdf.to_world(&local_wo);
    let p = chi_square(
        &|rng| {
            let u = [rng.next_f64(), rng.next_f64()];
            bsdf.sample(&wo, rng.next_f64(), u)
                .map(|s| (bsdf.to_local(&s.wi), s.is_delta()))
        },
        &|wi| bsdf.pdf(&wo, &bsdf.to_world(wi)),
        300_000,
    );
    assert!(p > SIGNIFICANCE, "p-value {p:e}");
    let smooth = sphere_integral(&|wi| bsdf.pdf(&wo, &bsdf.to_world(wi)), 1000, 2000);
    assert!(
        (smooth - bsdf.probability(BsdfFlags::CONTINUOUS)).abs() < 1e-3,
        "{smooth}"
    );
    // Weights are the mixture's eval over its pdf.
    let mut rng = Rng::new(1, 2);
    for _ in 0..1000 {
        let u = [rng.next_f64(), rng.next_f64()];
        let Some(s) = bsdf.sample(&wo, rng.next_f64(), u) else {
            continue;
        };
        if s.is_delta() {
            continue;
        }
        let expected = bsdf.eval(&wo, &s.wi) / bsdf.pdf(&wo, &s.wi);
        assert!((s.weight.g - expected.g).abs() < 1e-9 * expected.g.max(1.0));
    }
}
