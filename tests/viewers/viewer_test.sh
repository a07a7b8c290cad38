#!/usr/bin/env bash
# Real-viewer test: renders a NURBS file and a reference mesh file with the same viewer and
# compares their silhouettes.
#
#   viewer_test.sh VIEWER NURBS_FILE MESH_FILE MAX_DIFF
#
# VIEWER is xite (X_ITE in headless Chromium, render_xite.mjs) or view3dscene
# (render_view3dscene.sh). Both files are rendered at 400x300 from their own Viewpoint
# (they should carry the same one), then compare_images.mjs thresholds each picture into
# foreground / background and prints the fraction of pixels whose silhouettes differ
# ("diff") and the silhouettes' intersection over union ("iou").
# Fails (exit 1) when a render fails, when either picture is blank (foreground below 1% of
# the pixels: "blank image"), or when diff > MAX_DIFF ("silhouette differs"). Exit 2 on
# bad arguments.
# Pictures go to $VIEWER_TEST_OUT (default ./viewer-out), named after the viewer and the
# NURBS file, plus a side-by-side diff picture (masks: black both, red only NURBS, blue
# only mesh). For VRML97 files, X_ITE is served formats/vrml/protos next to the file, so
# EXTERNPROTO "cadnurbs-nurbs-protos.wrl#..." resolves to the project's PROTOs.
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
if [ $# -ne 4 ]; then
  echo "usage: viewer_test.sh xite|view3dscene NURBS_FILE MESH_FILE MAX_DIFF" >&2
  exit 2
fi
viewer=$1 nurbs=$2 mesh=$3 max_diff=$4
case "$viewer" in xite|view3dscene) ;; *) echo "viewer_test: unknown viewer '$viewer' (xite or view3dscene)" >&2; exit 2 ;; esac
for f in "$nurbs" "$mesh"; do [ -f "$f" ] || { echo "viewer_test: no such file: $f" >&2; exit 2; }; done
[[ "$max_diff" =~ ^[0-9]*\.?[0-9]+([eE][-+]?[0-9]+)?$ ]] || { echo "viewer_test: MAX_DIFF must be a number: $max_diff" >&2; exit 2; }
command -v node >/dev/null || { echo "viewer_test: node not installed (scripts/setup.sh installs it)" >&2; exit 2; }
[ -d "$here/node_modules/pngjs" ] || { echo "viewer_test: npm packages missing: run 'npm ci' in $here (scripts/setup.sh does)" >&2; exit 2; }

width=400 height=300
out_dir=${VIEWER_TEST_OUT:-$PWD/viewer-out}
mkdir -p "$out_dir"
# Unique per (viewer, NURBS file path): tests may run in parallel.
tag="$viewer-$(basename "$nurbs")-$(printf '%s' "$(cd "$(dirname "$nurbs")" && pwd)/$(basename "$nurbs")" | cksum | cut -d' ' -f1)"
nurbs_png="$out_dir/$tag.nurbs.png"
mesh_png="$out_dir/$tag.mesh.png"
diff_png="$out_dir/$tag.diff.png"

render() { # file png
  local start end status=0
  start=$(date +%s%N)
  if [ "$viewer" = xite ]; then
    node "$here/render_xite.mjs" "$1" "$2" --width "$width" --height "$height" || status=$?
  else
    bash "$here/render_view3dscene.sh" "$1" "$2" "$width" "$height" || status=$?
  fi
  end=$(date +%s%N)
  if [ "$status" -ne 0 ]; then
    echo "viewer_test: FAIL: $viewer could not render $1 (exit $status)" >&2
    exit 1
  fi
  local ms=$(( (end - start) / 1000000 ))
  printf 'viewer_test: %s rendered %s in %d.%02d s -> %s\n' "$viewer" "$1" $((ms / 1000)) $((ms % 1000 / 10)) "$2"
}

render "$nurbs" "$nurbs_png"
render "$mesh" "$mesh_png"

status=0
err_file=$(mktemp "${TMPDIR:-/tmp}/viewer_test.XXXXXX")
trap 'rm -f "$err_file"' EXIT
result=$(node "$here/compare_images.mjs" "$nurbs_png" "$mesh_png" --max-diff "$max_diff" --min-foreground 0.01 \
           --diff-image "$diff_png" 2>"$err_file") || status=$?
echo "viewer_test: $viewer $(basename "$nurbs") vs $(basename "$mesh"): $result (max diff $max_diff)"
if [ "$status" -ne 0 ]; then
  reason=$(cat "$err_file")
  echo "viewer_test: FAIL: ${reason#compare_images: } -- see $diff_png" >&2
  exit 1
fi
echo "viewer_test: PASS"
