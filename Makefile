# Thin wrapper (README.md): `make demo` installs, builds the cadnurbs command alone and runs the demo;
# `make test` builds everything and runs the fast tier of the tests (what CI runs); `make test-long` the
# long tier (tests/README.md says which tier holds what).
BUILD ?= build
JOBS ?= $(shell nproc)
CTEST = ctest --test-dir $(BUILD) --output-on-failure --timeout 900 -j $(JOBS)

.PHONY: setup configure build demo test test-long clean

setup:
	bash scripts/setup.sh

configure: setup
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCADNURBS_TESTS=ON

build: configure
	cmake --build $(BUILD) -j $(JOBS)

# The demo installs and configures only what the command needs; a build folder that already exists
# keeps its configuration (the tests stay on after `make test`, and `make test` turns them on).
demo:
	bash scripts/setup.sh demo
	test -f $(BUILD)/CMakeCache.txt || cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCADNURBS_TESTS=OFF
	cmake --build $(BUILD) -j $(JOBS) --target cadnurbs
	$(BUILD)/converters/cadnurbs demo -o $(BUILD)/demo

test: build
	$(CTEST) -L '^tier:fast$$'

test-long: build
	$(CTEST) -L '^tier:long$$'

clean:
	rm -rf $(BUILD)
