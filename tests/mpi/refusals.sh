#!/usr/bin/env bash
# refusals.sh SLIDE MPIEXEC OUT_DIR: what a run on several processes refuses (exit 2, nothing written, one message
# naming why), and a process that fails alone (a full disk) stopping all of them with its message and exit 1.
set -uo pipefail
slide="$1" mpiexec="$2" out="$3"
cases="$(dirname "$0")/../../cases"
rm -rf "$out"
mkdir -p "$out"
failed=0
# refused NAME EXPECTED_TEXT ARGS...: mpirun -np 2 slide run ARGS exits 2, says EXPECTED_TEXT, writes nothing.
refused() {
  local name="$1" expected="$2"
  shift 2
  local folder="$out/$name"
  "$mpiexec" --oversubscribe -np 2 "$slide" run "$@" --out "$folder" --threads 1 --quiet >"$out/$name.log" 2>&1
  local code=$?
  if [ "$code" -ne 2 ] || ! grep -q -- "$expected" "$out/$name.log" || [ -e "$folder" ]; then
    echo "FAIL $name: exit $code (expected 2), folder $([ -e "$folder" ] && echo written || echo absent):"
    cat "$out/$name.log"
    failed=1
  else
    echo "ok $name: $(grep -m1 -- "$expected" "$out/$name.log")"
  fi
}
refused bodies "a scene with rigid bodies cannot run on several processes yet" "$cases/floating_block_2d.yaml"
refused implicit "method.viscous_scheme implicit cannot run on several processes yet" "$cases/hb_poiseuille_2d.yaml"
refused pore_water "pore water under frictional sediment" "$cases/grilli2017_granular_slide_2d.yaml" \
  --set method.viscous_scheme=explicit
# A full disk on the first process, which writes: a small tmpfs where one can be mounted (root), else skipped.
disk="$out/full_disk"
mkdir -p "$disk"
if mount -t tmpfs -o size=60k tmpfs "$disk" 2>/dev/null; then
  timeout 120 "$mpiexec" --oversubscribe -np 3 "$slide" run "$cases/dam_break_2d.yaml" --out "$disk/run" --threads 1 \
    --quiet --set end_time=0.2 >"$out/full_disk.log" 2>&1
  code=$?
  umount "$disk"
  if [ "$code" -ne 1 ] || ! grep -q "by an error on process 0: .*No space left on device" "$out/full_disk.log"; then
    echo "FAIL full_disk: exit $code (expected 1: the failing process stops all):"
    cat "$out/full_disk.log"
    failed=1
  else
    echo "ok full_disk: $(grep -m1 "by an error" "$out/full_disk.log")"
  fi
else
  echo "full_disk not checked: no tmpfs can be mounted here (not root)"
fi
exit "$failed"
