#!/usr/bin/python3
"""Speed against accuracy on Ingraffea Case II (issue 5): one scene, every method and setting.

    tests/bench/trade_study.py --pumpd build/coupling/pumpd --out build/trade [--docs docs]

Runs, one process each (from the repository root, so the scenes' relative paths hold):
LEFM-only growth, the global-local cycle at several settings (PD spacing, horizon, box size,
exchange increment, exchange start load, global refinement) and the full-domain PD beam at two horizons (8 and 4 mm,
m = 4: the path change between them is the full-PD convergence check; 4 mm is the reference). For each: wall time, peak
memory (the process's maximum resident set), PD node-steps, global DoFs, and the crack path's
symmetric mean and Hausdorff distance from the finest coupled run and from the full PD run (each
pair compared over the shorter path's extent). Writes trade.csv, trade.md and trade_pareto.png
(wall time against mean path error from full PD) to --out and, with --docs, to that folder too.
Prints `pumpd-metric trade.<name> <value>` for the issue's three figures and the full-PD
path change (trade.fullpd_path_change_delta8_vs_4_mm). --replot redraws the
plot from <out>/trade.csv without running anything. --reuse NAME ... takes those runs from an
earlier study in the same --out (its trade.csv row, log and crack path) when their scene file is
unchanged, instead of running them again: for iterating on the coupled settings without the
40-minute full-PD reference. Only valid while the code those runs exercise is unchanged.
Run it with /usr/bin/python3 (Debian's python3-matplotlib, python3-numpy).
"""
import argparse
import csv
import math
import os
import shutil
import subprocess
import sys
import time

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

# name, base scene, overrides {subsection (nested ones as "A/B"): {entry: value}}, what the setting trades
COUPLED = "prm/ingraffea-case2.prm"
SCENARIOS = [
    ("lefm", "prm/ingraffea-case2-lefm.prm",
     {"Scene/Material": {"Young's modulus": "2.4e9", "Poisson's ratio": "0.25"}},
     "LEFM only (XFEM + maximum hoop stress), da = 4 mm"),
    ("coupled-default", COUPLED, {},
     "m = 8, delta = 4 mm, box 32 mm, da_max 8 mm, 2 tip refinements, each exchange from 0.9 P_c"),
    ("coupled-warm", COUPLED, {"Global-local": {"Start below the last load": "true"}},
     "each exchange from one load increment below the last accepted load (fewer PD states)"),
    ("coupled-m4", COUPLED, {"Peridynamics": {"Horizon over spacing": "4"}}, "PD spacing: m = 4"),
    ("coupled-delta2", COUPLED, {"Peridynamics": {"Horizon": "0.002"},
                                 "Global-local": {"Minimum advance": "0.002"}},
     "horizon 2 mm (h = 0.25 mm): the finest coupled run"),
    ("coupled-delta8", COUPLED, {"Peridynamics": {"Horizon": "0.008"},
                                 "Global-local": {"Box size": "0.064", "Maximum box size": "0.128",
                                                  "Box margin": "0.016", "Maximum advance": "0.016",
                                                  "Minimum advance": "0.008", "Near distance": "0.016"}},
     "horizon 8 mm (h = 1 mm), box and increments scaled with it"),
    ("coupled-box48", COUPLED, {"Global-local": {"Box size": "0.048", "Maximum box size": "0.096"}},
     "box 48 mm"),
    ("coupled-box64", COUPLED, {"Global-local": {"Box size": "0.064", "Maximum box size": "0.096",
                                                 "Box tip position": "0.15"}},
     "box 64 mm, tip 15 % from its rear (most of the box ahead of the tip, as the published boxes)"),
    ("coupled-da4", COUPLED, {"Global-local": {"Maximum advance": "0.004", "Minimum advance": "0.002"}},
     "exchange increment: da_max 4 mm (min 2 mm)"),
    ("coupled-da5", COUPLED, {"Global-local": {"Maximum advance": "0.005", "Minimum advance": "0.0025"}},
     "exchange increment: da_max 5 mm (min 2.5 mm)"),
    ("coupled-da16", COUPLED, {"Global-local": {"Maximum advance": "0.016"}}, "exchange increment: da_max 16 mm"),
    ("coupled-ref1", COUPLED, {"Global": {"Refinement levels near the tip": "1"}},
     "global refinement: 1 level at the tip (2 mm cells)"),
    ("coupled-ref3", COUPLED, {"Global": {"Refinement levels near the tip": "3"}},
     "global refinement: 3 levels at the tip (0.5 mm cells)"),
    ("fullpd-delta8", "prm/ingraffea-case2-fullpd.prm", {"Peridynamics": {"Horizon": "0.008"}},
     "full-domain PD beam, horizon 8 mm (h = 2 mm): the horizon convergence check"),
    ("fullpd", "prm/ingraffea-case2-fullpd.prm", {},
     "full-domain PD beam, horizon 4 mm (h = 1 mm), crack-mouth-opening control: the reference"),
]
FINEST = "coupled-delta2"
DEFAULT = "coupled-default"


