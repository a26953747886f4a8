#!/usr/bin/env bash
# A real single-node Slurm for tests (docs/sweeps.md): munged, slurmctld and slurmd on 127.0.0.1,
# all state, sockets, logs and pid files under one directory, no systemd, stopped by PID.
#   slurm-local.sh start DIR   # starts it; then: export SLURM_CONF=DIR/etc/slurm.conf
#   slurm-local.sh stop DIR    # cancels its jobs, stops the three daemons by their pid files
# Needs the Debian 12 packages slurm-wlm and munge, and root (the daemons run as root). Ports:
# VBIM_SLURM_PORT (default 6817) for slurmctld and the next one for slurmd. Configuration keys:
# https://slurm.schedmd.com/slurm.conf.html
set -euo pipefail

cmd=${1:?usage: slurm-local.sh start|stop DIR}
dir=${2:?usage: slurm-local.sh start|stop DIR}
port=${VBIM_SLURM_PORT:-6817}
conf="$dir/etc/slurm.conf"

# TERM a daemon by its pid file and wait for it to go (KILL after 15 s).
stop_pid() {
  local file=$1 pid
  [ -f "$file" ] || return 0
  pid=$(cat "$file")
  kill -TERM "$pid" 2>/dev/null || return 0
  for _ in $(seq 150); do
    kill -0 "$pid" 2>/dev/null || return 0
    sleep 0.1
  done
  kill -KILL "$pid" 2>/dev/null || true
}

start() {
  for tool in munged slurmctld slurmd sinfo; do
    command -v "$tool" >/dev/null || { echo "slurm-local: $tool not found (apt-get install slurm-wlm munge)" >&2; exit 1; }
  done
  mkdir -p "$dir"/{etc,state,spool,log,run}
  dir=$(cd "$dir" && pwd)
  conf="$dir/etc/slurm.conf"
  # munged wants every directory above its socket executable by all (a mktemp -d directory is
  # not): its socket and key live in a directory of their own under /tmp, removed by stop.
  local munge
  munge=$(mktemp -d /tmp/vbim-munge.XXXXXX)
  chmod 0755 "$munge"
  echo "$munge" >"$dir/run/munge.dir"
  head -c 1024 /dev/urandom >"$munge/munge.key"
  chmod 0400 "$munge/munge.key"
  # The daemons' stdio goes to /dev/null: they log to files, and must not hold a caller's pipe open.
  munged --socket="$munge/munge.socket.2" --key-file="$munge/munge.key" \
    --pid-file="$dir/run/munged.pid" --log-file="$dir/log/munged.log" --seed-file="$munge/munged.seed" \
    </dev/null >/dev/null 2>&1 || {
    echo "slurm-local: munged did not start:" >&2
    tail -n 3 "$dir/log/munged.log" >&2
    exit 1
  }
  # The node as slurmd sees it, with 512 MB of memory left to the system.
  # slurmctld accepts to run only on the host SlurmctldHost names: this one's short name.
  local host node cpus boards sockets cores threads memory
  host=$(hostname -s)
  node=$(slurmd -C | head -1)
  cpus=$(sed -n 's/.*CPUs=\([0-9]*\).*/\1/p' <<<"$node")
  boards=$(sed -n 's/.*Boards=\([0-9]*\).*/\1/p' <<<"$node")
  sockets=$(sed -n 's/.*SocketsPerBoard=\([0-9]*\).*/\1/p' <<<"$node")
  cores=$(sed -n 's/.*CoresPerSocket=\([0-9]*\).*/\1/p' <<<"$node")
  threads=$(sed -n 's/.*ThreadsPerCore=\([0-9]*\).*/\1/p' <<<"$node")
  memory=$(($(sed -n 's/.*RealMemory=\([0-9]*\).*/\1/p' <<<"$node") - 512))
  cat >"$conf" <<CONF
ClusterName=vbimlocal
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$munge/munge.socket.2
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/run/slurmctld.pid
SlurmdPidFile=$dir/run/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
PlugStackConfig=$dir/etc/plugstack.conf
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
DefMemPerCPU=1024
SchedulerParameters=batch_sched_delay=0
MinJobAge=300
ReturnToService=2
MailProg=/bin/true
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus Boards=$boards SocketsPerBoard=$sockets CoresPerSocket=$cores ThreadsPerCore=$threads RealMemory=$memory State=UNKNOWN
PartitionName=local Nodes=$host Default=YES MaxTime=INFINITE DefaultTime=60 State=UP
CONF
  : >"$dir/etc/plugstack.conf"
  export SLURM_CONF="$conf"
  slurmctld -f "$conf" </dev/null >/dev/null 2>&1
  slurmd -f "$conf" </dev/null >/dev/null 2>&1
  # Up when the node reports exactly "idle" ("idle*": not responding yet).
  for _ in $(seq 300); do
    if [ "$(sinfo -h -o %T 2>/dev/null)" = idle ]; then
      echo "slurm-local: up (export SLURM_CONF=$conf)"
      return 0
    fi
    sleep 0.1
  done
  echo "slurm-local: the node did not come up within 30 s; logs in $dir/log" >&2
  tail -n 5 "$dir/log/slurmctld.log" "$dir/log/slurmd.log" >&2 || true
  exit 1
}

stop() {
  dir=$(cd "$dir" && pwd)
  conf="$dir/etc/slurm.conf"
  # Jobs first: a job step's slurmstepd outlives slurmd.
  if [ -f "$conf" ] && [ -f "$dir/run/slurmctld.pid" ]; then
    SLURM_CONF="$conf" scancel --quiet --user="$(id -un)" 2>/dev/null || true
  fi
  stop_pid "$dir/run/slurmd.pid" &
  stop_pid "$dir/run/slurmctld.pid" &
  wait
  stop_pid "$dir/run/munged.pid"
  if [ -f "$dir/run/munge.dir" ]; then
    rm -rf "$(cat "$dir/run/munge.dir")"
    rm -f "$dir/run/munge.dir"
  fi
  echo "slurm-local: stopped"
}

case "$cmd" in
  start) start ;;
  stop) stop ;;
  *)
    echo "usage: slurm-local.sh start|stop DIR" >&2
    exit 2
    ;;
esac
