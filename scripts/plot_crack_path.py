#!/usr/bin/python3
"""Crack path of a run as a PNG: scripts/plot_crack_path.py <output dir> -> <dir>/crack_path.png.

Reads what the run wrote into the directory: crack_path.csv (our path; crack_path_2.csv, ... for
the further cracks of a run with several), body.csv (the outline and
the holes as curves, the named points of the boundary conditions), reference_path.csv where the
scene has a reference path, and for a global-local run boxes.csv (every PD box, drawn light to
dark blue as the run goes on). Run it with /usr/bin/python3 (Debian's python3-matplotlib).
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import Rectangle  # noqa: E402


def path(file):
    with open(file) as f:
        rows = list(csv.DictReader(f))
    return [1e3 * float(r["x_m"]) for r in rows], [1e3 * float(r["y_m"]) for r in rows]


directory = sys.argv[1]
curves = {}
with open(f"{directory}/body.csv") as f:
    for r in csv.DictReader(f):
        curves.setdefault(r["curve"], []).append((1e3 * float(r["x_m"]), 1e3 * float(r["y_m"])))

fig, ax = plt.subplots(figsize=(9, 4.4))
labelled = False
for name, points in curves.items():
    xs, ys = zip(*points)
    if name.startswith("point:"):
        ax.plot(xs, ys, "^", color="dimgray", ms=8, label="named points" if not labelled else None)
        for x0, y0 in points:
            ax.annotate(name[len("point:"):], (x0, y0), textcoords="offset points", xytext=(4, -12), fontsize=7,
                        color="dimgray")
        labelled = True
    else:
        ax.plot(xs, ys, color="black", lw=1)

boxes = f"{directory}/boxes.csv"
coupled = os.path.exists(boxes)
if coupled:
    with open(boxes) as f:
        rows = [r for r in csv.DictReader(f) if r["moved"] == "1"]
    for k, r in enumerate(rows):
        x0, y0, x1, y1 = (1e3 * float(r[c]) for c in ("x_min_m", "y_min_m", "x_max_m", "y_max_m"))
        shade = plt.cm.Blues(0.3 + 0.7 * k / max(1, len(rows) - 1))
        ax.add_patch(Rectangle((x0, y0), x1 - x0, y1 - y0, fill=False, color=shade, lw=0.9,
                               label="PD boxes (light: first, dark: last)" if k == 0 else None))

reference = f"{directory}/reference_path.csv"
if os.path.exists(reference):
    ax.plot(*path(reference), color="tab:green", lw=1.2, label="reference path")
others = 2
while os.path.exists(f"{directory}/crack_path_{others}.csv"):
    xo, yo = path(f"{directory}/crack_path_{others}.csv")
    ax.plot(xo, yo, color="tab:orange", lw=1.6, marker=".", ms=3,
            label="further cracks (pumpd)" if others == 2 else None)
    others += 1
x, y = path(f"{directory}/crack_path.csv")
ax.plot(x, y, color="tab:red", lw=1.6, marker=".", ms=3, label="crack path (pumpd)")
ax.plot(x[-1], y[-1], "o", color="tab:red", ms=5)

ax.set_aspect("equal")
ax.set_xlabel("x [mm]")
ax.set_ylabel("y [mm]")
ax.set_title(f"{os.path.basename(os.path.normpath(directory))}: crack path, end ({x[-1]:.1f}, {y[-1]:.1f}) mm")
ax.legend(loc="upper right", fontsize=8)
ax.autoscale_view()
fig.tight_layout()
fig.savefig(f"{directory}/crack_path.png", dpi=130)
print(f"wrote {directory}/crack_path.png")
