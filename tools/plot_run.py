#!/usr/bin/python3
"""Plots a slide run: wave gauges (gauges.png; against the measured records where the scene names them,
diagnostics.gauge_records, a panel a gauge); for a dam break the surge front against Martin & Moyce (1952)
(surge_front.png); for runs with bodies their position, velocity and fluid force against time (bodies.png);
free-surface profiles (profiles.png); for deformable slides the front and largest thickness against time and the upper
surface at the outline times (slide.png); for a scene with measured slide shapes (diagnostics.slide_shapes) the model's
upper surface against them at each measured time, with the front's error and the surfaces' rms distance
(slide_shapes.png); the particles themselves at up to four snapshot times, coloured by phase and by speed
(particles.png, from particles.h5, first run only); for a 3-D run the free surface seen from above (plan_view.png). Usage: tools/plot_run.py RUN_DIR [RUN_DIR ...]   (several runs:
overlaid, e.g. resolutions, or a free and a prescribed run).
Uses Debian's python3-matplotlib, python3-numpy and python3-h5py through /usr/bin/python3."""
import csv
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
REFERENCE = os.path.join(ROOT, "cases", "reference", "martin_moyce_1952_surge_front.csv")


def read_csv(path):
    with open(path) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def label_of(run_dir):
    try:
        run = json.load(open(os.path.join(run_dir, "run.json")))
        dp = run["scene"]["particle_spacing"]
        sets = [o for o in run.get("overrides", []) if not o.startswith(("particle_spacing", "output."))]
        return f"{run['case']} dp={dp:g} m ({run['scene']['method']['gradient']}){' ' + ' '.join(sets) if sets else ''}"
    except (OSError, KeyError, ValueError):
        return os.path.basename(os.path.normpath(run_dir))


def plot_front(runs, target):
    fig, (ax_z, ax_h) = plt.subplots(1, 2, figsize=(11, 4.2))
    sources = {}
    for row in read_csv(REFERENCE):
        sources.setdefault(row["source_id"], []).append(
            (float(row["T_dimless_t_sqrt_2g_over_a"]), float(row["Z_dimless_xfront_over_a"])))
    for marker, (source, points) in zip("osd^", sorted(sources.items())):
        ax_z.plot(*zip(*points), marker, mfc="none", color="k", ms=5, label=f"Martin & Moyce 1952 ({source})")
    for run in runs:
        rows = read_csv(os.path.join(run, "surge_front.csv"))
        T = [float(r["T"]) for r in rows]
        ax_z.plot(T, [float(r["Z"]) for r in rows], label=label_of(run))
        ax_h.plot(T, [float(r["H_over_2a"]) for r in rows], label=label_of(run))
    ax_z.set(xlabel="T = t sqrt(2g/a)", ylabel="Z = front / a", xlim=(0, 3.5), ylim=(1, 5), title="surge front")
    ax_h.set(xlabel="T = t sqrt(2g/a)", ylabel="H / 2a", xlim=(0, 3.5), title="water height at the wall")
    ax_z.legend(fontsize=6)
    ax_h.legend(fontsize=6)
    fig.tight_layout()
    fig.savefig(target, dpi=110)
    print("wrote", target)


def measured_gauges(run):
    """The records a run's scene compares its gauges with (diagnostics.gauge_records): ({gauge: (times on the model's
    clock, elevations)}, the window's end or None), or None without them."""
    try:
        info = json.load(open(os.path.join(run, "run.json")))
        spec = info["scene"]["diagnostics"]["gauge_records"]
    except (OSError, KeyError, ValueError, TypeError):
        return None
    if not spec.get("file"):
        return None
    try:
        rows = read_csv(os.path.join(os.path.dirname(info["scene_file"]), spec["file"]))
    except OSError:  # the scene's path as typed, read from another folder: draw the run alone
        return None
    offset = float(spec.get("time_offset", 0.0))
    t = [float(r["time_s"]) + offset for r in rows]
    records = {name: (t, [float(r[name]) for r in rows]) for name in rows[0] if name != "time_s"}
    return records, (float(spec["until"]) if float(spec.get("until", 0.0)) > 0 else None)


