# Entry points of the project. `make render` and `make test` are the two
# set-up commands of a fresh machine (see README.md).

CARGO ?= cargo
SCENE ?= testcases/smallpt.txt
SPP ?= 64
BIN := target/release/pathtracer

.PHONY: build render test test-browser test-portable portable portable-install lint bench bench-peers converge lookalike crosscheck crosscheck-glossy crosscheck-media crosscheck-dispersion mitsuba-converge gallery fuzz fuzz-seeds farm-test clean

build:
	$(CARGO) build --release

# The image of `make render`. After an interrupted render (Ctrl-C), its
# checkpoint OUT.checkpoint.exr is there and the next `make render` resumes it.
OUT ?= output/$(basename $(notdir $(SCENE))).bmp

render: build
	$(BIN) render $(SCENE) --spp $(SPP) -o $(OUT)$(if $(wildcard $(OUT).checkpoint.exr), --resume)

test:
	$(CARGO) test --release

# The page of `pathtracer view` in headless Chromium, driven over its
# DevTools pipe by scripts/browser/ (Python, standard library only; not part
# of `make test`): the picture shows, the exposure slider changes it with no
# new render, a saved scene brings the new picture, a broken one its error;
# against a coursework render (../shared) it writes
# docs/images/view_against.png. Installs Debian's chromium if missing.
CHROMIUM ?= /usr/bin/chromium
test-browser: build
	@test -x $(CHROMIUM) || \
		(apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium)
	python3 scripts/browser/view_in_chromium.py --chromium $(CHROMIUM)

# A binary for any x86-64 CPU (baseline x86-64: SSE2, no AVX), to copy to
# other machines or install with `make portable-install`:
# target/portable/release/pathtracer. The default build targets the CPU that
# builds it (.cargo/config.toml), 11-14% faster here on the curve scenes
# (docs/performance.md, "Portable binaries"). Compiles every dependency a
# second time, into its own target directory (about 5 minutes on 2 cores).
PORTABLE := target/portable/release/pathtracer
portable:
	RUSTFLAGS="" CARGO_TARGET_DIR=target/portable $(CARGO) build --release

portable-install:
	RUSTFLAGS="" CARGO_TARGET_DIR=target/portable $(CARGO) install --path .

# The portable binary on a CPU without AVX (QEMU's Nehalem, Debian's
# qemu-user, installed if missing; not part of `make test`): it renders,
# and its image is the default build's to the byte.
PORTABLE_CHECK := testcases/smallpt.txt --spp 4 --width 64 --height 48 --seed 1 --quiet
test-portable: portable build
	@command -v qemu-x86_64 >/dev/null || \
		(apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq qemu-user)
	mkdir -p output/portable
	$(BIN) render $(PORTABLE_CHECK) -o output/portable/default_build.pfm
	qemu-x86_64 -cpu Nehalem $(PORTABLE) render $(PORTABLE_CHECK) -o output/portable/nehalem.pfm
	cmp output/portable/default_build.pfm output/portable/nehalem.pfm
	@echo "test-portable: the portable binary renders on a CPU without AVX, the same image to the byte"

lint:
	$(CARGO) fmt --check
	$(CARGO) clippy --all-targets -- -D warnings

bench:
	$(CARGO) bench --bench throughput

# Our BVH against obvhs and Embree 3 on the same incoherent rays through the
# 871k-triangle dragon, one thread (examples/bench_peers.rs; not part of
# `make test`). Installs Debian's libembree-dev when libembree3 is missing.
# make bench-peers [PEER_RAYS=300000] [PEER_ROUNDS=3]
PEER_RAYS ?= 300000
PEER_ROUNDS ?= 3
bench-peers:
	@ldconfig -p | grep -q libembree3 || \
		(apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq libembree-dev)
	$(CARGO) run --release --features peers --example bench_peers -- \
		../shared/reference/meshes/dragon_vrip.obj $(PEER_RAYS) $(PEER_ROUNDS)

# Error against time for one scene: make converge SCENE=... [SPP=256]
converge: build
	$(BIN) converge $(SCENE) --max-spp $(SPP)

