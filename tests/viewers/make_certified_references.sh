#!/usr/bin/env bash
# make_certified_references.sh CADNURBS CORPUS_VRML_DIR OUT_DIR DEVIATION FILE...
# For each corpus FILE, writes OUT_DIR/certified-STEM.x3dv: `cadnurbs convert FILE --mesh --deviation
# DEVIATION` (every NURBS surface as triangles no farther than DEVIATION from the exact surface, as
# convert certifies), shown from FILE's own view: the mesh writer's computed Viewpoint is replaced by the
# first Viewpoint of OUT_DIR/STEM.x3dv (FILE converted with its scene graph kept, which
# make_scene_graph_files.sh writes first), or removed when FILE has none (X_ITE's default view then, as
# for FILE). Fails on the first conversion that fails or does not certify the deviation.
set -euo pipefail
[ $# -ge 5 ] || { echo "usage: make_certified_references.sh CADNURBS CORPUS_VRML_DIR OUT_DIR DEVIATION FILE..." >&2; exit 2; }
cadnurbs=$1 corpus=$2 out=$3 deviation=$4
shift 4
mkdir -p "$out"
for file in "$@"; do
  stem=${file%.*}
  [ -f "$out/$stem.x3dv" ] || { echo "make_certified_references: $out/$stem.x3dv missing (make_scene_graph_files.sh first)" >&2; exit 1; }
  mesh="$out/certified-$stem.mesh.x3dv"
  report=$("$cadnurbs" convert "$corpus/$file" -o "$mesh" --mesh --deviation "$deviation" 2>&1)
  grep -q ' 0 uncertified triangles' <<< "$report" || { echo "make_certified_references: $file: not certified: $report" >&2; exit 1; }
  viewpoint=$(grep -o -m1 '^Viewpoint {[^}]*}' "$out/$stem.x3dv" || true)
  if [ -n "$viewpoint" ]; then
    sed "s/^Viewpoint {[^}]*}/$viewpoint/" "$mesh" > "$out/certified-$stem.x3dv"
  else
    sed '/^Viewpoint {[^}]*}$/d' "$mesh" > "$out/certified-$stem.x3dv"
  fi
  rm -f "$mesh"
  grep -o ' [0-9]* meshes ([^)]*)' <<< "$report" | sed "s|^|make_certified_references: certified-$stem.x3dv:|"
done
