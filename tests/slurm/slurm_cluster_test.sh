#!/usr/bin/env bash
# A real single-node Slurm cluster on this machine runs contrib/slurm/submit.sh over a library (the
# samples and the corpus, copied into a temporary folder, as below) as 4 array tasks and a dependent
# merge job; the merged report must be the report of the same batch run on one machine, byte for byte.
#
#   slurm_cluster_test.sh CADNURBS SOURCE_DIR CORPUS_DIR [--smoke]
#
# --smoke: the fast tier's form: two sample cappings' STEP files (post, end) and the one sample that is no part
# (the PROTO library, which fails), as 2 array tasks.
#
# The cluster: munged with its own key and socket; slurmctld and slurmd in the foreground with a
# generated slurm.conf (proctrack/linuxproc, task/none, select/cons_tres, the node as `slurmd -C` sees it,
# free ports, every path in the test's folder, no cgroup.conf), run as root. Every daemon started here is
# stopped here, by its pid, whatever happens.
# The library: samples/ and the corpus files under 100 KB, STL left out (--inputs): about 40 parts, 8 of
# which fail (formats and nodes we do not read), each converted within seconds. The larger corpus parts
# and the STL ones (each record fits a Loop surface) take minutes each, twice over here (one machine,
# then Slurm); a part near its time limit could also end differently in the two runs.
set -uo pipefail

cadnurbs=$(realpath "$1")
source_dir=$2
corpus_dir=$3
smoke=${4:-}
[ -z "$smoke" ] || [ "$smoke" = --smoke ] || { echo "slurm_cluster_test: unknown option $smoke" >&2; exit 2; }
tasks=4
[ -n "$smoke" ] && tasks=2
fail() { echo "slurm_cluster_test: $*" >&2; exit 1; }
[ "$(id -u)" -eq 0 ] || fail "needs root (munged, slurmctld and slurmd run as root here)"
for tool in munged slurmctld slurmd sbatch squeue scontrol sinfo; do
  command -v "$tool" >/dev/null || fail "$tool not found: scripts/setup.sh installs slurm-wlm and munge"
done

