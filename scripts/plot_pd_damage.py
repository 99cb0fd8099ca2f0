#!/usr/bin/python3
"""Damage field of a PD run as a PNG: scripts/plot_pd_damage.py <output dir> -> <dir>/pd_damage.png."""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

directory = sys.argv[1]
with open(f"{directory}/damage.csv") as f:
    rows = list(csv.DictReader(f))
x = [1e3 * float(r["x_m"]) for r in rows]
y = [1e3 * float(r["y_m"]) for r in rows]
d = [float(r["damage"]) for r in rows]

fig, ax = plt.subplots(figsize=(6, 5.2))
points = ax.scatter(x, y, c=d, s=2, cmap="inferno_r", vmin=0, vmax=max(0.5, max(d)))
fig.colorbar(points, label="damage (failed bond fraction)")
ax.set_aspect("equal")
ax.set_xlabel("x [mm]")
ax.set_ylabel("y [mm]")
ax.set_title("PD damage, last load step (initial tip at x = 0)")
fig.tight_layout()
fig.savefig(f"{directory}/pd_damage.png", dpi=130)
print(f"wrote {directory}/pd_damage.png")
