#!/usr/bin/env bash
# same_outputs.sh SLIDE MPIEXEC PROCESSES OUT_DIR CASE [--set KEY=VALUE ...]: runs the shipped CASE (cases/CASE.yaml)
# on one process (without mpirun) and on PROCESSES (mpirun --oversubscribe), one thread each, and fails unless both
# complete and every file the one-process run wrote, but run.json (its wall times and process count), is in the other's
# folder byte for byte. Leaves both folders in OUT_DIR.
set -uo pipefail
slide="$1" mpiexec="$2" processes="$3" out="$4" case_name="$5"
shift 5
scene="$(dirname "$0")/../../cases/$case_name.yaml"
one="$out/one" many="$out/on_$processes"
rm -rf "$one" "$many"
mkdir -p "$out"
if ! "$slide" run "$scene" --out "$one" --threads 1 --quiet "$@"; then
  echo "FAIL: the one-process run of $case_name did not complete"
  exit 1
fi
if ! "$mpiexec" --oversubscribe -np "$processes" "$slide" run "$scene" --out "$many" --threads 1 --quiet "$@"; then
  echo "FAIL: the run of $case_name on $processes processes did not complete"
  exit 1
fi
same=0 differ=0
while IFS= read -r file; do
  if cmp -s "$one/$file" "$many/$file"; then
    same=$((same + 1))
  else
    differ=$((differ + 1))
    echo "differs: $file"
  fi
done < <(cd "$one" && find . -type f ! -name run.json | sort)
echo "$case_name on $processes processes: $same files the same byte for byte, $differ differ"
if ! grep -q "\"processes\": $processes" "$many/run.json"; then
  echo "FAIL: run.json does not say $processes processes"
  exit 1
fi
[ "$differ" -eq 0 ] && [ "$same" -ge 3 ]
