#!/usr/bin/env bash
# Installs what the benches need beyond scripts/setup.sh, on Debian 12, skipping what is already there:
# FreeCAD (freecadcmd, for bench/library_sizes.py's side-by-side), python3 and gzip (the driver).
# Run as root (or with sudo available). Idempotent. CI does not run the benches and does not need this.
set -euo pipefail

debian_packages=(freecad python3 gzip)

sudo_if_needed() { if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi; }

missing=()
for p in "${debian_packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup-bench: installing ${missing[*]}"
  sudo_if_needed apt-get update -q
  sudo_if_needed env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}"
else
  echo "setup-bench: Debian packages present"
fi
command -v freecadcmd >/dev/null || { echo "setup-bench: freecadcmd not found after installing freecad" >&2; exit 1; }
