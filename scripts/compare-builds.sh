#!/usr/bin/env bash
# Are two builds' images the same, byte for byte? Builds two git revisions of
# the renderer (each from `git archive` into its own folder outside the
# repository, with its own target dir) and renders, with both, the same
# scenes to PFM at a small size and few samples, with 1 and 2 threads:
#   - every scene of testcases/ (also with --integrator original and
#     raycast, and --no-light-paths),
#   - every scene of ../shared/scenes/,
#   - one scene per look of ../shared/reference/ (the first row of pairs.tsv
#     and oracle-pairs.tsv that the base build gives that look, by `check`;
#     PAIRS=all: every row), and one in the physical look (--look physical),
#   - smallpt with --dispersion yuzc19, and as two render jobs (--film)
#     merged into one image.
# The warnings and notes the renders print are compared too. Prints every
# file that differs and exits 1 if any does (2 on a failure to
# build or render). A refactor that must not change any image runs it
# against the commit it started from:
#
#   scripts/compare-builds.sh [BASE [NEW]]     # default: main HEAD
#   W=32 H=24 SPP=4 PAIRS=all scripts/compare-builds.sh f4eea95 HEAD
#
# Builds are kept per commit in $COMPARE_DIR (default
# ${TMPDIR:-/tmp}/pathtracer-compare), so a second run against the same base
# builds only the new commit; a new target dir starts from a copy of this
# checkout's target/$PROFILE when there is one (dependencies then need not
# rebuild). PROFILE (default release, the shipped build) chooses the cargo profile. The scenes are this checkout's files
# (both builds render the same ones); the images go to
# $COMPARE_DIR/images/base-<commit>/ and new-<commit>/.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)

base_rev=${1:-main}
new_rev=${2:-HEAD}
W=${W:-64}
H=${H:-48}
SPP=${SPP:-16}
PAIRS=${PAIRS:-looks}
PROFILE=${PROFILE:-release}
SHARED=${SHARED:-$root/../shared}
COMPARE_DIR=${COMPARE_DIR:-${TMPDIR:-/tmp}/pathtracer-compare}

log() { echo "compare-builds: $*" >&2; }
die() {
    echo "compare-builds: FAILED: $*" >&2
    exit 2
}

# build REV: prints the path of REV's binary, built once per commit.
build() {
    local sha source target binary
    sha=$(git rev-parse --verify "$1^{commit}") || die "no revision '$1'"
    source=$COMPARE_DIR/src/$sha
    target=$COMPARE_DIR/target/$sha
    binary=$COMPARE_DIR/bin/$PROFILE/$sha/pathtracer
    if [ ! -x "$binary" ]; then
        log "building $1 ($sha) with profile $PROFILE"
        rm -rf "$source"
        mkdir -p "$source" "$(dirname "$binary")"
        git archive "$sha" | tar -x -C "$source"
        if [ ! -d "$target" ] && [ -d "$root/target/$PROFILE" ]; then
            mkdir -p "$target"
            cp -a "$root/target/$PROFILE" "$target/"
        fi
        (cd "$source" && CARGO_TARGET_DIR=$target cargo build --profile "$PROFILE" \
            --locked --quiet --bin pathtracer) >&2 || die "cannot build $1"
        cp "$target/$PROFILE/pathtracer" "$binary"
    fi
    echo "$binary"
}

