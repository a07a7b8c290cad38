#!/usr/bin/env bash
# run_fuzz.sh SOURCE_DIR BUILD_DIR SEED_DIR...: builds the STEP/IGES pre-check fuzz target with clang
# (tests/brep/fuzz_precheck as its own CMake project in BUILD_DIR) and runs it for a bounded time over the
# seed folders' .step/.stp/.igs/.iges files, read only: new inputs go to BUILD_DIR/corpus (emptied first),
# findings to BUILD_DIR/artifacts. Fails on any crash, sanitizer report, input slower than 10 s, or RSS
# above 512 MB; prints libFuzzer's final figures. CADNURBS_FUZZ_SECONDS sets the time (default 30).
set -euo pipefail
source_dir=$1
build_dir=$2
shift 2
seconds=${CADNURBS_FUZZ_SECONDS:-30}

cxx=$(command -v clang++ || true)
if [ -z "$cxx" ]; then
  echo "run_fuzz.sh: clang++ not found (scripts/setup.sh installs clang and libclang-rt-14-dev)" >&2
  exit 1
fi
mkdir -p "$build_dir"
cmake -S "$source_dir/tests/brep/fuzz_precheck" -B "$build_dir" -DCMAKE_CXX_COMPILER="$cxx" \
  -DCADNURBS_SOURCE_DIR="$source_dir" >"$build_dir.configure.log" 2>&1 \
  || { cat "$build_dir.configure.log" >&2; exit 1; }
cmake --build "$build_dir" -j 2 >"$build_dir.build.log" 2>&1 || { tail -50 "$build_dir.build.log" >&2; exit 1; }

# The seeds: the STEP and IGES files of the given folders, linked into one folder (libFuzzer reads every
# file of a seed folder).
rm -rf "$build_dir/seeds" "$build_dir/corpus"
mkdir -p "$build_dir/seeds" "$build_dir/corpus" "$build_dir/artifacts"
for dir in "$@"; do
  for file in "$dir"/*; do
    case "${file,,}" in
      *.step | *.stp | *.igs | *.iges) ln -s "$(realpath "$file")" "$build_dir/seeds/$(basename "$dir")-$(basename "$file")" ;;
    esac
  done
done
[ -n "$(ls "$build_dir/seeds")" ] || { echo "run_fuzz.sh: no STEP or IGES seed in $*" >&2; exit 1; }

export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1}
status=0
"$build_dir/fuzz_precheck" -max_total_time="$seconds" -max_len=262144 -rss_limit_mb=512 -malloc_limit_mb=512 \
  -timeout=10 -print_final_stats=1 -artifact_prefix="$build_dir/artifacts/" "$build_dir/corpus" "$build_dir/seeds" \
  >"$build_dir/fuzz.log" 2>&1 || status=$?
grep -E '^(stat::|Done |INFO: seed corpus)|ERROR|SUMMARY|==[0-9]+==|runtime error|Test unit written' "$build_dir/fuzz.log" | head -60
if [ $status -ne 0 ]; then
  echo "run_fuzz.sh: fuzz_precheck failed (exit $status); log $build_dir/fuzz.log, inputs in $build_dir/artifacts" >&2
  tail -40 "$build_dir/fuzz.log" >&2
fi
exit $status
