#!/usr/bin/env bash
# A real Slurm on this machine, for tests, CI and trying out job scripts:
# Debian 12's slurm-wlm (slurmctld + slurmd + client tools) and munge, started
# without systemd; one node, or N nodes in network namespaces.
#
#   scripts/slurm-local.sh install   apt-get install slurm-wlm and munge if missing
#   scripts/slurm-local.sh start     configure and start munged, slurmctld, slurmd;
#                                    wait for the node; smoke test (sbatch, srun)
#   scripts/slurm-local.sh start --nodes N   N nodes cic-n1..N, each a slurmd in
#                                    its own network namespace (scripts/slurm-netns.sh)
#   scripts/slurm-local.sh start --fresh   the same from an empty state: cancels
#                                    all jobs, forgets them, empties the logs (CI)
#   scripts/slurm-local.sh stop      stop the daemons, remove the namespaces
#   scripts/slurm-local.sh status    daemons, sinfo, squeue (exit 0 when all run)
#   scripts/slurm-local.sh nodes     the node names, one per line
#   scripts/slurm-local.sh kill-node NODE    lose a node: SIGKILL to its slurmd and
#                                    every job process on it, and mark it DOWN
#   scripts/slurm-local.sh revive-node NODE  start its slurmd again and resume it
#   scripts/slurm-local.sh rsh NODE COMMAND...  run a command on a node (Open MPI's
#                                    plm_rsh_agent for mpirun --hostfile across nodes)
#
# Runs as root. Idempotent: `start` on a running cluster checks it and runs the
# smoke test again; a changed configuration restarts slurmctld and slurmd.
# Without --fresh, jobs are kept across stop/start (a job that was running
# when its processes were lost, e.g. by a reboot, is requeued or failed).
# Environment: CIC_SLURM_DIR (/tmp/cic-slurm), CIC_SLURM_TIMEOUT (60 s),
# CIC_SLURM_PROCTRACK (pgid; cgroup as on real clusters, where cgroups work).
#
# The node is this machine (hostname -s, address 127.0.0.1) with its real CPU
# count and memory (slurmd -C). Partitions: `debug` (default) and `urgent`,
# whose jobs preempt `debug` jobs by requeueing them (SIGTERM, KillWait, SIGKILL,
# back to pending), to try preemption. Everything lives under CIC_SLURM_DIR
# (default /tmp/cic-slurm): state, spool, logs, pid files, munged's log; except
# Debian's fixed paths /etc/slurm/slurm.conf (read by every client command),
# /etc/munge/munge.key and munged's socket /run/munge/munge.socket.2.
set -euo pipefail

PROG=slurm-local.sh
# shellcheck source=scripts/slurm-netns.sh
. "$(dirname "${BASH_SOURCE[0]}")/slurm-netns.sh"
# The daemons, munged and runuser live in /usr/sbin, not on every user's PATH.
export PATH="$PATH:/usr/sbin:/sbin"
DIR=${CIC_SLURM_DIR:-/tmp/cic-slurm}
CONF=/etc/slurm/slurm.conf
CGROUP_CONF=/etc/slurm/cgroup.conf
KEY=/etc/munge/munge.key
MUNGE_RUN=/run/munge
READY_TIMEOUT=${CIC_SLURM_TIMEOUT:-60}
# How slurmd finds a job's processes: pgid (default, works anywhere), or
# cgroup as on real clusters (needs a usable cgroup hierarchy), or linuxproc.
PROCTRACK=${CIC_SLURM_PROCTRACK:-pgid}
# iproute2: ip, for the namespace nodes of start --nodes N.
PACKAGES=(slurm-wlm slurmctld slurmd slurm-client munge iproute2)

say() { echo "$PROG: $*" >&2; }
die() { say "error: $*"; exit 1; }

usage() {
  sed -n '2,27p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//' >&2
  exit 2
}

need_root() {
  [ "$(id -u)" -eq 0 ] || die "run as root (it starts system daemons and writes $CONF)"
}

# Absolute folder, so that slurm.conf does not depend on where start ran.
DIR=$(realpath -m -- "$DIR")
case "$DIR" in *[[:space:]#]*) die "CIC_SLURM_DIR must not contain spaces or '#': $DIR" ;; esac
case "$PROCTRACK" in pgid | cgroup | linuxproc) ;; *) die "CIC_SLURM_PROCTRACK must be pgid, cgroup or linuxproc, not '$PROCTRACK'" ;; esac

