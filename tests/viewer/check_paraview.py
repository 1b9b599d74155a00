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
                             XDMFReader)

ARRAYS = {"velocity", "pressure", "number_density", "density", "phase", "kind", "id"}


def fail(message):
    print("viewer check FAILED: " + message)
    sys.exit(1)


def snapshots(run_dir):
    """(time, particle count, bounds) of each snapshot, from particles.h5."""
    out = []
    with h5py.File(f"{run_dir}/particles.h5", "r") as f:
        for i, t in enumerate(f["times"][()]):
            p = f[f"snapshots/{i:06d}/position"][()]
            out.append((float(t), p.shape[0], [p[:, k].min() for k in range(3)], [p[:, k].max() for k in range(3)]))
    return out


def check_reader(name, reader, expected):
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
        if not ARRAYS <= arrays:
            fail(f"{name} at t = {t}: arrays {sorted(arrays)} lack {sorted(ARRAYS - arrays)}")
        bounds = info.GetBounds()
        for k in range(3):
            if abs(bounds[2 * k] - lo[k]) > 1e-12 or abs(bounds[2 * k + 1] - hi[k]) > 1e-12:
                fail(f"{name} at t = {t}: bounds {bounds} differ from the positions' {lo} .. {hi}")
    print(f"{name}: {len(expected)} snapshots, {expected[0][1]}-{max(e[1] for e in expected)} points with as many "
          f"cells, arrays {sorted(ARRAYS)}, times {times[0]} .. {times[-1]}")


def main():
    run_dir, screenshot = sys.argv[1], sys.argv[2]
    expected = snapshots(run_dir)
    default = OpenDataFile(f"{run_dir}/particles.xdmf")
    check_reader(f"default reader ({default.GetXMLName()})", default, expected)
    check_reader("legacy reader (XDMFReader)", XDMFReader(FileNames=[f"{run_dir}/particles.xdmf"]), expected)

    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = [1200, 700]
    view.ViewTime = expected[-1][0]
    display = Show(default, view)
    display.SetRepresentationType("Points")
    display.PointSize = 3
    ColorBy(display, ("POINTS", "pressure"))
    display.RescaleTransferFunctionToDataRange(True)
    display.SetScalarBarVisibility(view, True)
    view.CameraPosition = [0, 0, 1]
    view.CameraViewUp = [0, 1, 0]
    ResetCamera(view)
    SaveScreenshot(screenshot, view, ImageResolution=[1200, 700])
    print(f"screenshot: {screenshot} (t = {expected[-1][0]} s, coloured by pressure)")


main()