work=$(mktemp -d /tmp/cadnurbs-slurm.XXXXXX)
chmod 755 "$work"  # munged wants its socket's folders searchable by everyone
pids=()
stop_daemons() {
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null; done
  for pid in "${pids[@]}"; do
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2>/dev/null
  done
  if [ -n "${keep_work:-}" ]; then echo "slurm_cluster_test: left $work" >&2; else rm -rf "$work"; fi
}
trap stop_daemons EXIT
show_logs() { for log in "$work"/*.log "$work"/out/slurm/*.log; do [ -f "$log" ] && { echo "== $log"; tail -20 "$log"; }; done >&2; }
die() { keep_work=1; show_logs; fail "$@"; }

# munge: a fresh key, its own socket, in the foreground so that $! is its pid.
dd if=/dev/urandom of="$work/munge.key" bs=1024 count=1 status=none
chmod 400 "$work/munge.key"
munged --foreground --force --key-file="$work/munge.key" --socket="$work/munge.socket" \
  --pid-file="$work/munged.pid" --log-file="$work/munged.log" --seed-file="$work/munge.seed" > "$work/munged.out" 2>&1 &
pids+=($!)
for _ in $(seq 100); do [ -S "$work/munge.socket" ] && break; sleep 0.1; done
[ -S "$work/munge.socket" ] || die "munged did not open its socket"

free_port() { python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'; }
host=$(hostname -s)
node_line=$(slurmd -C | head -1)  # "NodeName=<host> CPUs=.. Boards=.. ... RealMemory=.."
[[ "$node_line" == NodeName=* ]] || die "slurmd -C said: $node_line"
mkdir -p "$work/state" "$work/spool"
# MinJobAge=3600: slurmctld keeps a completed job's record an hour (by default 300 s), as the states
# are read once the merge has ended (within 10 minutes, or the test fails); on a loaded machine the
# first array task once ended 357 s before the merge, and its record was gone ("array task 0: ").
# (0, which the manual says keeps records for good, is taken as 2 s by Debian 12's Slurm 22.05.)
cat > "$work/slurm.conf" <<CONF
ClusterName=cadnurbs-test
SlurmctldHost=$host
AuthType=auth/munge
AuthInfo=socket=$work/munge.socket
CredType=cred/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
SlurmctldPort=$(free_port)
SlurmdPort=$(free_port)
ReturnToService=2
MpiDefault=none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MinJobAge=3600
$node_line State=UNKNOWN
PartitionName=test Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$work/slurm.conf
slurmctld -D -i -f "$SLURM_CONF" > "$work/slurmctld.out" 2>&1 &
pids+=($!)
slurmd -D -f "$SLURM_CONF" > "$work/slurmd.out" 2>&1 &
pids+=($!)
for _ in $(seq 120); do
  state=$(sinfo -h -o %T 2>/dev/null | head -1)
  [ "$state" = idle ] && break
  sleep 0.5
done
[ "$state" = idle ] || die "the node is not idle after 60 s (state '$state')"

# The library: samples and corpus side by side, as a user's folder would hold them.
mkdir -p "$work/lib"
if [ -n "$smoke" ]; then
  mkdir -p "$work/lib/samples"
  cp "$source_dir"/samples/capping-post.step "$source_dir"/samples/capping-end.step \
     "$source_dir/samples/cadnurbs-nurbs-protos.wrl" "$work/lib/samples/"
else
  cp -r "$source_dir/samples" "$work/lib/samples"
  while IFS= read -r -d '' file; do
    mkdir -p "$work/lib/corpus/$(dirname "$file")" && cp "$corpus_dir/$file" "$work/lib/corpus/$file" || die "cannot copy $file"
  done < <(cd "$corpus_dir" && find . -type f -size -100k -print0)
fi
options=(--inputs step,iges,3dm,wrl,x3d,x3dv --to x3dv --deviation 0.5)

# The same batch on one machine, for comparison.
"$cadnurbs" batch "$work/lib" -o "$work/single" --jobs 2 "${options[@]}" > "$work/single.out" 2> "$work/single.log"
single_status=$?
[ "$single_status" -eq 0 ] || [ "$single_status" -eq 3 ] || die "the single-machine batch exited $single_status"

jobs_line=$(CADNURBS="$cadnurbs" "$source_dir/contrib/slurm/submit.sh" "$tasks" "$work/lib" "$work/out" "${options[@]}") \
  || die "submit.sh failed: $jobs_line"
[[ "$jobs_line" =~ ^array\ job\ ([0-9]+),\ merge\ job\ ([0-9]+)$ ]] || die "submit.sh said: $jobs_line"
array=${BASH_REMATCH[1]}
merge=${BASH_REMATCH[2]}
for _ in $(seq 1200); do
  [ -z "$(squeue -h -j "$array,$merge" 2>/dev/null)" ] && break
  sleep 0.5
done
[ -z "$(squeue -h -j "$array,$merge" 2>/dev/null)" ] && [ -n "$(scontrol show job -o "$merge" 2>/dev/null)" ] \
  || die "the jobs did not end within 10 minutes"

# Every array task and the merge ran to their end, on this cluster.
for task in $(seq 0 $((tasks - 1))); do
  state=$(scontrol show job -o "${array}_$task" | grep -o 'JobState=[A-Z]*')
  [ "$state" = JobState=COMPLETED ] || die "array task $task: $state"
  for ext in md json csv; do
    [ -s "$work/out/report-$task-of-$tasks.$ext" ] || die "array task $task left no report-$task-of-$tasks.$ext"
  done
done
merge_info=$(scontrol show job -o "$merge")
merge_exit=$(grep -o ' ExitCode=[0-9]*' <<< "$merge_info")
[ " ExitCode=$single_status" = "$merge_exit" ] || die "the merge job's$merge_exit, the single batch's status $single_status"

# The merged report is the single machine's, and every part is in it once.
for ext in md csv json; do
  cmp -s "$work/single/report.$ext" "$work/out/report.$ext" || die "report.$ext differs: $(diff "$work/single/report.$ext" "$work/out/report.$ext" | head -5)"
done
parts=$(find "$work/lib" -type f \( -iname '*.step' -o -iname '*.stp' -o -iname '*.iges' -o -iname '*.igs' \
  -o -name '*.3dm' -o -name '*.wrl' -o -name '*.x3d' -o -name '*.x3dv' \) | wc -l)
reported=$(python3 -c 'import json, sys; print(len(json.load(open(sys.argv[1]))["parts"]))' "$work/out/report.json")
[ "$parts" -eq "$reported" ] || die "$parts parts in the library, $reported in the merged report"
shard_sum=0
for task in $(seq 0 $((tasks - 1))); do
  n=$(python3 -c 'import json, sys; print(len(json.load(open(sys.argv[1]))["parts"]))' "$work/out/report-$task-of-$tasks.json")
  shard_sum=$((shard_sum + n))
done
[ "$shard_sum" -eq "$parts" ] || die "the shards' reports hold $shard_sum parts, the library $parts"
echo "slurm_cluster_test: $parts parts, $tasks array tasks ($array) and the merge ($merge) on Slurm; merged report = single-machine report"