# The scenes: lines of "name<TAB>scene file<TAB>folder to run in<TAB>extra options".
scenes() {
    local scene
    for scene in testcases/*.txt; do
        local name
        name=$(basename "$scene" .txt)
        printf '%s\t%s\t%s\t%s\n' "$name" "$scene" "$root" ""
        printf '%s\t%s\t%s\t%s\n' "$name.original" "$scene" "$root" "--integrator original"
        printf '%s\t%s\t%s\t%s\n' "$name.raycast" "$scene" "$root" "--integrator raycast"
        printf '%s\t%s\t%s\t%s\n' "$name.no-light-paths" "$scene" "$root" "--no-light-paths"
    done
    printf '%s\t%s\t%s\t%s\n' smallpt.dispersion testcases/smallpt.txt "$root" "--dispersion yuzc19"
    if [ ! -d "$SHARED" ]; then
        log "skipped: $SHARED not found (only testcases/ compared)"
        return
    fi
    for scene in "$SHARED"/scenes/*.txt; do
        printf '%s\t%s\t%s\t%s\n' "shared.$(basename "$scene" .txt)" "$scene" "$root" ""
    done
    local seen=" " folder base file look
    local -A names=()
    for pairs in "$SHARED"/reference/pairs.tsv "$SHARED"/reference/oracle-pairs.tsv; do
        while IFS=$'\t' read -r folder base file _; do
            case "$folder" in '#'* | '') continue ;; esac
            local dir=$SHARED/reference/$folder/$base
            look=$(cd "$dir" && "$base_bin" check "$file" 2>/dev/null |
                grep -o 'look [a-z0-9]*' | head -n 1 | cut -d' ' -f2) || continue
            [ -n "$look" ] || continue
            case "$seen" in *" $look "*) [ "$PAIRS" = all ] || continue ;; esac
            case "$seen" in *" $look "*) ;; *) seen="$seen$look " ;; esac
            local name
            name="look-$look.$(basename "$folder").$(basename "$file" .txt)"
            [ -n "${names[$name]:-}" ] && continue
            names[$name]=1
            printf '%s\t%s\t%s\t%s\n' "$name" "$file" "$dir" ""
            if [ "$look" = original ]; then
                printf '%s\t%s\t%s\t%s\n' "look-physical.$(basename "$folder").$(basename "$file" .txt)" \
                    "$file" "$dir" "--look physical"
            fi
        done < "$pairs"
    done
    log "looks found in the reference pairs:$seen"
}

# render BIN OUT_DIR: every scene, 1 and 2 threads, into OUT_DIR.
render_all() {
    local bin=$1 out=$2 name scene dir extra threads
    rm -rf "$out"
    mkdir -p "$out"
    while IFS=$'\t' read -r name scene dir extra; do
        for threads in 1 2; do
            # shellcheck disable=SC2086 # extra holds several options
            (cd "$dir" && "$bin" render "$scene" --width "$W" --height "$H" --spp "$SPP" \
                --threads "$threads" --quiet $extra -o "$out/$name.t$threads.pfm") \
                > /dev/null 2>> "$out/stderr.log" || die "$bin cannot render $scene $extra"
        done
    done < "$scene_list"
    # One render as two jobs merged into one image.
    local half=$((SPP / 2))
    "$bin" render testcases/smallpt.txt --width "$W" --height "$H" --spp "$SPP" \
        --film "$out/part0.exr" --samples "0..$half" --quiet > /dev/null 2>> "$out/stderr.log"
    "$bin" render testcases/smallpt.txt --width "$W" --height "$H" --spp "$SPP" \
        --film "$out/part1.exr" --samples "$half..$SPP" --threads 1 --quiet \
        > /dev/null 2>> "$out/stderr.log"
    "$bin" merge "$out/part0.exr" "$out/part1.exr" -o "$out/smallpt.merged.pfm" \
        > /dev/null 2>> "$out/stderr.log" || die "$bin cannot merge render jobs"
    rm -f "$out"/part*.exr "$out"/*.json
}

base_bin=$(build "$base_rev")
new_bin=$(build "$new_rev")
base_sha=$(git rev-parse --short "$base_rev^{commit}")
new_sha=$(git rev-parse --short "$new_rev^{commit}")
scene_list=$(mktemp)
trap 'rm -f "$scene_list"' EXIT
scenes > "$scene_list"
log "$(wc -l < "$scene_list") renders per thread count, ${W}x$H at $SPP spp"
started=$SECONDS
base_images=$COMPARE_DIR/images/base-$base_sha
new_images=$COMPARE_DIR/images/new-$new_sha
render_all "$base_bin" "$base_images"
render_all "$new_bin" "$new_images"

differ=0 same=0
for image in "$base_images"/*.pfm; do
    other=$new_images/$(basename "$image")
    if cmp -s "$image" "$other"; then
        same=$((same + 1))
    else
        echo "differs: $(basename "$image")"
        differ=$((differ + 1))
    fi
done
if ! cmp -s "$base_images/stderr.log" "$new_images/stderr.log"; then
    echo "differs: the warnings and notes (stderr.log):"
    diff "$base_images/stderr.log" "$new_images/stderr.log" || true
    differ=$((differ + 1))
fi
log "$same images identical, $differ differ ($base_sha against $new_sha, $((SECONDS - started)) s of rendering)"
[ "$differ" -eq 0 ] || exit 1
[ "$same" -gt 0 ] || die "no image rendered"
