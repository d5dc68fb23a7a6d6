#!/usr/bin/env bash
# The README's recipes for grading a class across machines, run for real on this machine:
#
#   test.sh slurm    <root> <build> <work> <grading_class>
#   test.sh parallel <root> <build> <work> <grading_class>
#
# slurm: a single-node Slurm cluster (Debian's slurm-wlm and munge) is started here, with its
# own configuration, keys, sockets, ports and state in <work>/slurm, and stopped at the end
# whatever happens; the README's job script and commands then grade the class of 30
# (grading_class make) as a job array, and write the class files on this side. parallel: the
# README's GNU parallel commands, with the local machine as the only host (`:`, so no ssh).
# Both check every result, the class files, the similarity report and the LMS files
# (grading_class check), and that the final run graded nothing itself. The commands are taken
# from tests/grading/README.md (the blocks after "<!-- run by tests/grading/deploy/cluster/test.sh ... -->"), so
# the README says exactly what this runs. Slurm grades the class of 30, GNU parallel 10 of them.
# Exits 77 (skipped) with the reason when an engine
# cannot start here: Slurm needs root.
set -euo pipefail
engine=$1 root=$2 build=$3 work=$4 class_tool=$5

# Skipped (77) where an engine cannot start here; under CI=true that is a failure: CI must run it.
skip() {
  echo "SKIPPED: $*"
  [[ ${CI:-} == true ]] && { echo "CI=true: this test must run in CI"; exit 1; }
  exit 77
}
fail() { echo "FAILED: $*" >&2; exit 1; }

[[ $(cd "$build" && pwd -P) == $(cd "$root" && pwd -P)/build/solutions ]] ||
  skip "the README's recipes use the build in build/solutions; this test suite runs in $build"

