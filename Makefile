# Entry points of the project. `make render` and `make test` are the two
# set-up commands of a fresh machine (see README.md).

CARGO ?= cargo
SCENE ?= testcases/smallpt.txt
SPP ?= 64
BIN := target/release/pathtracer

.PHONY: build render test lint bench clean

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

clean:
	$(CARGO) clean
	rm -rf output
