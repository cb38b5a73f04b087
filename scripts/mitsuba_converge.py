#!/usr/bin/env python3
"""Error-against-time curve of Mitsuba 3 on a scene, in the CSV format of
`pathtracer converge` (spp,seconds,rmse,rel_mse,ssim), so that
`pathtracer plot ours=a.csv mitsuba=b.csv -o x.svg` draws both together.

    scripts/mitsuba_converge.py --scene SCENE [--variant llvm_ad_rgb]
        [--width 256 --height 192] [--max-spp 256] [--reference-spp 4096]
        [--reference PFM] [--our-reference PFM] [--pass-spp 64] [--seed 1]
        [--dialect auto|canonical|cambrian] [--repeats 1] [--flat-textures] [--no-ssim]
        [--out output/curves/NAME]

The scene is translated by scripts/crosscheck.py (its warnings list what could
not be translated exactly). Steps:
1. the reference: Mitsuba at --reference-spp in passes of --pass-spp (seeds
   disjoint from the curve's), or an existing PFM given by --reference (e.g. the
   llvm reference reused for scalar_rgb: same scene, same expectation);
2. Mitsuba at 1, 2, 4, ..., --max-spp spp, each an independent render with its
   own seed; `seconds` is the wall clock of the mi.render calls of that level
   (and the read-back of the image), nothing else: the scene is loaded once,
   before. JIT variants (llvm_*) compile a kernel for a new shape of work: each
   level is preceded by an untimed warm-up render of the same passes with
   another seed, so compilation is never counted (scalar_rgb needs none).
   With --repeats K each level is timed K times (same seeds) and the fastest
   is kept, against other load on a shared machine.
   Ours (`pathtracer converge`) renders progressively and reports cumulative
   time; both columns are "wall clock to obtain an N-spp image".
3. rmse and rel_mse (as src/metrics/mod.rs: mean over pixels and channels of
   (a-b)^2/(b^2+1e-2)) against Mitsuba's own reference; ssim by
   `target/release/pathtracer compare --json` on the saved PFMs (NaN if the
   binary is absent or --no-ssim).
Writes OUT/mitsuba_<variant>_converge.csv, OUT/mitsuba_<variant>_reference.pfm
(PFM rows bottom to top), the level images OUT/mitsuba_<variant>_<N>spp.pfm and
OUT/mitsuba_<variant>_converge.json (timings, warnings, and with --our-reference
the per-channel ratio of mean radiance Mitsuba reference / ours, ~1 when the two
estimators agree in expectation).
"""

import argparse
import json
import os
import subprocess
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import crosscheck as cc  # noqa: E402

LLVM_CANDIDATES = ("/usr/lib/x86_64-linux-gnu/libLLVM-19.so",
                   "/usr/lib/x86_64-linux-gnu/libLLVM.so.19.1",
                   "/usr/lib/llvm-19/lib/libLLVM.so")


