#!/usr/bin/env bash
# refusals.sh SLIDE MPIEXEC OUT_DIR: a run folder one process cannot read (exit 2 on every process, that one saying why,
# nothing written), a scene one process alone refuses while it is built (the same), a launcher whose processes MPI
# does not join (exit 2, nothing written), a process that fails alone (a full disk) stopping all of them with its
# message and exit 1, and a run that goes unstable: exit 3 on 3 processes as on one, with the same files (its last good
# snapshot, from every process's own last good state).
# (More processes than cells: tests/test_cell_partition.cpp.)
set -uo pipefail
slide="$(realpath "$1")" mpiexec="$2" out="$(realpath -m "$3")"
cases="$(realpath "$(dirname "$0")/../../cases")"
rm -rf "$out"
mkdir -p "$out"
failed=0
# A run folder not shared by every process: a checkpoint the first process reads and the second cannot (each started
# in its own folder, the run's given relative to it). Every process exits 2, the second says why, and the run's files
# are left as they were.
mkdir -p "$out/first" "$out/second"
(cd "$out/first" && "$slide" run "$cases/dam_break_2d.yaml" --out run --threads 1 --quiet --set end_time=0.05 \
  --stop-at 0.02) || { echo "FAIL: the stopped run for the unshared folder"; failed=1; }
timeout 120 "$mpiexec" --oversubscribe -np 1 --wdir "$out/first" "$slide" run --resume run --threads 1 : \
  -np 1 --wdir "$out/second" "$slide" run --resume run --threads 1 >"$out/unshared.log" 2>&1
code=$?
if [ "$code" -ne 2 ] || ! grep -q "process 1 of 2 .*is the folder shared by every process" "$out/unshared.log" ||
  ! grep -q '"status": "stopped"' "$out/first/run/run.json"; then
  echo "FAIL unshared: exit $code (expected 2):"
  cat "$out/unshared.log"
  failed=1
else
  echo "ok unshared: $(grep -m1 "process 1 of 2" "$out/unshared.log")"
fi
# expect_refusal CODE NAME PATTERN: the run NAME exited 2, wrote nothing ($out/NAME absent), and its log
# ($out/NAME.log) matches PATTERN.
expect_refusal() {
  local code="$1" name="$2" pattern="$3"
  if [ "$code" -ne 2 ] || [ -e "$out/$name" ] || ! grep -q "$pattern" "$out/$name.log"; then
    echo "FAIL $name: exit $code (expected 2, nothing written, the log saying: $pattern):"
    cat "$out/$name.log"
    failed=1
  else
    echo "ok $name: $(grep -m1 "$pattern" "$out/$name.log" | head -c 160)"
  fi
}
# Started by a launcher whose MPI the program does not share (srun without PMI, another MPI's mpirun): the launcher
# says 3 processes, MPI joins each alone. Exit 2 before anything is written, naming the variable.
for variable in OMPI_COMM_WORLD_SIZE PMI_SIZE SLURM_STEP_NUM_TASKS; do
  env "$variable=3" timeout 120 "$slide" run "$cases/dam_break_2d.yaml" --out "$out/alone_$variable" --threads 1 \
    --quiet --set end_time=0.01 >"$out/alone_$variable.log" 2>&1
  expect_refusal $? "alone_$variable" "launcher started 3 processes ($variable=3) but MPI joined 1"
done
# A scene refused while it is built by a process other than the first alone (here its own memory limit, 1 kB): every
# process exits 2 before the build shares the scene, and that process says why, with its number; nothing is written.
timeout 120 "$mpiexec" --oversubscribe -np 1 "$slide" run "$cases/dam_break_2d.yaml" --out "$out/refused_by_one" \
  --threads 1 --quiet --set end_time=0.01 : -np 1 -x SLIDE_MEMORY_LIMIT=1k "$slide" run "$cases/dam_break_2d.yaml" \
  --out "$out/refused_by_one" --threads 1 --quiet --set end_time=0.01 >"$out/refused_by_one.log" 2>&1
expect_refusal $? refused_by_one "process 1 of 2 .*particle_spacing: .*SLIDE_MEMORY_LIMIT"
# A 3-D scene is built in parts (cases/build_share.hpp): an overlap in the part of a process other than the first
# (two water boxes at the tank's far end) stops every process before the next step that reduces across them, and the
# processes that found it say why; exit 2, nothing written.
box='{type: box, min: [0.4, 0, 0], max: [0.45, 0.017145, 0.05]}'
timeout 120 "$mpiexec" --oversubscribe -np 3 "$slide" run "$cases/dam_break_3d.yaml" --out "$out/overlap_in_a_part" \
  --threads 1 --quiet --set particle_spacing=0.005715 \
  --set "fluid.regions=[{type: box, min: [0, 0, 0], max: [0.05715, 0.017145, 0.1143]}, $box, $box]" \
  >"$out/overlap_in_a_part.log" 2>&1
