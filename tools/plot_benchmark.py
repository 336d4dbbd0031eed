#!/usr/bin/env python3
"""Turns the JSON written by liquid_benchmark into SVG charts (Python standard library only).

    python3 tools/plot_benchmark.py out/benchmark/benchmark.json [-o out/benchmark]

Writes, where the JSON holds the data for them:
  paper_2d.svg    time per frame against particle count for the 2D paper scenes, ours beside the
                  paper's Quadro 2000M figures (the chapter's method and the DX11 SDK SPH sample)
  gpu_passes.svg  GPU time of every pass, stacked per configuration
  scaling.svg     time per step against particle count (256^2 grid) and against grid size (64k)
"""

import argparse
import json
import math
import os
import sys
from xml.sax.saxutils import escape

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
FONT = "font-family='DejaVu Sans, Arial, sans-serif'"


class Svg:
    """A flat list of SVG elements on a white canvas."""

    def __init__(self, width, height):
        self.width, self.height = width, height
        self.items = [f"<rect x='0' y='0' width='{width}' height='{height}' fill='white'/>"]

    def text(self, x, y, s, size=12, anchor="start", weight="normal", rotate=None, color="#222"):
        transform = f" transform='rotate({rotate} {x:.1f} {y:.1f})'" if rotate else ""
        self.items.append(
            f"<text x='{x:.1f}' y='{y:.1f}' font-size='{size}' text-anchor='{anchor}' font-weight='{weight}' "
            f"fill='{color}' {FONT}{transform}>{escape(str(s))}</text>")

    def line(self, x1, y1, x2, y2, color="#000", width=1.0, dash=None):
        d = f" stroke-dasharray='{dash}'" if dash else ""
        self.items.append(f"<line x1='{x1:.1f}' y1='{y1:.1f}' x2='{x2:.1f}' y2='{y2:.1f}' stroke='{color}' "
                          f"stroke-width='{width}'{d}/>")

    def rect(self, x, y, w, h, fill, stroke="none", title=None):
        tip = f"<title>{escape(title)}</title>" if title else ""
        self.items.append(f"<rect x='{x:.1f}' y='{y:.1f}' width='{max(w, 0):.1f}' height='{max(h, 0):.1f}' "
                          f"fill='{fill}' stroke='{stroke}'>{tip}</rect>")

    def polyline(self, points, color, width=2.0, dash=None):
        d = f" stroke-dasharray='{dash}'" if dash else ""
        pts = " ".join(f"{x:.1f},{y:.1f}" for x, y in points)
        self.items.append(f"<polyline points='{pts}' fill='none' stroke='{color}' stroke-width='{width}'{d}/>")

    def marker(self, x, y, color, shape="circle", title=None):
        tip = f"<title>{escape(title)}</title>" if title else ""
        if shape == "square":
            self.items.append(f"<rect x='{x - 4:.1f}' y='{y - 4:.1f}' width='8' height='8' fill='{color}'>{tip}</rect>")
        elif shape == "diamond":
            self.items.append(f"<polygon points='{x:.1f},{y - 5:.1f} {x + 5:.1f},{y:.1f} {x:.1f},{y + 5:.1f} "
                              f"{x - 5:.1f},{y:.1f}' fill='{color}'>{tip}</polygon>")
        else:
            self.items.append(f"<circle cx='{x:.1f}' cy='{y:.1f}' r='4' fill='{color}'>{tip}</circle>")

    def save(self, path):
        body = "\n".join(self.items)
        text = (f"<svg xmlns='http://www.w3.org/2000/svg' width='{self.width}' height='{self.height}' "
                f"viewBox='0 0 {self.width} {self.height}'>\n{body}\n</svg>\n")
        temporary = path + ".partial"
        with open(temporary, "w", encoding="utf-8") as f:
            f.write(text)
        os.replace(temporary, path)


# ---------------------------------------------------------------------------------------------
# Axes

def log_ticks(lo, hi):
    """1-2-5 ticks per decade when the range is short, decades otherwise."""
    first, last = math.floor(math.log10(lo)), math.ceil(math.log10(hi))
    steps = (1, 2, 5) if last - first <= 4 else (1,)
    return [m * 10 ** e for e in range(first, last + 1) for m in steps if lo <= m * 10 ** e <= hi]


def linear_ticks(lo, hi, count=5):
    span = hi - lo or 1.0
    raw = span / count
    magnitude = 10 ** math.floor(math.log10(raw))
    step = next(m * magnitude for m in (1, 2, 2.5, 5, 10) if m * magnitude >= raw)
    first = math.ceil(lo / step) * step
    return [first + i * step for i in range(int((hi - first) / step + 1e-9) + 1)]