def scene_file(base, overrides, out_dir, path):
    with open(os.path.join(ROOT, base)) as f:
        text = f.read()
    overrides = {**overrides, "Scene": {"Output directory": out_dir}}
    for section, entries in overrides.items():
        levels = section.split("/")
        text += "\n" + "".join(f"subsection {level}\n" for level in levels)
        text += "".join(f"  set {k} = {v}\n" for k, v in entries.items()) + "end\n" * len(levels)
    with open(path, "w") as f:
        f.write(text)


def read_run(out, name, ok):
    """The pumpd-metric lines of <out>/<name>.log and the crack path of <out>/<name>/ (if ok)."""
    metrics = {}
    with open(os.path.join(out, name + ".log")) as f:
        for line in f:
            if line.startswith("pumpd-metric "):
                _, key, value = line.split()
                metrics[key] = float(value)
    path_file = os.path.join(out, name, "crack_path.csv")
    ok = ok and os.path.exists(path_file)
    path = np.loadtxt(path_file, delimiter=",", skiprows=1, ndmin=2) if ok else None
    return {"metrics": metrics, "path": path, "ok": ok}


def run(pumpd, name, base, overrides, out):
    out_dir = os.path.join(out, name)
    shutil.rmtree(out_dir, ignore_errors=True)
    os.makedirs(out_dir)
    prm = os.path.join(out, name + ".prm")
    scene_file(base, overrides, out_dir, prm)
    log = open(os.path.join(out, name + ".log"), "w")
    t0 = time.monotonic()
    child = subprocess.Popen([pumpd, prm], cwd=ROOT, stdout=log, stderr=subprocess.STDOUT)
    _, status, usage = os.wait4(child.pid, 0)
    seconds = time.monotonic() - t0
    log.close()
    r = read_run(out, name, os.waitstatus_to_exitcode(status) == 0)
    return {**r, "seconds": seconds, "peak_mib": usage.ru_maxrss / 1024.}


def reused(name, base, overrides, out, previous):
    """The earlier run `name` from <out> if its scene file is the one this study would write and
    the earlier trade.csv has its row; else None."""
    prm = os.path.join(out, name + ".prm")
    if name not in previous or not os.path.exists(prm) or not os.path.exists(os.path.join(out, name + ".log")):
        return None
    fresh = prm + ".new"
    scene_file(base, overrides, os.path.join(out, name), fresh)
    with open(prm) as a, open(fresh) as b:
        same = a.read() == b.read()
    os.remove(fresh)
    if not same:
        return None
    row = previous[name]
    return {**read_run(out, name, True), "seconds": float(row["wall_s"]), "peak_mib": float(row["peak_mib"])}


def segment_distance(p, a, b):
    e = b - a
    t = np.clip(((p - a) @ e) / max(e @ e, 1e-300), 0., 1.)
    return np.linalg.norm(p - (a + t * e))


def to_polyline(p, line):
    return min(segment_distance(p, line[k], line[k + 1]) for k in range(len(line) - 1))


