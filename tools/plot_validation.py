#!/usr/bin/env python3
"""Turns the JSON written by liquid_validate into SVG plots (Python standard library only).

    python3 tools/plot_validation.py out/validation/validation.json [-o out/validation]

Writes, where the JSON holds the runs for them:
  front.svg        surge front Z = x/a against T = t sqrt(2g/a) of every collapsing-column run,
                   with Martin and Moyce's (1952) measurements (n^2 = 2) as points
  energy.svg       kinetic, potential and mechanical energy against time of the rest pool and the
                   dam break, each as a share of its initial potential energy
  rest_pool.svg    the rest pool's kinetic energy (log scale) against its target, and its surface
                   deviation in cells
  volume.svg       occupied volume against time, relative to the first frame
"""

import argparse
import json
import math
import os
import sys
from xml.sax.saxutils import escape

FONT = "font-family='DejaVu Sans, Arial, sans-serif'"
COLORS = ["#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b"]
# Martin and Moyce (1952), n^2 = 2, a = 2.25 in (the table in liquid/validation.cpp).
MARTIN_MOYCE = [(0.41, 1.11), (0.84, 1.22), (1.19, 1.44), (1.43, 1.67), (1.63, 1.89), (1.83, 2.11), (1.98, 2.33),
                (2.20, 2.56), (2.32, 2.78), (2.51, 3.00), (2.65, 3.22), (2.83, 3.44), (2.98, 3.67), (3.11, 3.89),
                (3.33, 4.11)]
T, KE, PE, E, VOLUME, FRONT, SPREAD = range(7)


class Plot:
    """One chart: axes with ticks, polylines, points and a legend, as a flat list of SVG elements."""

    def __init__(self, title, xlabel, ylabel, xrange, yrange, log_y=False, width=760, height=460):
        self.w, self.h = width, height
        self.left, self.right, self.top, self.bottom = 80, 200, 40, 60
        self.x0, self.x1 = xrange
        self.log_y = log_y
        self.y0, self.y1 = (math.log10(yrange[0]), math.log10(yrange[1])) if log_y else yrange
        self.items = [f"<rect x='0' y='0' width='{width}' height='{height}' fill='white'/>"]
        self.legend = []
        self.text(width / 2 - self.right / 2, 24, title, 15, "middle", "bold")
        self.text(self.left + (width - self.left - self.right) / 2, height - 16, xlabel, 12, "middle")
        self.text(18, self.top + (height - self.top - self.bottom) / 2, ylabel, 12, "middle", rotate=-90)
        self.axes()

    def text(self, x, y, s, size=11, anchor="start", weight="normal", rotate=None):
        transform = f" transform='rotate({rotate} {x:.1f} {y:.1f})'" if rotate else ""
        self.items.append(f"<text x='{x:.1f}' y='{y:.1f}' font-size='{size}' text-anchor='{anchor}' "
                          f"font-weight='{weight}' fill='#222' {FONT}{transform}>{escape(str(s))}</text>")

    def px(self, x):
        return self.left + (x - self.x0) / (self.x1 - self.x0) * (self.w - self.left - self.right)

    def py(self, y):
        if self.log_y:
            y = math.log10(max(y, 10 ** self.y0))
        y = min(max(y, self.y0), self.y1)
        return self.h - self.bottom - (y - self.y0) / (self.y1 - self.y0) * (self.h - self.top - self.bottom)

    def axes(self):
        x_left, x_right = self.left, self.w - self.right
        y_top, y_bottom = self.top, self.h - self.bottom
        self.items.append(f"<rect x='{x_left}' y='{y_top}' width='{x_right - x_left}' height='{y_bottom - y_top}' "
                          f"fill='none' stroke='#444'/>")
        for i in range(6):
            x = self.x0 + (self.x1 - self.x0) * i / 5
            self.text(self.px(x), y_bottom + 16, f"{x:.3g}", 10, "middle")
            self.items.append(f"<line x1='{self.px(x):.1f}' y1='{y_top}' x2='{self.px(x):.1f}' y2='{y_bottom}' "
                              f"stroke='#eee'/>")
        if self.log_y:
            ticks = [10.0 ** k for k in range(math.ceil(self.y0), math.floor(self.y1) + 1)]
        else:
            ticks = [self.y0 + (self.y1 - self.y0) * i / 5 for i in range(6)]
        for y in ticks:
            self.text(x_left - 6, self.py(y) + 4, f"{y:.3g}", 10, "end")
            self.items.append(f"<line x1='{x_left}' y1='{self.py(y):.1f}' x2='{x_right}' y2='{self.py(y):.1f}' "
                              f"stroke='#eee'/>")

    def series(self, xs, ys, label, color, dash=None):
        pts = " ".join(f"{self.px(x):.1f},{self.py(y):.1f}" for x, y in zip(xs, ys) if self.x0 <= x <= self.x1)
        d = f" stroke-dasharray='{dash}'" if dash else ""
        self.items.append(f"<polyline points='{pts}' fill='none' stroke='{color}' stroke-width='1.8'{d}/>")
        self.legend.append((label, color, "line", dash))

    def points(self, xs, ys, label, color):
        for x, y in zip(xs, ys):
            self.items.append(f"<circle cx='{self.px(x):.1f}' cy='{self.py(y):.1f}' r='3.5' fill='{color}'/>")
        self.legend.append((label, color, "point", None))

    def save(self, path):
        x = self.w - self.right + 12
        for i, (label, color, kind, dash) in enumerate(self.legend):
            y = self.top + 14 + 18 * i
            if kind == "line":
                d = f" stroke-dasharray='{dash}'" if dash else ""
                self.items.append(f"<line x1='{x}' y1='{y - 4}' x2='{x + 18}' y2='{y - 4}' stroke='{color}' "
                                  f"stroke-width='2'{d}/>")
            else:
                self.items.append(f"<circle cx='{x + 9}' cy='{y - 4}' r='3.5' fill='{color}'/>")
            self.text(x + 24, y, label, 10)
        body = "\n".join(self.items)
        with open(path, "w") as f:
            f.write(f"<svg xmlns='http://www.w3.org/2000/svg' width='{self.w}' height='{self.h}'>\n{body}\n</svg>\n")
        print(path)