def format_number(v):
    if v >= 1e6 and v % 1e6 == 0:
        return f"{v / 1e6:g}M"
    if v >= 1e4:
        return f"{v / 1e3:g}k"
    return f"{v:g}"


def format_count(v):
    return f"{v / 1000:.0f}k" if v >= 1000 else f"{v:g}"


class Axis:
    """Maps data values to pixels on a linear or logarithmic scale."""

    def __init__(self, lo, hi, p0, p1, log=False):
        if log:
            lo, hi = max(lo, 1e-9), max(hi, lo * 1.0001)
        elif hi <= lo:
            hi = lo + 1.0
        self.lo, self.hi, self.p0, self.p1, self.log = lo, hi, p0, p1, log

    def __call__(self, v):
        if self.log:
            t = (math.log(max(v, 1e-12)) - math.log(self.lo)) / (math.log(self.hi) - math.log(self.lo))
        else:
            t = (v - self.lo) / (self.hi - self.lo)
        return self.p0 + t * (self.p1 - self.p0)


def padded_log_range(values, pad=1.35):
    lo, hi = min(values), max(values)
    return lo / pad, hi * pad


class XYPlot:
    """A plot area with axes, grid lines, labels and a legend; series are lines with markers."""

    def __init__(self, svg, box, title, xlabel, ylabel, xrange, yrange, xlog=True, ylog=True, xticks=None,
                 xformat=format_number):
        x0, y0, w, h = box
        self.svg, self.box = svg, box
        self.x = Axis(xrange[0], xrange[1], x0, x0 + w, xlog)
        self.y = Axis(yrange[0], yrange[1], y0 + h, y0, ylog)
        self.legend = []
        svg.text(x0 + w / 2, y0 - 12, title, size=14, anchor="middle", weight="bold")
        yt = log_ticks(*yrange) if ylog else linear_ticks(*yrange)
        for v in yt:
            py = self.y(v)
            svg.line(x0, py, x0 + w, py, "#ddd")
            svg.text(x0 - 6, py + 4, format_number(v), size=11, anchor="end")
        xt = xticks if xticks else (log_ticks(*xrange) if xlog else linear_ticks(*xrange))
        for v in xt:
            px = self.x(v)
            svg.line(px, y0, px, y0 + h, "#eee")
            svg.text(px, y0 + h + 16, xformat(v), size=11, anchor="middle")
        svg.line(x0, y0 + h, x0 + w, y0 + h, "#444")
        svg.line(x0, y0, x0, y0 + h, "#444")
        svg.text(x0 + w / 2, y0 + h + 38, xlabel, size=12, anchor="middle")
        svg.text(x0 - 52, y0 + h / 2, ylabel, size=12, anchor="middle", rotate=-90)

    def series(self, label, points, color, shape="circle", dash=None, ranges=None, unit="ms"):
        points = sorted(p for p in points if p[1] is not None and p[1] > 0)
        if not points:
            return
        pixels = [(self.x(px), self.y(py)) for px, py in points]
        if len(pixels) > 1:
            self.svg.polyline(pixels, color, dash=dash)
        for i, ((px, py), (sx, sy)) in enumerate(zip(points, pixels)):
            if ranges:  # min..max bar
                lo, hi = ranges[i]
                self.svg.line(sx, self.y(lo), sx, self.y(hi), color, 1.5)
            self.svg.marker(sx, sy, color, shape, f"{label}: {format_count(px)}, {py:.3g} {unit}")
        self.legend.append((label, color, shape, dash))

    def draw_legend(self, lx, ly, columns=1, column_width=300):
        """A framed legend with its top-left corner at (lx, ly), outside the data area."""
        if not self.legend:
            return
        rows = (len(self.legend) + columns - 1) // columns
        self.svg.rect(lx, ly, column_width * columns, 18 * rows + 8, "white", "#bbb")
        for i, (label, color, shape, dash) in enumerate(self.legend):
            cx, cy = lx + column_width * (i // rows), ly + 14 + 18 * (i % rows)
            self.svg.line(cx + 6, cy, cx + 28, cy, color, 2, dash)
            self.svg.marker(cx + 17, cy, color, shape)
            self.svg.text(cx + 34, cy + 4, label, size=11)


# ---------------------------------------------------------------------------------------------
# The charts

def footer(svg, x, y, data, extra=None):
    """Two or three grey lines under a chart: the device, the date and the run's settings."""
    device = data.get("device", {})
    settings = data.get("settings", {})
    lines = [f"ours: {device.get('name', '?')}, {device.get('driver', '?')}; {data.get('date', '')}",
             f"{settings.get('warmup_frames', '?')} warm-up frames, then {settings.get('timed_frames', '?')} timed "
             f"frames per configuration ({settings.get('scaling_timed_frames', '?')} per scaling point); "
             f"{settings.get('steps_per_frame', 1)} step per frame"]
    for i, line in enumerate(lines + ([extra] if extra else [])):
        svg.text(x, y + 15 * i, line, size=11, color="#555")


def median(stats):
    return stats["median"] if stats else None


def paper_2d_chart(data, path):
    rows = [r for r in data["results"] if r["group"] == "paper" and r["scene"].startswith("paper_2d")]
    if not rows:
        return False
    svg = Svg(1200, 580)
    render = sorted((r for r in rows if r["mode"] == "sim+render"), key=lambda r: r["particles"])
    sim = sorted((r for r in rows if r["mode"] == "sim"), key=lambda r: r["particles"])
    values = [r["frame_wall_ms"]["max"] for r in rows] + [r["frame_wall_ms"]["min"] for r in rows]
    for r in render:
        values += [r["paper"]["frame_ms"]] + ([r["paper"]["sph_frame_ms"]] if r["paper"]["sph_frame_ms"] else [])
    counts = sorted({r["particles"] for r in rows})
    plot = XYPlot(svg, (90, 60, 720, 400), "2D, 256\u00b2 grid: time per frame (one step, plus rendering where noted)",
                  "active particles", "wall time per frame, ms (log scale; lower is better)",
                  (counts[0] / 1.25, counts[-1] * 1.25), padded_log_range(values), xticks=counts,
                  xformat=format_count)

    def pts(rs, key):
        return [(r["particles"], r[key]["median"]) for r in rs]

    def ranges(rs, key):
        return [(r[key]["min"], r[key]["max"]) for r in sorted(rs, key=lambda r: r["particles"])]

    plot.series("ours: simulation + 2D view + FXAA (bar: min..max)", pts(render, "frame_wall_ms"), "#d62728",
                ranges=ranges(render, "frame_wall_ms"))
    plot.series("ours: simulation only", pts(sim, "frame_wall_ms"), "#1f77b4", "square", ranges=ranges(sim, "frame_wall_ms"))
    plot.series("paper, Quadro 2000M: this method (sim + render)", [(r["particles"], r["paper"]["frame_ms"]) for r in render],
                "#d62728", "diamond", dash="6 4")
    plot.series("paper, Quadro 2000M: DX11 SDK SPH (sim + render)",
                [(r["particles"], r["paper"]["sph_frame_ms"]) for r in render], "#555", "diamond", dash="2 3")
    plot.draw_legend(830, 60, column_width=350)
    footer(svg, 90, 530, data, "paper figures: ms = 1000 / fps, one step + rendering per frame (Guay, GPU Pro 5, section 7)")
    svg.save(path)
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
              ("2D scaling runs (simulation only)", [r for r in rows if r["group"] == "scaling"])]
    panels = [(t, rs) for t, rs in panels if rs]
    names = pass_names(rows)
    extra = {}
    bar, gap, left, width = 22, 8, 220, 560
    height = 70 + sum(60 + len(rs) * (bar + gap) for _, rs in panels) + 40
    svg = Svg(left + width + 200, height)
    svg.text((left + width) / 2 + 40, 28, "GPU time per pass (median per frame, graph timestamps)", size=15,
             anchor="middle", weight="bold")
    y = 70
    for title, rs in panels:
        totals = [sum(median(r["gpu_ms_per_frame"].get(n)) or 0 for n in names) for r in rs]
        axis = Axis(0, max(totals) * 1.12, left, left + width)
        svg.text(left, y - 8, title, size=13, weight="bold")
        top, bottom = y, y + len(rs) * (bar + gap)
        for v in linear_ticks(0, axis.hi, 6):
            svg.line(axis(v), top, axis(v), bottom, "#ddd")
            svg.text(axis(v), bottom + 14, format_number(v), size=10, anchor="middle")
        svg.text(left + width / 2, bottom + 30, "ms per frame", size=11, anchor="middle")
        for r, total in zip(rs, totals):
            svg.text(left - 8, y + bar * 0.7, r["name"], size=11, anchor="end")
            stacked = 0.0
            for n in names:
                ms = median(r["gpu_ms_per_frame"].get(n))
                if not ms:
                    continue
                svg.rect(axis(stacked), y, axis(stacked + ms) - axis(stacked), bar, pass_color(n, extra),
                         title=f"{r['name']} {n}: {ms:.3f} ms")
                stacked += ms
            svg.text(axis(stacked) + 5, y + bar * 0.7, f"{total:.1f} ms", size=10)
            y += bar + gap
        svg.line(left, top, left, bottom, "#444")
        y += 60
    lx = left + width + 30
    svg.text(lx, 70, "pass", size=12, weight="bold")
    for i, n in enumerate(names):
        svg.rect(lx, 80 + 20 * i, 14, 14, pass_color(n, extra))
        svg.text(lx + 20, 92 + 20 * i, n, size=11)
    footer(svg, 20, height - 30, data)
    svg.save(path)
    return True