# --- daemons ----------------------------------------------------------------

# Daemons: munged, slurmctld, slurmd (the single node) and slurmd@NODE (a
# namespace node; its files carry the node name, as slurm.conf's %n does).
pidfile_of() {
  case "$1" in
    munged) echo "$DIR/munge/munged.pid" ;;
    slurmctld) echo "$DIR/run/slurmctld.pid" ;;
    slurmd) echo "$DIR/run/slurmd.pid" ;;
    slurmd@*) echo "$DIR/run/slurmd-${1#slurmd@}.pid" ;;
  esac
}

logfile_of() {
  case "$1" in
    munged) echo "$DIR/munge/munged.log" ;;
    slurmctld) echo "$DIR/log/slurmctld.log" ;;
    slurmd) echo "$DIR/log/slurmd.log" ;;
    slurmd@*) echo "$DIR/log/slurmd-${1#slurmd@}.log" ;;
  esac
}

# The node count of the cluster: 0 for the single node (this machine), N for
# the namespace nodes cic-n1..N; start --nodes writes it, the others read it.
NODES_FILE=$DIR/nodes
cluster_node_count() { cat "$NODES_FILE" 2>/dev/null || echo 0; }

# The slurmd daemon names of the cluster.
slurmd_daemons() {
  local n k
  n=$(cluster_node_count)
  if [ "$n" -eq 0 ]; then echo slurmd; return; fi
  for ((k = 1; k <= n; k++)); do echo "slurmd@$(netns_node_name "$k")"; done
}

cluster_nodes() {
  local d
  for d in $(slurmd_daemons); do
    if [ "$d" = slurmd ]; then node_name; else echo "${d#slurmd@}"; fi
  done
}

# A process that exists and is not a zombie (a killed daemon stays one until
# an init that reaps orphans gets to it; some container inits take seconds).
alive() {
  local stat
  stat=$(cat "/proc/$1/stat" 2>/dev/null) || return 1
  stat=${stat##*) }
  [ "${stat%% *}" != Z ]
}

# Prints the pid of a daemon started by this script (from its pid file) when
# that process still runs that program; fails otherwise.
daemon_pid() {
  local f pid comm
  f=$(pidfile_of "$1")
  [ -r "$f" ] || return 1
  pid=$(tr -dc '0-9' <"$f")
  [ -n "$pid" ] || return 1
  alive "$pid" || return 1
  comm=$(cat "/proc/$pid/comm" 2>/dev/null) || return 1
  # /proc/PID/comm of slurmd-wlm (Debian's alternative for slurmd) is slurmd-wlm
  local base=${1%@*}
  case "$comm" in "$base" | "$base"-wlm) echo "$pid" ;; *) return 1 ;; esac
}

# Pids of the same program that this script did not start (other pid file or
# an init.d script): they hold the ports and the socket, so they are reported.
foreign_pids() {
  local own p d
  own=$(daemon_pid "$1" || true)
  if [ "$1" = slurmd ]; then   # the namespace nodes' slurmd are ours too
    for d in $(ls "$DIR"/run/slurmd-*.pid 2>/dev/null); do own="$own $(tr -dc '0-9' <"$d")"; done
  fi
  for p in $(pgrep -x "$1" 2>/dev/null) $(pgrep -x "$1-wlm" 2>/dev/null); do
    case " $own " in *" $p "*) continue ;; esac
    ! alive "$p" || printf '%s ' "$p"
  done
}

log_tail() {
  local f
  f=$(logfile_of "$1")
  if [ -s "$f" ]; then
    say "last lines of $f:"
    tail -n "${2:-25}" "$f" | sed 's/^/    /' >&2
  else
    say "($f is empty or missing)"
  fi
}

fail_daemon() {
  local name=$1
  shift
  say "error: $name: $*"
  log_tail "$name"
  exit 1
}

stop_daemon() {
  local name=$1 pid i
  pid=$(daemon_pid "$name") || {
    rm -f "$(pidfile_of "$name")"
    return 0
  }
  say "stopping $name (pid $pid)"
  kill -TERM "$pid" 2>/dev/null || true
  for ((i = 0; i < 150; i++)); do
    alive "$pid" || break
    sleep 0.1
  done
  if alive "$pid"; then
    say "$name (pid $pid) still runs after 15 s, sending SIGKILL"
    kill -KILL "$pid" 2>/dev/null || true
    sleep 0.5
  fi
  rm -f "$(pidfile_of "$name")"
}

