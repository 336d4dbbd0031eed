#!/usr/bin/env python3
"""Turns the JSON written by liquid_benchmark into SVG charts (with matplotlib).

    python3 tools/liquid_benchmark/plot_benchmark.py out/benchmark/benchmark.json [-o out/benchmark]

Writes, where the JSON holds the data for them:
  paper_2d.svg    time per frame against particle count for the 2D paper scenes, ours beside the
                  paper's Quadro 2000M figures (the chapter's method and the DX11 SDK SPH sample)
  gpu_passes.svg  GPU time of every pass, stacked per configuration
  scaling.svg     time per step against particle count (256^2 grid) and against grid size (64k)
  scaling_3d.svg  3D: time per step and per particle, and the device memory held, against particle
                  count (paper_3d, separable splat, the grid growing as N^(1/3))
"""

import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import plot_files  # noqa: E402 (tools/common/, found through the line above)

plot_files.matplotlib_or_exit("plot_benchmark")
from matplotlib.figure import Figure  # noqa: E402 (after the backend is chosen)
from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter, NullLocator  # noqa: E402

PASS_COLORS = {
    "liquid.splat": "#1f77b4",
    "liquid.grid": "#ff7f0e",
    "liquid.particle": "#2ca02c",
    "liquid.occupancy": "#9467bd",
    "liquid.raymarch": "#d62728",
    "liquid.view2d": "#8c564b",
    "liquid.height_field": "#e377c2",
    "fxaa": "#7f7f7f",
}
EXTRA_COLORS = ["#bcbd22", "#17becf", "#aec7e8", "#ffbb78", "#98df8a"]


def format_count(v):
    if v >= 1e6:
        return f"{v / 1e6:.2g}M"
    return f"{v / 1000:.0f}k" if v >= 1000 else f"{v:g}"


def footer(fig, data, extra=None):
    """Two or three grey lines under the charts: the device, the date and the run's settings."""
    device = data.get("device", {})
    settings = data.get("settings", {})
    lines = [f"ours: {device.get('name', '?')}, {device.get('driver', '?')}; {data.get('date', '')}",
             f"{settings.get('warmup_frames', '?')} warm-up frames, then {settings.get('timed_frames', '?')} timed "
             f"frames per configuration ({settings.get('scaling_timed_frames', '?')} per scaling point); "
             f"{settings.get('steps_per_frame', 1)} step per frame"] + ([extra] if extra else [])
    # The layout keeps the charts above a strip of the figure's height that holds the lines.
    strip = (0.1 + 0.17 * len(lines)) / fig.get_figheight()
    fig.get_layout_engine().set(rect=(0, strip, 1, 1 - strip))
    fig.text(0.01, 0.1 / fig.get_figheight(), "\n".join(lines), fontsize=9, color="#555", linespacing=1.5)


def log_log(ax, title, xlabel, ylabel, xs, xformat, pad):
    """Log-log axes with a tick at every x of the data, named by xformat, and 1-2-5 ticks on y."""
    ax.set(xscale="log", yscale="log", xlim=(xs[0] / pad, xs[-1] * pad), xlabel=xlabel, ylabel=ylabel)
    ax.set_title(title, fontweight="bold")
    ax.set_xticks(xs, [xformat(v) for v in xs])
    ax.xaxis.set_minor_locator(NullLocator())
    ax.yaxis.set_major_locator(LogLocator(subs=(1, 2, 5)))
    ax.yaxis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
    ax.yaxis.set_minor_formatter(NullFormatter())
    ax.grid(color="#e4e4e4")


def series(ax, label, points, color, marker="o", linestyle="-"):
    """A line with markers through the (x, y) or (x, y, min, max) points with y > 0, sorted by x; min..max as a bar."""
    points = sorted(p for p in points if p[1] is not None and p[1] > 0)
    if not points:
        return
    bars = None
    if len(points[0]) == 4:  # errorbar takes the distances below and above y
        bars = [[y - lo for _, y, lo, _ in points], [hi - y for _, y, _, hi in points]]
    ax.errorbar([p[0] for p in points], [p[1] for p in points], yerr=bars, label=label, color=color, marker=marker,
                ms=6, linestyle=linestyle, lw=2, elinewidth=1.5)


def median(stats):
    return stats["median"] if stats else None


