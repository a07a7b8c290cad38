#!/usr/bin/env bash
# Library viewer check: converts real parts and looks at every output with both viewers.
#
#   library_viewer_check.sh [--cadnurbs EXE] [--deviation D] [--background R,G,B] [--out DIR]
#                           [--max-diff F] PART.step...
#
# For each part: cadnurbs convert to .x3dv, .wrl, .x3dvz and .wrz (a format the binary refuses is
# skipped with a note), and our reference mesh (convert --mesh --deviation D, .x3dv and .wrl; the
# converter writes the same Viewpoint for the same part). Then
#   X_ITE (render_xite.mjs --time --background): load time of each file (seconds from loadURL to the
#     world loaded, PROTO Scripts included), the .wrl / .x3dv ratio, and the silhouette diff of each
#     NURBS file against the mesh (compare_images.mjs: fraction of all pixels in exactly one
#     silhouette; the project's target is <= 0.0005 with no cracks);
#   view3dscene (render_view3dscene.sh on a copy with the same Background inserted): load errors,
#     and whether it drew every surface: its foreground against its own rendering of the mesh
#     ("drawn" = NURBS foreground / mesh foreground; view3dscene ignores trimming, so a complete
#     drawing is >= ~1, a missing face shows as less; VRML97 TrimmedSurface it cannot draw at all).
# Prints one table line per part and file, and writes the pictures, the logs and table.txt to DIR
# (default ./library-viewer-check). Slow (two Chromium starts per file): not part of ctest.
# Exit status 0 when every file was rendered by X_ITE, 1 otherwise; 2 on bad arguments.
set -uo pipefail

here=$(cd "$(dirname "$0")" && pwd)
exe=${CADNURBS:-$here/../../build/converters/cadnurbs}
deviation=0.01
background=0.2,0.3,0.6
out=$PWD/library-viewer-check
max_diff=0.0005
parts=()
while [ $# -gt 0 ]; do
  case "$1" in
    --cadnurbs) exe=$2; shift 2 ;;
    --deviation) deviation=$2; shift 2 ;;
    --background) background=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --max-diff) max_diff=$2; shift 2 ;;
    -h|--help) sed -n '2,22p' "$0"; exit 0 ;;
    -*) echo "library_viewer_check: unknown option $1" >&2; exit 2 ;;
    *) parts+=("$1"); shift ;;
  esac