def plot_gauges(runs, target):
    """One axes for all gauges; with measured records (diagnostics.gauge_records), one panel a gauge: the record, each
    run's elevation from its first value, and gauge_records.csv's rms in the title."""
    measured = measured_gauges(runs[0])
    names = [c for c in read_csv(os.path.join(runs[0], "gauges.csv"))[0].keys() if c != "time"]
    panels = names if measured else [None]
    fig, axes = plt.subplots(len(panels), 1, figsize=(8, 4 if not measured else 2.6 * len(panels)), squeeze=False)
    for ax, panel in zip(axes[:, 0], panels):
        titles = []
        if measured and panel in measured[0]:
            ax.plot(*measured[0][panel], "k-", lw=0.8, label="measured")
            if measured[1] is not None:
                ax.axvline(measured[1], color="0.6", ls=":", lw=0.8, label="compared up to")
        for run in runs:
            rows = read_csv(os.path.join(run, "gauges.csv"))
            t = [float(r["time"]) for r in rows]
            for name in [panel] if panel else [c for c in rows[0].keys() if c != "time"]:
                eta = [float(r[name]) for r in rows]
                still = next((e for e in eta if e == e), 0.0) if panel else 0.0
                ax.plot(t, [e - still for e in eta], label=f"{name}: {label_of(run)}")
            if panel and os.path.exists(os.path.join(run, "gauge_records.csv")):
                for r in read_csv(os.path.join(run, "gauge_records.csv")):
                    if r["gauge"] == panel:
                        titles.append(f"rms {1000 * float(r['rms']):.1f} mm "
                                      f"({100 * float(r['rms_over_height']):.0f} % of the measured height)")
        if panel:
            ax.set(ylabel="elevation (m)", title=f"{panel}: " + "; ".join(titles) if titles else panel)
            ax.title.set_fontsize(9)
        else:
            ax.set(ylabel="free-surface elevation (m)", title="wave gauges")
        ax.legend(fontsize=6)
    axes[-1, 0].set(xlabel="time (s)")
    fig.tight_layout()
    fig.savefig(target, dpi=110)
    print("wrote", target)


def plot_bodies(runs, target):
    """2-D bodies.csv: x, y, angle; 3-D: x, y, z and the orientation as roll, pitch and yaw."""
    fig, axes = plt.subplots(2, 2, figsize=(11, 7))
    three_d = False
    for run in runs:
        rows = read_csv(os.path.join(run, "bodies.csv"))
        dims = ("x", "y", "z") if rows and "z" in rows[0] else ("x", "y")
        three_d = three_d or len(dims) == 3
        for body in sorted({r["body"] for r in rows}):
            mine = [r for r in rows if r["body"] == body]
            t = [float(r["time"]) for r in mine]
            start = [float(mine[0][d]) for d in dims]
            dist = [sum((float(r[d]) - s0) ** 2 for d, s0 in zip(dims, start)) ** 0.5 for r in mine]
            speed = [sum(float(r["v" + d]) ** 2 for d in dims) ** 0.5 for r in mine]
            label = f"{body}: {label_of(run)}"
            axes[0][0].plot(t, dist, label=label)
            axes[0][1].plot(t, speed, label=label)
            for d, style in zip(dims, ("-", "--", ":")):
                axes[1][0].plot(t, [float(r["f" + d]) for r in mine], style, label=f"f{d} {label}")
            if len(dims) == 2:
                axes[1][1].plot(t, [float(r["angle"]) for r in mine], label=label)
            else:
                for name, style in (("roll", "-"), ("pitch", "--"), ("yaw", ":")):
                    axes[1][1].plot(t, [float(r[name]) for r in mine], style, label=f"{name} {label}")
    axes[0][0].set(xlabel="time (s)", ylabel="distance travelled by the centre of mass (m)", title="position")
    axes[0][1].set(xlabel="time (s)", ylabel="speed (m/s)", title="velocity")
    axes[1][0].set(xlabel="time (s)", ylabel="fluid force (N)" if three_d else "fluid force (N/m)",
                   title="fluid force (pressure + viscous)")
    axes[1][1].set(xlabel="time (s)", ylabel="angle (rad)",
                   title="orientation (roll, pitch, yaw: z-y'-x'')" if three_d else "rotation")
    for ax in axes.flat:
        ax.legend(fontsize=6)
    fig.tight_layout()
    fig.savefig(target, dpi=110)
    print("wrote", target)