def paper_2d_chart(data, path):
    all_rows = [r for r in data["results"] if r["group"] == "paper" and r["scene"].startswith("paper_2d")]
    # The chapter's point-sprite splat (no "splat" in JSON of older runs); other modes get series of their own.
    rows = [r for r in all_rows if r.get("splat") in (None, "point_sprite")]
    other_modes = sorted({r["splat"] for r in all_rows if r.get("splat") not in (None, "point_sprite")})
    if not rows:
        return False
    render = [r for r in rows if r["mode"] == "sim+render"]
    sim = [r for r in rows if r["mode"] == "sim"]
    fig = Figure(figsize=(12, 5.8), layout="constrained")
    ax = fig.subplots()
    log_log(ax, "2D, 256\u00b2 grid: time per frame (one step, plus rendering where noted)", "active particles",
            "wall time per frame, ms (log scale; lower is better)", sorted({r["particles"] for r in rows}),
            format_count, 1.25)

    def measured(rs):
        return [(r["particles"], r["frame_wall_ms"]["median"], r["frame_wall_ms"]["min"], r["frame_wall_ms"]["max"])
                for r in rs]

    series(ax, "ours: simulation + 2D view + FXAA (bar: min..max)", measured(render), "#d62728")
    series(ax, "ours: simulation only", measured(sim), "#1f77b4", "s")
    for mode in other_modes:
        mode_rows = [r for r in all_rows if r.get("splat") == mode]
        series(ax, f"ours, {mode} splat: simulation + 2D view + FXAA",
               measured([r for r in mode_rows if r["mode"] == "sim+render"]), "#ff9896", "o", (0, (5, 2)))
        series(ax, f"ours, {mode} splat: simulation only",
               measured([r for r in mode_rows if r["mode"] == "sim"]), "#aec7e8", "s", (0, (5, 2)))
    series(ax, "paper, Quadro 2000M: this method (sim + render)",
           [(r["particles"], r["paper"]["frame_ms"]) for r in render], "#d62728", "D", (0, (3, 2)))
    series(ax, "paper, Quadro 2000M: DX11 SDK SPH (sim + render)",
           [(r["particles"], r["paper"]["sph_frame_ms"]) for r in render], "#555", "D", (0, (1, 1.5)))
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1), fontsize="small", handlelength=3)
    footer(fig, data, "paper figures: ms = 1000 / fps, one step + rendering per frame (Guay, GPU Pro 5, section 7)")
    plot_files.save_svg(fig, path)
    return True


def pass_color(name, extra):
    if name in PASS_COLORS:
        return PASS_COLORS[name]
    if name not in extra:
        extra[name] = EXTRA_COLORS[len(extra) % len(EXTRA_COLORS)]
    return extra[name]


def pass_names(rows):
    order = list(PASS_COLORS)
    seen = []
    for r in rows:
        for name in r.get("pass_order", r["gpu_ms_per_frame"].keys()):
            if name not in seen:
                seen.append(name)
    return [n for n in order if n in seen] + [n for n in seen if n not in order]


def gpu_passes_chart(data, path):
    rows = [r for r in data["results"] if r["gpu_ms_per_frame"]]
    if not rows:
        return False
    # One panel per kind, each with its own scale: a 3D frame takes ~50x a 2D one.
    panels = [("2D paper scenes", [r for r in rows if r["group"] == "paper" and r["dimension"] == 2]),
              ("3D paper scene", [r for r in rows if r["group"] == "paper" and r["dimension"] == 3]),
              ("2D scaling runs (simulation only)", [r for r in rows if r["group"] == "scaling"]),
              ("3D scaling runs (simulation only)", [r for r in rows if r["group"] == "scaling3d"])]
    panels = [(t, rs) for t, rs in panels if rs]
    names = pass_names(rows)
    extra = {}
    fig = Figure(figsize=(9.8, 1.5 + sum(0.75 + 0.3 * len(rs) for _, rs in panels)), layout="constrained")
    axes = fig.subplots(len(panels), 1, squeeze=False, height_ratios=[len(rs) + 2.5 for _, rs in panels])[:, 0]
    fig.suptitle("GPU time per pass (median per frame, graph timestamps)", fontweight="bold")
    for ax, (title, rs) in zip(axes, panels):
        rows_at = range(len(rs))
        stacked = [0.0] * len(rs)
        for n in names:
            ms = [median(r["gpu_ms_per_frame"].get(n)) or 0 for r in rs]
            bars = ax.barh(rows_at, ms, left=stacked, height=0.75, color=pass_color(n, extra), label=n)
            stacked = [s + m for s, m in zip(stacked, ms)]
        # The last pass's bars end at the totals.
        ax.bar_label(bars, [f"{total:.1f} ms" for total in stacked], padding=4, fontsize=8)
        ax.set_yticks(rows_at, [r["name"] for r in rs], fontsize=9)
        ax.invert_yaxis()  # the first configuration on top
        ax.set_xlim(0, max(stacked) * 1.12 or 1.0)
        ax.set_xlabel("ms per frame")
        ax.set_title(title, loc="left", fontweight="bold", fontsize=11)
        ax.grid(axis="x", color="#ddd")
        ax.set_axisbelow(True)
        ax.tick_params(axis="y", length=0)
    axes[0].legend(title="pass", loc="upper left", bbox_to_anchor=(1.02, 1), frameon=False, fontsize="small")
    footer(fig, data)
    plot_files.save_svg(fig, path)
    return True