expect_refusal $? overlap_in_a_part "process [12] of 3 .*fluid.regions\[2\]: overlaps fluid.regions\[1\]"
# A damaged checkpoint of a 3-D run resumed on 3 processes, which each read a part of its particles and where the first
# alone checks the whole file's checksum (tools/checkpoint.hpp, read_checkpoint_part): a byte flipped in the middle
# (among the particles) stops every process with exit 2, the first saying why, the run's files as they were.
damaged="$out/damaged_3d"
"$slide" run "$cases/dam_break_3d.yaml" --out "$damaged" --threads 1 --quiet --set particle_spacing=0.005715 \
  --set end_time=0.03 --stop-at 0.02 || { echo "FAIL: the stopped 3-D run"; failed=1; }
python3 - "$damaged/checkpoint.bin" <<'PY'
import sys
data = bytearray(open(sys.argv[1], "rb").read())
data[len(data) // 2] ^= 1
open(sys.argv[1], "wb").write(data)
PY
gauges_before=$(md5sum <"$damaged/gauges.csv")
timeout 120 "$mpiexec" --oversubscribe -np 3 "$slide" run --resume "$damaged" --threads 1 --quiet \
  >"$out/damaged_3d.log" 2>&1
code=$?
if [ "$code" -ne 2 ] || ! grep -q "is damaged (its checksum does not match" "$out/damaged_3d.log" ||
  [ "$(md5sum <"$damaged/gauges.csv")" != "$gauges_before" ]; then
  echo "FAIL damaged_3d: exit $code (expected 2, the checksum named, gauges.csv as it was):"
  cat "$out/damaged_3d.log"
  failed=1
else
  echo "ok damaged_3d: $(grep -m1 "is damaged" "$out/damaged_3d.log" | head -c 160)"
fi
# A checkpoint whose last particle's id is past the scene's (its checksum made anew): the last of 3 processes, which
# reads that part, refuses it alone; every process exits 2 and that one says why, with its number.
"$slide" run "$cases/dam_break_3d.yaml" --out "$out/wrong_id" --threads 1 --quiet --set particle_spacing=0.005715 \
  --set end_time=0.03 --stop-at 0.02 || { echo "FAIL: the stopped 3-D run"; failed=1; }
python3 - "$out/wrong_id/checkpoint.bin" <<'PY'
import struct, sys
data = bytearray(open(sys.argv[1], "rb").read())
at = 12  # magic, format
def string():
    global at
    n = struct.unpack_from("<Q", data, at)[0]
    at += 8 + n
string(); string()  # version, scene file
overrides = struct.unpack_from("<Q", data, at)[0]
at += 8
for _ in range(overrides):
    string()
string()  # resolved scene
at += 8 + 8 + 1  # time, step, settling
record_bytes, particles = struct.unpack_from("<QQ", data, at + 1)
last = at + 17 + (particles - 1) * record_bytes
id_at = bytes(data[last:last + record_bytes]).find(struct.pack("<Q", particles - 1))
struct.pack_into("<Q", data, last + id_at, particles + 5)
h = 1469598103934665603
for b in data[:-8]:
    h = ((h ^ b) * 1099511628211) & 0xFFFFFFFFFFFFFFFF
struct.pack_into("<Q", data, len(data) - 8, h)
open(sys.argv[1], "wb").write(data)
PY
timeout 120 "$mpiexec" --oversubscribe -np 3 "$slide" run --resume "$out/wrong_id" --threads 1 --quiet \
  >"$out/wrong_id.log" 2>&1
code=$?
if [ "$code" -ne 2 ] || ! grep -q "process 2 of 3 .*the checkpoint's particles are not the scene's" "$out/wrong_id.log"
then
  echo "FAIL wrong_id: exit $code (expected 2, the last process saying why):"
  cat "$out/wrong_id.log"
  failed=1
else
  echo "ok wrong_id: $(grep -m1 "process 2 of 3" "$out/wrong_id.log" | head -c 160)"
fi
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
# Unstable (a sound speed far too low for the water, as tests/test_cli.cpp's Cli.UnstableRunExits3WithSnapshot).
unstable=(run "$cases/dam_break_2d.yaml" --threads 1 --quiet --set method.sound_speed=0.3
          --set method.initial_state=lattice)
"$slide" "${unstable[@]}" --out "$out/unstable_one" >"$out/unstable_one.log" 2>&1
code_one=$?
timeout 300 "$mpiexec" --oversubscribe -np 3 "$slide" "${unstable[@]}" --out "$out/unstable_three" \
  >"$out/unstable_three.log" 2>&1
code_three=$?
differ=$(cd "$out/unstable_one" && find . -type f ! -name run.json | sort | while read -r f; do
  cmp -s "$f" "$out/unstable_three/$f" || echo "$f"; done)
if [ "$code_one" -ne 3 ] || [ "$code_three" -ne 3 ] || [ -n "$differ" ] ||
  ! grep -q "unstable at t = .*last good snapshot" "$out/unstable_three.log"; then
  echo "FAIL unstable: exit $code_one on one process and $code_three on 3 (expected 3), files that differ: $differ"
  cat "$out/unstable_three.log"
  failed=1
else
  echo "ok unstable: $(grep -m1 "unstable at" "$out/unstable_three.log" | head -c 160); the same files as one process"
fi
exit "$failed"