def plot_profiles(runs, target):
    """Each profile against x (2-D), or against the distance along its line from its first point (3-D: profiles.csv
    has a y column)."""
    fig, ax = plt.subplots(figsize=(10, 4))
    xlabel = "x (m)"
    for run in runs:
        rows = read_csv(os.path.join(run, "profiles.csv"))
        for time in sorted({r["time"] for r in rows}, key=float):
            mine = [r for r in rows if r["time"] == time]
            if "y" in mine[0]:
                x0, y0 = float(mine[0]["x"]), float(mine[0]["y"])
                along = [math.hypot(float(r["x"]) - x0, float(r["y"]) - y0) for r in mine]
                xlabel = f"distance along the line from ({x0:g}, {y0:g}) to ({mine[-1]['x']}, {mine[-1]['y']}) (m)"
            else:
                along = [float(r["x"]) for r in mine]
            ax.plot(along, [float(r["eta"]) for r in mine], label=f"t = {float(time):.3f} s: {label_of(run)}")
    ax.set(xlabel=xlabel, ylabel="free-surface elevation (m)", title="free-surface profiles")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(target, dpi=110)
    print("wrote", target)


def plot_slides(runs, target):
    fig, (front, shape) = plt.subplots(1, 2, figsize=(12, 4.5))
    for run in runs:
        rows = read_csv(os.path.join(run, "slide_front.csv"))
        for slide in sorted({r["slide"] for r in rows}):
            mine = [r for r in rows if r["slide"] == slide]
            t = [float(r["time"]) for r in mine]
            front.plot(t, [float(r["front_along"]) - float(mine[0]["front_along"]) for r in mine],
                       label=f"{slide} front: {label_of(run)}")
            front.plot(t, [float(r["thickness_max"]) for r in mine], "--", label=f"{slide} largest thickness")
        outline = os.path.join(run, "slide_outline.csv")
        if os.path.exists(outline):
            rows = read_csv(outline)
            for time in sorted({r["time"] for r in rows}, key=float):
                mine = [r for r in rows if r["time"] == time]
                if "z" in mine[0]:  # 3-D: a height map; its side view, the highest z of each x column over y
                    top = {}
                    for r in mine:
                        top[float(r["x"])] = max(top.get(float(r["x"]), -math.inf), float(r["z"]))
                    xs, ys = sorted(top), [top[x] for x in sorted(top)]
                else:
                    xs, ys = [float(r["x"]) for r in mine], [float(r["y"]) for r in mine]
                shape.plot(xs, ys, ".-", markersize=3, label=f"t = {float(time):.2f} s: {label_of(run)}")
    front.set(xlabel="t (s)", ylabel="m", title="slide front (distance along its direction) and largest thickness")
    shape.set(xlabel="x (m)", ylabel="height (m): y in 2-D, z in 3-D (the highest over y)", title="slide upper surface",
              aspect="equal")
    front.legend(fontsize=7)
    shape.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(target, dpi=110)
    print("wrote", target)


def measured_shapes(run):
    """The measured shapes a run compared itself with: {measured time: [(x, y)]}, and the time offset."""
    info = json.load(open(os.path.join(run, "run.json")))
    spec = info["scene"]["diagnostics"]["slide_shapes"]
    path = os.path.join(os.path.dirname(info["scene_file"]), spec["file"])
    shapes = {}
    for r in read_csv(path):
        shapes.setdefault(float(r["t_exp_s"]), []).append((float(r["x_m"]), float(r["y_m"])))
    return shapes, float(spec["time_offset"])