def samples(line, step):
    pts, w = [], []
    for k in range(len(line) - 1):
        seg = np.linalg.norm(line[k + 1] - line[k])
        n = max(1, math.ceil(seg / step))
        for j in range(0 if k == 0 else 1, n + 1):
            pts.append(line[k] + j / n * (line[k + 1] - line[k]))
            w.append(seg / n * (0.5 if j in (0, n) else 1.))
    return np.array(pts), np.array(w)


def up_to_nearest(line, x):
    best = (math.inf, 0, 0.)
    for k in range(len(line) - 1):
        e = line[k + 1] - line[k]
        t = float(np.clip(((x - line[k]) @ e) / max(e @ e, 1e-300), 0., 1.))
        d = np.linalg.norm(x - (line[k] + t * e))
        if d < best[0]:
            best = (d, k, t)
    _, k, t = best
    return np.vstack([line[:k + 1], line[k] + t * (line[k + 1] - line[k])])


def distance(a, b, step=2.5e-4):
    """Symmetric mean and Hausdorff distance [m] (as coupling/path_metrics.h), over the shorter
    path's extent: the longer one is cut at its point nearest the other's tip."""
    la, lb = np.sum(np.linalg.norm(np.diff(a, axis=0), axis=1)), np.sum(np.linalg.norm(np.diff(b, axis=0), axis=1))
    if la > lb:
        a = up_to_nearest(a, b[-1])
    else:
        b = up_to_nearest(b, a[-1])
    directed = []
    for x, y in ((a, b), (b, a)):
        pts, w = samples(x, step)
        d = np.array([to_polyline(p, y) for p in pts])
        directed.append((float((d * w).sum() / w.sum()), float(d.max())))
    return 0.5 * (directed[0][0] + directed[1][0]), max(directed[0][1], directed[1][1])


