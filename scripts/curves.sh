#!/usr/bin/env bash
# Error-against-time curves for docs/performance.md: both of our integrators
# and Mitsuba 3 on the same scenes, at the same size, on this machine, in one
# run. Writes output/curves/<scene>/ (CSV, PFM) and docs/curves/<scene>.svg.
#
#   scripts/curves.sh            # all three scenes
#   SCENES="sample_rec" W=128 H=96 REF_SPP=1024 scripts/curves.sh
#   BASELINE=../old/target/release/pathtracer scripts/curves.sh
#
# With BASELINE (another build of pathtracer, e.g. of the previous commit),
# its curves are drawn too, in the same run: how a change moves
# time-to-error ("baseline path" against "path").
#
# Every scene renders in the ported renderer's look (LOOK=original: five
# scattering vertices, Schlick glass), the conventions Mitsuba's translation
# follows (scripts/crosscheck.py: max_depth 6), so that both render the same
# scene; `sample_rec`'s own look (`cambrian`: no depth limit, Cambrian's
# sphere test) would be another image.
#
# Our reference is the path integrator at REF_SPP (the same expected image as
# the original estimator: tests/integrator_agreement/); Mitsuba's error is
# measured against Mitsuba's own reference, since its translation of a scene
# differs slightly in expectation (see scripts/crosscheck.py).
set -euo pipefail
cd "$(dirname "$0")/.."

W=${W:-256}
H=${H:-192}
MAX_SPP=${MAX_SPP:-256}
REF_SPP=${REF_SPP:-4096}
VARIANT=${VARIANT:-llvm_ad_rgb}
LOOK=${LOOK:-original}
SCENES=${SCENES:-"sample_rec report_scene15_spheres report_scene11_dragons"}
BIN=target/release/pathtracer
PYTHON=${PYTHON:-.venv-crosscheck/bin/python}

scene_path() {
    case "$1" in
        sample_rec) echo ../shared/reference/cambrian-pathtracer/testcases/sample_rec.txt ;;
        *) echo "../shared/scenes/$1.txt" ;;
    esac
}

cargo build --release --quiet
mkdir -p docs/curves
for name in $SCENES; do
    scene=$(scene_path "$name")
    out=output/curves/$name
    reference=$out/ours_reference_$LOOK.pfm
    mkdir -p "$out"
    if [ ! -f "$reference" ]; then
        $BIN render "$scene" --width "$W" --height "$H" --spp "$REF_SPP" --seed 4242 \
            --integrator path --look "$LOOK" -o "$reference" --quiet
    fi
    for integrator in original path; do
        $BIN converge "$scene" --width "$W" --height "$H" --max-spp "$MAX_SPP" --seed 1 \
            --integrator "$integrator" --look "$LOOK" --reference "$reference" \
            --csv "$out/ours_$integrator.csv" --plot "$out/ours_$integrator.svg" > /dev/null
    done
    curves=("original=$out/ours_original.csv" "path=$out/ours_path.csv")
    if [ -n "${BASELINE:-}" ]; then
        for integrator in original path; do
            "$BASELINE" converge "$scene" --width "$W" --height "$H" --max-spp "$MAX_SPP" \
                --seed 1 --integrator "$integrator" --look "$LOOK" --reference "$reference" \
                --csv "$out/baseline_$integrator.csv" --plot "$out/baseline_$integrator.svg" \
                > /dev/null
            curves+=("baseline $integrator=$out/baseline_$integrator.csv")
        done
    fi
    if [ -x "$PYTHON" ]; then
        $PYTHON scripts/mitsuba_converge.py --scene "$scene" --variant "$VARIANT" \
            --width "$W" --height "$H" --max-spp "$MAX_SPP" --reference-spp "$REF_SPP" \
            --our-reference "$reference" --out "$out" > "$out/mitsuba.log"
        curves+=("mitsuba $VARIANT=$out/mitsuba_${VARIANT}_converge.csv")
    else
        echo "note: $PYTHON not found (make crosscheck installs it): no Mitsuba curve" >&2
    fi
    # The error the original estimator reaches at MAX_SPP, and when each
    # renderer reaches it.
    target=$(tail -n 1 "$out/ours_original.csv" | cut -d, -f4)
    echo "== $name ($W x $H): relMSE of the original at $MAX_SPP spp = $target"
    $BIN plot "${curves[@]}" -o "docs/curves/$name.svg" --title "$name, ${W}x${H}" \
        --time-to "$target"
done
