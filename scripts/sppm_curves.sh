#!/usr/bin/env bash
# SPPM's error-against-time curves beside the path integrator's
# (docs/performance.md, "Photon mapping"): testcases/smallpt.txt and
# testcases/caustic.txt, the whole image and the glass ball's caustic
# region, one run. Writes output/curves/sppm/ (CSV, PFM) and
# docs/curves/sppm_<scene>[_caustic].svg.
#
#   scripts/sppm_curves.sh
#   W=128 H=96 REF_SPP=256 MAX_SPP=32 scripts/sppm_curves.sh
#
# The reference is the path integrator's at REF_SPP (SPPM converges to the
# same image: tests/sppm.rs). Both curves are measured against it; its own
# noise puts a floor under both.
set -euo pipefail
cd "$(dirname "$0")/.."

W=${W:-256}
H=${H:-192}
MAX_SPP=${MAX_SPP:-64}
REF_SPP=${REF_SPP:-512}
BIN=target/release/pathtracer

# The caustic region of each scene at 256x192 (x0,y0,x1,y1), scaled to W, H.
region() {
    local x0 y0 x1 y1
    case "$1" in
        smallpt) read -r x0 y0 x1 y1 <<< "150 160 215 185" ;;
        caustic) read -r x0 y0 x1 y1 <<< "100 88 160 115" ;;
    esac
    echo "$((x0 * W / 256)),$((y0 * H / 192)),$((x1 * W / 256)),$((y1 * H / 192))"
}

cargo build --release --quiet
mkdir -p docs/curves
for name in smallpt caustic; do
    scene=testcases/$name.txt
    out=output/curves/sppm/$name
    reference=$out/reference.pfm
    mkdir -p "$out"
    if [ ! -f "$reference" ]; then
        $BIN render "$scene" --width "$W" --height "$H" --spp "$REF_SPP" --seed 4242 \
            --integrator path -o "$reference" --quiet
    fi
    for part in whole caustic; do
        extra=()
        [ "$part" = caustic ] && extra=(--region "$(region "$name")")
        for integrator in path sppm; do
            $BIN converge "$scene" --width "$W" --height "$H" --max-spp "$MAX_SPP" --seed 1 \
                --integrator "$integrator" --reference "$reference" "${extra[@]}" \
                --csv "$out/${integrator}_$part.csv" --plot "$out/${integrator}_$part.svg" > /dev/null
        done
        svg=docs/curves/sppm_$name.svg
        [ "$part" = caustic ] && svg=docs/curves/sppm_${name}_caustic.svg
        $BIN plot "path=$out/path_$part.csv" "sppm=$out/sppm_$part.csv" \
            --title "$name ($part), ${W}x${H}" -o "$svg" --time-to 0.01
    done
done