def plot_shapes(runs, target):
    """One panel per measured time after the start: the measured points and each run's upper surface at the first
    output time at or after it (slide_outline.csv), titled with slide_shapes.csv's errors."""
    shapes, offset = measured_shapes(runs[0])
    times = sorted(shapes)[1:]
    fig, axes = plt.subplots(len(times), 1, figsize=(12, 2.8 * len(times)), squeeze=False)
    for ax, t_exp in zip(axes[:, 0], times):
        ax.plot(*zip(*shapes[sorted(shapes)[0]]), "s", color="0.7", ms=3, mfc="none", label="measured at the start")
        ax.plot(*zip(*shapes[t_exp]), "ko", ms=3, mfc="none", label=f"measured, t = {t_exp:.2f} s (experiment)")
        titles = []
        for run in runs:
            outline = [r for r in read_csv(os.path.join(run, "slide_outline.csv"))]
            at = [float(r["time"]) for r in outline if float(r["time"]) >= t_exp + offset - 1e-9]
            if at:
                mine = [r for r in outline if float(r["time"]) == min(at)]
                ax.plot([float(r["x"]) for r in mine], [float(r["y"]) for r in mine], ".-", ms=3,
                        label=f"model t = {min(at):.3f} s: {label_of(run)}")
            for r in read_csv(os.path.join(run, "slide_shapes.csv")):
                if abs(float(r["time_measured"]) - t_exp) < 1e-9:
                    titles.append(f"front {float(r['front_error_percent']):+.0f} % of travel, "
                                  f"surface rms {100 * float(r['surface_rms']):.1f} cm")
        ax.set(xlabel="x (m)", ylabel="y (m)", aspect="equal",
               title=f"t = {t_exp:.2f} s (model {t_exp + offset:.2f} s): " + "; ".join(titles))
        ax.title.set_fontsize(8)
        ax.legend(fontsize=6, loc="upper left", bbox_to_anchor=(1.02, 1.0))
    fig.tight_layout()
    fig.savefig(target, dpi=110)
    print("wrote", target)


PHASE_COLOURS = ["#3a7bd5", "#a0522d", "#e0a030", "#6a9a3a", "#8060c0"]  # water first, then slides' phases


def snapshot_indices(count, wanted=4):
    """Up to `wanted` snapshots spread over the series, the first and the last among them."""
    if count <= wanted:
        return list(range(count))
    return sorted({round(k * (count - 1) / (wanted - 1)) for k in range(wanted)})


def plot_plan_view(run, target):
    """A 3-D run's free surface seen from above at up to four snapshot times: in each square (below), the
    highest particle of the scene's own fluid phases (not a deformable slide's) less the median of those heights in
    the first snapshot (the still level, where the run starts at rest); white where no water stands."""
    try:
        import h5py
        import numpy as np
    except ImportError:
        print("plot_run: plan_view.png skipped (it needs python3-h5py)", file=sys.stderr)
        return
    with open(os.path.join(run, "run.json")) as f:
        scene = json.load(f)["scene"]
    dp, water_phases = float(scene["particle_spacing"]), len(scene["fluid"]["phases"])
    # Squares of two fcc plane spacings (2 x 0.7937 dp) hold columns of both parities, whose tops differ by a plane;
    # one spacing holds a column of the cubic lattice.
    square = dp if scene.get("lattice") == "square" else 2.0 * 0.5 ** (1.0 / 3.0) * dp
    frames = []
    with h5py.File(os.path.join(run, "particles.h5"), "r") as f:
        times = list(f["times"][()])
        fluid_code = kind_code(f["snapshots/%06d/kind" % 0].attrs.get("codes", b""), "fluid")
        for i in snapshot_indices(len(times)):
            g = f["snapshots/%06d" % i]
            x = g["position"][()]
            water = g["kind"][()] == fluid_code
            if "phase" in g:
                water &= g["phase"][()] < water_phases
            frames.append((times[i], x[water]))
    if not frames or not len(frames[0][1]):  # a dry scene (slides only), or no water at the first snapshot
        print("plot_run: plan_view.png skipped (no water of the scene's own phases in the first snapshot)",
              file=sys.stderr)
        return
    lo = np.min([x[:, :2].min(axis=0) for _, x in frames if len(x)], axis=0)
    hi = np.max([x[:, :2].max(axis=0) for _, x in frames if len(x)], axis=0)
    cells = np.maximum(np.ceil((hi - lo) / square).astype(int), 1)
    tops = []
    for t, x in frames:
        top = np.full(cells, np.nan)
        ij = np.minimum(((x[:, :2] - lo) / square).astype(int), cells - 1)
        np.fmax.at(top, (ij[:, 0], ij[:, 1]), x[:, 2])
        tops.append((t, top))
    reference = float(np.nanmedian(tops[0][1]))
    reach = max(float(np.nanmax(np.abs(top - reference))) for _, top in tops) or 1e-6
    aspect = (hi[1] - lo[1]) / max(hi[0] - lo[0], 1e-12)
    width = 4.2
    fig, axes = plt.subplots(1, len(tops), figsize=(width * len(tops) + 1.2, width * aspect + 1.0), squeeze=False,
                             layout="constrained")
    for ax, (t, top) in zip(axes[0], tops):
        image = ax.imshow((top - reference).T, origin="lower", extent=(lo[0], hi[0], lo[1], hi[1]), cmap="RdBu_r",
                          vmin=-reach, vmax=reach, interpolation="nearest")
        ax.set_title(f"t = {t:.3g} s", fontsize=9)
        ax.set(xlabel="x (m)", ylabel="y (m)")
        ax.tick_params(labelsize=7)
    fig.colorbar(image, ax=list(axes[0]), label=f"highest water particle - {reference:.4g} m (m)", shrink=0.8)
    fig.suptitle(f"{label_of(run)}: free surface from above (squares of {square:.3g} m; reference: its median at t = "
                 f"{tops[0][0]:.3g} s)", fontsize=10)
    fig.savefig(target, dpi=110)
    plt.close(fig)
    print("wrote", target)


