#!/usr/bin/env bash
# Installs what the benches need beyond scripts/setup.sh, on Debian 12, skipping what is already there:
# FreeCAD (freecadcmd, for bench/library_sizes.py's side-by-side), python3 and gzip (the driver),
# assimp (bench_normals's peer; OpenMesh comes with setup.sh).
# Run as root (or with sudo available). Idempotent. CI does not run the benches and does not need this.
set -euo pipefail

debian_packages=(freecad python3 gzip libassimp-dev)

"$(dirname "$0")/install-debian-packages.sh" setup-bench "${debian_packages[@]}"
command -v freecadcmd >/dev/null || { echo "setup-bench: freecadcmd not found after installing freecad" >&2; exit 1; }
