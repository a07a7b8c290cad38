#!/usr/bin/env bash
# The compact writer's exactness check (tests/brep/compact_exactness.hpp) on the corpus files too slow
# for ctest (faces of hundreds of knots: the area to 1e-7 takes minutes). Usage, after a build:
#   bench/compact_exactness.sh [BUILD_DIR]
set -euo pipefail
build=${1:-$(dirname "$0")/../build}
exec "$build/tests/brep/compact_exactness_long"