def kind_code(codes, name):
    """The code of a particle kind in a snapshot's kind attribute ("0 fluid, 1 wall, 2 dummy": tools/snapshot_writer.hpp)."""
    codes = codes.decode() if isinstance(codes, bytes) else str(codes)
    for item in codes.split(","):
        words = item.split()
        if len(words) == 2 and words[1] == name:
            return int(words[0])
    return 0


def plot_particles(run, target):
    """The particles at up to four times: top row by phase (boundary particles grey), bottom row by speed. A 3-D run is
    drawn as a side view (x, z) of the slab one spacing thick across the middle of its y extent."""
    try:
        import h5py
        import numpy as np
    except ImportError:
        print("plot_run: particles.png skipped (it needs python3-h5py)", file=sys.stderr)
        return
    path = os.path.join(run, "particles.h5")
    with h5py.File(path, "r") as f:
        times = list(f["times"][()])
        picked = [(i, times[i]) for i in snapshot_indices(len(times))]
        frames, missing = [], set()
        for i, t in picked:
            g = f["snapshots/%06d" % i]
            kind = g["kind"][()]
            dim = int(g.attrs.get("dim", 2))  # positions are stored with three columns in 2-D too
            position = g["position"][()][:, :dim]
            # A snapshot may leave out velocity or phase (output.snapshot_fields): drawn as zero speed, one phase.
            velocity = g["velocity"][()][:, :dim] if "velocity" in g else np.zeros_like(position)
            phase = g["phase"][()] if "phase" in g else np.zeros(len(kind), dtype=np.uint8)
            missing.update(name for name in ("velocity", "phase") if name not in g)
            frames.append((t, position, velocity, phase, kind))
        kind_codes = f["snapshots/%06d/kind" % picked[0][0]].attrs.get("codes", b"")
    if not frames:
        return
    # Markers one spacing wide: the axes' points per metre times dp (run.json), so that the lattice shows no gaps.
    try:
        with open(os.path.join(run, "run.json")) as f:
            dp = float(json.load(f)["scene"]["particle_spacing"])
    except (OSError, KeyError, ValueError):
        dp = None
    three_d = frames[0][1].shape[1] == 3
    if three_d:
        y_mid = 0.5 * (frames[0][1][:, 1].min() + frames[0][1][:, 1].max())
        half = 0.5 * (dp if dp else 0.01 * np.ptp(frames[0][1][:, 1]))
        slabs = []
        for t, x, v, phase, kind in frames:
            m = np.abs(x[:, 1] - y_mid) <= half
            slabs.append((t, x[m][:, [0, 2]], v[m], phase[m], kind[m]))
        frames = slabs
    fluid_code = kind_code(kind_codes, "fluid")
    all_xy = np.concatenate([x[:, :2] for _, x, _, _, _ in frames])
    lo, hi = all_xy.min(axis=0), all_xy.max(axis=0)
    aspect = (hi[1] - lo[1]) / max(hi[0] - lo[0], 1e-12)
    width = 4.2
    fig, axes = plt.subplots(2, len(frames), figsize=(width * len(frames) + 1.0, 2 * width * aspect + 1.0),
                             squeeze=False, layout="constrained")
    top_speed = max(float(np.linalg.norm(v[k == fluid_code], axis=1).max(initial=0.0))
                    for _, _, v, _, k in frames) or 1.0
    if dp is None:
        dp = (hi[0] - lo[0]) / 200.0
    size = (1.15 * dp * width * 72.0 / max(hi[0] - lo[0], 1e-12)) ** 2
    for col, (t, x, v, phase, kind) in enumerate(frames):
        fluid = kind == fluid_code
        colours = np.array([PHASE_COLOURS[p % len(PHASE_COLOURS)] for p in phase], dtype=object)
        colours[~fluid] = "#888888"
        ax = axes[0][col]
        ax.scatter(x[:, 0], x[:, 1], s=size, c=list(colours), linewidths=0)
        ax.set_title(f"t = {t:.3g} s: phase" + (" (not in the snapshots)" if "phase" in missing else ""), fontsize=9)
        ax = axes[1][col]
        ax.scatter(x[~fluid, 0], x[~fluid, 1], s=size, c="#888888", linewidths=0)
        sc = ax.scatter(x[fluid, 0], x[fluid, 1], s=size, c=np.linalg.norm(v[fluid], axis=1), cmap="viridis",
                        vmin=0.0, vmax=top_speed, linewidths=0)
        ax.set_title(f"t = {t:.3g} s: speed" + (" (not in the snapshots)" if "velocity" in missing else ""), fontsize=9)
        for a in (axes[0][col], axes[1][col]):
            a.set_aspect("equal")
            a.set_xlim(lo[0], hi[0])
            a.set_ylim(lo[1], hi[1])
            a.tick_params(labelsize=7)
    fig.colorbar(sc, ax=[a for row in axes for a in row], label="speed, m/s", shrink=0.6)
    view = f" (3-D: side view, x and z, of the slab |y - {y_mid:.3g} m| <= dp/2)" if three_d else ""
    fig.suptitle(f"{label_of(run)}: particles (grey: walls and bodies){view}", fontsize=10)
    fig.savefig(target, dpi=110)
    plt.close(fig)