def scaling_chart(data, path):
    rows = [r for r in data["results"] if r["group"] == "scaling"]
    if not rows:
        return False
    fixed_grid = [r for r in rows if r["grid"][0] == 256]
    # The grid curve holds the points at the 64k count (the 256^2 point is shared).
    sixty_four = min((r["particles"] for r in rows), key=lambda n: abs(n - 64000))
    fixed_count = [r for r in rows if r["particles"] == sixty_four]
    svg = Svg(1180, 640)
    svg.text(590, 26, "2D scaling, simulation only: time per step (log-log; lower is better)", size=15,
             anchor="middle", weight="bold")

    def panel(box, rs, xkey, title, xlabel, xformat):
        rs = sorted(rs, key=xkey)
        if not rs:
            return
        xs = [xkey(r) for r in rs]
        values = [r["step_wall_ms"]["max"] for r in rs] + [r["step_wall_ms"]["min"] for r in rs]
        for r in rs:
            values += [v["median"] for v in r["gpu_ms_per_frame"].values() if v["median"] > 0]
        plot = XYPlot(svg, box, title, xlabel, "ms per step (log scale)", (xs[0] / 1.3, xs[-1] * 1.3),
                      padded_log_range(values), xticks=xs, xformat=xformat)
        plot.series("wall time per step (bar: min..max)", [(xkey(r), r["step_wall_ms"]["median"]) for r in rs], "#000",
                    ranges=[(r["step_wall_ms"]["min"], r["step_wall_ms"]["max"]) for r in rs])
        steps = lambda r: r["steps_per_frame"]
        for name in ("liquid.splat", "liquid.grid", "liquid.particle"):
            plot.series(f"GPU {name}", [(xkey(r), median(r["gpu_ms_per_frame"].get(name)) / steps(r))
                                        for r in rs if r["gpu_ms_per_frame"].get(name)],
                        PASS_COLORS[name], "square", dash="5 3")
        x0, y0, w, h = box
        plot.draw_legend(x0, y0 + h + 50, columns=2, column_width=w / 2)

    panel((90, 70, 460, 390), fixed_grid, lambda r: r["particles"], "particle count at a 256\u00b2 grid",
          "active particles", format_count)
    panel((680, 70, 460, 390), fixed_count, lambda r: r["grid"][0],
          f"grid size at {format_count(sixty_four)} particles", "grid cells per side (N x N grid)", lambda v: f"{v:g}")
    footer(svg, 90, 595, data)
    svg.save(path)
    return True


def main():
    parser = argparse.ArgumentParser(description="Plots liquid_benchmark JSON as SVG charts.")
    parser.add_argument("json", nargs="?", default="out/benchmark/benchmark.json", help="liquid_benchmark output")
    parser.add_argument("-o", "--out", help="folder for the SVG files (default: the JSON's folder)")
    args = parser.parse_args()
    try:
        with open(args.json, encoding="utf-8") as f:
            data = json.load(f)
        if "results" not in data:
            raise ValueError("no 'results' array: not a liquid_benchmark file")
        out = args.out or os.path.dirname(os.path.abspath(args.json))
        os.makedirs(out, exist_ok=True)
        for name, chart in (("paper_2d.svg", paper_2d_chart), ("gpu_passes.svg", gpu_passes_chart),
                            ("scaling.svg", scaling_chart)):
            path = os.path.join(out, name)
            print(f"wrote {path}" if chart(data, path) else f"skipped {name} (no data for it in the JSON)")
    except KeyError as error:
        print(f"plot_benchmark: error: {args.json}: missing field {error}", file=sys.stderr)
        return 1
    except (OSError, ValueError, TypeError) as error:
        print(f"plot_benchmark: error: {error}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
