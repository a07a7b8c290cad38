#!/usr/bin/env bash
# make_scene_graph_files.sh CADNURBS CORPUS_VRML_DIR OUT_DIR FILE...
# Copies each corpus FILE into OUT_DIR as original-FILE and converts it with `cadnurbs convert` to
# .x3dv, .x3d and .wrl beside it (the whole scene graph kept: VRML/X3D to VRML/X3D), for the X_ITE
# comparisons of tests/viewers/CMakeLists.txt. Fails on the first conversion that fails.
set -euo pipefail
[ $# -ge 4 ] || { echo "usage: make_scene_graph_files.sh CADNURBS CORPUS_VRML_DIR OUT_DIR FILE..." >&2; exit 2; }
cadnurbs=$1 corpus=$2 out=$3
shift 3
mkdir -p "$out"
for file in "$@"; do
  cp "$corpus/$file" "$out/original-$file"
  stem=${file%.*}
  for ext in x3dv x3d wrl; do
    rm -f "$out/$stem.$ext"
    "$cadnurbs" convert "$corpus/$file" -o "$out/$stem.$ext" > /dev/null
  done
done
