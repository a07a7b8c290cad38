#!/usr/bin/env bash
# setup.sh [demo]: installs what cadnurbs needs on Debian 12, skipping what is already there. With
# `demo`, only what building and running the cadnurbs command needs (what `make demo` uses); without,
# the tests' tools too (viewers, Chromium, clang for the fuzz targets, Emscripten and Debian's zlib source
# for the browser module, Slurm, the npm test drivers).
# Run as root (or with sudo available). Idempotent.
set -euo pipefail

here=$(cd "$(dirname "$0")/.." && pwd)
scope=${1:-all}
case "$scope" in
  demo | all) ;;
  *) echo "setup.sh: unknown scope '$scope' (demo, or nothing for everything)" >&2; exit 2 ;;
esac

debian_packages=(
  build-essential cmake pkg-config git
  libeigen3-dev zlib1g-dev libpng-dev
  libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev
  libocct-data-exchange-dev libocct-ocaf-dev libocct-visualization-dev
  libcgal-dev libopenmesh-dev libdraco-dev libmeshoptimizer-dev libtinygltf-dev nlohmann-json3-dev libtbb-dev
  libosd-dev
)
if [ "$scope" = all ]; then
  debian_packages+=(
    libgtest-dev libgmock-dev libbenchmark-dev
    view3dscene xvfb xauth chromium fonts-dejavu-core
    clang libclang-rt-14-dev
    emscripten curl bzip2
    python3
    slurm-wlm munge
  )
fi

# node/npm may come from elsewhere than Debian; the packages only when the commands are missing.
if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
  debian_packages+=(nodejs npm)
fi
"$here/scripts/install-debian-packages.sh" setup "${debian_packages[@]}"

# npm_ci FOLDER PACKAGE...: `npm ci` in FOLDER (relative to the project) unless each PACKAGE is installed
# there and its package-lock.json is no newer than what npm installed from it.
npm_ci() {
  local dir="$here/$1" package
  shift
  [ -f "$dir/package-lock.json" ] || return 0
  for package in "$@"; do
    if [ ! -d "$dir/node_modules/$package" ] || [ "$dir/package-lock.json" -nt "$dir/node_modules/.package-lock.json" ]; then
      echo "setup: npm ci in ${dir#"$here"/}"
      (cd "$dir" && npm ci --no-audit --no-fund --loglevel=error)
      return 0
    fi
  done
  echo "setup: npm packages present in ${dir#"$here"/}"
}

if [ "$scope" = all ]; then
  npm_ci tests/viewers x_ite playwright-core      # the viewer test drivers
  npm_ci tests/3dm/generate rhino3dm              # the .3dm test-file generator, run at test time
  # The viewer (three.js) and its bundler, bundled into the page `convert X -o X.html` writes (web/CMakeLists.txt).
  npm_ci web/viewer three esbuild
fi
# What the HTML report inlines (Chart.js, X_ITE), embedded into the library at build time
# (report/html/CMakeLists.txt); the demo builds it too.
npm_ci report/html chart.js x_ite

# Debian's zlib source, which the browser module (web/module) compiles with Emscripten.
if [ "$scope" = all ]; then
  "$here/scripts/fetch-zlib-source.sh" >/dev/null
fi