done
[ ${#parts[@]} -gt 0 ] || { echo "usage: library_viewer_check.sh [options] PART.step..." >&2; exit 2; }
[ -x "$exe" ] || { echo "library_viewer_check: no cadnurbs binary at $exe (--cadnurbs)" >&2; exit 2; }
mkdir -p "$out" || exit 2
out=$(cd "$out" && pwd)
table=$out/table.txt
status=0

# R,G,B in 0..1 (or 0..255) as VRML numbers in 0..1
bg_vrml=$(node -e 'const c=process.argv[1].split(",").map(Number);const s=c.some(v=>v>1)?255:1;console.log(c.map(v=>(v/s).toFixed(4)).join(" "))' "$background")

# copy of a VRML/X3D file (gunzipped) with a Background bound first, next to the original so that
# relative EXTERNPROTO URLs still resolve
with_background() { # in out
  local text
  if [ "$(head -c 2 "$1" | od -An -tx1 | tr -d ' ')" = 1f8b ]; then text=$(gzip -dc "$1"); else text=$(cat "$1"); fi
  printf '%s\n' "$text" | awk -v bg="Background { skyColor [ $bg_vrml ] }" '
    !done && NR > 1 && !/^(PROFILE|COMPONENT|META|UNIT|#)/ { print bg; done = 1 }
    { print }
    END { if (!done) print bg }' >"$2"
}

fg() { node -e 'const r=JSON.parse(process.argv[1]);console.log(r.foreground_a)' "$1" 2>/dev/null; }

printf '%-42s %-6s %8s %7s %9s %-9s %s\n' part file "xite s" "wrl/x3dv" "xite diff" "v3d drawn" notes | tee "$table"
for step in "${parts[@]}"; do
  name=$(basename "$step"); name=${name%.*}
  dir=$out/$name
  mkdir -p "$dir"
  notes_part=""
  for ext in x3dv wrl x3dvz wrz; do
    if ! "$exe" convert "$step" -o "$dir/$name.$ext" >"$dir/convert-$ext.log" 2>&1; then
      rm -f "$dir/$name.$ext"
      notes_part+=" $ext refused ($(tail -1 "$dir/convert-$ext.log" | cut -c1-60))"
    fi
  done
  for ext in x3dv wrl; do
    "$exe" convert "$step" --mesh --deviation "$deviation" -o "$dir/$name-mesh.$ext" >"$dir/convert-mesh-$ext.log" 2>&1 \
      || notes_part+=" mesh.$ext refused"
  done
  # the PROTO library the converter writes next to .wrl: use the source tree's (render_xite's
  # --protos default) so the check sees the PROTOs under test
  rm -f "$dir/cadnurbs-nurbs-protos.wrl"
  # reference pictures
  mesh=$dir/$name-mesh.x3dv
  node "$here/render_xite.mjs" "$mesh" "$dir/xite-mesh.png" --background "$background" --time --timeout 300 \
    >"$dir/xite-mesh.time" 2>"$dir/xite-mesh.err" || notes_part+=" xite mesh failed"
  with_background "$mesh" "$dir/$name-mesh.bg.x3dv"
  bash "$here/render_view3dscene.sh" "$dir/$name-mesh.bg.x3dv" "$dir/v3d-mesh.png" 400 300 2>"$dir/v3d-mesh.err" \
    || notes_part+=" v3d mesh failed"
  x3dv_time=""
  for ext in x3dv wrl x3dvz wrz; do
    file=$dir/$name.$ext
    [ -f "$file" ] || continue
    notes=""
    # X_ITE
    xt=""; xd=""
    if node "$here/render_xite.mjs" "$file" "$dir/xite-$ext.png" --background "$background" --time --timeout 300 \
         >"$dir/xite-$ext.time" 2>"$dir/xite-$ext.err"; then
      xt=$(sed -n 's/render_xite: time load \([0-9.]*\) .*/\1/p' "$dir/xite-$ext.time")
      xd=$(node "$here/compare_images.mjs" "$dir/xite-$ext.png" "$dir/xite-mesh.png" --diff-image "$dir/xite-$ext.diff.png" \
             | node -e 'let s="";process.stdin.on("data",d=>s+=d).on("end",()=>console.log(JSON.parse(s).diff))')
      node -e 'process.exit(Number(process.argv[1]) > Number(process.argv[2]) ? 1 : 0)' "$xd" "$max_diff" || notes+=" diff>$max_diff"
    else
      status=1
      notes+=" xite: $(tail -c 120 "$dir/xite-$ext.err" | tr '\n' ' ')"
    fi
    [ "$ext" = x3dv ] && x3dv_time=$xt
    ratio=""
    if [ "$ext" != x3dv ] && [ "$ext" != x3dvz ] && [ -n "$xt" ] && [ -n "$x3dv_time" ]; then
      ratio=$(node -e 'console.log((process.argv[1]/process.argv[2]).toFixed(2))' "$xt" "$x3dv_time")
    fi
    # view3dscene on a copy with the Background
    case "$ext" in x3dv|x3dvz) bgfile=$dir/$name.$ext.bg.x3dv ;; *) bgfile=$dir/$name.$ext.bg.wrl ;; esac
    with_background "$file" "$bgfile"
    drawn=""
    if bash "$here/render_view3dscene.sh" "$bgfile" "$dir/v3d-$ext.png" 400 300 2>"$dir/v3d-$ext.err"; then
      a=$(fg "$(node "$here/compare_images.mjs" "$dir/v3d-$ext.png" "$dir/v3d-mesh.png" 2>/dev/null)")
      m=$(fg "$(node "$here/compare_images.mjs" "$dir/v3d-mesh.png" "$dir/v3d-mesh.png" 2>/dev/null)")
      drawn=$(node -e 'const a=+process.argv[1],m=+process.argv[2];console.log(m>0?(a/m).toFixed(2):"-")' "${a:-0}" "${m:-0}")
    else
      drawn=error
      notes+=" v3d: $(grep -m1 -o 'load error: .\{0,80\}\|failed.\{0,80\}' "$dir/v3d-$ext.err")"
    fi
    printf '%-42s %-6s %8s %7s %9s %-9s %s\n' "$name" "$ext" "${xt:--}" "${ratio:--}" "${xd:--}" "$drawn" "${notes# }" | tee -a "$table"
  done
  [ -n "$notes_part" ] && printf '%-42s %s\n' "$name" "note:$notes_part" | tee -a "$table"
done
exit $status
