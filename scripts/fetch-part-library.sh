#!/usr/bin/env bash
# Fetches the real part library the bench and the library tests use: Debian's kicad-packages3d 6.0.10
# (KiCad's 3D models, each part as STEP and as the mesh VRML KiCad ships), downloaded once with
# `apt-get download` (about 380 MB) into a cache outside the repository, never committed. Only the
# families below are unpacked (about 1,360 parts); the others are kept for independent checks, so the
# project is not tuned to them.
#
#   scripts/fetch-part-library.sh            # prints the library folder (FAMILY.3dshapes/ under it)
#   CADNURBS_CACHE=/some/dir scripts/fetch-part-library.sh
#
# Idempotent: a second run finds the unpacked families and only prints the folder.
set -euo pipefail

version=6.0.10-1
cache=${CADNURBS_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/cadnurbs}
library="$cache/kicad-packages3d-$version"
families=(
  Connector_PinHeader_2.54mm Package_DIP Package_DFN_QFN Package_QFP Package_BGA
  Resistor_THT Inductor_THT LED_THT Connector_Phoenix_MC
)

complete() {
  for f in "${families[@]}"; do [ -d "$library/$f.3dshapes" ] || return 1; done
  [ -f "$library/.complete" ]
}

if ! complete; then
  mkdir -p "$cache"
  deb="$cache/kicad-packages3d_${version}_all.deb"
  if [ ! -f "$deb" ]; then
    echo "fetch-part-library: downloading kicad-packages3d $version into $cache" >&2
    # apt-get download writes into the current folder; _apt may not be able to write the cache.
    (cd "$cache" && apt-get download "kicad-packages3d=$version" >&2)
  fi
  staging=$(mktemp -d "$cache/unpack.XXXXXX")
  trap 'rm -rf "$staging"' EXIT
  patterns=()
  for f in "${families[@]}"; do patterns+=("./usr/share/kicad/3dmodels/$f.3dshapes"); done
  dpkg-deb --fsys-tarfile "$deb" | tar -x -C "$staging" "${patterns[@]}"
  rm -rf "$library"
  mv "$staging/usr/share/kicad/3dmodels" "$library"
  date -u +%FT%TZ > "$library/.complete"
fi
echo "$library"
