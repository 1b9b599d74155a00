#!/usr/bin/env bash
# restart.sh SLIDE MPIEXEC OUT_DIR: the dam break to 0.05 s straight on one process, and stopped at 0.03 s (--stop-at,
# which writes a checkpoint) on STOP processes and resumed (--resume) on RESUME processes, for STOP/RESUME 3/2 and 1/3:
# every file but run.json the same byte for byte. The checkpoint is the run's state as one process holds it, whatever
# the processes that wrote it. The same of the 3-D dam break, whose resumed run is built in parts, each process
# reading a part of the checkpoint's particles (tools/checkpoint.hpp, read_checkpoint_part). Then SIGTERM to mpirun
# during the run and while the water settles (2-D and 3-D), resumed on 2.
set -uo pipefail
slide="$1" mpiexec="$2" out="$3"
scene="$(dirname "$0")/../../cases/dam_break_2d.yaml"
rm -rf "$out"
mkdir -p "$out"
"$slide" run "$scene" --out "$out/straight" --threads 1 --quiet --set end_time=0.05 || exit 1
# on PROCESSES ARGS...: slide run ARGS on PROCESSES processes (1: without mpirun).
on() {
  local processes="$1"
  shift
  if [ "$processes" -eq 1 ]; then
    "$slide" run "$@" --threads 1 --quiet
  else
    "$mpiexec" --oversubscribe -np "$processes" "$slide" run "$@" --threads 1 --quiet
  fi
}
failed=0
# same_as STRAIGHT RUN LABEL: every file of STRAIGHT but run.json is in RUN byte for byte (else failed=1).
same_as() {
  local same=0 differ=0
  while IFS= read -r file; do
    if cmp -s "$1/$file" "$2/$file"; then same=$((same + 1)); else differ=$((differ + 1)); echo "differs: $file"; fi
  done < <(cd "$1" && find . -type f ! -name run.json | sort)
  echo "$3: $same files as the straight run's byte for byte, $differ differ"
  if [ "$differ" -ne 0 ] || [ "$same" -lt 3 ]; then failed=1; fi
}
# stop_and_resume STRAIGHT RUN STOP RESUME AT SCENE ARGS...: SCENE with ARGS stopped at AT on STOP processes, resumed on
# RESUME, against STRAIGHT.
stop_and_resume() {
  local straight="$1" run="$2" stop="$3" resume="$4" at="$5"
  shift 5
  on "$stop" "$@" --out "$run" --stop-at "$at" || { echo "FAIL: stop on $stop"; exit 1; }
  [ -f "$run/checkpoint.bin" ] || { echo "FAIL: no checkpoint after the stop on $stop"; exit 1; }
  on "$resume" --resume "$run" || { echo "FAIL: resume on $resume"; exit 1; }
  same_as "$straight" "$run" "$(basename "$run")"
}
for pair in 3/2 1/3; do
  stop="${pair%/*}" resume="${pair#*/}"
  stop_and_resume "$out/straight" "$out/stopped_on_${stop}_resumed_on_${resume}" "$stop" "$resume" 0.03 "$scene" \
    --set end_time=0.05
done
scene_3d=("$(dirname "$0")/../../cases/dam_break_3d.yaml" --set particle_spacing=0.005715 --set end_time=0.03)
"$slide" run "${scene_3d[@]}" --out "$out/straight_3d" --threads 1 --quiet || exit 1
for pair in 3/2 1/3; do
  stop="${pair%/*}" resume="${pair#*/}"
  stop_and_resume "$out/straight_3d" "$out/3d_stopped_on_${stop}_resumed_on_${resume}" "$stop" "$resume" 0.02 \
    "${scene_3d[@]}"
done
# No process of the 3-D resumed runs made the whole scene: each built its part (run.json's particles made at build).
python3 - "$out"/3d_stopped_on_*/run.json <<'PY' || { echo "FAIL: a 3-D resumed run built whole"; failed=1; }
import json, sys
for path in sys.argv[1:]:
    run = json.load(open(path))
    made = [m["particles_made_at_build"] for m in run["partition"]["memory"]]
    print(f"{path}: made at build {made} of {run['particles']['total']}")
    if max(made) >= run["particles"]["total"]:
        sys.exit(1)
