#!/usr/bin/env bash
# Runs a rockroll study as N shards through GNU parallel, then merges them into OUT_DIR
# (study.csv, study.json: byte-identical to the unsharded study's).
#
#   scripts/cluster/parallel-study.sh STUDY.toml OUT_DIR N [PARALLEL_OPTION...]
#
# Shard K writes OUT_DIR.shards/shard-K. Options after N go to GNU parallel, e.g.
# `--jobs 4`, or `--sshloginfile hosts.txt` to spread the shards over machines that share
# this file system and have rockroll (set ROCKROLL to its path; default: rockroll on PATH).
# RR_JOBS_PER_SHARD (default 1) is each shard's --jobs. Rerunning the same command
# continues: a finished shard is kept, an interrupted one resumes from its journal.
# Exit: merge's code (0; 4 when a point failed), or 2 when a shard did not finish.
set -euo pipefail
if [ $# -lt 3 ]; then
  sed -n '2,13p' "$0" >&2
  exit 2
fi
study=$(realpath "$1")
out=$(realpath -m "$2")
shards=$3
shift 3
export RR_STUDY="$study" RR_SHARD_DIR="$out.shards" RR_SHARDS="$shards"
export RR_JOBS_PER_SHARD="${RR_JOBS_PER_SHARD:-1}" ROCKROLL="${ROCKROLL:-rockroll}"
mkdir -p "$RR_SHARD_DIR"

# One shard: skipped when its directory is complete; exit 4 (points failed, recorded in
# its study.json) still lets the merge run.
run_shard() {
  local k=$1 dir="$RR_SHARD_DIR/shard-$1" rc=0
  [ -d "$dir" ] && return 0
  "$ROCKROLL" study "$RR_STUDY" --shard "$k/$RR_SHARDS" --out "$dir" --jobs "$RR_JOBS_PER_SHARD" --resume || rc=$?
  [ "$rc" -eq 4 ] && return 0
  return "$rc"
}
export -f run_shard
export SHELL=/bin/bash  # parallel runs the jobs with $SHELL: the exported function needs bash

rc=0
parallel --will-cite --line-buffer --tagstring 'shard {}' --env run_shard --env RR_STUDY --env RR_SHARD_DIR \
  --env RR_SHARDS --env RR_JOBS_PER_SHARD --env ROCKROLL "$@" run_shard ::: $(seq 1 "$shards") || rc=$?
if [ "$rc" -ne 0 ]; then
  echo "parallel-study.sh: $rc shard(s) did not finish; rerun the same command to resume them" >&2
  exit 2
fi
shard_dirs=()
for k in $(seq 1 "$shards"); do shard_dirs+=("$RR_SHARD_DIR/shard-$k"); done
exec "$ROCKROLL" merge "${shard_dirs[@]}" --out "$out"
