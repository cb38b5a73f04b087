#!/usr/bin/env python3
"""Cross-check of dispersion against Mitsuba 3, whose dielectric has one index.

    python3 scripts/crosscheck_dispersion.py --mode cauchy|channels
        [--scene testcases/crosscheck_dispersion.txt] [--channels 1.55,1.65,1.85]
        [--nodes 17] [--spp 1024] [--reference-spp 512] [--width 128 --height 96]
        [--max-depth 12] [--variant scalar_rgb] [--seed 1] [--tile 8]
        [--out output/crosscheck_dispersion_MODE] [--tolerance 0.01]

Mitsuba renders the scene with a glass of one index at a time; the script
composes what a dispersive glass gives from those renders, and compares
ours (`--look physical`, the path integrator) with the composite:

- `channels` (yuzc19's kind, `--dispersion R,G,B`): a path picks a channel
  and the glass takes that channel's index, so our red channel has the
  expectation of the red channel of the scene with a plain glass of index
  n_R, and so on. Mitsuba renders the glass at n_R, n_G and n_B; the
  composite takes R from the first, G from the second, B from the third.
  Any colours work.
- `cauchy` (Cambrian's `cauchy A B` with the camera's `dispersion` flag):
  a path draws one wavelength, uniform over [LAMBDA_MIN, LAMBDA_MAX], at the
  first dispersive glass and is read by our sensor, the dual basis c~(λ)
  of src/spectral/basis.rs. When every albedo, emitter and the background
  is grey (spectrally flat; the script refuses other scenes), the radiance
  at λ is the grey image L(n(λ)) of the glass at index n(λ) = A + B / λ²
  (λ in µm), and our channel k has the expectation
  ∫ c~_k(λ) L(n(λ)) dλ. Cauchy's index is affine in u = 1/λ², so the
  script takes --nodes indices n_q evenly spaced in u over the range,
  renders Mitsuba at each (every dispersive material at its own n(u_q)),
  and integrates with product weights W_kq = ∫ c~_k(λ) φ_q(u(λ)) dλ, φ_q
  the hat functions of the nodes in u (piecewise-linear interpolation of
  L in u; the sensor is integrated on a 0.1 nm grid, so its kinks cost
  nothing). The weights are ours (examples/spectral_sensor.rs prints
  them); the transport is Mitsuba's. The quadrature error of the mean is
  bounded by max|M''| Δu² / 8 ∫|c~_k| (M the mean image, M'' from second
  differences of the node means), printed beside the figures.

Both compare ours with the composite: per channel the ratio of mean
radiance (ours / composite) with its standard error (from the pixel
differences, as scripts/crosscheck.py), relative MSE, and per tile of
--tile pixels a z-score of the mean difference (sample standard error
within the tile): chi2 per tile near 1 when the images agree tile by tile.
Dispersion moves light sideways, hardly changing a channel's mean over the
image, so the script also gives the same figures for the glass at one
index (n at 550 nm; n_G) against the composite: what the tiles would show
if our dispersion were not there. Mitsuba renders with the pixel filter
matched to ours (crosscheck.py --match-filter): every pixel has the same
expectation in both.

Exit status: 0 when every channel's mean ratio is within --tolerance of 1,
1 when not, 2 when our renderer could not be run.
"""

import argparse
import os
import subprocess
import sys
import time
import types

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import crosscheck  # noqa: E402  (the scene translator and the metrics)

ROOT = crosscheck.ROOT
GREEN_NM = 550.0


def sensor_table():
    """Our sensor c~(λ) on a 0.1 nm grid: (nm, weights (N, 3), λ_min, λ_max)."""
    binary = os.path.join(ROOT, "target", "release", "examples", "spectral_sensor")
    if not os.path.exists(binary):
        subprocess.run(["cargo", "build", "--release", "--example", "spectral_sensor"],
                       cwd=ROOT, check=True)
    text = subprocess.run([binary, "0.1"], capture_output=True, text=True, check=True).stdout
    lines = text.splitlines()
    lambda_min, lambda_max = (float(v) for v in lines[0].lstrip("#").split())
    table = np.array([[float(v) for v in line.split()] for line in lines[1:]])
    return table[:, 0], table[:, 1:], lambda_min, lambda_max


def trapezoid(values, nm):
    """∫ values dλ over the grid, along the first axis."""
    h = np.diff(nm)[:, None] if values.ndim == 2 else np.diff(nm)
    return ((values[1:] + values[:-1]) * 0.5 * h).sum(axis=0)


