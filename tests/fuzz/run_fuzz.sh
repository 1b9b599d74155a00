#!/usr/bin/env bash
# The `fuzz` test (ctest -L fuzz; tools/test -L fuzz installs clang's runtime first): builds the scene loader's
# libFuzzer target with AddressSanitizer and UndefinedBehaviorSanitizer in BUILD_DIR (clang++), seeds it with the
# shipped scenes (and a few --set lines), and fuzzes for SECONDS (default 60). A crash, an escaped exception other
# than SceneError, a leak or undefined behaviour fails the test; the input that caused it is left in BUILD_DIR.
# Exits 77 (ctest: skipped) where clang++ or its sanitizer runtime is missing.
set -euo pipefail
source_dir="$1" build_dir="$2" seconds="${3:-60}"
if ! command -v clang++ >/dev/null; then echo "fuzz test skipped: clang++ not found (Debian: clang)"; exit 77; fi
if ! echo 'int main(){}' | clang++ -x c++ -fsanitize=fuzzer-no-link,address -o /dev/null - 2>/dev/null; then
  echo "fuzz test skipped: clang's sanitizer runtime is missing (Debian: libclang-rt-14-dev)"; exit 77
fi
cmake -S "$source_dir" -B "$build_dir" -DSLIDE_FUZZ=ON -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_C_COMPILER=clang \
      -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build_dir" --target fuzz_scene_loader -j "$(nproc)"
seeds="$build_dir/fuzz_seeds" corpus="$build_dir/fuzz_corpus"
mkdir -p "$seeds" "$corpus"
cp "$source_dir"/cases/*.yaml "$seeds/"
{ cat "$source_dir/cases/dam_break_2d.yaml"; printf '%%%%\nend_time=0.5\nmethod.gradient=pmin\nbodies[0].density=900\n'; } \
  > "$seeds/dam_break_with_sets.yaml"
{ cat "$source_dir/cases/floating_block_2d.yaml"; printf '%%%%\nbodies[0].shape.angle=10\nfluid.phases[0].rheology.model=herschel_bulkley\n'; } \
  > "$seeds/floating_block_with_sets.yaml"
# Anchors and aliases: a cycle, an exponential tree, repeats that are fine.
cat > "$seeds/aliases.yaml" <<'YAML'
particle_spacing: &dp 0.02
end_time: *dp
fluid:
  phases: [&water {name: water}]
  regions: [{type: rectangle, min: &origin [0, 0], max: [0.2, 0.2]}]
walls:
  - points: [[0, 0.4], *origin, [0.6, 0], [0.6, 0.4]]
laughs: &l1 [&l0 [x, x, x], *l0, *l0]
again: [*l1, *l1, *l1]
cycle: &c [*c]
YAML
cd "$build_dir"
# Leaks and undefined behaviour end the run like a crash; -timeout flags an input that holds the loader more than a
# few seconds (a second unsanitized, issue 30's bound, is some three under AddressSanitizer).
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
./fuzz_scene_loader -max_total_time="$seconds" -timeout=3 -rss_limit_mb=2048 -max_len=16384 \
  -dict="$source_dir/tests/fuzz/scene.dict" \
  -print_final_stats=1 "$corpus" "$seeds"