# The block of README.md after the marker line, as it is there.
recipe() {
  local text
  text=$(awk -v m="<!-- run by tests/grading/deploy/cluster/test.sh $1 -->" '
    $0 == m { found = 1; next }
    found && !inside && /^```sh$/ { inside = 1; next }
    inside && /^```$/ { exit }
    inside { print }' "$root/tests/grading/README.md")
  [[ -n $text ]] || fail "tests/grading/README.md has no block marked '$1'"
  printf '%s\n' "$text"
}

# Slurm grades the class of 30; GNU parallel 10 of them (one of each kind the report must tell
# apart), to keep the suite's time: the two recipes share everything but the engine.
size=30
[[ $engine == parallel ]] && size=10
rm -rf "$work" && mkdir -p "$work"
"$class_tool" make --setup "$build/grading" --out "$work/submissions" --expect "$work/expected.tsv" --size "$size"
export WORKBOOK=$root SUBMISSIONS=$work/submissions GRADES=$work/grades

# ---- Slurm -------------------------------------------------------------------------------------
slurm_dir=$work/slurm
free_port() {  # a port nothing listens on, from $1 up
  local p=$1
  while (exec 3<>"/dev/tcp/127.0.0.1/$p") 2>/dev/null; do p=$((p + 1)); done
  echo "$p"
}

stop_slurm() {
  [[ -f $slurm_dir/slurm.conf ]] && SLURM_CONF=$slurm_dir/slurm.conf scontrol shutdown >/dev/null 2>&1 || true
  local pidfile pid
  for pidfile in "$slurm_dir"/slurmctld.pid "$slurm_dir"/slurmd.pid "$slurm_dir"/munge/munged.pid; do
    [[ -f $pidfile ]] || continue
    pid=$(cat "$pidfile")
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -0 "$pid" 2>/dev/null && kill "$pid" 2>/dev/null
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    if kill -0 "$pid" 2>/dev/null; then kill -9 "$pid" 2>/dev/null || true; fi
  done
  return 0
}

start_slurm() {
  [[ $(id -u) -eq 0 ]] || skip "a single-node Slurm needs root to start here (slurmd runs jobs as their user)"
  local missing=""
  for p in munged slurmctld slurmd sbatch scontrol sinfo; do command -v "$p" >/dev/null 2>&1 || missing+=" $p"; done
  [[ -z $missing ]] || skip "not installed:$missing (cmake/workbook test installs slurm-wlm and munge)"
  mkdir -p "$slurm_dir"/{munge,state,spool,log}
  chmod 755 "$slurm_dir" "$slurm_dir/munge"
  head -c 1024 /dev/urandom > "$slurm_dir/munge/munge.key" && chmod 600 "$slurm_dir/munge/munge.key"
  trap stop_slurm EXIT
  "$(command -v munged)" --force --socket="$slurm_dir/munge/socket" --key-file="$slurm_dir/munge/munge.key" \
    --pid-file="$slurm_dir/munge/munged.pid" --log-file="$slurm_dir/munge/munged.log" --seed-file="$slurm_dir/munge/seed" ||
    skip "munged does not start here: $(tail -n 3 "$slurm_dir/munge/munged.log" 2>/dev/null)"
  local host ctld_port
  host=$(hostname -s)
  ctld_port=$(free_port $((20000 + $$ % 20000)))
  write_slurm_conf "$host" "$ctld_port" "$(free_port $((ctld_port + 1)))"
  export SLURM_CONF=$slurm_dir/slurm.conf
  "$(command -v slurmctld)" -i || skip "slurmctld does not start here: $(tail -n 3 "$slurm_dir/log/slurmctld.log" 2>/dev/null)"
  "$(command -v slurmd)" -N "$host" || skip "slurmd does not start here: $(tail -n 3 "$slurm_dir/log/slurmd.log" 2>/dev/null)"
  for _ in $(seq 100); do
    [[ $(sinfo -h -N -o %T 2>/dev/null) == idle ]] && return 0
    sleep 0.2
  done
  skip "the Slurm node did not come up: $(tail -n 3 "$slurm_dir/log/slurmd.log" 2>/dev/null)"
}

write_slurm_conf() {
  cat > "$slurm_dir/slurm.conf" <<EOF
# A single-node cluster for the test suite (tests/grading/deploy/cluster/test.sh); nothing outside $slurm_dir.
ClusterName=workbook
SlurmctldHost=$1(127.0.0.1)
SlurmctldPort=$2
SlurmdPort=$3
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$slurm_dir/munge/socket
StateSaveLocation=$slurm_dir/state
SlurmdSpoolDir=$slurm_dir/spool
SlurmctldPidFile=$slurm_dir/slurmctld.pid
SlurmdPidFile=$slurm_dir/slurmd.pid
SlurmctldLogFile=$slurm_dir/log/slurmctld.log
SlurmdLogFile=$slurm_dir/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
SchedulerParameters=sched_min_interval=100000,batch_sched_delay=0
ReturnToService=2
NodeName=$1 NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=workbook Nodes=$1 Default=YES MaxTime=INFINITE State=UP
EOF
}

# ---- the run -------------------------------------------------------------------------------------
case "$engine" in
  slurm)
    start_slurm
    recipe "slurm, as grade.sh" > "$work/grade.sh"
    commands=$(recipe slurm)
    ;;
  parallel)
    command -v parallel >/dev/null 2>&1 || skip "GNU parallel is not installed (cmake/workbook test installs it)"
    export HOSTS="$(nproc)/:"   # the local machine, $(nproc) jobs at once, no ssh
    export PARALLEL_HOME=$work/parallel-home   # its cache, here rather than in ~/.parallel
    commands=$(recipe parallel)
    ;;
  *) fail "unknown engine $engine" ;;
esac

echo "== The README's $engine recipe, in $work:"
printf '%s\n' "$commands" | sed 's/^/    /'
start=$(date +%s.%N)
(cd "$work" && bash -euo pipefail -c "$commands") > "$work/run.txt" 2>&1 || { cat "$work/run.txt"; fail "the recipe failed"; }
end=$(date +%s.%N)
tail -n 4 "$work/run.txt"
grep -q '"graded": 0,' "$GRADES/run.json" || fail "the class files' run graded something itself: $(head -c 400 "$GRADES/run.json")"
[[ -z $(ls "$GRADES/.work" 2>/dev/null) ]] || fail "left in $GRADES/.work: $(ls "$GRADES/.work")"
"$class_tool" check --setup "$build/grading" --class "$SUBMISSIONS" --expect "$work/expected.tsv" --grades "$GRADES" --size "$size"
awk -v e="$engine" -v n="$(ls "$SUBMISSIONS" | wc -l)" -v s="$start" -v t="$end" \
  'BEGIN { printf "== %s: %d submissions graded and the class files written in %.1f s of wall time\n", e, n, t - s }'
