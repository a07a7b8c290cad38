#!/usr/bin/env bash
# three.js test of a glTF binary: renders our own mesh (REFERENCE, an STL in millimetres, +Z up) and the
# .glb with render_glb.mjs in the same three orthographic views, framed by the reference's bounding box
# in both pictures, and compares the silhouettes with compare_images.mjs.
#
#   glb_viewer_test.sh REFERENCE.stl FILE.glb MAX_DIFF
#
# Fails (exit 1) when a render fails, when either picture is blank (foreground below 1 %: "blank
# image"), or when the fraction of pixels in exactly one silhouette exceeds MAX_DIFF ("silhouette
# differs"). Exit 2 on bad arguments. Pictures go to $VIEWER_TEST_OUT (default ./viewer-out).
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
if [ $# -ne 3 ]; then
  echo "usage: glb_viewer_test.sh REFERENCE.stl FILE.glb MAX_DIFF" >&2
  exit 2
fi
reference=$1 glb=$2 max_diff=$3
for f in "$reference" "$glb"; do [ -f "$f" ] || { echo "glb_viewer_test: no such file: $f" >&2; exit 2; }; done
[[ "$max_diff" =~ ^[0-9]*\.?[0-9]+([eE][-+]?[0-9]+)?$ ]] || { echo "glb_viewer_test: MAX_DIFF must be a number: $max_diff" >&2; exit 2; }
command -v node >/dev/null || { echo "glb_viewer_test: node not installed (scripts/setup.sh installs it)" >&2; exit 2; }
[ -d "$here/node_modules/three" ] || { echo "glb_viewer_test: npm packages missing: run 'npm ci' in $here (scripts/setup.sh does)" >&2; exit 2; }

out_dir=${VIEWER_TEST_OUT:-$PWD/viewer-out}
mkdir -p "$out_dir"
tag="three-$(basename "$glb" .glb)"
reference_png="$out_dir/$tag.reference.png" glb_png="$out_dir/$tag.png" diff_png="$out_dir/$tag.diff.png"

seen=$(node "$here/render_glb.mjs" "$reference" "$reference_png") || { echo "glb_viewer_test: FAIL: cannot render $reference" >&2; exit 1; }
echo "glb_viewer_test: reference $(basename "$reference"): $seen"
frame=$(printf '%s' "$seen" | node -e 'let s="";process.stdin.on("data",d=>s+=d).on("end",()=>console.log(JSON.parse(s).box.join(",")))')
seen=$(node "$here/render_glb.mjs" "$glb" "$glb_png" --frame "$frame") || { echo "glb_viewer_test: FAIL: three.js could not render $glb" >&2; exit 1; }
echo "glb_viewer_test: $(basename "$glb"): $seen"

status=0
err_file=$(mktemp "${TMPDIR:-/tmp}/glb_viewer_test.XXXXXX")
trap 'rm -f "$err_file"' EXIT
result=$(node "$here/compare_images.mjs" "$reference_png" "$glb_png" --max-diff "$max_diff" --min-foreground 0.01 \
           --diff-image "$diff_png" 2>"$err_file") || status=$?
echo "glb_viewer_test: $(basename "$glb") vs $(basename "$reference"): $result (max diff $max_diff)"
if [ "$status" -ne 0 ]; then
  echo "glb_viewer_test: FAIL: $(sed 's/^compare_images: //' "$err_file") -- see $diff_png" >&2
  exit 1
fi
echo "glb_viewer_test: PASS"