# --- install ----------------------------------------------------------------

cmd_install() {
  local missing=() p policy_made=0
  for p in "${PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -gt 0 ] || { say "slurm-wlm and munge are installed"; return 0; }
  need_root
  say "installing ${missing[*]}"
  # Without systemd, the packages' postinst scripts would start the daemons
  # through /etc/init.d (slurmd fails there without a slurm.conf, failing the
  # install): forbid service starts for the duration, as Docker images do.
  if [ ! -e /usr/sbin/policy-rc.d ]; then
    printf '#!/bin/sh\nexit 101\n' >/usr/sbin/policy-rc.d
    chmod 755 /usr/sbin/policy-rc.d
    policy_made=1
    trap 'rm -f /usr/sbin/policy-rc.d' EXIT
  fi
  # Wait for a concurrent apt-get instead of failing on its lock.
  local apt=(apt-get -q -y -o DPkg::Lock::Timeout=600)
  DEBIAN_FRONTEND=noninteractive "${apt[@]}" update
  DEBIAN_FRONTEND=noninteractive "${apt[@]}" install --no-install-recommends "${PACKAGES[@]}"
  if [ "$policy_made" -eq 1 ]; then
    rm -f /usr/sbin/policy-rc.d
    trap - EXIT
  fi
  say "installed: $(slurmd -V)"
}

# --- configuration ----------------------------------------------------------

node_name() { hostname -s; }

# CPUs and RealMemory (MB) as slurmd sees them; nproc/free as a fallback.
node_resources() {
  local line cpus mem
  line=$(slurmd -C 2>/dev/null | head -n 1 || true)
  cpus=$(sed -n 's/.* CPUs=\([0-9]*\).*/\1/p' <<<"$line")
  mem=$(sed -n 's/.* RealMemory=\([0-9]*\).*/\1/p' <<<"$line")
  [ -n "$cpus" ] || cpus=$(nproc)
  [ -n "$mem" ] || mem=$(free -m | awk '/^Mem:/ {print $2}')
  echo "$cpus $mem"
}