def main():
    runs = sys.argv[1:]
    if not runs:
        sys.exit(__doc__)
    out = runs[0]
    if all(os.path.exists(os.path.join(r, "surge_front.csv")) for r in runs):
        plot_front(runs, os.path.join(out, "surge_front.png"))
    if all(os.path.exists(os.path.join(r, "gauges.csv")) for r in runs):
        plot_gauges(runs, os.path.join(out, "gauges.png"))
    if all(os.path.exists(os.path.join(r, "bodies.csv")) for r in runs):
        plot_bodies(runs, os.path.join(out, "bodies.png"))
    if all(os.path.exists(os.path.join(r, "profiles.csv")) for r in runs):
        plot_profiles(runs, os.path.join(out, "profiles.png"))
    if all(os.path.exists(os.path.join(r, "slide_front.csv")) for r in runs):
        plot_slides(runs, os.path.join(out, "slide.png"))
    if all(os.path.exists(os.path.join(r, "slide_shapes.csv")) for r in runs):
        plot_shapes(runs, os.path.join(out, "slide_shapes.png"))
    if os.path.exists(os.path.join(out, "particles.h5")):
        plot_particles(out, os.path.join(out, "particles.png"))
        try:
            three_d = json.load(open(os.path.join(out, "run.json")))["scene"].get("dimension") == 3
        except (OSError, KeyError, ValueError):
            three_d = False
        if three_d:
            plot_plan_view(out, os.path.join(out, "plan_view.png"))


if __name__ == "__main__":
    main()
