#!/usr/bin/env bash
# Runs `cadnurbs batch` over a library as a Slurm job array of N shards followed by the merge:
#
#   contrib/slurm/submit.sh N IN_DIR OUT_DIR [batch options: --to wrl,x3dv --inputs step ...]
#
# Prints "array job A, merge job M" (job ids) on stdout. Extra sbatch options for both jobs (partition,
# account, time, memory, --cpus-per-task for the array) go in $CADNURBS_SBATCH_OPTIONS, split on spaces.
# $CADNURBS names the cadnurbs binary the jobs run (default: cadnurbs on the nodes' PATH); the jobs
# inherit this environment. The logs land in OUT_DIR/slurm/. When the merge job has ended,
# OUT_DIR/report.* is the whole library's report.
set -euo pipefail

if [ $# -lt 3 ] || ! [[ "$1" =~ ^[1-9][0-9]*$ ]]; then
  echo "usage: $0 N IN_DIR OUT_DIR [cadnurbs batch options]" >&2
  exit 2
fi
shards=$1
in_dir=$(realpath -e -- "$2") || { echo "submit.sh: $2: no such folder" >&2; exit 2; }
out_dir=$(realpath -m -- "$3")
shift 3
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out_dir/slurm"
read -r -a extra <<< "${CADNURBS_SBATCH_OPTIONS:-}"

array=$(sbatch --parsable --export=ALL "${extra[@]}" --array="0-$((shards - 1))" \
  --output="$out_dir/slurm/batch-%A_%a.log" "$here/cadnurbs-batch.sbatch" "$in_dir" "$out_dir" "$@")
array=${array%%;*}  # --parsable prints "id" or "id;cluster"
merge=$(sbatch --parsable --export=ALL "${extra[@]}" --dependency="afterany:$array" \
  --output="$out_dir/slurm/merge-%j.log" "$here/cadnurbs-merge.sbatch" "$out_dir")
merge=${merge%%;*}
echo "array job $array, merge job $merge"
