#!/usr/bin/python3
"""The Pareto plot of a study: scripts/plot_trade.py <study dir> -> <dir>/trade.png.

Reads <dir>/trade.csv (written by pumpd --study) and draws each run's wall time against the mean
distance of its crack path from the finest run's, and, where full PD ran, from the full-PD path;
each run labelled, the recommended one ringed. A distance of zero (the reference itself) sits on
the axis floor. Run it with /usr/bin/python3 (Debian's python3-matplotlib).
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

COLOURS = {"lefm-growth": "tab:orange", "global-local": "tab:blue", "full-pd": "tab:green"}


def number(text):
    return float(text) if text else None


directory = sys.argv[1]
with open(f"{directory}/trade.csv") as f:
    rows = [r for r in csv.DictReader(f) if number(r["wall_s"]) and r["status"] == "ok"]
references = [("mean_vs_finest_mm", "the finest run")]
if any(number(r["mean_vs_fullpd_mm"]) is not None for r in rows):
    references.append(("mean_vs_fullpd_mm", "full PD"))

fig, axes = plt.subplots(1, len(references), figsize=(6.5 * len(references), 5.5), squeeze=False)
for ax, (column, name) in zip(axes[0], references):
    points = [(number(r["wall_s"]), number(r[column]), r) for r in rows if number(r[column]) is not None]
    positive = [d for _, d, _ in points if d > 0]
    floor = min(positive) / 3 if positive else 1e-3
    for seconds, distance, r in points:
        y = max(distance, floor)
        ax.scatter(seconds, y, color=COLOURS.get(r["method"], "tab:gray"), zorder=3)
        if r["recommended"] == "yes":
            ax.scatter(seconds, y, s=220, facecolors="none", edgecolors="tab:red", zorder=4, label="recommended")
        ax.annotate(r["run"], (seconds, y), textcoords="offset points", xytext=(4, 4), fontsize=8)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("wall time [s]")
    ax.set_ylabel(f"mean path distance from {name} [mm]")
    ax.grid(True, which="both", alpha=0.3)
    if any(r["recommended"] == "yes" for _, _, r in points):
        ax.legend(fontsize=8)
fig.suptitle("Speed against accuracy (pumpd --study)")
fig.tight_layout()
fig.savefig(f"{directory}/trade.png", dpi=130)
