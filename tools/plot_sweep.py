#!/usr/bin/python3
"""Plots a finished sweep (slide sweep; its results.csv and plan.json) into its folder:
  accuracy_cost.png   error against time to answer (setup + loop wall seconds), log-log, one series per method
                      option (the varied keys other than the resolution key, particle_spacing unless the sweep's
                      plots.resolution_key says otherwise), the Pareto front (no run both cheaper and more accurate)
                      marked and labelled; runs without an error (unstable, missing) are counted in the legend.
  stability_map.png   the outcome of every run over two varied keys (the sweep's plots.map.x and .y, else the first
                      two), one panel per value of a third (plots.map.panels, else the third varied key): completed,
                      inaccurate, unstable (with the time it failed), invalid (with the key it was refused on),
                      interrupted, missing; the worst where several runs share a cell, refused (invalid) ones only
                      where no other run of the cell ran.
Usage: tools/plot_sweep.py SWEEP_DIR. Uses Debian's python3-matplotlib through /usr/bin/python3."""
import csv
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

COLOURS = {"completed": "#2a9d4b", "inaccurate": "#f0a030", "unstable": "#d03030", "invalid": "#8060c0",
           "interrupted": "#a0a0a0", "missing": "#e0e0e0"}
SEVERITY = ["completed", "inaccurate", "interrupted", "missing", "invalid", "unstable"]


def number(text):
    try:
        return float(text)
    except ValueError:
        return math.nan


def load(sweep_dir):
    with open(os.path.join(sweep_dir, "results.csv")) as f:
        rows = list(csv.DictReader(f))
    plan = json.load(open(os.path.join(sweep_dir, "plan.json")))
    return rows, plan


def cost(row):
    return number(row["setup_seconds"]) + number(row["wall_seconds"])


def option_label(row, keys):
    return ", ".join(f"{k}={row[k]}" for k in keys if row[k] != "") or "base scene"


def pareto(points):
    """The points (cost, error, label) that no other point beats in both cost and error, by increasing cost."""
    front, best = [], math.inf
    for p in sorted(points):
        if p[1] < best:
            front.append(p)
            best = p[1]
    return front


def plot_accuracy_cost(rows, plan, target):
    keys = plan["varied_keys"]
    resolution = plan.get("plots", {}).get("resolution_key", "particle_spacing")
    option_keys = [k for k in keys if k != resolution]
    series = {}
    for r in rows:
        series.setdefault(option_label(r, option_keys), []).append(r)
    # Too many series to read (a sweep of several method keys): one series per value of the first method key, its
    # points not joined.
    joined = resolution in keys
    with_error = [rs for rs in series.values() if any(math.isfinite(number(r["error"])) for r in rs)]
    if len(with_error) > 12 and option_keys:
        series, joined = {}, False
        for r in rows:
            series.setdefault(option_label(r, option_keys[:1]), []).append(r)
    fig, ax = plt.subplots(figsize=(11, 8))
    if len(series) > 10:
        ax.set_prop_cycle(color=plt.get_cmap("tab20").colors)
    no_error = []
    points = []
    for label, rs in series.items():
        xy = sorted((cost(r), number(r["error"]), r) for r in rs if math.isfinite(number(r["error"])) and cost(r) > 0)
        failed = sum(1 for r in rs if r["outcome"] == "unstable")
        text = label + (f" ({failed} unstable)" if failed else "")
        if xy:
            ax.plot([p[0] for p in xy], [p[1] for p in xy], "o-" if joined else "o", label=text)
            points += [(p[0], p[1], f"{p[2]['run']}: {option_label(p[2], keys)}") for p in xy]
        else:
            no_error.append(text)
    if no_error:
        ax.plot([], [], " ", label=f"no error (every run unstable or refused): {len(no_error)} more series")
    front = pareto(points)
    if front:
        ax.step([p[0] for p in front], [p[1] for p in front], where="post", color="k", lw=1.2, alpha=0.6,
                label="Pareto front")
        for k, (c, e, text) in enumerate(front):
            ax.annotate(text, (c, e), textcoords="offset points", xytext=(8, 4 - 10 * (k % 2)), fontsize=6.5,
                        ha="left", bbox=dict(boxstyle="round,pad=0.1", fc="white", ec="none", alpha=0.7))
    threshold = plan["error"].get("threshold")
    if threshold is not None:
        ax.axhline(threshold, color="#f0a030", ls="--", lw=1, label=f"threshold {threshold:g}")
    if points:
        ax.set_xscale("log")
        ax.set_yscale("log")
    else:  # no run has an error (every one unstable, refused or missing): an empty chart that says so
        ax.text(0.5, 0.5, "no run completed with an error: see stability_map.png and results.csv",
                transform=ax.transAxes, ha="center", va="center")
    ax.set_xlabel("time to answer: setup + loop wall seconds")
    ax.set_ylabel(f"error ({plan['error']['measure']})")
    ax.set_title(f"sweep {plan['sweep']}: accuracy against cost")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.1), ncol=2)
    fig.tight_layout()
    fig.savefig(target, dpi=110)
    plt.close(fig)