# How alike our renders look to the images the coursework renderers wrote
# for the same scenes: the `ok` pairs of ../shared/reference/pairs.tsv (the
# repositories' own renders) and of ../shared/reference/oracle-pairs.tsv
# (renders made by building the renderers' own code), at 160 px wide and
# 64 spp, one after another (about 4 minutes on 2 cores), into
# output/lookalike/ (index.html with ours, theirs and their difference per
# pair, lookalike.csv, images/), summed up file by file.
PAIRS ?= ../shared/reference/pairs.tsv ../shared/reference/oracle-pairs.tsv
lookalike: build
	$(BIN) lookalike $(PAIRS) --only ok --out output/lookalike

# Cross-check against Mitsuba 3 (installs mitsuba from PyPI into a local venv;
# not part of `make test`). VARIANT=llvm_ad_rgb needs Debian's libllvm19.
VENV := .venv-crosscheck
VARIANT ?= scalar_rgb
crosscheck: build
	python3 -m venv $(VENV)
	$(VENV)/bin/pip install -q mitsuba numpy
	$(VENV)/bin/python scripts/crosscheck.py --variant $(VARIANT)

# The microfacet lobes against Mitsuba's roughconductor and roughdielectric
# (GGX, same alpha), with the exact Fresnel equations of the physical look.
crosscheck-glossy: build
	python3 -m venv $(VENV)
	$(VENV)/bin/pip install -q mitsuba numpy
	$(VENV)/bin/python scripts/crosscheck.py --variant $(VARIANT) --look physical \
		--scene testcases/crosscheck_glossy.txt --spp 256 --reference-spp 4096 \
		--tolerance 0.01 --out output/crosscheck_glossy

# Participating media against Mitsuba's volpath (homogeneous media, HG phase
# function), deep paths so that the two depth conventions do not matter;
# MEDIA_SCENE=testcases/crosscheck_fog.txt for a scene-wide medium.
MEDIA_SCENE ?= testcases/crosscheck_media.txt
crosscheck-media: build
	python3 -m venv $(VENV)
	$(VENV)/bin/pip install -q mitsuba numpy
	$(VENV)/bin/python scripts/crosscheck.py --variant $(VARIANT) --look physical \
		--scene $(MEDIA_SCENE) --max-depth 32 --spp 256 --reference-spp 2048 \
		--width 128 --height 96 --tolerance 0.01 --out output/$(basename $(notdir $(MEDIA_SCENE)))

# Dispersion against Mitsuba 3, whose dielectric has one index: Mitsuba
# renders testcases/crosscheck_dispersion.txt's glass at fixed indices and
# scripts/crosscheck_dispersion.py composes them: one channel from each of
# three renders for per-channel indices (--dispersion R,G,B), and for
# Cauchy's index 17 indices integrated with our sensor's weights
# (examples/spectral_sensor.rs). About 15 minutes on 2 cores.
crosscheck-dispersion: build
	python3 -m venv $(VENV)
	$(VENV)/bin/pip install -q mitsuba numpy
	$(CARGO) build --release --example spectral_sensor
	$(VENV)/bin/python scripts/crosscheck_dispersion.py --variant $(VARIANT) --mode channels \
		--reference-spp 1024
	$(VENV)/bin/python scripts/crosscheck_dispersion.py --variant $(VARIANT) --mode cauchy \
		--reference-spp 256

# Mitsuba's error-against-time curve (same CSV as `make converge`), into
# output/curves/<scene>/ (venv from `make crosscheck`):
# make mitsuba-converge SCENE=... [VARIANT=llvm_ad_rgb]
mitsuba-converge:
	$(VENV)/bin/python scripts/mitsuba_converge.py --scene $(SCENE) --variant $(VARIANT)

# The side-by-side pictures of docs/gallery/ (ours next to the coursework
# renderer's own image), with numpy and Pillow in the cross-check venv.
gallery: build
	python3 -m venv $(VENV)
	$(VENV)/bin/pip install -q numpy pillow
	$(VENV)/bin/python scripts/gallery.py