def cauchy_nodes(nodes):
    """Nodes evenly spaced in u = 1/λ² (µm⁻²) and the product weights W (3, K)."""
    nm, sensor, lambda_min, lambda_max = sensor_table()
    u = 1.0 / (nm * 1e-3) ** 2
    u_nodes = np.linspace(1.0 / (lambda_max * 1e-3) ** 2, 1.0 / (lambda_min * 1e-3) ** 2, nodes)
    du = u_nodes[1] - u_nodes[0]
    weights = np.zeros((3, nodes))
    for q, uq in enumerate(u_nodes):
        hat = np.clip(1.0 - np.abs(u - uq) / du, 0.0, None)
        weights[:, q] = trapezoid(sensor * hat[:, None], nm)
    sensor_sums = trapezoid(sensor, nm)
    sensor_abs = trapezoid(np.abs(sensor), nm)
    return {"u": u_nodes, "du": du, "weights": weights, "sensor_integral": sensor_sums,
            "sensor_abs_integral": sensor_abs, "lambda_range": (lambda_min, lambda_max),
            "nm_of_node": 1e3 / np.sqrt(u_nodes)}


def grey(color):
    return max(color) - min(color) <= 1e-12


def with_indices(scene, index_of):
    """A copy of the scene's materials with each refractive one's index set by
    index_of(material) (None: unchanged)."""
    materials = []
    for m in scene.materials:
        n = index_of(m) if m["refract"] > 0 else None
        materials.append(dict(m, ior=n) if n is not None else m)
    copy = types.SimpleNamespace(**vars(scene))
    copy.materials = materials
    return copy


def tile_statistics(test, reference, tile):
    """z-scores of the per-tile, per-channel mean difference, with the sample
    standard error of the pixels' differences within the tile."""
    h, w = reference.shape[0] // tile, reference.shape[1] // tile
    d = (test.astype(np.float64) - reference)[:h * tile, :w * tile]
    d = d.reshape(h, tile, w, tile, 3)
    n = tile * tile
    mean = d.mean(axis=(1, 3))
    variance = ((d - mean[:, None, :, None, :]) ** 2).sum(axis=(1, 3)) / (n - 1)
    z = mean / np.sqrt(np.maximum(variance / n, 1e-30))
    worst = np.unravel_index(np.argmax(np.abs(z)), z.shape)
    return {"tiles": int(h * w), "tile_pixels": tile,
            "chi2_per_tile_rgb": [float(v) for v in (z ** 2).mean(axis=(0, 1))],
            "max_abs_z": float(np.abs(z).max()),
            "worst_tile_row_col_channel": [int(v) for v in worst],
            "share_abs_z_over_3": float((np.abs(z) > 3).mean())}


def compare(test, reference, tile):
    m = crosscheck.metrics(test, reference)
    m["tiles"] = tile_statistics(test, reference, tile)
    return m


