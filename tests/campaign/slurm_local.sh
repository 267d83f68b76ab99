#!/usr/bin/env bash
# Runs the campaign runner's Slurm executor against a real, single-node Slurm on this machine.
#
#   bash tests/campaign/slurm_local.sh CAMPAIGN_DRIVER WORK_DIR
#
# As root on Debian 12 (no systemd needed): installs slurm-wlm and munge when missing, creates a
# munge key, writes a minimal /etc/slurm/slurm.conf (one node "localhost", partition "debug",
# no cgroups, no accounting), starts munged, slurmctld and slurmd as daemons, waits (bounded)
# for the node to be idle, then runs a campaign of fake jobs (campaign_driver) through
# `sbatch --array`: one job fails once and must be retried, one always fails and must be
# reported failed; a second run must repeat nothing that finished. If Slurm already answers
# (sinfo shows an idle node), it is used as it is. Every wait is bounded; on failure the
# daemons' logs are printed.
set -uo pipefail

driver=${1:?usage: slurm_local.sh CAMPAIGN_DRIVER WORK_DIR}
work=${2:?usage: slurm_local.sh CAMPAIGN_DRIVER WORK_DIR}
conf=/etc/slurm/slurm.conf
log_dir=/var/log/slurm

fail() {
  echo "slurm_local: FAIL: $*" >&2
  for f in "$log_dir/slurmctld.log" "$log_dir/slurmd.log" /var/log/munge/munged.log; do
    [ -f "$f" ] && { echo "---- last lines of $f" >&2; tail -n 25 "$f" >&2; }
  done
  exit 1
}

# Waits up to $1 seconds for the command in the other arguments to succeed.
wait_for() {
  local limit=$1; shift
  local t=0
  until "$@" >/dev/null 2>&1; do
    t=$((t + 1))
    [ "$t" -ge "$limit" ] && return 1
    sleep 1
  done
}

node_idle() { sinfo -h -N -o '%N %T' 2>/dev/null | grep -Eq '^localhost (idle|mixed|allocated)'; }

setup_slurm() {
  [ "$(id -u)" -eq 0 ] || fail "not root: cannot install or start Slurm (start it yourself, then re-run)"
  if ! command -v slurmctld >/dev/null || ! command -v munged >/dev/null; then
    echo "slurm_local: installing slurm-wlm and munge"
    export DEBIAN_FRONTEND=noninteractive
    timeout 300 apt-get update -qq || fail "apt-get update failed"
    timeout 600 apt-get install -y -qq --no-install-recommends slurm-wlm munge >/dev/null ||
      fail "apt-get install slurm-wlm munge failed"
  fi

  # munge: key, run and log directories, daemon (as user munge).
  mkdir -p /etc/munge /var/lib/munge /var/log/munge /run/munge
  if [ ! -s /etc/munge/munge.key ]; then
    dd if=/dev/urandom of=/etc/munge/munge.key bs=1 count=1024 status=none || fail "cannot create the munge key"
  fi
  chown -R munge:munge /etc/munge /var/lib/munge /var/log/munge /run/munge
  chmod 700 /etc/munge; chmod 400 /etc/munge/munge.key; chmod 755 /run/munge
  if ! munge -n 2>/dev/null | unmunge >/dev/null 2>&1; then
    pkill_pid=$(cat /run/munge/munged.pid 2>/dev/null || true)
    [ -n "$pkill_pid" ] && kill "$pkill_pid" 2>/dev/null
    runuser -u munge -- /usr/sbin/munged --force || fail "munged did not start"
    wait_for 20 sh -c 'munge -n | unmunge' || fail "munge does not work (munge -n | unmunge)"
  fi

  # slurm.conf for one node; CPUs and memory from this machine.
  local cpus mem
  cpus=$(nproc)
  mem=$(awk '/MemTotal/ {print int($2 / 1024 * 0.8)}' /proc/meminfo)
  mkdir -p /etc/slurm /var/spool/slurmctld /var/spool/slurmd "$log_dir" /run/slurm
  chown slurm:slurm /var/spool/slurmctld "$log_dir"
  cat > "$conf" <<EOF
# Minimal single-node Slurm written by tests/campaign/slurm_local.sh
ClusterName=paddytest
SlurmctldHost=localhost
AuthType=auth/munge
CredType=cred/munge
SlurmUser=slurm
SlurmctldPort=6817
SlurmdPort=6818
StateSaveLocation=/var/spool/slurmctld
SlurmdSpoolDir=/var/spool/slurmd
SlurmctldPidFile=/run/slurm/slurmctld.pid
SlurmdPidFile=/run/slurm/slurmd.pid
SlurmctldLogFile=$log_dir/slurmctld.log
SlurmdLogFile=$log_dir/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/backfill
ReturnToService=2
MpiDefault=none
SlurmctldTimeout=30
SlurmdTimeout=60
InactiveLimit=0
MinJobAge=300
KillWait=5
NodeName=localhost NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$mem State=UNKNOWN
PartitionName=debug Nodes=localhost Default=YES MaxTime=INFINITE State=UP
EOF
  rm -f /etc/slurm/cgroup.conf  # no cgroups (proctrack/linuxproc, task/none)

  # Daemons in the background (they daemonise); restarted if already running with another config.
  for pidfile in /run/slurm/slurmd.pid /run/slurm/slurmctld.pid; do
    if [ -s "$pidfile" ]; then kill "$(cat "$pidfile")" 2>/dev/null; fi
  done
  sleep 1
  /usr/sbin/slurmctld -c || fail "slurmctld did not start"
  wait_for 30 scontrol ping || fail "slurmctld does not answer (scontrol ping)"
  /usr/sbin/slurmd -N localhost || fail "slurmd did not start"
  wait_for 60 node_idle || { sinfo -N >&2; fail "node localhost did not become idle within 60 s"; }
}