PY
# terminate_and_resume LABEL STRAIGHT RUN EXPECTED WAIT SCENE ARGS...: slide run SCENE ARGS on 3 processes into RUN,
# SIGTERM to mpirun once WAIT (a command, given mpirun's process id and RUN) returns, its run.json's message holding
# EXPECTED and a checkpoint left; then
# resumed on 2 processes to the files of STRAIGHT (the same run straight on one process).
terminate_and_resume() {
  local label="$1" straight="$2" run="$3" expected="$4" wait_for="$5" scene="$6"
  shift 6
  "$slide" run "$scene" --out "$straight" --threads 1 --quiet "$@" || exit 1
  "$mpiexec" --oversubscribe -np 3 "$slide" run "$scene" --out "$run" --threads 1 --quiet "$@" &
  local pid=$!
  $wait_for "$pid" "$run"
  kill -TERM "$pid"
  wait "$pid"
  if ! grep -q "$expected" "$run/run.json" || [ ! -f "$run/checkpoint.bin" ]; then
    echo "FAIL: SIGTERM to mpirun ($label) left no checkpoint:"
    grep '"message"' "$run/run.json"
    exit 1
  fi
  echo "$(grep -m1 '"message"' "$run/run.json")"
  on 2 --resume "$run" || { echo "FAIL: resume on 2 after SIGTERM ($label)"; exit 1; }
  same_as "$straight" "$run" "terminated on 3 ($label), resumed on 2"
}
# SIGTERM to mpirun (what a scheduler sends before it kills a job): every process stops at the same step and the
# checkpoint resumes, here on 2 processes, to the straight run's files (to 0.6 s; the stop falls where it falls, a
# second after the run's first outputs).
running() {
  for _ in $(seq 1 600); do [ -f "$2/run.json" ] && break; sleep 0.1; done
  sleep 1
}
terminate_and_resume "running" "$out/straight_long" "$out/terminated_on_3_resumed_on_2" '"status": "interrupted"' \
  running "$scene" --set end_time=0.6
# SIGTERM while the water settles: the gated dam break settles for 2 s before t = 0, shared among the processes; the
# checkpoint settles on and runs on 2 processes. SIGTERM goes once every process catches it (its bit in SigCgt of
# /proc/PID/status: slide takes it from the end of the scene's build, before which it ends a process at once and
# writes nothing), then half a second more: a fixed 2 s wait ended the build instead with another run beside it on
# the 2 cores (measured at stop 60).
settling() {
  local pid="$1" caught children mask
  for _ in $(seq 1 600); do
    children=$(pgrep -P "$pid") caught=0
    for child in $children; do
      mask=$(awk '/^SigCgt/ {print $2}' "/proc/$child/status" 2>/dev/null || echo 0)
      (( 0x${mask:-0} >> 14 & 1 )) && caught=$((caught + 1))
    done
    [ -n "$children" ] && [ "$caught" -eq "$(wc -w <<<"$children")" ] && break
    sleep 0.1
  done
  sleep 0.5
}
terminate_and_resume "settling" "$out/straight_gated" "$out/terminated_settling_on_3_resumed_on_2" \
  'while the water settled' settling "$(dirname "$0")/../../cases/dam_break_gated_2d.yaml" --set end_time=0.02 \
  --set method.settling_time=2
# The same in 3-D: the floating box's water settles 0.3 s (6 s here) around the box held; built in parts, and resumed
# in parts from the settling's checkpoint.
terminate_and_resume "settling in 3-D" "$out/straight_box" "$out/3d_terminated_settling_on_3_resumed_on_2" \
  'while the water settled' settling "$(dirname "$0")/../../cases/floating_box_3d.yaml" --set particle_spacing=0.02 \
  --set method.settling_time=0.3 --set end_time=0.02
exit "$failed"
