#!/usr/bin/env bash
# Check the SLURM profile on a one-node SLURM cluster started on this machine (as root).
#
# Installs Debian's slurmctld, slurmd, slurm-client and munge with apt-get when missing, writes a
# slurm.conf for this machine alone (its CPUs and memory as `slurmd -C` reports them; no
# accounting, proctrack/linuxproc, task/none, select/cons_tres with cores and memory as consumable
# resources, one partition), starts munged, slurmctld and slurmd in the foreground of background
# jobs (no systemd needed), waits until the node is idle, then builds the same configuration twice:
#   SLURM:  snakemake --profile workflow/profiles/slurm    --config outdir=$CHECK_DIR/slurm
#   local:  snakemake --profile workflow/profiles/default  --config outdir=$CHECK_DIR/local
# and checks that every rule except the localrules ran as a SLURM job with as many CPUs as its
# `threads`, and that both builds hold the same files with identical contents apart from timings
# (workflow/cluster/compare_builds.py). The daemons are stopped on exit, whatever happens.
#
# Writes only to a temporary directory (removed on exit) and to $CHECK_DIR (recreated each run):
# local/ and slurm/ (the two builds), local.log, slurm.log, jobs.txt (the SLURM job table),
# comparison.txt, summary.txt, logs/ (daemon and SLURM job logs). Exit status 0 when all checks pass.
#
# Environment: CONFIGFILE (default config/test.yaml), CHECK_DIR (default results/slurm-check; must
# be under results/), VENV (a virtual environment with environment.txt + environment-cluster.txt;
# default: create .venv with CLUSTER=1 workflow/setup_env.sh), SLURM_PORT (slurmctld's port,
# default 16817; slurmd uses the next one), SOURCE_DATE_EPOCH (default: the last commit's time,
# so that PDF dates agree between the builds).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cd "$root"
say() { echo "slurm_single_node: $*" >&2; }
die() { say "$*"; exit 1; }

configfile="${CONFIGFILE:-config/test.yaml}"
check_dir="${CHECK_DIR:-results/slurm-check}"
port="${SLURM_PORT:-16817}"
case "$check_dir" in
  results/?*) ;;
  *) say "CHECK_DIR must be a folder under results/ (got '$check_dir')"; exit 2 ;;
esac
[[ "$port" =~ ^[0-9]+$ ]] && [ "$port" -ge 1024 ] && [ "$port" -le 65000 ] \
  || { say "SLURM_PORT must be an integer in [1024, 65000] (got '$port')"; exit 2; }
[ -f "$configfile" ] || { say "CONFIGFILE '$configfile' does not exist"; exit 2; }
if [ "$(id -u)" != "0" ]; then
  die "needs root: it installs Debian's slurm-wlm and munge packages when missing and starts munged," \
      "slurmctld and slurmd for a one-node cluster. On a real cluster run" \
      "'snakemake --profile workflow/profiles/slurm' instead (see the profile's comments)."
fi
start_all=$(date +%s)

# --- Python environment with the executor plugin, and TeX for the `paper` localrule ---------------
if [ -n "${VENV:-}" ]; then
  venv="$VENV"
else
  CLUSTER=1 bash workflow/setup_env.sh
  venv="$root/.venv"
fi
"$venv/bin/python" -c "import snakemake_executor_plugin_slurm" 2>/dev/null \
  || die "$venv lacks snakemake-executor-plugin-slurm: run CLUSTER=1 bash workflow/setup_env.sh"
bash workflow/ensure_tex.sh
export PATH="$venv/bin:$PATH"
# this checkout's sources first, wherever the venv's editable install points; jobs inherit it
export PYTHONPATH="$root/src${PYTHONPATH:+:$PYTHONPATH}"
export SOURCE_DATE_EPOCH="${SOURCE_DATE_EPOCH:-$(git log -1 --format=%ct 2>/dev/null || echo 1700000000)}"

