#!/usr/bin/env bash
# The `viewer` test (ctest -L viewer, or tools/test -L viewer, which installs ParaView first): runs the shipped dam
# break as shipped and the 3-D one (0.05 s, two fields in single precision) and opens their snapshots in ParaView
# (tests/viewer/check_paraview.py). Leaves the run and the
# screenshot in OUT_DIR (build/viewer/). Exits 77 (ctest: skipped) where ParaView's Python or xvfb-run is missing.
set -euo pipefail
slide="$1" source_dir="$2" out_dir="$3"
for tool in pvpython xvfb-run; do
  if ! command -v "$tool" >/dev/null; then
    echo "viewer test skipped: $tool not found (Debian: python3-paraview xvfb xauth; tools/test -L viewer installs them)"
    exit 77
  fi
done
rm -rf "$out_dir"
mkdir -p "$out_dir"
"$slide" run "$source_dir/cases/dam_break_2d.yaml" --out "$out_dir/dam_break_2d" --quiet --threads 1
xvfb-run -a pvpython "$source_dir/tests/viewer/check_paraview.py" "$out_dir/dam_break_2d" "$out_dir/paraview_dam_break_2d.png"
# A 3-D run, its first 0.05 s, with the snapshot options a large run would take: two fields, single precision.
"$slide" run "$source_dir/cases/dam_break_3d.yaml" --out "$out_dir/dam_break_3d" --quiet --threads 1 \
  --set end_time=0.05 --set output.snapshot_interval=0.01 --set 'output.snapshot_fields=[velocity, pressure]' \
  --set output.snapshot_precision=single
xvfb-run -a pvpython "$source_dir/tests/viewer/check_paraview.py" "$out_dir/dam_break_3d" "$out_dir/paraview_dam_break_3d.png"
