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
  libeigen3-dev zlib1g-dev
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

# Viewer test drivers (x_ite, playwright-core), pinned by package-lock.json.
viewer_dir="$here/tests/viewers"
if [ "$scope" = all ] && [ -f "$viewer_dir/package-lock.json" ]; then
  if [ ! -d "$viewer_dir/node_modules/x_ite" ] || [ ! -d "$viewer_dir/node_modules/playwright-core" ] \
     || [ "$viewer_dir/package-lock.json" -nt "$viewer_dir/node_modules/.package-lock.json" ]; then
    echo "setup: npm ci in tests/viewers"
    (cd "$viewer_dir" && npm ci --no-audit --no-fund --loglevel=error)
  else
    echo "setup: npm packages present"
  fi
fi

# The .3dm test-file generator (rhino3dm), pinned by package-lock.json; the 3dm tests run it at test time.
rhino3dm_dir="$here/tests/3dm/generate"
if [ "$scope" = all ] && [ -f "$rhino3dm_dir/package-lock.json" ]; then
  if [ ! -d "$rhino3dm_dir/node_modules/rhino3dm" ] \
     || [ "$rhino3dm_dir/package-lock.json" -nt "$rhino3dm_dir/node_modules/.package-lock.json" ]; then
    echo "setup: npm ci in tests/3dm/generate"
    (cd "$rhino3dm_dir" && npm ci --no-audit --no-fund --loglevel=error)
  else
    echo "setup: rhino3dm npm package present"
  fi
fi

# What the HTML report inlines (Chart.js, X_ITE), pinned by package-lock.json and embedded into the
# library at build time (report/html/CMakeLists.txt).
report_dir="$here/report/html"
if [ -f "$report_dir/package-lock.json" ]; then
  if [ ! -d "$report_dir/node_modules/chart.js" ] || [ ! -d "$report_dir/node_modules/x_ite" ] \
     || [ "$report_dir/package-lock.json" -nt "$report_dir/node_modules/.package-lock.json" ]; then
    echo "setup: npm ci in report/html"
    (cd "$report_dir" && npm ci --no-audit --no-fund --loglevel=error)
  else
    echo "setup: report npm packages present"
  fi
fi

# The viewer's npm packages (three.js, esbuild), pinned by package-lock.json, bundled into the page that
# `convert X -o X.html` writes (web/CMakeLists.txt).
viewer_npm="$here/web/viewer"
if [ "$scope" = all ]; then
  if [ ! -d "$viewer_npm/node_modules/three" ] || [ ! -d "$viewer_npm/node_modules/esbuild" ] \
     || [ "$viewer_npm/package-lock.json" -nt "$viewer_npm/node_modules/.package-lock.json" ]; then
    echo "setup: npm ci in web/viewer"
    (cd "$viewer_npm" && npm ci --no-audit --no-fund --loglevel=error)
  else
    echo "setup: viewer npm packages present"
  fi
fi

# Debian's zlib source, which the browser module (web/module) compiles with Emscripten.
if [ "$scope" = all ]; then
  "$here/scripts/fetch-zlib-source.sh" >/dev/null
fi
