#!/usr/bin/env bash
# ctest ClusterScripts.SlurmArrayShardsMergeToTheUnshardedStudy (label cluster, not in the
# default run): scripts/cluster/slurm-study.sh submits a 2-shard study as a Slurm job
# array and a merge job with --dependency=afterok to a single-node Slurm (Debian's
# slurm-wlm: slurmctld and slurmd on this host, munge for authentication) that this
# script configures in WORK_DIR, starts, and stops again; the merged study.csv and
# study.json must be byte-identical to the unsharded study's.
#   slurm_study_test.sh ROCKROLL_BIN SOURCE_DIR WORK_DIR
# ctest registers it only when configured with -DROCKROLL_CLUSTER_TESTS=ON. It installs
# slurm-wlm and munge with apt-get when they are missing (as root); build.sh does not.
set -euo pipefail
bin=$1 source=$2 work=$3
if ! command -v slurmctld > /dev/null || ! command -v munged > /dev/null; then
  [ "$(id -u)" -eq 0 ] || { echo "FAIL: slurm-wlm and munge are not installed (apt-get install slurm-wlm munge)"; exit 1; }
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends slurm-wlm munge > /dev/null
fi
rm -rf "$work" && mkdir -p "$work"
# Slurm's and munge's sockets live under their state folders, whose paths must stay short
# (a Unix socket path has at most 108 bytes): a folder of our own under /tmp, removed at the end.
daemons=$(mktemp -d /tmp/rr-slurm.XXXXXX)
mkdir -p "$daemons/slurm/state" "$daemons/slurm/spool" "$daemons/munge"
chmod 700 "$daemons/munge"
ln -s "$daemons" "$work/daemons"
cfg="$daemons/slurm"
stop() {
  for f in "$cfg/slurmd.pid" "$cfg/slurmctld.pid" "$daemons/munge/munged.pid"; do
    [ -f "$f" ] && kill "$(cat "$f")" 2> /dev/null || true
  done
  sleep 1
  cp "$cfg"/*.log "$work/" 2> /dev/null || true
  rm -rf "$daemons" "$work/daemons"
}
trap stop EXIT
node=$(hostname -s)
user=$(id -un)

# munge: a key of our own and a socket of our own, so nothing of the host's is touched.
dd if=/dev/urandom of="$daemons/munge/munge.key" bs=1024 count=1 status=none
chmod 400 "$daemons/munge/munge.key"
munged --force --key-file="$daemons/munge/munge.key" --socket="$daemons/munge/munge.sock" \
  --pid-file="$daemons/munge/munged.pid" --log-file="$daemons/munge/munged.log" --seed-file="$daemons/munge/munged.seed"

cat > "$cfg/slurm.conf" <<CONF
ClusterName=rockrolltest
SlurmctldHost=$node(127.0.0.1)
SlurmUser=$user
SlurmdUser=root
SlurmctldPort=16817
SlurmdPort=16818
AuthType=auth/munge
AuthInfo=socket=$daemons/munge/munge.sock
CredType=cred/munge
StateSaveLocation=$cfg/state
SlurmdSpoolDir=$cfg/spool
SlurmctldPidFile=$cfg/slurmctld.pid
SlurmdPidFile=$cfg/slurmd.pid
SlurmctldLogFile=$cfg/slurmctld.log
SlurmdLogFile=$cfg/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
MpiDefault=none
ReturnToService=2
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
JobCompType=jobcomp/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
NodeName=$node NodeAddr=127.0.0.1 CPUs=2 State=UNKNOWN
PartitionName=test Nodes=$node Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="$cfg/slurm.conf"

slurmctld -c
slurmd -c
for _ in $(seq 1 60); do
  sinfo -h -o '%t' 2> /dev/null | grep -qE '^(idle|mix|alloc)' && break
  sleep 1
done
sinfo -h -o '%P %t %D' || true
sinfo -h -o '%t' | grep -qE '^(idle|mix|alloc)' || { tail -20 "$cfg/slurmctld.log" "$cfg/slurmd.log"; echo "FAIL: the node did not come up"; exit 1; }

. "$source/tests/cluster/make_study.sh"
make_study "$source" "$work" "$bin"
submitted=$(ROCKROLL="$bin" "$source/scripts/cluster/slurm-study.sh" "$work/study.toml" "$work/merged" 2)
echo "$submitted"
merge=$(echo "$submitted" | sed -n 's/.*merge: job \([0-9]*\).*/\1/p')
for _ in $(seq 1 300); do
  [ -z "$(squeue -h -j "$merge" 2> /dev/null)" ] && break
  sleep 1
done
ls "$work/merged.shards"
for f in "$work/merged.shards"/*.log; do echo "== $f"; cat "$f"; done
[ -d "$work/merged" ] || { tail -20 "$cfg/slurmctld.log" "$cfg/slurmd.log"; echo "FAIL: the merge job wrote no $work/merged"; exit 1; }
for k in 1 2; do
  grep -q "\"k\": $k" "$work/merged.shards/shard-$k/study.json" || { echo "FAIL: shard-$k is not shard $k"; exit 1; }
done
compare_study "$work/whole" "$work/merged"
echo "1 passed, 0 failed"
