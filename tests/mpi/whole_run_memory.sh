#!/usr/bin/env bash
# whole_run_memory.sh SLIDE MPIEXEC OUT_DIR: over a whole run on 4 processes every process's peak stays below its
# memory estimate. The 3-D bench at dp 0.02 to its end (0.25 s): its water moves across the shares (a repartition)
# and spreads over the floor (its neighbour list grows), and its arrays are made and freed at every re-sort. Found at
# stop 60: at dp 0.01 on 4 processes, peaks of up to 211.2 MB against estimates of 182.4 MB (the shares' growth up
# to the rebalance threshold, not counted then; glibc's heap, kept since tools/large_blocks_to_system.hpp).
set -uo pipefail
slide="$(realpath "$1")" mpiexec="$2" out="$(realpath -m "$3")"
scene="$(realpath "$(dirname "$0")/../../cases/dam_break_bench_3d.yaml")"
rm -rf "$out"
mkdir -p "$out"
"$mpiexec" --oversubscribe -np 4 "$slide" run "$scene" --out "$out/four" --threads 1 --quiet \
  --set particle_spacing=0.02 || { echo "FAIL: the run on 4 processes"; exit 1; }
python3 - "$out/four/run.json" <<'PY'
import json, sys
run = json.load(open(sys.argv[1]))
p = run["partition"]
print(f"owned at the end {p['owned_particles']}, repartitions {p['repartitions']}")
failed = False
for r, m in enumerate(p["memory"]):
    e, peak = m["memory_estimate_bytes"], m["peak_resident_bytes"]
    listed, held = m["listed_neighbours"], m["particles_held"]
    print(f"process {r}: estimate {e / 1e6:.1f} MB, peak {peak / 1e6:.1f} MB ({100 * (e / peak - 1):+.1f} %), "
          f"listed {listed['at_first_build']:.0f} at the first build, at most {listed['most']:.0f}; "
          f"held {held['at_first_build']:.0f}, at most {held['most']:.0f}; made {m['particles_made_at_build']:.0f}")
    if not peak < e:
        print(f"FAIL: process {r}'s peak is above its estimate")
        failed = True
if run["simulated_time"] < 0.25 - 1e-9:
    print("FAIL: the run did not reach its end")
    failed = True
sys.exit(1 if failed else 0)
PY
