#!/usr/bin/env bash
# Renders a VRML/X3D file with view3dscene (Castle Game Engine, Debian package) in a
# virtual X server and saves a screenshot of the scene from the file's own first Viewpoint.
#
#   render_view3dscene.sh IN OUT.png [WIDTH HEIGHT]     (default 400 300)
#
# Runs `view3dscene IN --screenshot 0 OUT.png --geometry WIDTHxHEIGHT` under
# `xvfb-run -a -s "-screen 0 1024x768x24"`, with HOME pointing at a scratch folder so the
# viewer's configuration never touches the user's. view3dscene writes its messages to
# $HOME/.config/view3dscene/view3dscene.log, not to the terminal: its warnings are copied
# to stderr, and these fail the run (exit 1) as load errors: a parse error ("Error when
# reading", view3dscene then skips the rest of the file), an unknown node type, an
# EXTERNPROTO that cannot be loaded, a node not allowed where it stands.
# A file that declares its NURBS nodes by EXTERNPROTO "cadnurbs-nurbs-protos.wrl#..." with no
# such file next to it is rendered from a scratch copy beside the project's PROTO library
# (formats/vrml/protos, or $CADNURBS_PROTOS), as render_xite.mjs serves it.
# Exit status: 0 with OUT.png written; 1 with a one-line error on stderr; 2 on bad
# arguments or a missing tool. The background is view3dscene's (dark grey without a
# Background node); compare_images.mjs finds it by itself.
set -euo pipefail

if [ $# -ne 2 ] && [ $# -ne 4 ]; then
  echo "usage: render_view3dscene.sh IN OUT.png [WIDTH HEIGHT]" >&2
  exit 2
fi
in=$1 out=$2 width=${3:-400} height=${4:-300}
[ -f "$in" ] || { echo "render_view3dscene: no such file: $in" >&2; exit 2; }
for tool in view3dscene xvfb-run; do
  command -v "$tool" >/dev/null || { echo "render_view3dscene: $tool not installed (scripts/setup.sh installs it)" >&2; exit 2; }
done

out_dir=$(cd "$(dirname "$out")" 2>/dev/null && pwd) || { echo "render_view3dscene: no folder for $out" >&2; exit 2; }
out_abs="$out_dir/$(basename "$out")"
scratch=$(mktemp -d "${TMPDIR:-/tmp}/render_view3dscene.XXXXXX")
trap 'rm -rf "$scratch"' EXIT
rm -f "$out_abs"
log="$scratch/home/.config/view3dscene/view3dscene.log"
protos_dir=${CADNURBS_PROTOS:-$(cd "$(dirname "$0")/../../formats/vrml/protos" && pwd)}
if grep -q "cadnurbs-nurbs-protos.wrl" "$in" 2>/dev/null && [ ! -f "$(dirname "$in")/cadnurbs-nurbs-protos.wrl" ] \
   && [ -f "$protos_dir/cadnurbs-nurbs-protos.wrl" ]; then
  mkdir -p "$scratch/scene"
  cp "$in" "$scratch/scene/"
  cp "$protos_dir/cadnurbs-nurbs-protos.wrl" "$scratch/scene/"
  in="$scratch/scene/$(basename "$in")"
fi

# xvfb-run -a can lose a race for a display number against another xvfb-run started at
# the same moment; one retry covers it.
status=0
for _ in 1 2; do
  rm -rf "${scratch:?}/home"; mkdir -p "$scratch/home"
  status=0
  HOME="$scratch/home" timeout 120 xvfb-run -a -s "-screen 0 1024x768x24" \
    view3dscene "$in" --hide-extras --no-sound --geometry "${width}x${height}" \
    --screenshot 0 "$out_abs" >"$scratch/stdout" 2>&1 || status=$?
  [ "$status" -eq 0 ] && [ -s "$out_abs" ] && break
  grep -q -i "xvfb failed\|server already active\|cannot open display" "$scratch/stdout" || break
  sleep 1
done

warnings=""
if [ -f "$log" ]; then
  warnings=$(grep "^Warning: \(VRML/X3D\|X3D\)" "$log" || true)
fi
if [ -n "$warnings" ]; then
  # head closes the pipe early when there are many warnings: not an error
  { printf '%s\n' "$warnings" | head -n 20 | sed 's/^/render_view3dscene: /' >&2; } || true
fi

if [ "$status" -ne 0 ] || [ ! -s "$out_abs" ]; then
  msg=$(grep -i -m1 -E "error|exception|fatal|segmentation" "$scratch/stdout" "$log" 2>/dev/null | sed 's/^[^:]*://' || true)
  [ "$status" -eq 139 ] && msg="view3dscene crashed (segmentation fault)${msg:+: $msg}"
  echo "render_view3dscene: $in: failed (exit $status): ${msg:-no screenshot written}" >&2
  rm -f "$out_abs"
  exit 1
fi

fatal=$(printf '%s\n' "$warnings" | grep -m1 -E "Error when reading|Unknown node of type|cannot be loaded|is not allowed in the field" || true)
if [ -n "$fatal" ]; then
  echo "render_view3dscene: $in: load error: ${fatal#Warning: }" >&2
  rm -f "$out_abs"
  exit 1
fi
exit 0
