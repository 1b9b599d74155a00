#!/usr/bin/env bash
# memory_guard.sh SLIDE MPIEXEC OUT_DIR: the memory guard holds each process's share of a run against its limit
# (SLIDE_MEMORY_LIMIT is a process's). The 3-D bench case: every process's estimate on four lies above its peak and
# below one process's estimate, and each made only its part of the scene; at a limit between them the scene is
# refused on one process (exit 2, naming particle_spacing, nothing written) and runs on four, every process's peak
# below the limit. A machine's memory
# (SLIDE_MACHINE_MEMORY, as MemAvailable) is shared by the processes on it: at a limit between one process's estimate
# and the four's together, one process runs and four on this machine are refused.
set -uo pipefail
slide="$(realpath "$1")" mpiexec="$2" out="$(realpath -m "$3")"
scene="$(realpath "$(dirname "$0")/../../cases/dam_break_bench_3d.yaml")"
rm -rf "$out"
mkdir -p "$out"
run_one() { "$slide" run "$scene" --out "$1" --threads 1 --quiet --set end_time=0.0005; }
run_four() { "$mpiexec" --oversubscribe -np 4 ${SLIDE_MEMORY_LIMIT:+-x SLIDE_MEMORY_LIMIT} \
  ${SLIDE_MACHINE_MEMORY:+-x SLIDE_MACHINE_MEMORY} "$slide" run "$scene" --out "$1" --threads 1 --quiet \
  --set end_time=0.0005; }
unset SLIDE_MEMORY_LIMIT SLIDE_MACHINE_MEMORY
run_one "$out/one" || { echo "FAIL: the one-process run"; exit 1; }
run_four "$out/four" || { echo "FAIL: the four-process run"; exit 1; }
# The limit halfway between the largest estimate on four and the estimate on one; every peak below its estimate.
limit=$(python3 - "$out" <<'PY'
import json, sys
one = json.load(open(sys.argv[1] + "/one/run.json"))
four = json.load(open(sys.argv[1] + "/four/run.json"))["partition"]["memory"]
e1 = one["memory_estimate_bytes"]
largest = max(m["memory_estimate_bytes"] for m in four)
for r, m in enumerate(four):
    print(f"process {r} of 4: estimate {m['memory_estimate_bytes'] / 1e6:.1f} MB, peak "
          f"{m['peak_resident_bytes'] / 1e6:.1f} MB", file=sys.stderr)
print(f"one process: estimate {e1 / 1e6:.1f} MB, peak {one['peak_resident_bytes'] / 1e6:.1f} MB", file=sys.stderr)
if not largest < e1:
    sys.exit(f"the largest estimate on four, {largest / 1e6:.1f} MB, is not below one process's, {e1 / 1e6:.1f} MB")
# Built in parts (cases/build_share.hpp): each process made fewer than half the scene's particles (its slab and a
# margin), and together at least all of them.
total = one["particles"]["total"]
made = [m["particles_made_at_build"] for m in four]
print(f"particles made at the build: {', '.join(f'{m:.0f}' for m in made)} of {total}", file=sys.stderr)
if not (max(made) < total / 2 and sum(made) >= total):
    sys.exit("the processes did not each make their part of the scene")
for r, m in enumerate(four):
    if not m["peak_resident_bytes"] < m["memory_estimate_bytes"]:
        sys.exit(f"process {r}'s peak is above its estimate")
print(int((largest + e1) / 2))
PY
) || { echo "FAIL: the estimates"; exit 1; }
echo "limit: $limit bytes a process"
# expect_refused NAME PATTERN: the run NAME (its log $out/NAME.log) exited 2, wrote nothing, and said PATTERN.
expect_refused() {
  local code="$?" name="$1" pattern="$2"
  if [ "$code" -ne 2 ] || [ -e "$out/$name" ] || ! grep -q "$pattern" "$out/$name.log"; then
    echo "FAIL: $name: exit $code (expected 2, nothing written, the log saying: $pattern):"
    cat "$out/$name.log"
    exit 1
  fi
}
export SLIDE_MEMORY_LIMIT="$limit"
run_one "$out/one_limited" >"$out/one_limited.log" 2>&1
expect_refused one_limited "particle_spacing: the run of its"
echo "ok one process refused: $(cat "$out/one_limited.log")"
run_four "$out/four_limited" || { echo "FAIL: four processes at the limit"; exit 1; }
python3 - "$out" "$limit" <<'PY' || { echo "FAIL: a peak on four above the limit"; exit 1; }
import json, sys
four = json.load(open(sys.argv[1] + "/four_limited/run.json"))["partition"]["memory"]
peaks = [m["peak_resident_bytes"] for m in four]
print("ok four processes ran: peaks", ", ".join(f"{p / 1e6:.1f}" for p in peaks),
      f"MB, limit {int(sys.argv[2]) / 1e6:.1f} MB")
sys.exit(0 if max(peaks) < int(sys.argv[2]) else 1)
PY
unset SLIDE_MEMORY_LIMIT
# The machine's memory halfway between one process's estimate and the sum of the four's.
machine=$(python3 - "$out" <<'PY'
import json, sys
e1 = json.load(open(sys.argv[1] + "/one/run.json"))["memory_estimate_bytes"]
four = sum(m["memory_estimate_bytes"] for m in json.load(open(sys.argv[1] + "/four/run.json"))["partition"]["memory"])
if not four > e1:
    sys.exit(f"four processes' estimates together, {four / 1e6:.1f} MB, are not above one process's, {e1 / 1e6:.1f} MB")
print(int((four + e1) / 2), int(0.99 * four))
PY
) || { echo "FAIL: the machine's estimates"; exit 1; }
read -r machine just_below <<<"$machine"
export SLIDE_MACHINE_MEMORY="$machine"
run_one "$out/one_machine" || { echo "FAIL: one process within the machine's $machine bytes"; exit 1; }
run_four "$out/four_machine" >"$out/four_machine.log" 2>&1
expect_refused four_machine "4 processes of the run on this machine"
echo "ok one process ran and four on this machine were refused at $machine bytes: $(head -1 "$out/four_machine.log")"
# Just below the four estimates together (1 %): the arrays' even part passes, the run's estimates summed do not.
export SLIDE_MACHINE_MEMORY="$just_below"
run_four "$out/four_just_below" >"$out/four_just_below.log" 2>&1
expect_refused four_just_below "on the 4 processes of the run on this machine together"
echo "ok four on this machine refused at $just_below bytes: $(head -1 "$out/four_just_below.log")"