write_conf() {
  local node cpus mem res n ctld_addr nodelist k
  node=$(node_name)
  res=$(node_resources)
  cpus=${res% *}
  mem=${res#* }
  n=$(cluster_node_count)
  ctld_addr=127.0.0.1
  [ "$n" -eq 0 ] || ctld_addr=$NETNS_HOST_ADDR
  cat <<EOF
# Written by scripts/slurm-local.sh (cic): a test cluster on this machine, one
# node or $n in network namespaces. Rewritten by every 'slurm-local.sh start';
# edit the script instead.
ClusterName=cic
SlurmctldHost=$node($ctld_addr)
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
# Job credentials live 10 s instead of 120: a requeued job waits that long
# (Reason=BeginTime) before it may run again.
AuthInfo=cred_expire=10
SlurmctldPort=6817
SlurmdPort=6818

StateSaveLocation=$DIR/state
SlurmctldPidFile=$DIR/run/slurmctld.pid
SlurmctldLogFile=$DIR/log/slurmctld.log
EOF
  if [ "$n" -eq 0 ]; then
    cat <<EOF
SlurmdSpoolDir=$DIR/spool
SlurmdPidFile=$DIR/run/slurmd.pid
SlurmdLogFile=$DIR/log/slurmd.log
EOF
  else
    cat <<EOF
# %n: the node name, so that the namespace nodes' slurmd keep apart files.
SlurmdSpoolDir=$DIR/spool/%n
SlurmdPidFile=$DIR/run/slurmd-%n.pid
SlurmdLogFile=$DIR/log/slurmd-%n.log
EOF
  fi
  cat <<EOF
SlurmctldDebug=info
SlurmdDebug=info

# No systemd, maybe no cgroups (containers): by default a job's processes are
# its process groups (a process that calls setsid/setpgid, e.g. under
# 'timeout', escapes; proctrack/linuxproc instead loses children whose parent
# died, and they outlive the job). No CPU binding, no accounting daemon:
# finished jobs are in jobcomp.log, and 'scontrol show job' keeps them
# MinJobAge seconds.
ProctrackType=proctrack/$PROCTRACK
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/filetxt
JobCompLoc=$DIR/log/jobcomp.log
MpiDefault=none
SwitchType=switch/none
MailProg=/bin/true

# One CPU is one slot: N one-CPU jobs run at once on N CPUs. The node gives
# CPUs only: with Sockets/Cores/Threads, CR_CPU allocates whole cores.
SchedulerType=sched/backfill
# Look at pending jobs every 2 s (default 60 s, backfill 30 s): a job that
# becomes eligible by time (requeued, --begin) starts within seconds.
SchedulerParameters=sched_interval=2,bf_interval=2
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
MaxArraySize=100001
MaxJobCount=200000

# Requeue and preemption: jobs in 'urgent' requeue running 'debug' jobs.
JobRequeue=1
PreemptType=preempt/partition_prio
PreemptMode=REQUEUE

# Short timeouts for tests: SIGTERM, then SIGKILL KillWait seconds later.
KillWait=10
SlurmdTimeout=30
SlurmctldTimeout=30
InactiveLimit=0
MinJobAge=300
ReturnToService=2

EOF
  if [ "$n" -eq 0 ]; then
    echo "NodeName=$node NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$mem State=UNKNOWN"
    nodelist=$node
  else
    # Every node offers the machine's CPUs and a share of its memory: the nodes
    # share the cores, as the jobs of a busy cluster node would.
    for ((k = 1; k <= n; k++)); do
      echo "NodeName=$(netns_node_name "$k") NodeAddr=$(netns_node_addr "$k") NodeHostname=$(netns_node_name "$k") CPUs=$cpus RealMemory=$((mem / n)) State=UNKNOWN"
    done
    nodelist="${NETNS_PREFIX}[1-$n]"
  fi
  cat <<EOF
PartitionName=debug Nodes=$nodelist Default=YES MaxTime=INFINITE State=UP PriorityTier=1
PartitionName=urgent Nodes=$nodelist Default=NO MaxTime=INFINITE State=UP PriorityTier=10 PreemptMode=OFF
EOF
}

# --- start ------------------------------------------------------------------

prepare_dirs() {
  mkdir -p "$DIR"/{state,spool,run,log,smoke} /etc/slurm
  chmod 755 "$DIR"
  # munged runs as user munge and refuses folders others may write to.
  mkdir -p "$DIR/munge" "$MUNGE_RUN"
  chown munge:munge "$DIR/munge" "$MUNGE_RUN"
  chmod 755 "$DIR/munge"
  chmod 755 "$MUNGE_RUN"
}

start_munged() {
  if [ ! -s "$KEY" ]; then
    say "creating the munge key $KEY"
    mkdir -p "$(dirname "$KEY")"
    chown munge:munge "$(dirname "$KEY")"
    chmod 700 "$(dirname "$KEY")"
    runuser -u munge -- mungekey --create --keyfile="$KEY"
  fi
  chown munge:munge "$KEY"
  chmod 400 "$KEY"
  if ! daemon_pid munged >/dev/null; then
    local other
    other=$(foreign_pids munged)
    [ -z "$other" ] || die "munged already runs (pid $other) but was not started by $PROG: stop it first"
    say "starting munged"
    rm -f "$MUNGE_RUN/munge.socket.2.lock"
    runuser -u munge -- /usr/sbin/munged \
      --pid-file="$(pidfile_of munged)" --log-file="$(logfile_of munged)" \
      --seed-file="$DIR/munge/munged.seed" 9>&- ||
      fail_daemon munged "munged did not start"
  fi
  local i
  for ((i = 0; i < 50; i++)); do
    munge -n </dev/null 2>/dev/null | unmunge >/dev/null 2>&1 && return 0
    sleep 0.1
  done
  fail_daemon munged "munge -n | unmunge fails: munged does not answer on $MUNGE_RUN/munge.socket.2"
}

start_slurmctld() {
  if ! daemon_pid slurmctld >/dev/null; then
    local other
    other=$(foreign_pids slurmctld)
    [ -z "$other" ] || die "slurmctld already runs (pid $other) but was not started by $PROG: stop it first"
    say "starting slurmctld"
    # 9>&-: the daemons must not inherit the lock of this script, or it stays held
    slurmctld 2>>"$(logfile_of slurmctld)" 9>&- || fail_daemon slurmctld "slurmctld exited with status $?"
  fi
  local i
  for ((i = 0; i < READY_TIMEOUT * 2; i++)); do
    if ! daemon_pid slurmctld >/dev/null; then
      sleep 0.5
      daemon_pid slurmctld >/dev/null || fail_daemon slurmctld "slurmctld died after starting"
    fi
    scontrol ping 2>/dev/null | grep -q 'is UP' && return 0
    sleep 0.5
  done
  fail_daemon slurmctld "slurmctld does not answer 'scontrol ping' after ${READY_TIMEOUT} s"
}

# Starts one slurmd: `slurmd` on this machine, `slurmd@NODE` in NODE's namespace.
start_slurmd() {
  local d=${1:-slurmd}
  if ! daemon_pid "$d" >/dev/null; then
    local other
    other=$(foreign_pids slurmd)
    [ -z "$other" ] || die "slurmd already runs (pid $other) but was not started by $PROG: stop it first"
    say "starting $d"
    if [ "$d" = slurmd ]; then
      slurmd -N "$(node_name)" 2>>"$(logfile_of "$d")" 9>&- || fail_daemon "$d" "slurmd exited with status $?"
    else
      mkdir -p "$DIR/spool/${d#slurmd@}"
      netns_exec "${d#slurmd@}" slurmd -N "${d#slurmd@}" 2>>"$(logfile_of "$d")" 9>&- ||
        fail_daemon "$d" "slurmd exited with status $?"
    fi
    sleep 0.5
    daemon_pid "$d" >/dev/null || fail_daemon "$d" "slurmd died after starting"
  fi
}

node_state() { sinfo -h -N -n "$1" -o '%T' 2>/dev/null | head -n 1; }

slurmd_of() { if [ "$(cluster_node_count)" -eq 0 ]; then echo slurmd; else echo "slurmd@$1"; fi; }

wait_nodes_ready() {
  local node
  for node in $(cluster_nodes); do wait_node_ready "$node"; done
}

wait_node_ready() {
  local node=$1 i state resumed=0 d
  d=$(slurmd_of "$node")
  for ((i = 0; i < READY_TIMEOUT * 2; i++)); do
    state=$(node_state "$node")
    case "$state" in
      idle | mixed | allocated | completing) say "node $node is $state"; return 0 ;;
      *drain*)
        # Left drained by an earlier configuration (state is kept across
        # restarts): resume once; a node that drains again fails below.
        if [ "$resumed" -eq 0 ]; then
          say "node $node is $state ($(scontrol show node "$node" | sed -n 's/.*Reason=//p')): resuming it"
          scontrol update NodeName="$node" State=RESUME || true
          resumed=1
        fi
        ;;
    esac
    daemon_pid "$d" >/dev/null || fail_daemon "$d" "slurmd died while the node registered"
    daemon_pid slurmctld >/dev/null || fail_daemon slurmctld "slurmctld died while the node registered"
    sleep 0.5
  done
  say "error: node $node is not idle after ${READY_TIMEOUT} s: state '${state:-unknown}'"
  scontrol show node "$node" 2>&1 | sed 's/^/    /' >&2 || true
  log_tail slurmctld 15
  log_tail "$d" 15
  exit 1
}

