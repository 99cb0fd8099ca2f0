#!/usr/bin/python3
"""Load and crack length of a run as a PNG:
scripts/plot_load_displacement.py <output dir> [scene.prm] -> <dir>/load_displacement.png.

Reads load_displacement.csv (one row per accepted step of any method: lambda, the reported load
and displacement, crack length). The scene file, if given, names the axes with its `Report`
entries (`Load`, `Displacement`); without it they are "load" and "displacement". Left: load
against displacement, each step a marker, from the origin (the body elastic
up to the first growth); right: load against crack length, where a crack that
grows stably rises and one that runs unstably falls. Run it with /usr/bin/python3 (Debian's
python3-matplotlib).
"""
import csv
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def report_entries(scene):
    """The Report subsection's Load and Displacement of a scene file ("" where not set)."""
    entries = {"Load": "", "Displacement": ""}
    inside = False
    with open(scene) as f:
        for line in f:
            text = line.split("#", 1)[0].strip()
            if re.fullmatch(r"subsection\s+Report", text):
                inside = True
            elif inside and text == "end":
                inside = False
            elif inside:
                m = re.fullmatch(r"set\s+(Load|Displacement)\s*=\s*(.*)", text)
                if m:
                    entries[m.group(1)] = m.group(2).strip()
    return entries


def number(field):
    """A CSV number; an empty field (pumpd's for a value that is not finite) is NaN."""
    return float(field) if field.strip() else float("nan")


directory = sys.argv[1]
names = report_entries(sys.argv[2]) if len(sys.argv) > 2 else {"Load": "", "Displacement": ""}
with open(f"{directory}/load_displacement.csv") as f:
    rows = list(csv.DictReader(f))
if not rows:
    print(f"no load_displacement.png: {directory}/load_displacement.csv has no rows")
    sys.exit(0)
load = [number(r["load"]) for r in rows]
displacement = [number(r["displacement"]) for r in rows]
length = [1e3 * number(r["crack_length_m"]) for r in rows]

fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
# Before the first growth the body is linear elastic: load and displacement rise from 0 together.
left.plot([0., displacement[0]], [0., load[0]], color="gray", ls="--", lw=0.9, label="elastic loading")
left.plot(displacement, load, color="tab:red", marker=".", ms=5, lw=1.2, label="accepted steps")
left.legend(fontsize=8)
left.set_xlabel(f"displacement ({names['Displacement'] or 'displacement'})")
left.set_ylabel(f"load ({names['Load'] or 'load'})")
right.plot(length, load, color="tab:blue", marker=".", ms=5, lw=1.2)
right.set_xlabel("crack length [mm]")
right.set_ylabel(f"load ({names['Load'] or 'load'})")
for ax in (left, right):
    ax.grid(True, lw=0.3)
    ax.ticklabel_format(style="sci", scilimits=(-3, 4))
fig.suptitle(f"{os.path.basename(os.path.normpath(directory))}: {len(rows)} steps")
fig.tight_layout()
fig.savefig(f"{directory}/load_displacement.png", dpi=130)
print(f"wrote {directory}/load_displacement.png")
