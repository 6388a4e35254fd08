#!/usr/bin/env bash
# A single-node Slurm cluster on localhost, from Debian's packages (munge, slurmctld, slurmd),
# with every file in one directory: a fresh munge key, its socket, slurm.conf, state, spool and
# logs. Slurm's and munge's files in /etc are neither read nor changed, so it runs beside a
# system Slurm. Ports are chosen free.
#   scripts/slurm-localhost.sh start DIR   starts munged, slurmctld and slurmd; waits until the
#                                          node is idle; prints "export SLURM_CONF=DIR/slurm.conf"
#   scripts/slurm-localhost.sh stop DIR    stops them (and every job they run)
# start fails (exit 1) with the daemons' own log lines when the cluster does not come up.
# Run it as root (as CI does). Run as another user, the daemons and the jobs run as that user
# (not tested here).
# Installs the packages when missing (apt-get; .ci/run and the test set-up rely on this).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
action="${1:?usage: slurm-localhost.sh start|stop DIR}"
dir="${2:?usage: slurm-localhost.sh start|stop DIR}"

stop() {
    local p
    for p in slurmd slurmctld munged; do
        [ -f "$dir/$p.pid" ] || continue
        kill "$(cat "$dir/$p.pid")" 2>/dev/null || true
    done
    # slurmd's job steps end with it; wait (bounded) for the daemons to exit
    for _ in $(seq 100); do
        local alive=0
        for p in slurmd slurmctld munged; do
            [ -f "$dir/$p.pid" ] && kill -0 "$(cat "$dir/$p.pid")" 2>/dev/null && alive=1
        done
        [ "$alive" = 0 ] && break
        sleep 0.1
    done
    rm -f "$dir"/*.pid
}

fail() {
    echo "slurm-localhost: $1" >&2
    local log
    for log in "$dir"/munged.log "$dir"/slurmctld.log "$dir"/slurmd.log; do
        [ -s "$log" ] && { echo "--- $log (last lines)" >&2; tail -n 15 "$log" >&2; }
    done
    stop
    exit 1
}

# A TCP port in 20000-39999 that nobody on localhost listens on (a connection is refused)
free_port() {
    local p
    for _ in $(seq 100); do
        p=$((20000 + RANDOM % 20000))
        (exec 3<>"/dev/tcp/127.0.0.1/$p") 2>/dev/null || { echo "$p"; return 0; }
    done
    echo "slurm-localhost: no free port found" >&2
    return 1
}

if [ "$action" = stop ]; then
    stop
    exit 0
fi
[ "$action" = start ] || { echo "usage: slurm-localhost.sh start|stop DIR" >&2; exit 2; }

source "$root/scripts/packages.sh"
kiln_install_missing munge slurmctld slurmd slurm-client

mkdir -p "$dir/state" "$dir/spool"
dir="$(cd "$dir" && pwd)"
chmod 700 "$dir"
user="$(id -un)"
node="$(hostname -s)"
cpus="$(nproc)"

# munge: a key of our own, and a socket in DIR
/usr/sbin/mungekey --create --keyfile="$dir/munge.key" --force 2>/dev/null ||
    dd if=/dev/urandom of="$dir/munge.key" bs=1024 count=1 status=none
chmod 600 "$dir/munge.key"
/usr/sbin/munged --force --key-file="$dir/munge.key" --socket="$dir/munge.socket" \
    --pid-file="$dir/munged.pid" --log-file="$dir/munged.log" --seed-file="$dir/munge.seed" ||
    fail "munged did not start"

ctld_port="$(free_port)"
slurmd_port="$(free_port)"
[ "$ctld_port" != "$slurmd_port" ] || slurmd_port=$((ctld_port + 1))
cat >"$dir/slurm.conf" <<EOF
# Written by kiln's scripts/slurm-localhost.sh: one node, localhost, everything in $dir
ClusterName=kiln-localhost
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=$user
SlurmdUser=$user
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$dir/munge.socket
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
PlugStackConfig=$dir/plugstack.conf
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SchedulerType=sched/builtin
SchedulerParameters=batch_sched_delay=0,sched_min_interval=0
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
SlurmdTimeout=30
InactiveLimit=0
KillWait=5
# A job whose dependency can no longer be met (a failed render) is cancelled, not left pending
DependencyParameters=kill_invalid_depend
NodeName=$node NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=kiln Nodes=$node Default=YES MaxTime=INFINITE State=UP
EOF
: >"$dir/plugstack.conf"
export SLURM_CONF="$dir/slurm.conf"

/usr/sbin/slurmctld -f "$SLURM_CONF" -i || fail "slurmctld did not start"
/usr/sbin/slurmd -f "$SLURM_CONF" -N "$node" || fail "slurmd did not start"

# Up when the node reports idle (bounded: 60 s)
for _ in $(seq 300); do
    state="$(sinfo -h -n "$node" -o %T 2>/dev/null || true)"
    [ "$state" = idle ] && { echo "export SLURM_CONF=$SLURM_CONF"; exit 0; }
    sleep 0.2
done
fail "the node did not become idle within 60 s (state: '${state:-none}')"