# Jobs that slurmctld recovered from its state as running, while no job
# process (slurmstepd) is left on this machine: their processes died with the
# daemons (a killed session, a reboot). Slurm would notice only at a later
# registration of slurmd, so mark the node down and back up at once, as after a
# node failure: requeuable jobs go back to pending, the others end NODE_FAIL.
recover_lost_jobs() {
  local node jobs p
  for p in $(pgrep -x slurmstepd); do
    alive "$p" && return 0
  done
  for node in $(cluster_nodes); do
    jobs=$(squeue -h -t R,CG,S -w "$node" -o %i 2>/dev/null | tr '\n' ' ')
    [ -n "${jobs// /}" ] || continue
    say "jobs $jobs are recorded as running on $node but their processes are gone: node down and up, so that they are requeued or failed"
    scontrol update NodeName="$node" State=DOWN Reason="slurm-local.sh: job processes lost" || true
    # With ReturnToService=2 the node is often back already; RESUME then fails.
    scontrol update NodeName="$node" State=RESUME 2>/dev/null || true
    wait_node_ready "$node"
  done
}

smoke_test() {
  local out id
  out=$DIR/smoke
  local queued
  queued=$(squeue -h -o %i 2>/dev/null | wc -l)
  if [ "$queued" -gt 0 ]; then
    say "$queued jobs in the queue: smoke test skipped (it would wait for them)"
    return 0
  fi
  rm -f "$out"/smoke-*.out
  id=$(cd "$out" && timeout "$READY_TIMEOUT" sbatch --parsable --wait -J cic-smoke -o "$out/smoke-%j.out" --wrap 'echo ok') || {
    id=${id%%;*}
    say "error: smoke test: 'sbatch --wait --wrap \"echo ok\"' failed or took over ${READY_TIMEOUT} s (job ${id:-not submitted})"
    [ -z "$id" ] || scancel "$id" 2>/dev/null || true
    log_tail slurmctld 15
    log_tail slurmd 15
    exit 1
  }
  id=${id%%;*}
  grep -qx ok "$out/smoke-$id.out" 2>/dev/null ||
    { say "error: smoke test: job $id did not write 'ok' to $out/smoke-$id.out"; log_tail slurmd 15; exit 1; }
  local all
  all=$(cluster_nodes | wc -l)
  (cd "$out" && timeout "$READY_TIMEOUT" srun -N "$all" -n "$all" -J cic-smoke-srun true) ||
    { say "error: smoke test: 'srun -N $all -n $all true' failed"; log_tail slurmctld 15; log_tail slurmd 15; exit 1; }
  say "smoke test passed: sbatch --wait (job $id) and srun -N $all true"
}

