#!/usr/bin/env bash
# behaviour_snapshot.sh CADNURBS OUT_DIR [BENCH_TESSELLATION]
# Writes what a change that should not change behaviour must keep: `cadnurbs demo`'s files and
# printout; every corpus STEP/IGES/3DM file converted to .x3dv and with --mesh to .stl, with what
# convert printed; and, given the bench binary, bench_tessellation's table without its timings.
# Paths are relative to OUT_DIR and STEP/IGES time stamps fixed (SOURCE_DATE_EPOCH=0), so that two
# snapshots compare with `diff -r OLD NEW`. Lines that hold seconds are left out of the printouts.
set -euo pipefail
cadnurbs=$(realpath "$1")
bench=${3:+$(realpath "$3")}
corpus=$(cd "$(dirname "$0")/../../shared/corpus" && pwd)
mkdir -p "$2"
cd "$2"
mkdir -p demo convert
export SOURCE_DATE_EPOCH=0

untimed() { grep -v -E '[0-9.]+ s\b|seconds' || true; }

"$cadnurbs" demo -o demo 2>&1 | untimed > demo.txt

convert_one() {
  local cadnurbs=$1 input=$2
  local name
  name=$(basename "$(dirname "$input")")_$(basename "$input")
  { "$cadnurbs" convert "$input" -o "convert/$name.x3dv" 2>&1; echo "exit $?"; } | grep -v -E '[0-9.]+ s\b|seconds' \
    > "convert/$name.x3dv.log" || true
  { "$cadnurbs" convert "$input" --mesh -o "convert/$name.stl" 2>&1; echo "exit $?"; } | grep -v -E '[0-9.]+ s\b|seconds' \
    > "convert/$name.stl.log" || true
}
export -f convert_one
find "$corpus/step" "$corpus/iges" "$corpus/3dm" -type f | sort |
  xargs -P "$(nproc)" -I{} bash -c 'convert_one "$@"' _ "$cadnurbs" {}

if [ -n "$bench" ]; then
  # The table without its timing columns (no benchmark is run): model, faces, D, triangles (ours, OCCT,
  # ratio), deviations / D, open edges, uncertified / unshared.
  "$bench" --benchmark_filter=NONE 2>/dev/null | awk -F'|' '/^\| /{print $2"|"$3"|"$4"|"$5"|"$6"|"$7"|"$11"|"$12"|"$13"|"$14}' \
    > bench_tessellation.txt
fi