start=$(date +%s)
if node_idle && scontrol ping >/dev/null 2>&1; then
  echo "slurm_local: using the running Slurm"
else
  setup_slurm
fi
echo "slurm_local: Slurm is up after $(( $(date +%s) - start )) s:"
sinfo -N -o '%N %T %c %m %P'

rm -rf "$work"
mkdir -p "$work"
run_campaign() {
  timeout 300 "$driver" "$work/campaign" 4 1 --executor slurm --partition debug --parallel 0 --poll 1 \
    --fail-once 1 --fail-always 3 > "$work/$1.txt" 2> "$work/$1.err"
  echo $?
}

rc=$(run_campaign first)
cat "$work/first.txt"; cat "$work/first.err" >&2
[ "$rc" = 1 ] || fail "first campaign: exit code $rc (expected 1: one job fails for good)"
statuses=$(awk '{print $2 " " $3}' "$work/first.txt" | tr '\n' ',')
[ "$statuses" = "done 1,done 2,done 1,failed 2," ] ||
  fail "first campaign: status/executions '$statuses', expected 'done 1,done 2,done 1,failed 2,'"
grep -q "error: fake failure 2" "$work/first.txt" || fail "the failed job does not report its error"
ls "$work/campaign/slurm/"batch_*.sh >/dev/null || fail "no generated batch script"

# Resume: the three finished jobs must not run again; the failed one gets two more attempts.
rc=$(run_campaign second)
cat "$work/second.txt"
statuses=$(awk '{print $2 " " $3}' "$work/second.txt" | tr '\n' ',')
[ "$rc" = 1 ] && [ "$statuses" = "done 1,done 2,done 1,failed 4," ] ||
  fail "resumed campaign: exit $rc, status/executions '$statuses', expected 'done 1,done 2,done 1,failed 4,'"

# Real paddy through Slurm, driven from Lua (paddy.campaign{executor = "slurm"}), if built.
paddy="$(dirname "$driver")/paddy"
if [ -x "$paddy" ]; then
  mkdir -p "$work/lua"
  cat > "$work/lua/tiny.lua" <<'LUA'
local P = paddy.parameters{a = {default = 1.0, min = -10, max = 10, description = "a number"}}
paddy.result{twice = 2 * P.a, seed = paddy.seed, threads = paddy.threads}
LUA
  cat > "$work/lua/calibrate.lua" <<'LUA'
local c = paddy.campaign{dir = paddy.out_dir .. "/camp", executor = "slurm", progress = false,
                         slurm = {partition = "debug", time = "00:05:00", cpus_per_task = 1, poll_interval = 1}}
c:submit{script = "tiny.lua", params = {a = 0.25}, seed = 4}
c:submit{script = "tiny.lua", params = {a = 3}}
local runs = c:run()
paddy.result{summary = string.format("%s %g %d | %s %g %d", runs[1].status, runs[1].result.twice,
             runs[1].result.seed, runs[2].status, runs[2].result.twice, runs[2].result.threads)}
LUA
  (cd "$work/lua" && timeout 300 "$paddy" run calibrate.lua --out out) > "$work/lua.log" 2>&1 ||
    { cat "$work/lua.log" >&2; fail "paddy run calibrate.lua (executor slurm) failed"; }
  grep -q '"summary": "done 0.5 4 | done 6 1"' "$work/lua/out/result.json" ||
    { cat "$work/lua/out/result.json" >&2; fail "unexpected results of the Lua campaign through Slurm"; }
  echo "slurm_local: Lua campaign with real paddy through Slurm: ok"
else
  echo "slurm_local: $paddy not built: skipped the Lua campaign with real paddy"
fi

echo "slurm_local: PASS in $(( $(date +%s) - start )) s"