def passes_of(spp, pass_spp):
    return [pass_spp] * (spp // pass_spp) + ([spp % pass_spp] if spp % pass_spp else [])


def render(mi, scene, spp, seed, pass_spp):
    """Mean of passes of at most pass_spp samples (box filter: the mean of the
    passes weighted by their spp is the mean of all samples); returns the
    image and the wall clock of the render calls and read-backs."""
    total = None
    seconds = 0.0
    for index, n in enumerate(passes_of(spp, pass_spp)):
        t0 = time.perf_counter()
        image = np.array(mi.render(scene, spp=n, seed=seed + index), dtype=np.float64)
        seconds += time.perf_counter() - t0
        total = image * n if total is None else total + image * n
    return (total / spp)[..., :3].astype(np.float32), seconds


def ssim_of(image_path, reference_path):
    binary = os.path.join(cc.ROOT, "target", "release", "pathtracer")
    if not os.path.exists(binary):
        return float("nan")
    result = subprocess.run([binary, "compare", image_path, reference_path, "--json"],
                            capture_output=True, text=True)
    if result.returncode != 0:
        cc.warn(f"pathtracer compare failed: {result.stderr.strip()[-300:]}")
        return float("nan")
    try:
        return float(json.loads(result.stdout)["ssim"])
    except (ValueError, KeyError) as error:
        cc.warn(f"pathtracer compare output not understood ({error})")
        return float("nan")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--scene", required=True)
    parser.add_argument("--variant", default="llvm_ad_rgb", choices=["scalar_rgb", "llvm_ad_rgb"])
    parser.add_argument("--width", type=int, default=256)
    parser.add_argument("--height", type=int, default=192)
    parser.add_argument("--max-spp", type=int, default=256)
    parser.add_argument("--reference-spp", type=int, default=4096)
    parser.add_argument("--reference", default=None,
                        help="use this PFM as Mitsuba's reference instead of rendering one")
    parser.add_argument("--our-reference", default=None,
                        help="our reference PFM: report the mean radiance ratio against it")
    parser.add_argument("--pass-spp", type=int, default=None,
                        help="samples per render pass (default 64 for llvm, 4096 for scalar)")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--dialect", default="auto", choices=["auto", "canonical", "cambrian"])
    parser.add_argument("--repeats", type=int, default=1,
                        help="time each level this many times (same seeds) and keep the "
                             "fastest: the machine may be shared")
    parser.add_argument("--flat-textures", action="store_true",
                        help="give textured materials their mean texel instead of the map")
    parser.add_argument("--no-ssim", action="store_true")
    parser.add_argument("--out", default=None, help="default output/curves/<scene name>")
    args = parser.parse_args()
    for name in ("scene", "reference", "our_reference"):
        if getattr(args, name):
            setattr(args, name, os.path.abspath(getattr(args, name)))
    os.chdir(cc.ROOT)
    if args.out is None:
        args.out = os.path.join("output", "curves",
                                os.path.splitext(os.path.basename(args.scene))[0])
    os.makedirs(args.out, exist_ok=True)

    jit = args.variant.startswith("llvm")
    if jit and not os.environ.get("DRJIT_LIBLLVM_PATH"):
        for candidate in LLVM_CANDIDATES:
            if os.path.exists(candidate):
                os.environ["DRJIT_LIBLLVM_PATH"] = candidate
                break
    import mitsuba as mi
    mi.set_variant(args.variant)
    if args.pass_spp is None:
        args.pass_spp = 64 if jit else 4096

    scene = cc.Scene(args.scene, dialect=args.dialect)
    inputs = os.path.abspath(os.path.join(args.out, "mitsuba_inputs"))
    os.makedirs(inputs, exist_ok=True)
    scene_dict = cc.mitsuba_scene_dict(mi, scene, args, 1, inputs)
    t0 = time.perf_counter()
    loaded = mi.load_dict(scene_dict)
    load_seconds = time.perf_counter() - t0
    print(f"scene {args.scene} ({scene.dialect} dialect): {len(scene.shapes)} shapes; "
          f"Mitsuba {mi.__version__} {args.variant}; {args.width}x{args.height}; "
          f"load {load_seconds:.2f} s", flush=True)
    prefix = os.path.join(args.out, f"mitsuba_{args.variant}")

    # 1. reference
    reference_path = f"{prefix}_reference.pfm"
    if args.reference:
        reference = cc.read_pfm(args.reference)
        if reference.shape[:2] != (args.height, args.width):
            raise SystemExit(f"{args.reference}: {reference.shape[1]}x{reference.shape[0]}, "
                             f"expected {args.width}x{args.height}")
        reference_info = {"from": args.reference}
        reference_path = args.reference
        print(f"reference: {args.reference}", flush=True)
    else:
        print(f"reference at {args.reference_spp} spp (passes of {args.pass_spp}) ...", flush=True)
        if jit:  # compile outside the timing, as for the curve
            render(mi, loaded, min(args.pass_spp, args.reference_spp), 999_999, args.pass_spp)
        reference, seconds = render(mi, loaded, args.reference_spp, 1_000_000 * args.seed,
                                    args.pass_spp)
        cc.write_pfm(reference_path, reference)
        cc.preview(mi, f"{prefix}_reference.png", reference)
        reference_info = {"spp": args.reference_spp, "seconds": seconds,
                          "pass_spp": args.pass_spp}
        print(f"reference: {seconds:.1f} s", flush=True)
    reference_info["mean_rgb"] = [float(v) for v in reference.reshape(-1, 3).mean(0)]
    reference_info["nonfinite_pixels"] = int((~np.isfinite(reference)).any(axis=2).sum())

    # 2-3. the curve
    rows = []
    csv_path = f"{prefix}_converge.csv"
    spp = 1
    levels = []
    while spp < args.max_spp:
        levels.append(spp)
        spp *= 2
    levels.append(args.max_spp)
    print(f"{'spp':>6}{'seconds':>10}{'rmse':>14}{'rel_mse':>14}{'ssim':>10}"
          f"{'warm-up s':>11}", flush=True)
    for level, spp in enumerate(levels):
        seed = 1000 * args.seed + 100 * level  # passes use seed + pass index (< 100)
        warm = 0.0
        if jit:
            _, warm = render(mi, loaded, spp, 500_000 + seed, args.pass_spp)
        image, seconds = render(mi, loaded, spp, seed, args.pass_spp)
        times = [seconds]
        for repeat in range(1, args.repeats):  # same seeds: only the clock differs
            times.append(render(mi, loaded, spp, seed, args.pass_spp)[1])
        seconds = min(times)
        m = cc.metrics(image, reference)
        image_path = f"{prefix}_{spp}spp.pfm"
        cc.write_pfm(image_path, image)
        ssim = float("nan") if args.no_ssim else ssim_of(image_path, reference_path)
        rows.append({"spp": spp, "seconds": seconds, "rmse": m["rmse"],
                     "rel_mse": m["rel_mse"], "ssim": ssim, "warmup_seconds": warm, "all_seconds": times,
                     "mean_ratio_rgb": m["mean_ratio_rgb"]})
        print(f"{spp:>6}{seconds:>10.3f}{m['rmse']:>14.6e}{m['rel_mse']:>14.6e}{ssim:>10.4f}"
              f"{warm:>11.3f}", flush=True)
        with open(csv_path, "w") as f:  # same format as src/converge.rs
            f.write("spp,seconds,rmse,rel_mse,ssim\n")
            for r in rows:
                f.write(f"{r['spp']},{r['seconds']:.6f},{r['rmse']:.8e},{r['rel_mse']:.8e},"
                        f"{r['ssim']:.6f}\n")

    report = {
        "scene": args.scene, "dialect": scene.dialect, "variant": args.variant,
        "mitsuba_version": mi.__version__, "width": args.width, "height": args.height,
        "cpu_count": os.cpu_count(), "load_seconds": load_seconds, "pass_spp": args.pass_spp,
        "reference": reference_info, "curve": rows,
        "timing": "wall clock of mi.render calls + image read-back per level; JIT variants: "
                  "an untimed warm-up render of the same passes precedes each level; "
                  f"fastest of {args.repeats} timed repeats",
        "repeats": args.repeats,
        "warnings": cc.WARNINGS,
    }
    if args.our_reference:
        ours = cc.read_pfm(args.our_reference)
        if ours.shape != reference.shape:
            cc.warn(f"our reference is {ours.shape[1]}x{ours.shape[0]}: only mean ratios")
            ratio = reference.reshape(-1, 3).mean(0) / ours.reshape(-1, 3).mean(0)
            report["mitsuba_over_ours_mean_ratio_rgb"] = [float(v) for v in ratio]
        else:
            m = cc.metrics(reference, ours)
            report["mitsuba_over_ours"] = m
            report["mitsuba_over_ours_mean_ratio_rgb"] = m["mean_ratio_rgb"]
            print(f"tiles (luminance, 4x4) Mitsuba/ours: {m['tile_ratio_min']:.3f}.."
                  f"{m['tile_ratio_max']:.3f}")
        ratio = report["mitsuba_over_ours_mean_ratio_rgb"]
        print("mean radiance ratio Mitsuba reference / ours (R G B): "
              + " ".join(f"{v:.4f}" for v in ratio))
    with open(f"{prefix}_converge.json", "w") as f:
        json.dump(report, f, indent=2)
    print(f"wrote {csv_path}")
    if cc.WARNINGS:
        print("translation warnings:\n  " + "\n  ".join(cc.WARNINGS))
    return 0


if __name__ == "__main__":
    sys.exit(main())