def column(run):
    """(T, Z) of a collapsing-column run; a = 0.1 m, g = 9.81 m/s^2 (liquid_validate's scenes)."""
    a, g = 0.1, 9.81
    k = math.sqrt(2 * g / a)
    return [s[T] * k for s in run["samples"]], [s[FRONT] / a for s in run["samples"]]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("json")
    parser.add_argument("-o", "--out", help="output folder (default: the JSON's folder)")
    args = parser.parse_args()
    with open(args.json) as f:
        data = json.load(f)
    out = args.out or os.path.dirname(os.path.abspath(args.json))
    os.makedirs(out, exist_ok=True)
    runs = data["runs"]
    columns = [r for r in runs if "column" in r["name"].lower()]
    others = [r for r in runs if r not in columns]

    if columns:
        p = Plot("Collapsing column: surge front", "T = t sqrt(2g/a)", "Z = x / a", (0, 3.5), (1, 4.5))
        for i, r in enumerate(columns):
            xs, ys = column(r)
            p.series([0.0] + xs, [1.0] + ys, r["name"].replace("Collapsing column ", ""), COLORS[i % len(COLORS)])
        p.points([t for t, _ in MARTIN_MOYCE], [z for _, z in MARTIN_MOYCE], "Martin & Moyce 1952", "#000")
        p.save(os.path.join(out, "front.svg"))

    if others:
        t_end = max(s[T] for r in others for s in r["samples"])
        p = Plot("Energy / initial potential energy", "t (s)", "share of PE(0)", (0, t_end), (0, 1.05))
        for i, r in enumerate(others):
            pe0 = r["samples"][0][PE] or 1.0
            ts = [s[T] for s in r["samples"]]
            color = COLORS[i % len(COLORS)]
            p.series(ts, [s[E] / pe0 for s in r["samples"]], r["name"] + ": KE + PE", color)
            p.series(ts, [s[KE] / pe0 for s in r["samples"]], r["name"] + ": KE", color, dash="4,3")
        p.save(os.path.join(out, "energy.svg"))

        p = Plot("Volume under the free surface / first frame", "t (s)", "V / V(first frame)", (0, t_end),
                 (0.96, 1.04))
        for i, r in enumerate(others):
            v0 = r["samples"][0][VOLUME] or 1.0
            p.series([s[T] for s in r["samples"]], [s[VOLUME] / v0 for s in r["samples"]], r["name"],
                     COLORS[i % len(COLORS)])
        p.series([0, t_end], [1.01, 1.01], "+1 % (target)", "#888", dash="6,4")
        p.series([0, t_end], [0.99, 0.99], "-1 % (target)", "#888", dash="6,4")
        p.save(os.path.join(out, "volume.svg"))

    pools = [r for r in others if "rest" in r["name"].lower()]
    for r in pools:
        pe0 = r["samples"][0][PE] or 1.0
        ts = [s[T] for s in r["samples"]]
        t_end = ts[-1]
        p = Plot("Pool at rest: kinetic energy / PE(0)", "t (s)", "KE / PE(0)", (0, t_end), (1e-9, 1e-1), log_y=True)
        p.series(ts, [max(s[KE] / pe0, 1e-12) for s in r["samples"]], "KE / PE(0)", COLORS[0])
        p.series([1, t_end], [5e-4, 5e-4], "target (from 1 s)", "#d62728", dash="6,4")
        p.save(os.path.join(out, "rest_pool.svg"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
