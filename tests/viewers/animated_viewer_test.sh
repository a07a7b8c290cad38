#!/usr/bin/env bash
# Animated real-viewer test: renders two files with X_ITE at the same scene times on a clock that
# stands still between them (render_xite.mjs --times, virtual_clock.mjs) and compares the
# silhouettes at each time.
#
#   animated_viewer_test.sh [--route-loop] FILE REFERENCE MAX_DIFF T1,T2,... [ALLOW_MISSING]
#
# T1,T2,...: increasing scene times in seconds (time 0: every looping TimeSensor with startTime 0
# at the start of its cycle). ALLOW_MISSING: comma-separated file names both scenes may lack
# (render_xite --allow-missing), e.g. textures a corpus file names but does not ship.
# --route-loop: for a scene whose ROUTEs form a loop that flips the picture between two states in every
# frame (robot_opengl.x3dv: ProximitySensor1, a child of Transform8, routes the viewer's position and
# orientation in its own coordinates to Transform8's translation and rotation; with translation T it
# reports V - T, so the Transform alternates between 0 and V = (0 0 10) frame by frame). Which state a
# picture shows is the parity of the frames drawn since the load began, and the load's frame count is the
# wall clock's (X_ITE draws frames while fetching and parsing), not the file's content. So the reference is
# also drawn one frame later at each time (render_xite --next-frame) and FILE passes at a time when it is
# within MAX_DIFF of either state; the line of each time also gives the reference's two states' diff.
# Prints one line per time (compare_images' JSON) and "animated_viewer_test: max diff M at time T";
# fails (exit 1) when a render fails, when a picture is blank (foreground < 1%) or when the diff at
# any time exceeds MAX_DIFF. Exit 2 on bad arguments. Pictures in $VIEWER_TEST_OUT (default
# ./viewer-out): <tag>.file.t<i>.png, <tag>.reference.t<i>.png, <tag>.diff.t<i>.png.
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
route_loop=0
[ "${1:-}" = --route-loop ] && { route_loop=1; shift; }
if [ $# -lt 4 ] || [ $# -gt 5 ]; then
  echo "usage: animated_viewer_test.sh [--route-loop] FILE REFERENCE MAX_DIFF T1,T2,... [ALLOW_MISSING]" >&2
  exit 2
fi
file=$1 reference=$2 max_diff=$3 times=$4 allow=${5:-}
for f in "$file" "$reference"; do [ -f "$f" ] || { echo "animated_viewer_test: no such file: $f" >&2; exit 2; }; done
[[ "$max_diff" =~ ^[0-9]*\.?[0-9]+([eE][-+]?[0-9]+)?$ ]] || { echo "animated_viewer_test: MAX_DIFF must be a number: $max_diff" >&2; exit 2; }
[[ "$times" =~ ^[0-9.]+(,[0-9.]+)*$ ]] || { echo "animated_viewer_test: times must be T1,T2,...: $times" >&2; exit 2; }

out_dir=${VIEWER_TEST_OUT:-$PWD/viewer-out}
mkdir -p "$out_dir"
# Unique per file path: tests may run in parallel.
tag="anim-$(basename "$file")-$(printf '%s' "$(cd "$(dirname "$file")" && pwd)/$(basename "$file")" | cksum | cut -d' ' -f1)"

render() { # input png [render_xite option...]
  local args=("$1" "$2" --width 400 --height 300 --times "$times" --timeout 300 "${@:3}")
  [ -n "$allow" ] && args+=(--allow-missing "$allow")
  local start=$SECONDS
  node "$here/render_xite.mjs" "${args[@]}" || { echo "animated_viewer_test: FAIL: X_ITE could not render $1" >&2; exit 1; }
  echo "animated_viewer_test: rendered $1 at $times in $((SECONDS - start)) s"
}
render "$file" "$out_dir/$tag.file.png"
if [ "$route_loop" -eq 1 ]; then render "$reference" "$out_dir/$tag.reference.png" --next-frame
else render "$reference" "$out_dir/$tag.reference.png"; fi

IFS=, read -r -a time_list <<< "$times"
worst=0 worst_time= failed=0
for k in "${!time_list[@]}"; do
  a="$out_dir/$tag.file.t$k.png" b="$out_dir/$tag.reference.t$k.png"
  status=0
  result=$(node "$here/compare_images.mjs" "$a" "$b" --min-foreground 0.01 --diff-image "$out_dir/$tag.diff.t$k.png" 2>&1) || status=$?
  echo "animated_viewer_test: t=${time_list[$k]} s: $result"
  [ "$status" -eq 0 ] || { echo "animated_viewer_test: FAIL at t=${time_list[$k]} s: $result" >&2; failed=1; continue; }
  diff=$(node -e 'process.stdout.write(String(JSON.parse(process.argv[1]).diff))' "$result")
  if [ "$route_loop" -eq 1 ]; then
    next="$out_dir/$tag.reference.t$k.next.png"
    status=0
    result=$(node "$here/compare_images.mjs" "$a" "$next" --min-foreground 0.01 --diff-image "$out_dir/$tag.diff.t$k.next.png" 2>&1) || status=$?
    [ "$status" -eq 0 ] || { echo "animated_viewer_test: FAIL at t=${time_list[$k]} s (next frame): $result" >&2; failed=1; continue; }
    diff_next=$(node -e 'process.stdout.write(String(JSON.parse(process.argv[1]).diff))' "$result")
    states=$(node "$here/compare_images.mjs" "$b" "$next" 2>&1) || true
    states=$(node -e 'try { process.stdout.write(String(JSON.parse(process.argv[1]).diff)); } catch { process.stdout.write("?"); }' "$states")
    echo "animated_viewer_test: t=${time_list[$k]} s: vs reference one frame later: diff $diff_next (reference's two states differ by $states)"
    node -e 'process.exit(Number(process.argv[1]) < Number(process.argv[2]) ? 0 : 1)' "$diff_next" "$diff" && diff=$diff_next
  fi
  if node -e 'process.exit(Number(process.argv[1]) > Number(process.argv[2]) ? 0 : 1)' "$diff" "$worst"; then
    worst=$diff worst_time=${time_list[$k]}
  fi
done
echo "animated_viewer_test: $(basename "$file") vs $(basename "$reference"): max diff $worst at time ${worst_time:-${time_list[0]}} (max diff $max_diff)"
[ "$failed" -eq 0 ] || exit 1
if node -e 'process.exit(Number(process.argv[1]) > Number(process.argv[2]) ? 0 : 1)' "$worst" "$max_diff"; then
  echo "animated_viewer_test: FAIL: silhouette differs by $worst > $max_diff at time $worst_time -- see $out_dir/$tag.diff.t*.png" >&2
  exit 1
fi
echo "animated_viewer_test: PASS"
