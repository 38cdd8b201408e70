#!/usr/bin/env bash
# ctest ClusterScripts.GnuParallelShardsMergeToTheUnshardedStudy: a 2-shard study run by
# scripts/cluster/parallel-study.sh through GNU parallel merges to exactly the unsharded
# study.csv and study.json.
#   parallel_study_test.sh ROCKROLL_BIN SOURCE_DIR WORK_DIR
set -euo pipefail
bin=$1 source=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
. "$source/tests/cluster/make_study.sh"
make_study "$source" "$work" "$bin"
ROCKROLL="$bin" RR_JOBS_PER_SHARD=1 "$source/scripts/cluster/parallel-study.sh" "$work/study.toml" "$work/merged" 2 \
  --jobs 2 > "$work/parallel.log" 2>&1 || { cat "$work/parallel.log"; echo "FAIL: parallel-study.sh exited $?"; exit 1; }
grep -q "shard 1" "$work/parallel.log" && grep -q "shard 2" "$work/parallel.log" ||
  { cat "$work/parallel.log"; echo "FAIL: GNU parallel did not run both shards"; exit 1; }
for k in 1 2; do
  grep -q "\"k\": $k" "$work/merged.shards/shard-$k/study.json" || { echo "FAIL: shard-$k is not shard $k"; exit 1; }
done
compare_study "$work/whole" "$work/merged"
echo "1 passed, 0 failed"