# start --fresh: cancel every job while slurmctld still runs, stop, and remove
# the state, spool and logs, so that nothing of an earlier session runs again.
reset_state() {
  local i
  if daemon_pid slurmctld >/dev/null && scontrol ping 2>/dev/null | grep -q 'is UP'; then
    local jobs
    jobs=$(squeue -h -o %A 2>/dev/null | sort -u | tr '\n' ' ')
    if [ -n "${jobs// /}" ]; then
      say "--fresh: cancelling jobs $jobs"
      # shellcheck disable=SC2086
      scancel $jobs 2>/dev/null || true
      for ((i = 0; i < 60; i++)); do
        squeue -h -t R,CG,S 2>/dev/null | grep -q . || break
        sleep 0.5
      done
    fi
  fi
  stop_slurmds
  stop_daemon slurmctld
  say "--fresh: removing $DIR/{state,spool,log,smoke}"
  rm -rf "${DIR:?}"/state "${DIR:?}"/spool "${DIR:?}"/log "${DIR:?}"/smoke
}

# Every slurmd this script may have started: the single node's and every
# namespace node's (whatever the node count was).
stop_slurmds() {
  local f
  stop_daemon slurmd
  for f in "$DIR"/run/slurmd-*.pid; do
    [ -e "$f" ] || continue
    f=${f##*/slurmd-}
    stop_daemon "slurmd@${f%.pid}"
  done
}

cmd_start() {
  need_root
  local t0=$SECONDS p fresh=0 nodes=0
  while [ $# -gt 0 ]; do
    case "$1" in
      --fresh) fresh=1 ;;
      --nodes)
        [ $# -ge 2 ] && [[ "$2" =~ ^[0-9]+$ ]] && [ "$2" -ge 1 ] && [ "$2" -le 16 ] ||
          die "start: --nodes takes a count from 1 to 16"
        nodes=$2
        shift
        ;;
      *) die "start: unknown option '$1' (--fresh, --nodes N)" ;;
    esac
    shift
  done
  for p in munged slurmctld slurmd sbatch srun sinfo scontrol; do
    command -v "$p" >/dev/null || die "$p is missing: run '$0 install' first"
  done
  [ "$fresh" -eq 0 ] || reset_state
  prepare_dirs
  # Another node count: stop the old cluster's slurmd before its nodes change.
  if [ "$(cluster_node_count)" != "$nodes" ]; then
    stop_slurmds
    [ "$nodes" -gt 0 ] || netns_down
    echo "$nodes" >"$NODES_FILE"
  fi
  [ "$nodes" -eq 0 ] || netns_up "$nodes"
  start_munged

  local new
  new=$(write_conf)
  if [ ! -f "$CONF" ] || [ "$new" != "$(cat "$CONF")" ]; then
    if daemon_pid slurmctld >/dev/null || [ -n "$(ls "$DIR"/run/slurmd*.pid 2>/dev/null)" ]; then
      say "configuration changed: restarting slurmctld and slurmd"
      stop_slurmds
      stop_daemon slurmctld
    fi
    printf '%s\n' "$new" >"$CONF"
    say "wrote $CONF"
  fi
  # Tells cgroup-aware code (none is loaded with proctrack/pgid and task/none)
  # not to call systemd; harmless where cgroups are absent.
  if [ ! -f "$CGROUP_CONF" ] || ! grep -q 'slurm-local.sh' "$CGROUP_CONF"; then
    printf '# Written by scripts/slurm-local.sh (cic)\nCgroupPlugin=autodetect\nIgnoreSystemd=yes\n' >"$CGROUP_CONF"
  fi

  start_slurmctld
  local d
  for d in $(slurmd_daemons); do start_slurmd "$d"; done
  wait_nodes_ready
  recover_lost_jobs
  smoke_test
  say "Slurm is up in $((SECONDS - t0)) s: node(s) $(cluster_nodes | tr '\n' ' ')with $(node_resources | awk '{print $1 " CPUs, " $2 " MB"}') each, state and logs in $DIR"
}

