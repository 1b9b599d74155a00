"""Opens a run's particles.xdmf in ParaView as a user would, and checks what ParaView shows.

Run with ParaView's Python (Debian: python3-paraview) under a virtual display:
    xvfb-run -a pvpython tests/viewer/check_paraview.py RUN_DIR SCREENSHOT.png
For ParaView's default reader (Xdmf3, the one File > Open picks) and the legacy XDMF reader, at every snapshot
time: the points and one cell per point (a Polyvertex without connectivity gives zero cells in Xdmf3 and a blank
view), the arrays, the time values and the points' bounds, each against particles.h5 read with h5py. Then renders
the last snapshot coloured by pressure into SCREENSHOT.png. Exits 1 on the first mismatch, naming it.
"""
import sys

import h5py
from paraview.simple import (ColorBy, GetActiveViewOrCreate, OpenDataFile, ResetCamera, SaveScreenshot, Show,
                             Threshold, XDMFReader)



def fail(message):
    print("viewer check FAILED: " + message)
    sys.exit(1)


def snapshots(run_dir):
    """(time, particle count, bounds) of each snapshot, from particles.h5; the arrays its first snapshot holds (all but
    the geometry: output.snapshot_fields chooses them); its dimension."""
    out = []
    with h5py.File(f"{run_dir}/particles.h5", "r") as f:
        first = f["snapshots/000000"]
        arrays = set(first.keys()) - {"position", "connectivity"}
        dim = int(first.attrs["dim"])
        for i, t in enumerate(f["times"][()]):
            p = f[f"snapshots/{i:06d}/position"][()]
            out.append((float(t), p.shape[0], [p[:, k].min() for k in range(3)], [p[:, k].max() for k in range(3)]))
    return out, arrays, dim


def check_reader(name, reader, expected, expected_arrays):
    times = list(reader.TimestepValues)
    if len(times) != len(expected) or any(abs(a - b[0]) > 1e-12 for a, b in zip(times, expected)):
        fail(f"{name}: time values {times} differ from particles.h5's {[e[0] for e in expected]}")
    for t, n, lo, hi in expected:
        reader.UpdatePipeline(time=t)
        info = reader.GetDataInformation()
        points, cells = info.GetNumberOfPoints(), info.GetNumberOfCells()
        if points != n or cells != n:
            fail(f"{name} at t = {t}: {points} points and {cells} cells, particles.h5 has {n} particles")
        arrays = {reader.PointData.GetArray(i).GetName() for i in range(len(reader.PointData))}
        if not expected_arrays <= arrays:
            fail(f"{name} at t = {t}: arrays {sorted(arrays)} lack {sorted(expected_arrays - arrays)}")
        bounds = info.GetBounds()
        for k in range(3):
            if abs(bounds[2 * k] - lo[k]) > 1e-12 or abs(bounds[2 * k + 1] - hi[k]) > 1e-12:
                fail(f"{name} at t = {t}: bounds {bounds} differ from the positions' {lo} .. {hi}")
    print(f"{name}: {len(expected)} snapshots, {expected[0][1]}-{max(e[1] for e in expected)} points with as many "
          f"cells, arrays {sorted(expected_arrays)}, times {times[0]} .. {times[-1]}")


def main():
    run_dir, screenshot = sys.argv[1], sys.argv[2]
    expected, arrays, dim = snapshots(run_dir)
    default = OpenDataFile(f"{run_dir}/particles.xdmf")
    check_reader(f"default reader ({default.GetXMLName()})", default, expected, arrays)
    check_reader("legacy reader (XDMFReader)", XDMFReader(FileNames=[f"{run_dir}/particles.xdmf"]), expected, arrays)

    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = [1200, 700]
    view.ViewTime = expected[-1][0]
    # In 3-D the tank's walls hide the water: the water alone (kind 0) is drawn, as a user would threshold it.
    shown = default
    if dim == 3:
        shown = Threshold(Input=default)
        shown.Scalars = ["POINTS", "kind"]
        shown.ThresholdMethod = "Between"
        shown.LowerThreshold, shown.UpperThreshold = 0, 0
        shown.UpdatePipeline(expected[-1][0])
        with h5py.File(f"{run_dir}/particles.h5", "r") as f:
            water = int((f[f"snapshots/{len(expected) - 1:06d}/kind"][()] == 0).sum())
        if shown.GetDataInformation().GetNumberOfPoints() != water:
            fail(f"the water alone (kind 0): {shown.GetDataInformation().GetNumberOfPoints()} points, particles.h5 "
                 f"has {water}")
    display = Show(shown, view)
    display.SetRepresentationType("Points")
    display.PointSize = 3
    ColorBy(display, ("POINTS", "pressure"))
    display.RescaleTransferFunctionToDataRange(True)
    display.SetScalarBarVisibility(view, True)
    # 2-D: the x-y plane from the front; 3-D: a side view from -y, z up, turned a little to show the depth.
    view.CameraPosition = [0, 0, 1] if dim == 2 else [0.4, -1, 0.3]
    view.CameraViewUp = [0, 1, 0] if dim == 2 else [0, 0, 1]
    ResetCamera(view)
    SaveScreenshot(screenshot, view, ImageResolution=[1200, 700])
    print(f"screenshot: {screenshot} (t = {expected[-1][0]} s, coloured by pressure)")


main()
