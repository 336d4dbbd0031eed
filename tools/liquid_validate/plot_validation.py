#!/usr/bin/env python3
"""Turns the JSON written by liquid_validate into SVG plots (with matplotlib).

    python3 tools/liquid_validate/plot_validation.py out/validation/validation.json [-o out/validation]

Writes, where the JSON holds the runs for them:
  front.svg        surge front Z = x/a against T = t sqrt(2g/a) of every collapsing-column run,
                   with Martin and Moyce's (1952) measurements (n^2 = 2) as points
  energy.svg       kinetic, potential and mechanical energy against time of the rest pool and the
                   dam break, each as a share of its initial potential energy
  rest_pool.svg    the rest pool's kinetic energy (log scale) against its target, and its surface
                   deviation in cells
  volume.svg       occupied volume against time, relative to the first frame
"""

import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import plot_files  # noqa: E402 (tools/common/, found through the line above)

plot_files.matplotlib_or_exit("plot_validation")
from matplotlib.figure import Figure  # noqa: E402 (after the backend is chosen)
from matplotlib.ticker import FuncFormatter, NullFormatter  # noqa: E402

COLORS = ["#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b"]
# Martin and Moyce (1952), n^2 = 2, a = 2.25 in (the table in liquid/analysis/validation.cpp).
MARTIN_MOYCE = [(0.41, 1.11), (0.84, 1.22), (1.19, 1.44), (1.43, 1.67), (1.63, 1.89), (1.83, 2.11), (1.98, 2.33),
                (2.20, 2.56), (2.32, 2.78), (2.51, 3.00), (2.65, 3.22), (2.83, 3.44), (2.98, 3.67), (3.11, 3.89),
                (3.33, 4.11)]
T, KE, PE, E, VOLUME, FRONT, SPREAD = range(7)


def new_plot(title, xlabel, ylabel, xlim, ylim, log_y=False):
    """One chart with fixed limits: what falls outside them is clipped."""
    fig = Figure(figsize=(7.6, 4.6), layout="constrained")
    ax = fig.subplots()
    if log_y:  # decades named 0.001, 1e-05 (the default names are TeX math, which is off)
        ax.set_yscale("log")
        ax.yaxis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
        ax.yaxis.set_minor_formatter(NullFormatter())
    ax.set(xlabel=xlabel, ylabel=ylabel, xlim=xlim, ylim=ylim)
    ax.set_title(title, fontweight="bold")
    ax.grid(color="#eee")
    return fig, ax


def save(fig, ax, path):
    """Adds the legend right of the axes and writes the SVG through a temporary file in the same folder."""
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1), frameon=False, fontsize="small")
    plot_files.save_svg(fig, path)
    print(path)


def column(run):
    """(T, Z) of a collapsing-column run; a = 0.1 m, g = 9.81 m/s^2 (liquid_validate's scenes)."""
    a, g = 0.1, 9.81
    k = math.sqrt(2 * g / a)
    return [s[T] * k for s in run["samples"]], [s[FRONT] / a for s in run["samples"]]


def plot(data, out):
    runs = data["runs"]
    columns = [r for r in runs if "column" in r["name"].lower()]
    others = [r for r in runs if r not in columns]

    if columns:
        fig, ax = new_plot("Collapsing column: surge front", "T = t sqrt(2g/a)", "Z = x / a", (0, 3.5), (1, 4.5))
        for i, r in enumerate(columns):
            xs, ys = column(r)
            ax.plot([0.0] + xs, [1.0] + ys, color=COLORS[i % len(COLORS)], lw=1.8,
                    label=r["name"].replace("Collapsing column ", ""))
        ax.plot([t for t, _ in MARTIN_MOYCE], [z for _, z in MARTIN_MOYCE], "o", color="#000", ms=5,
                label="Martin & Moyce 1952")
        save(fig, ax, os.path.join(out, "front.svg"))

    if others:
        t_end = max(s[T] for r in others for s in r["samples"])
        fig, ax = new_plot("Energy / initial potential energy", "t (s)", "share of PE(0)", (0, t_end), (0, 1.05))
        for i, r in enumerate(others):
            pe0 = r["samples"][0][PE] or 1.0
            ts = [s[T] for s in r["samples"]]
            color = COLORS[i % len(COLORS)]
            ax.plot(ts, [s[E] / pe0 for s in r["samples"]], color=color, lw=1.8, label=r["name"] + ": KE + PE")
            ax.plot(ts, [s[KE] / pe0 for s in r["samples"]], "--", color=color, lw=1.8, label=r["name"] + ": KE")
        save(fig, ax, os.path.join(out, "energy.svg"))

        fig, ax = new_plot("Volume under the free surface / first frame", "t (s)", "V / V(first frame)", (0, t_end),
                           (0.96, 1.04))
        for i, r in enumerate(others):
            v0 = r["samples"][0][VOLUME] or 1.0
            ax.plot([s[T] for s in r["samples"]], [s[VOLUME] / v0 for s in r["samples"]], color=COLORS[i % len(COLORS)],
                    lw=1.8, label=r["name"])
        ax.axhline(1.01, ls="--", color="#888", lw=1.8, label="+1 % (target)")
        ax.axhline(0.99, ls="--", color="#888", lw=1.8, label="-1 % (target)")
        save(fig, ax, os.path.join(out, "volume.svg"))

    pools = [r for r in others if "rest" in r["name"].lower()]
    for r in pools:
        pe0 = r["samples"][0][PE] or 1.0
        ts = [s[T] for s in r["samples"]]
        t_end = ts[-1]
        fig, ax = new_plot("Pool at rest: kinetic energy / PE(0)", "t (s)", "KE / PE(0)", (0, t_end), (1e-9, 1e-1),
                           log_y=True)
        # Held at the axis' floor: a pool with no motion at all (KE 0) runs along it instead of off the log scale.
        ax.plot(ts, [max(s[KE] / pe0, 1e-9) for s in r["samples"]], color=COLORS[0], lw=1.8, label="KE / PE(0)")
        ax.plot([1, t_end], [5e-4, 5e-4], "--", color="#d62728", lw=1.8, label="target (from 1 s)")
        save(fig, ax, os.path.join(out, "rest_pool.svg"))


if __name__ == "__main__":
    sys.exit(plot_files.main("plot_validation", __doc__.split("\n")[0], None, "runs", "liquid_validate", plot))