def scaling_chart(data, path):
    rows = [r for r in data["results"] if r["group"] == "scaling"]
    if not rows:
        return False
    fixed_grid = [r for r in rows if r["grid"][0] == 256]
    # The grid curve holds the points at the 64k count (the 256^2 point is shared).
    sixty_four = min((r["particles"] for r in rows), key=lambda n: abs(n - 64000))
    fixed_count = [r for r in rows if r["particles"] == sixty_four]
    fig = Figure(figsize=(11.8, 6.4), layout="constrained")
    fig.suptitle("2D scaling, simulation only: time per step (log-log; lower is better)", fontweight="bold")

    def panel(ax, rs, xkey, title, xlabel, xformat):
        rs = sorted(rs, key=xkey)
        if not rs:
            ax.set_axis_off()
            return
        log_log(ax, title, xlabel, "ms per step (log scale)", [xkey(r) for r in rs], xformat, 1.3)
        series(ax, "wall time per step (bar: min..max)",
               [(xkey(r), r["step_wall_ms"]["median"], r["step_wall_ms"]["min"], r["step_wall_ms"]["max"]) for r in rs],
               "#000")
        for name in ("liquid.splat", "liquid.grid", "liquid.particle"):
            series(ax, f"GPU {name}", [(xkey(r), median(r["gpu_ms_per_frame"].get(name)) / r["steps_per_frame"])
                                       for r in rs if r["gpu_ms_per_frame"].get(name)],
                   PASS_COLORS[name], "s", (0, (2.5, 1.5)))
        ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.13), ncol=2, fontsize="small", handlelength=3)

    count_axes, grid_axes = fig.subplots(1, 2)
    panel(count_axes, fixed_grid, lambda r: r["particles"], "particle count at a 256\u00b2 grid", "active particles",
          format_count)
    panel(grid_axes, fixed_count, lambda r: r["grid"][0], f"grid size at {format_count(sixty_four)} particles",
          "grid cells per side (N x N grid)", lambda v: f"{v:g}")
    footer(fig, data)
    plot_files.save_svg(fig, path)
    return True


def scaling_3d_chart(data, path):
    rows = sorted((r for r in data["results"] if r["group"] == "scaling3d"), key=lambda r: r["particles"])
    if not rows:
        return False
    xs = [r["particles"] for r in rows]
    fig = Figure(figsize=(11.8, 6.4), layout="constrained")
    fig.suptitle("3D scaling, simulation only: paper_3d, separable splat, grid growing as N^(1/3) (log-log)",
                 fontweight="bold")
    time_axes, memory_axes = fig.subplots(1, 2)
    log_log(time_axes, "time per step", "active particles", "ms per step (log scale)", xs, format_count, 1.3)
    series(time_axes, "wall time per step (bar: min..max)",
           [(r["particles"], r["step_wall_ms"]["median"], r["step_wall_ms"]["min"], r["step_wall_ms"]["max"])
            for r in rows], "#000")
    series(time_axes, "solver GPU time per step", [(r["particles"], r["solver_gpu_ms_per_step"]["median"])
                                                   for r in rows], PASS_COLORS["liquid.splat"], "s", (0, (2.5, 1.5)))
    time_axes.legend(loc="upper center", bbox_to_anchor=(0.5, -0.13), ncol=2, fontsize="small", handlelength=3)
    log_log(memory_axes, "device memory held", "active particles", "MiB (log scale)", xs, format_count, 1.3)
    series(memory_axes, "the engine's buffers and images at most at once",
           [(r["particles"], r.get("device_memory_bytes", 0) / 2**20) for r in rows], "#9467bd")
    memory_axes.legend(loc="upper center", bbox_to_anchor=(0.5, -0.13), fontsize="small", handlelength=3)
    per_particle = ", ".join(f"{format_count(r['particles'])}: {1e6 * r['step_wall_ms']['median'] / r['particles']:.3g}"
                             for r in rows)
    footer(fig, data, f"wall time per particle and step (ns): {per_particle}")
    plot_files.save_svg(fig, path)
    return True


def plot(data, out):
    for name, chart in (("paper_2d.svg", paper_2d_chart), ("gpu_passes.svg", gpu_passes_chart),
                        ("scaling.svg", scaling_chart), ("scaling_3d.svg", scaling_3d_chart)):
        path = os.path.join(out, name)
        print(f"wrote {path}" if chart(data, path) else f"skipped {name} (no data for it in the JSON)")


if __name__ == "__main__":
    sys.exit(plot_files.main("plot_benchmark", "Plots liquid_benchmark JSON as SVG charts.",
                             "out/benchmark/benchmark.json", "results", "liquid_benchmark", plot))