def ordered_values(rows, key):
    out = []
    for r in rows:
        if r[key] not in out:
            out.append(r[key])
    return out


def plot_stability_map(rows, plan, target):
    keys = plan["varied_keys"]
    spec = plan.get("plots", {})
    x_key = spec.get("map_x") or keys[0]
    y_key = spec.get("map_y") or (keys[1] if len(keys) > 1 else None)
    panel_key = spec.get("map_panels") or next((k for k in keys if k not in (x_key, y_key)), None)
    if panel_key == "none":  # one panel: the other keys follow the map's two (plots.map.panels: none)
        panel_key = None
    panels = ordered_values(rows, panel_key) if panel_key else [None]
    xs = ordered_values(rows, x_key)
    ys = ordered_values(rows, y_key) if y_key else [""]
    fig, axes = plt.subplots(1, len(panels), figsize=(3.2 + 2.6 * len(panels), 1.2 + 0.55 * len(ys) + 1.2),
                             squeeze=False)
    for ax, panel in zip(axes[0], panels):
        for i, xv in enumerate(xs):
            for j, yv in enumerate(ys):
                cell = [r for r in rows if r[x_key] == xv and (y_key is None or r[y_key] == yv)
                        and (panel_key is None or r[panel_key] == panel)]
                # A refused combination (invalid) did not run, nor did a missing or interrupted one: these are shown
                # only where nothing else in the cell ran.
                ran = [r for r in cell if r["outcome"] not in ("invalid", "missing", "interrupted")]
                cell = ran or cell
                if not cell:
                    continue
                worst = max(cell, key=lambda r: SEVERITY.index(r["outcome"]) if r["outcome"] in SEVERITY else 0)
                ax.add_patch(plt.Rectangle((i - 0.45, j - 0.45), 0.9, 0.9, color=COLOURS.get(worst["outcome"], "w")))
                note = worst["outcome"]
                if worst["outcome"] == "unstable" and worst["failure_time"]:
                    settling = worst["note"].startswith("while settling")
                    note += f"\n{'settling' + chr(10) if settling else ''}t={number(worst['failure_time']):.3g} s"
                elif worst["outcome"] == "invalid" and worst["note"]:
                    # The key the run was refused on, broken at its dots to fit the cell.
                    note += "\n" + worst["note"].split(":")[0].replace(".", ".\n")
                elif math.isfinite(number(worst["error"])):
                    note += f"\n{number(worst['error']):.3g}"
                ax.text(i, j, note, ha="center", va="center", fontsize=7)
        ax.set_xlim(-0.5, len(xs) - 0.5)
        ax.set_ylim(-0.5, len(ys) - 0.5)
        ax.set_xticks(range(len(xs)), xs, rotation=30, fontsize=8)
        ax.set_yticks(range(len(ys)), ys, fontsize=8)
        ax.set_xlabel(x_key)
        if y_key:
            ax.set_ylabel(y_key)
        if panel_key:
            ax.set_title(f"{panel_key} = {panel}", fontsize=9)
    fig.suptitle(f"sweep {plan['sweep']}: outcome of each run\n(the worst of a cell's runs; "
                 "a refused combination only where no other ran)", fontsize=10)
    fig.tight_layout()
    fig.savefig(target, dpi=110)
    plt.close(fig)


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    sweep_dir = sys.argv[1]
    rows, plan = load(sweep_dir)
    written = []
    if plan["error"]["measure"] != "none":
        plot_accuracy_cost(rows, plan, os.path.join(sweep_dir, "accuracy_cost.png"))
        written.append("accuracy_cost.png")
    plot_stability_map(rows, plan, os.path.join(sweep_dir, "stability_map.png"))
    written.append("stability_map.png")
    print("plot_sweep: wrote " + ", ".join(os.path.join(sweep_dir, w) for w in written))


if __name__ == "__main__":
    main()