def render_ours(args, out_path, extra):
    binary = os.path.join(ROOT, "target", "release", "pathtracer")
    if not os.path.exists(binary):
        subprocess.run(["cargo", "build", "--release"], cwd=ROOT, check=True)
    command = [binary, "render", args.scene, "-o", out_path, "--spp", str(args.spp),
               "--seed", str(args.seed), "--width", str(args.width), "--height",
               str(args.height), "--look", "physical", "--max-depth", str(args.max_depth),
               "--quiet"] + extra
    t0 = time.perf_counter()
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        raise RuntimeError(f"{' '.join(command)} failed ({result.returncode}):\n"
                           f"{result.stderr.strip()[-2000:]}")
    return crosscheck.read_pfm(out_path), time.perf_counter() - t0, command


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--mode", required=True, choices=["cauchy", "channels"])
    parser.add_argument("--scene", default="testcases/crosscheck_dispersion.txt")
    parser.add_argument("--channels", default="1.55,1.65,1.85",
                        help="the indices R,G,B of --mode channels (ours: --dispersion R,G,B)")
    parser.add_argument("--nodes", type=int, default=17, help="indices Mitsuba renders (cauchy)")
    parser.add_argument("--spp", type=int, default=1024, help="ours")
    parser.add_argument("--reference-spp", type=int, default=512,
                        help="Mitsuba, per index, per pixel of our size")
    parser.add_argument("--width", type=int, default=128)
    parser.add_argument("--height", type=int, default=96)
    parser.add_argument("--max-depth", type=int, default=12,
                        help="scattering vertices (ours; Mitsuba's max_depth is one more)")
    parser.add_argument("--variant", default="scalar_rgb", choices=["scalar_rgb", "llvm_ad_rgb"])
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--tile", type=int, default=8, help="tile side (pixels)")
    parser.add_argument("--out", default=None)
    parser.add_argument("--tolerance", type=float, default=0.01,
                        help="largest accepted |mean ratio - 1| per channel")
    args = parser.parse_args()
    os.chdir(ROOT)
    args.out = args.out or f"output/crosscheck_dispersion_{args.mode}"
    os.makedirs(args.out, exist_ok=True)

    import mitsuba as mi
    mi.set_variant(args.variant)
    scene = crosscheck.Scene(args.scene)
    refractive = [m for m in scene.materials if m["refract"] > 0]
    if not refractive:
        raise SystemExit(f"{args.scene}: no refractive material")
    translate_args = types.SimpleNamespace(width=args.width, height=args.height,
                                           max_depth=args.max_depth, look="physical",
                                           flat_textures=False, match_filter=True)
    tmpdir = os.path.abspath(os.path.join(args.out, "mitsuba_inputs"))
    os.makedirs(tmpdir, exist_ok=True)
    pass_spp = 64 if args.variant.startswith("llvm") else args.reference_spp

    if args.mode == "channels":
        indices = [float(v) for v in args.channels.split(",")]
        if len(indices) != 3:
            raise SystemExit("--channels expects three indices R,G,B")
        ours_extra = ["--dispersion", ",".join(repr(v) for v in indices)]
        plan = [(f"n={n}", lambda m, n=n: n) for n in indices]
        one_index = 1  # n_G
    else:
        if not scene.camera.get("dispersion"):
            raise SystemExit(f"{args.scene}: the camera has no 'dispersion' flag: "
                             "its 'cauchy' coefficients are not rendered")
        dispersive = [m for m in refractive if m.get("cauchy")]
        if not dispersive:
            raise SystemExit(f"{args.scene}: no refractive material has 'cauchy A B'")
        colours = ([m["color"] for m in scene.materials] + [m["emission"] for m in scene.materials]
                   + [scene.background])
        if not all(grey(c) for c in colours) or any(m.get("texture") for m in scene.materials):
            raise SystemExit(f"{args.scene}: a colour is not grey (or a material is textured): "
                             "the radiance at a wavelength would not depend on the index alone")
        quadrature = cauchy_nodes(args.nodes)
        ours_extra = []
        plan = [(f"u={u:.4f} ({nm:.1f} nm)",
                 lambda m, u=u: m["cauchy"][0] + m["cauchy"][1] * u if m.get("cauchy") else None)
                for u, nm in zip(quadrature["u"], quadrature["nm_of_node"])]
        one_u = 1.0 / (GREEN_NM * 1e-3) ** 2
        one_index = int(np.argmin(np.abs(quadrature["u"] - one_u)))
        print(f"{args.nodes} nodes in u = 1/λ² over {quadrature['lambda_range']} nm; "
              f"∫ c~_k dλ = {np.round(quadrature['sensor_integral'], 6).tolist()}, "
              f"Σ_q W_kq = {np.round(quadrature['weights'].sum(axis=1), 6).tolist()}", flush=True)

    print(f"scene {args.scene}; Mitsuba {mi.__version__} {args.variant}; "
          f"{args.width}x{args.height}; {len(plan)} renders at {args.reference_spp} spp",
          flush=True)
    # Each index in two halves of independent seeds: their composites, one
    # against the other, give the figures of two renders of one expectation.
    halves, seconds = ([], []), 0.0
    half_spp = max(1, args.reference_spp // 2)
    for q, (label, index_of) in enumerate(plan):
        variant_scene = with_indices(scene, index_of)
        scene_dict = crosscheck.mitsuba_scene_dict(mi, variant_scene, translate_args,
                                                   half_spp, tmpdir)
        for h in range(2):
            image, _, elapsed = crosscheck.render_mitsuba(
                mi, scene_dict, half_spp, args.seed + 1000 + 2 * q + h, min(pass_spp, half_spp))
            halves[h].append(image.astype(np.float64))
            seconds += elapsed
        mean = ((halves[0][-1] + halves[1][-1]) / 2).reshape(-1, 3).mean(0)
        print(f"  Mitsuba {label}: mean {mean.round(5).tolist()}", flush=True)
    images = [(a + b) / 2 for a, b in zip(*halves)]

    report = {"mode": args.mode, "scene": args.scene, "width": args.width,
              "height": args.height, "spp": args.spp, "reference_spp": args.reference_spp,
              "max_depth": args.max_depth, "seed": args.seed, "variant": args.variant,
              "mitsuba_version": mi.__version__, "mitsuba_seconds": seconds,
              "pixel_filter": "matched (Mitsuba 2x size, tent radius 1, 2x2 mean)"}
    if args.mode == "channels":
        def compose(renders):
            return np.stack([renders[k][..., k] for k in range(3)], axis=-1)
        report["indices_rgb"] = indices
    else:
        w = quadrature["weights"]

        def compose(renders):
            return np.stack([sum(w[k, q] * renders[q][..., k] for q in range(len(renders)))
                             for k in range(3)], axis=-1)
    composite = compose(images)
    report["mitsuba_halves"] = compare(compose(halves[0]).astype(np.float32),
                                       compose(halves[1]), args.tile)
    if args.mode == "cauchy":
        # Quadrature error of the mean: |M''| du² / 8 ∫|c~_k|, M'' from second
        # differences of the node means (their noise makes this an overestimate).
        means = np.array([im.reshape(-1, 3).mean(0) for im in images])
        second = np.abs(means[2:] - 2 * means[1:-1] + means[:-2]).max(axis=0)
        bound = second / 8 * quadrature["sensor_abs_integral"]
        report["quadrature"] = {
            "nodes": args.nodes, "u_nodes": quadrature["u"].tolist(),
            "nm_of_nodes": quadrature["nm_of_node"].tolist(),
            "weights_rgb_by_node": w.tolist(),
            "sensor_integral_rgb": quadrature["sensor_integral"].tolist(),
            "relative_error_bound_rgb": (bound / composite.reshape(-1, 3).mean(0)).tolist(),
            "node_means": means.tolist()}
    composite = composite.astype(np.float32)
    crosscheck.write_pfm(os.path.join(args.out, "mitsuba_composite.pfm"), composite)
    crosscheck.preview(mi, os.path.join(args.out, "mitsuba_composite.png"), composite)
    single = images[one_index].astype(np.float32)
    report["one_index"] = {"label": plan[one_index][0], **compare(single, composite, args.tile)}

    status = 0
    try:
        ours, ours_time, command = render_ours(args, os.path.join(args.out, "ours.pfm"),
                                               ours_extra)
        crosscheck.preview(mi, os.path.join(args.out, "ours.png"), ours)
        report["ours"] = dict(seconds=ours_time, command=" ".join(command),
                              **compare(ours, composite, args.tile))
    except (RuntimeError, subprocess.CalledProcessError, OSError) as error:
        print(f"error: our renderer did not run: {error}", file=sys.stderr)
        report["ours_error"] = str(error)
        status = 2

    print(f"\n{'against the composite':<28}{'mean ratio R G B':<23}{'s.e. R G B':<21}"
          f"{'relMSE':>8}  {'tile chi2 R G B':<18}{'max |z|':>7}")
    rows = [("Mitsuba half / half", report["mitsuba_halves"]),
            ("Mitsuba, one index", report["one_index"])]
    if report.get("ours"):
        rows.append((f"ours {args.spp} spp", report["ours"]))
    for name, m in rows:
        ratio = " ".join(f"{r:.4f}" for r in m["mean_ratio_rgb"])
        se = " ".join(f"{e:.4f}" for e in m["mean_ratio_standard_error_rgb"])
        chi2 = " ".join(f"{c:.2f}" for c in m["tiles"]["chi2_per_tile_rgb"])
        print(f"{name:<28}{ratio:<23}{se:<21}{m['rel_mse']:>8.5f}  {chi2:<18}"
              f"{m['tiles']['max_abs_z']:>7.1f}")
    print(f"(one index: {plan[one_index][0]}; half / half: the composites of two halves "
          f"of the Mitsuba samples, {half_spp} spp each)")
    if args.mode == "cauchy":
        bound = report["quadrature"]["relative_error_bound_rgb"]
        print(f"quadrature error bound of the means (relative): "
              f"{' '.join(f'{b:.2e}' for b in bound)}")
    if report.get("ours"):
        if not crosscheck.check_tolerance(report, report["ours"]["mean_ratio_rgb"],
                                          args.tolerance):
            status = 1
    crosscheck.write_report(args.out, report)
    return status


if __name__ == "__main__":
    sys.exit(main())
