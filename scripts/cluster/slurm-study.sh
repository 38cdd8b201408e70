#!/usr/bin/env bash
# Submits a rockroll study to Slurm: a job array of N shards (sbatch --array=1-N, shard K
# from SLURM_ARRAY_TASK_ID), then a merge job that starts when every shard succeeded
# (--dependency=afterok). The merged study.csv and study.json land in OUT_DIR.
#
#   scripts/cluster/slurm-study.sh STUDY.toml OUT_DIR N [SBATCH_OPTION...]
#
# OUT_DIR must be on a file system every node sees. Options after N go to both sbatch
# calls (e.g. --partition=long, --cpus-per-task=4: each shard then runs --jobs 4).
# ROCKROLL: the rockroll binary on the nodes (default: rockroll on this PATH). Prints the
# array and merge job ids. Resubmitting continues: finished shards are kept, interrupted
# ones resume from their journals.
set -euo pipefail
if [ $# -lt 3 ]; then
  sed -n '2,13p' "$0" >&2
  exit 2
fi
here=$(dirname "$(realpath "$0")")
study=$(realpath "$1")
out=$(realpath -m "$2")
shards=$3
shift 3
rockroll=$(command -v "${ROCKROLL:-rockroll}" || true)
[ -n "$rockroll" ] || { echo "slurm-study.sh: rockroll not found (set ROCKROLL)" >&2; exit 2; }
mkdir -p "$out.shards"
env="ALL,RR_STUDY=$study,RR_SHARD_DIR=$out.shards,RR_OUT=$out,RR_SHARDS=$shards,ROCKROLL=$rockroll"
array=$(sbatch --parsable --array=1-"$shards" --chdir="$out.shards" --export="$env" "$@" "$here/slurm-shard.sbatch")
array=${array%%;*}
merge=$(sbatch --parsable --dependency=afterok:"$array" --chdir="$out.shards" --export="$env" "$@" \
  "$here/slurm-merge.sbatch")
echo "shards: job $array (array 1-$shards); merge: job ${merge%%;*}"