# A node lost mid-study, as when its machine dies: every process on it gets
# SIGKILL (slurmd, slurmstepd, the jobs), and the node is marked DOWN, which
# is what slurmctld concludes after SlurmdTimeout. Jobs submitted with
# --requeue go back to pending and run on the other nodes; others end NODE_FAIL.
cmd_kill_node() {
  need_root
  local node=${1:-}
  [ "$(cluster_node_count)" -gt 0 ] || die "kill-node needs a cluster started with --nodes N"
  cluster_nodes | grep -x "$node" >/dev/null || die "kill-node: no node '$node' (nodes: $(cluster_nodes | tr '\n' ' '))"
  say "losing node $node: SIGKILL to every process in its namespace"
  netns_kill_all "$node"
  rm -f "$(pidfile_of "slurmd@$node")"
  scontrol update NodeName="$node" State=DOWN Reason="lost (slurm-local.sh kill-node)"
  say "node $node is $(node_state "$node")"
}

cmd_revive_node() {
  need_root
  local node=${1:-}
  cluster_nodes | grep -x "$node" >/dev/null || die "revive-node: no node '$node' (nodes: $(cluster_nodes | tr '\n' ' '))"
  start_slurmd "slurmd@$node"
  scontrol update NodeName="$node" State=RESUME 2>/dev/null || true
  wait_node_ready "$node"
}

cmd_stop() {
  need_root
  stop_slurmds
  stop_daemon slurmctld
  stop_daemon munged
  netns_down
  local steps
  steps=$(pgrep -x slurmstepd | tr '\n' ' ' || true)
  [ -z "$steps" ] || say "note: job steps still run (slurmstepd $steps); a new start reattaches them"
  say "stopped"
}

cmd_status() {
  local name pid ok=0 other
  for name in munged slurmctld $(slurmd_daemons); do
    if pid=$(daemon_pid "$name"); then
      echo "$name: running (pid $pid)"
    else
      other=$(foreign_pids "$name")
      if [ -n "$other" ]; then
        echo "$name: not started by $PROG, but runs as pid $other"
      else
        echo "$name: not running"
      fi
      ok=1
    fi
  done
  if command -v scontrol >/dev/null && [ -f "$CONF" ]; then
    scontrol ping 2>&1 | sed 's/^/scontrol ping: /' || true
    echo "--- sinfo"
    timeout 15 sinfo -N -l 2>&1 || true
    echo "--- squeue"
    timeout 15 squeue 2>&1 || true
  fi
  echo "state and logs: $DIR"
  return "$ok"
}

# One start or stop at a time (parallel test runners may call start together).
lock() {
  need_root
  mkdir -p "$DIR"
  exec 9>"$DIR/.lock"
  flock -w 300 9 || die "another slurm-local.sh holds $DIR/.lock"
}

case "${1:-}" in
  install) cmd_install ;;
  start) shift; lock; cmd_start "$@" ;;
  stop) lock; cmd_stop ;;
  status) cmd_status ;;
  nodes) cluster_nodes ;;
  kill-node) shift; lock; cmd_kill_node "$@" ;;
  revive-node) shift; lock; cmd_revive_node "$@" ;;
  rsh)
    # Open MPI calls the agent as: AGENT HOST COMMAND-WORDS...; they form one shell command.
    shift
    [ $# -ge 2 ] || die "rsh: NODE COMMAND..."
    need_root
    node=$1
    shift
    netns_exec "$node" sh -c "$*"
    ;;
  *) usage ;;
esac