# Coverage-guided fuzzing with cargo-fuzz (docs/guide/development.md, "Fuzzing"; needs
# `cargo install cargo-fuzz` and a nightly toolchain): each target of
# fuzz/fuzz_targets runs FUZZ_SECONDS (scene_text SCENE_TEXT_SECONDS) in
# turn, one libFuzzer job that keeps going past crashes, timeouts and OOMs
# (saved in fuzz/artifacts/<target>/), then its execution count is printed.
# Seeds are copied at run time from testcases/, mesh/, texture/ and
# ../shared/ into fuzz/seeds/ (git-ignored, like fuzz/corpus/).
FUZZ_SECONDS ?= 300
SCENE_TEXT_SECONDS ?= $(FUZZ_SECONDS)
FUZZ_TARGETS ?= scene_text obj texture pfm
FUZZ_SANITIZER ?= none
FUZZ_FLAGS := -rss_limit_mb=1024 -timeout=10 -max_len=1048576
FUZZ_DIR := $(CURDIR)/fuzz
# Run by absolute path: libFuzzer's -fork restarts the binary by argv[0],
# and each target changes its working directory into its sandbox.
FUZZ_BIN := $(FUZZ_DIR)/target/$(shell rustc -vV | sed -n 's/^host: //p')/release
SHARED ?= ../shared
# Copies the files that `find` lists under name = their hash (no clashes).
seed = mkdir -p $(FUZZ_DIR)/seeds/$(1) && find $(2) -type f -size -1024k $(3) 2>/dev/null | \
	while read -r f; do cp "$$f" "$(FUZZ_DIR)/seeds/$(1)/$$(sha1sum < "$$f" | cut -c1-40)"; done

fuzz-seeds: build
	rm -rf $(FUZZ_DIR)/seeds
	$(call seed,scene_text,testcases $(SHARED),-name '*.txt')
	$(call seed,obj,mesh $(SHARED),\( -name '*.obj' -o -name '*.mtl' \))
	$(call seed,texture,texture $(SHARED),-size -300k \( -iname '*.bmp' -o -iname '*.png' -o -iname '*.jpg' -o -iname '*.tga' \))
	$(call seed,pfm,$(SHARED),-size -100k \( -iname '*.pfm' -o -iname '*.exr' -o -iname '*.bmp' -o -iname '*.png' \))
	for format in pfm exr; do $(BIN) render testcases/smallpt.txt --width 8 --height 6 --spp 1 \
		--quiet -o $(FUZZ_DIR)/seeds/pfm/smallpt.$$format > /dev/null; done
	rm -f $(FUZZ_DIR)/seeds/pfm/*.json

fuzz: fuzz-seeds
	cd $(FUZZ_DIR) && $(CARGO) +nightly fuzz build -s $(FUZZ_SANITIZER)
	mkdir -p $(FUZZ_DIR)/logs
	for target in $(FUZZ_TARGETS); do \
		seconds=$(FUZZ_SECONDS); [ $$target = scene_text ] && seconds=$(SCENE_TEXT_SECONDS); \
		mkdir -p $(FUZZ_DIR)/corpus/$$target $(FUZZ_DIR)/artifacts/$$target; \
		$(FUZZ_BIN)/$$target $(FUZZ_DIR)/corpus/$$target $(FUZZ_DIR)/seeds/$$target \
			-max_total_time=$$seconds $(FUZZ_FLAGS) -fork=1 \
			-ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
			-artifact_prefix=$(FUZZ_DIR)/artifacts/$$target/ \
			> $(FUZZ_DIR)/logs/$$target.log 2>&1; \
		runs=$$(grep -oE '^#[0-9]+' $(FUZZ_DIR)/logs/$$target.log | tail -n 1 | tr -d '#'); \
		found=$$(ls $(FUZZ_DIR)/artifacts/$$target | wc -l); \
		echo "$$target: $${runs:-0} executions in $$seconds s ($$(( $${runs:-0} / $$seconds )) exec/s), $$found files in fuzz/artifacts/$$target"; \
	done

# A distributed render through Slurm on this machine (not part of `make
# test`; needs root): installs Debian's slurmctld, slurmd and munge if
# missing, starts a one-node cluster under output/farm-test/, renders SCENE
# at SPP as an array of TASKS tasks (default 4, at WIDTH x HEIGHT, default
# 160x120) and checks the merged image against a one-process render byte
# for byte (scripts/farm/farm-test.sh).
farm-test: build
	SCENE=$(SCENE) SPP=$(SPP) scripts/farm/farm-test.sh

clean:
	$(CARGO) clean
	rm -rf output