def plot(rows, targets):
    """Wall time against the mean path distance from each reference (finest coupled, full PD)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(13, 6))
    for ax, ref in zip(axes, (FINEST, "fullpd")):
        for row in rows:
            err = float(row[f"mean_vs_{ref}_mm"])
            if row["run"] == ref or not math.isfinite(err):
                continue
            colour = "tab:blue" if row["run"].startswith("coupled") else ("tab:orange" if row["run"] == "lefm" else "tab:green")
            ax.scatter(float(row["wall_s"]), err, color=colour, zorder=3)
            ax.annotate(row["run"], (float(row["wall_s"]), err), textcoords="offset points", xytext=(4, 4), fontsize=8)
        reference = next((row for row in rows if row["run"] == ref), None)
        if reference is not None:
            ax.axvline(float(reference["wall_s"]), color="gray", ls="--", lw=1, label=f"{ref} wall time")
        if ref == "fullpd":
            ax.axhline(2., color="tab:red", ls=":", lw=1, label="issue 5 target: 2 mm")
        ax.legend(fontsize=8, loc="center right")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("wall time [s] (2 cores)")
        ax.set_ylabel(f"mean path distance from {ref} [mm]")
        ax.grid(True, which="both", alpha=0.3)
    fig.suptitle("Ingraffea Case II: speed against accuracy")
    fig.tight_layout()
    for folder in targets:
        fig.savefig(os.path.join(folder, "trade_pareto.png"), dpi=130)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pumpd", required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--docs")
    parser.add_argument("--replot", action="store_true", help="only redraw the plot from <out>/trade.csv")
    parser.add_argument("--reuse", nargs="+", default=[], metavar="NAME",
                        help="take these runs from the earlier study in --out if their scene file is unchanged")
    args = parser.parse_args()
    out = os.path.abspath(args.out)
    if args.replot:
        with open(os.path.join(out, "trade.csv")) as f:
            plot(list(csv.DictReader(f)), [out] + ([os.path.abspath(args.docs)] if args.docs else []))
        return 0
    os.makedirs(out, exist_ok=True)
    pumpd = os.path.abspath(args.pumpd)

    unknown = set(args.reuse) - {s[0] for s in SCENARIOS}
    if unknown:
        parser.error(f"--reuse: no run named {', '.join(sorted(unknown))} (runs: {', '.join(s[0] for s in SCENARIOS)})")
    previous = {}
    if args.reuse and os.path.exists(os.path.join(out, "trade.csv")):
        with open(os.path.join(out, "trade.csv")) as f:
            previous = {row["run"]: row for row in csv.DictReader(f)}

    results = {}
    for name, base, overrides, what in SCENARIOS:
        if not os.path.exists(os.path.join(ROOT, base)):
            print(f"skipped {name}: {base} does not exist", flush=True)
            continue
        r = reused(name, base, overrides, out, previous) if name in args.reuse else None
        if r is None:
            if name in args.reuse:
                print(f"{name}: no earlier run with this scene in {out}: running it", flush=True)
            r = run(pumpd, name, base, overrides, out)
        else:
            print(f"{name}: reused from the earlier study in {out} (scene unchanged)", flush=True)
        r["what"] = what
        results[name] = r
        print(f"{name}: {r['seconds']:.1f} s, {r['peak_mib']:.0f} MiB, {'ok' if r['ok'] else 'FAILED'}", flush=True)

    rows = []
    for name, r in results.items():
        m = r["metrics"]
        node_steps = m.get("coupling.pd_node_steps", m.get("fullpd.node_steps", 0.))
        dofs = m.get("coupling.global_dofs", m.get("lefm.global_dofs", 0.))
        row = {"run": name, "setting": r["what"], "wall_s": round(r["seconds"], 1), "peak_mib": round(r["peak_mib"]),
               "pd_node_steps": f"{node_steps:.3g}", "global_dofs": int(dofs)}
        for ref in (FINEST, "fullpd"):
            ok = r["ok"] and ref in results and results[ref]["ok"]
            mean, haus = distance(r["path"], results[ref]["path"]) if ok else (math.nan, math.nan)
            row[f"mean_vs_{ref}_mm"] = round(1e3 * mean, 2)
            row[f"hausdorff_vs_{ref}_mm"] = round(1e3 * haus, 2)
        end = r["path"][-1] if r["ok"] else (math.nan, math.nan)
        row["tip_end_mm"] = f"({1e3 * end[0]:.1f}, {1e3 * end[1]:.1f})"
        rows.append(row)

    targets = [out] + ([os.path.abspath(args.docs)] if args.docs else [])
    for folder in targets:
        os.makedirs(folder, exist_ok=True)
        with open(os.path.join(folder, "trade.csv"), "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
            w.writeheader()
            w.writerows(rows)
        with open(os.path.join(folder, "trade.md"), "w") as f:
            f.write("| " + " | ".join(rows[0].keys()) + " |\n| " + " | ".join("---" for _ in rows[0]) + " |\n")
            for row in rows:
                f.write("| " + " | ".join(str(v) for v in row.values()) + " |\n")

    plot(rows, targets)

    def value(run, key):
        return next((row[key] for row in rows if row["run"] == run), math.nan)

    full = results.get("fullpd")
    if full and full["ok"] and results[DEFAULT]["ok"]:
        print(f"pumpd-metric trade.coupled_over_fullpd_time {results[DEFAULT]['seconds'] / full['seconds']:.4g}")
        print(f"pumpd-metric trade.coupled_vs_fullpd_mean_dev_mm {value(DEFAULT, 'mean_vs_fullpd_mm')}")
    coarse = results.get("fullpd-delta8")
    if full and full["ok"] and coarse and coarse["ok"]:
        print(f"pumpd-metric trade.fullpd_path_change_delta8_vs_4_mm {value('fullpd-delta8', 'mean_vs_fullpd_mm')}")
    if "lefm" in results and results["lefm"]["ok"] and results[DEFAULT]["ok"]:
        print(f"pumpd-metric trade.lefm_vs_coupled_mean_dev_mm {1e3 * distance(results['lefm']['path'], results[DEFAULT]['path'])[0]:.3g}")
    for row in rows:
        print(" ".join(f"{k}={v}" for k, v in row.items()))
    return 0 if all(r["ok"] for r in results.values()) else 1


if __name__ == "__main__":
    sys.exit(main())
