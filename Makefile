# Entry points of the project. `make render` and `make test` are the two
# set-up commands of a fresh machine (see README.md).

CARGO ?= cargo
SCENE ?= testcases/smallpt.txt
SPP ?= 64
BIN := target/release/pathtracer

.PHONY: build render test lint bench converge lookalike crosscheck crosscheck-glossy mitsuba-converge gallery farm-test clean

build:
	$(CARGO) build --release

render: build
	$(BIN) render $(SCENE) --spp $(SPP)

test:
	$(CARGO) test --release

lint:
	$(CARGO) fmt --check
	$(CARGO) clippy --all-targets -- -D warnings

bench:
	$(CARGO) bench --bench throughput

# Error against time for one scene: make converge SCENE=... [SPP=256]
converge: build
	$(BIN) converge $(SCENE) --max-spp $(SPP)

# How alike our renders look to the images the coursework renderers wrote
# for the same scenes: the `ok` pairs of ../shared/reference/pairs.tsv at
# 160 px wide and 64 spp, one after another (about 2.5 minutes on 2 cores),
# into output/lookalike/ (index.html, lookalike.csv, images/).
PAIRS ?= ../shared/reference/pairs.tsv
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