# --- Debian packages ---------------------------------------------------------------------------------
missing=0
for cmd in slurmctld slurmd munged munge sinfo sbatch squeue scancel srun; do
  command -v "$cmd" >/dev/null 2>&1 || missing=1
done
if [ "$missing" = "1" ]; then
  command -v apt-get >/dev/null 2>&1 || die "SLURM is not installed and there is no apt-get to install it"
  say "installing slurmctld slurmd slurm-client munge from Debian's packages"
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
    slurmctld slurmd slurm-client munge >/dev/null
fi

# --- temporary cluster: configuration, daemons, clean-up ---------------------------------------------
work="$(mktemp -d "${TMPDIR:-/tmp}/torsional-slurm.XXXXXX")"
chmod 711 "$work"  # munged requires search permission for all on its socket's folders
mkdir -p "$work/munge" "$work/state" "$work/spool" "$work/log" "$work/jobs"
chmod 711 "$work/munge"
rm -rf "$check_dir"
mkdir -p "$check_dir/logs"
daemon_pids=()
snakemake_pid=""

stop_all() {
  local status=$?
  trap - EXIT INT TERM
  [ "$status" = "0" ] || say "stopping (status $status)"
  local pid
  if [ -n "$snakemake_pid" ] && kill -0 "$snakemake_pid" 2>/dev/null; then
    say "interrupting snakemake (it cancels its SLURM jobs)"
    kill -INT "$snakemake_pid" 2>/dev/null || true
    for _ in $(seq 60); do kill -0 "$snakemake_pid" 2>/dev/null || break; sleep 1; done
    kill -KILL "$snakemake_pid" 2>/dev/null || true
    wait "$snakemake_pid" 2>/dev/null || true
  fi
  if [ -n "${SLURM_CONF:-}" ] && [ "${#daemon_pids[@]}" -ge 2 ]; then
    local left
    left="$(squeue -h -t PENDING,RUNNING,CONFIGURING,COMPLETING -o %i 2>/dev/null || true)"
    [ -z "$left" ] || scancel $left 2>/dev/null || true
    for _ in $(seq 30); do
      [ -z "$(squeue -h -t RUNNING,COMPLETING -o %i 2>/dev/null || true)" ] && break
      sleep 1
    done
  fi
  local i
  for ((i = ${#daemon_pids[@]} - 1; i >= 0; i--)); do  # slurmd, slurmctld, munged
    pid="${daemon_pids[$i]}"
    kill -TERM "$pid" 2>/dev/null || true
    for _ in $(seq 20); do kill -0 "$pid" 2>/dev/null || break; sleep 0.5; done
    kill -KILL "$pid" 2>/dev/null || true
    wait "$pid" 2>/dev/null || true
  done
  cp -r "$work/log" "$check_dir/logs/daemons" 2>/dev/null || true
  cp -r "$work/jobs" "$check_dir/logs/slurm-jobs" 2>/dev/null || true
  cp "$work/slurm.conf" "$check_dir/logs/" 2>/dev/null || true
  rm -rf "$work"
  [ "$status" = "0" ] || say "failed (status $status); logs in $check_dir/logs"
  exit "$status"
}
trap stop_all EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

node="$(hostname -s)"
node_hardware="$(slurmd -C | head -n 1)"  # NodeName=... CPUs=... RealMemory=...
cat > "$work/slurm.conf" <<EOF
# One-node cluster written by workflow/cluster/slurm_single_node.sh (temporary).
ClusterName=torsional
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$work/munge/munge.socket
CredType=cred/munge
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/log/slurmctld.log
SlurmdLogFile=$work/log/slurmd.log
MailProg=/bin/true
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
SchedulerType=sched/backfill
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
JobCompType=jobcomp/none
MpiDefault=none
SwitchType=switch/none
ReturnToService=2
# finished jobs stay visible to squeue for 2 hours (the whole build, however slow the machine): the
# status queries and the job table below use squeue (no sacct here)
MinJobAge=7200
$node_hardware NodeAddr=127.0.0.1 State=UNKNOWN
PartitionName=torsional Nodes=$node Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF="$work/slurm.conf"
# Inside each job the jobstep plugin (0.6.1) clears every SLURM_* variable but a few job IDs before
# its nested `srun`, SLURM_CONF included; a real cluster's srun finds /etc/slurm/slurm.conf (or asks
# slurmctld, configless), this temporary one's cannot. An srun first on PATH (which jobs inherit)
# puts SLURM_CONF back.
mkdir -p "$work/bin"
printf '#!/bin/sh\nSLURM_CONF=%q exec %q "$@"\n' "$SLURM_CONF" "$(command -v srun)" > "$work/bin/srun"
chmod 755 "$work/bin/srun"
export PATH="$work/bin:$PATH"

wait_for() {  # wait_for SECONDS DESCRIPTION COMMAND...: poll COMMAND every second
  local seconds="$1" what="$2"
  shift 2
  for _ in $(seq "$seconds"); do
    if "$@" >/dev/null 2>&1; then return 0; fi
    sleep 1
  done
  tail -n 20 "$work"/log/* >&2 || true
  die "$what did not happen within $seconds s"
}
node_idle() { [ "$(sinfo -h -n "$node" -o %T)" = "idle" ]; }
munge_works() { munge -n -S "$work/munge/munge.socket" | unmunge -S "$work/munge/munge.socket"; }

(umask 077 && head -c 1024 /dev/urandom > "$work/munge/munge.key")
munged --foreground --key-file="$work/munge/munge.key" --socket="$work/munge/munge.socket" \
  --pid-file="$work/munge/munged.pid" --seed-file="$work/munge/munged.seed" \
  --log-file="$work/log/munged.log" > "$work/log/munged.out" 2>&1 &
daemon_pids+=($!)
wait_for 20 "munged answering" munge_works
slurmctld -D -c -f "$SLURM_CONF" > "$work/log/slurmctld.out" 2>&1 &
daemon_pids+=($!)
wait_for 30 "slurmctld answering" scontrol ping
slurmd -D -f "$SLURM_CONF" > "$work/log/slurmd.out" 2>&1 &
daemon_pids+=($!)
wait_for 60 "node $node idle in sinfo" node_idle
say "cluster up: $(sinfo -h -o '%P %a %D %T %c CPUs %m MB')"

run_snakemake() {  # run_snakemake LOG ARGS...: in the background, so that signals reach the trap
  local log="$1"
  shift
  # a background command of a script ignores SIGINT; Snakemake needs it to cancel its jobs on exit
  env --default-signal=INT snakemake "$@" > "$log" 2>&1 &
  snakemake_pid=$!
  local status=0
  wait "$snakemake_pid" || status=$?
  snakemake_pid=""
  if [ "$status" != "0" ]; then
    tail -n 40 "$log" >&2
    die "snakemake $* failed (status $status); log: $log"
  fi
}

# --- the two builds ----------------------------------------------------------------------------------
t0=$(date +%s)
TORSIONAL_SLURM_PARTITION=torsional run_snakemake "$check_dir/slurm.log" \
  --profile workflow/profiles/slurm --configfile "$configfile" --config outdir="$check_dir/slurm" \
  --slurm-status-command squeue --slurm-init-seconds-before-status-checks 5 \
  --slurm-logdir "$work/jobs" --slurm-keep-successful-logs
slurm_seconds=$(( $(date +%s) - t0 ))
say "SLURM build: $slurm_seconds s"
# job table: id|comment (rule_<name>[_wildcards_...])|state|CPUs requested|CPUs allocated|memory|time used
squeue -h -t all -o '%i|%k|%T|%c|%C|%m|%M' | sort -n > "$check_dir/jobs.txt"

t0=$(date +%s)
run_snakemake "$check_dir/local.log" --profile workflow/profiles/default --configfile "$configfile" \
  --config outdir="$check_dir/local"
local_seconds=$(( $(date +%s) - t0 ))
say "local build: $local_seconds s"

# --- checks --------------------------------------------------------------------------------------------
failures=0
n_jobs=$(wc -l < "$check_dir/jobs.txt")
# the localrules (the `localrules:` block of the workflow) run on this host, not as SLURM jobs
local_rules=$(awk '/^localrules:/ { inside = 1; next } inside && /^    [A-Za-z0-9_]+,?$/ { gsub(/[ ,]/, ""); print; next }
                   { inside = 0 }' Snakefile workflow/rules/*.smk | sort -u | tr '\n' ' ')
# jobs the local run planned (its job table), less those of the localrules
expected_jobs=$(sed -n '/^Job stats:/,/^total/p' "$check_dir/local.log" | awk -v local_rules="$local_rules" '
  BEGIN { split(local_rules, names, " "); for (k in names) is_local[names[k]] = 1 }
  $1 == "total" { next } $2 ~ /^[0-9]+$/ && !($1 in is_local) { sum += $2 } END { print sum + 0 }')
if [ "$expected_jobs" = 0 ] || [ "$n_jobs" != "$expected_jobs" ]; then
  say "expected $expected_jobs SLURM jobs (the local run's jobs less the localrules: $local_rules), got $n_jobs"
  failures=$((failures + 1))
fi
if awk -F'|' '$3 != "COMPLETED"' "$check_dir/jobs.txt" | grep -q .; then
  say "SLURM jobs not COMPLETED:"; awk -F'|' '$3 != "COMPLETED"' "$check_dir/jobs.txt" >&2
  failures=$((failures + 1))
fi
for rule in $local_rules; do
  if grep -Eq "\|rule_${rule}(_wildcards|\|)" "$check_dir/jobs.txt"; then
    say "the localrule $rule was submitted to SLURM"; failures=$((failures + 1))
  fi
done
# each rule's `threads:` (1 when not declared) must reach SLURM as --cpus-per-task (CPUs requested;
# the allocated CPUs can be more: the benchmarks also ask for --exclusive)
awk '/^rule [A-Za-z0-9_]+:/ { rule = substr($2, 1, length($2) - 1) }
     /^    threads: *[0-9]+/ { print rule "|" $2 }' Snakefile workflow/rules/*.smk > "$work/threads.txt"
wrong_cpus=$(awk -F'|' 'NR == FNR { threads[$1] = $2; next }
  { rule = $2; sub(/^rule_/, "", rule); sub(/_wildcards_.*/, "", rule)
    want = (rule in threads) ? threads[rule] : 1; if ($4 != want) print }' "$work/threads.txt" "$check_dir/jobs.txt")
if [ -n "$wrong_cpus" ]; then
  say "jobs whose CPU count is not the rule's threads:"; echo "$wrong_cpus" >&2
  failures=$((failures + 1))
fi
compare_status=0
python workflow/cluster/compare_builds.py "$check_dir/local" "$check_dir/slurm" \
  --report "$check_dir/comparison.txt" > /dev/null || compare_status=$?
[ "$compare_status" = "0" ] || { say "the builds differ: see $check_dir/comparison.txt"; failures=$((failures + 1)); }

{
  echo "single-node SLURM check of workflow/profiles/slurm ($configfile)"
  echo "cluster: $(sinfo -h -o '%P %D node(s), %c CPUs, %m MB')"
  echo "local build $local_seconds s; SLURM build $slurm_seconds s ($n_jobs SLURM jobs);" \
       "whole check $(( $(date +%s) - start_all )) s"
  tail -n 1 "$check_dir/comparison.txt"
  echo "failed checks: $failures"
} > "$check_dir/summary.txt"
cat "$check_dir/summary.txt" >&2
[ "$failures" = "0" ]
