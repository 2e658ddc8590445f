#!/usr/bin/env python3
"""The local α predictor checked against the global α: reads the alpha.csv (column
alpha_predicted) and verdicts.csv of stability sweeps written by `hpcontact sweep`.

A configuration (one row of alpha.csv: one pairing on one mesh) is unstable if its global α < 0.1,
predicted unstable if alpha_predicted < 0.2 (infsup/local_alpha.hpp). A false "stable" is a
configuration predicted stable with α < 0.1; a false "unstable" one predicted unstable with
α >= 0.1, counted apart when its sweep finds the pairing's α decaying under refinement (the
prediction is then right for the family of meshes).

Writes into OUT: predictor_check.csv (one row per sweep and the total) and predictor_check.png
(α against the prediction); prints the table as Markdown. Exits 1 if any false "stable".
Usage: plot_predictor_check.py OUT SWEEP_DIR [SWEEP_DIR ...]
"""
import csv
import math
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from figure_file import save_figure  # noqa: E402

ALPHA_MIN = 0.1       # a configuration is unstable below this global α
PREDICTED_MIN = 0.2   # kStablePatchAlpha: predicted unstable below this
FLOOR = 1e-9          # α = 0 (singular, or a flagged patch) drawn here on the log scales


def read(path):
    with open(path, newline="") as handle:
        return list(csv.DictReader(handle))


def configuration_key(row):
    return (row["problem"], row["norm"], row["p"], row["pC"], row["family"], f"{float(row['ratio']):.9f}")


def check(folder):
    for name in ("alpha.csv", "verdicts.csv"):
        if not (folder / name).is_file():
            sys.exit(f"plot_predictor_check.py: {folder} has no {name} (not a finished `hpcontact sweep` folder)")
    verdicts = {configuration_key(r): r["verdict"] for r in read(folder / "verdicts.csv")}
    counts = dict(configurations=0, unstable=0, predicted_unstable=0, false_stable=0, false_unstable=0,
                  false_unstable_decaying=0)
    points = []
    for row in read(folder / "alpha.csv"):
        alpha, predicted = float(row["alpha"]), float(row["alpha_predicted"])
        if math.isnan(predicted):
            continue  # a 3-D pairing: the local predictor is planar and predicts nothing there
        unstable, predicted_unstable = alpha < ALPHA_MIN, predicted < PREDICTED_MIN
        counts["configurations"] += 1
        counts["unstable"] += unstable
        counts["predicted_unstable"] += predicted_unstable
        counts["false_stable"] += unstable and not predicted_unstable
        if predicted_unstable and not unstable:
            counts["false_unstable"] += 1
            counts["false_unstable_decaying"] += verdicts.get(configuration_key(row)) in ("decaying", "singular")
        points.append((max(predicted, FLOOR), max(alpha, FLOOR)))
    return counts, points


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    out = Path(sys.argv[1])
    out.mkdir(parents=True, exist_ok=True)
    rows, clouds = [], {}
    for name in sys.argv[2:]:
        folder = Path(name)
        counts, points = check(folder)
        rows.append(dict(sweep=folder.name, **counts))
        clouds[folder.name] = points
    total = dict(sweep="total", **{k: sum(r[k] for r in rows) for k in rows[0] if k != "sweep"})
    rows.append(total)
    with open(out / "predictor_check.csv", "w", newline="") as handle:
        writer = csv.DictWriter(handle, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    print("| sweep | configurations | unstable (α < 0.1) | predicted unstable | false stable | false unstable "
          "(of which α decays) |")
    print("|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['sweep']} | {r['configurations']} | {r['unstable']} | {r['predicted_unstable']} | "
              f"{r['false_stable']} | {r['false_unstable']} ({r['false_unstable_decaying']}) |")

    figure, axes = plt.subplots(figsize=(7.5, 6))
    markers = "os^vD<>ph*Xd8"
    for k, (name, points) in enumerate(clouds.items()):
        x, y = zip(*points)
        axes.scatter(x, y, s=9, alpha=0.6, marker=markers[k % len(markers)], label=name)
    axes.set_xscale("log")
    axes.set_yscale("log")
    axes.axhline(ALPHA_MIN, color="k", lw=0.8)
    axes.axvline(PREDICTED_MIN, color="k", lw=0.8, ls="--")
    bottom = FLOOR / 3
    axes.fill_between([PREDICTED_MIN, 2], bottom, ALPHA_MIN, color="#d32f2f", alpha=0.12, lw=0,
                      label=f"false stable: {total['false_stable']}")
    axes.set_xlim(FLOOR / 3, 2)
    axes.set_ylim(bottom, 2)
    axes.set_xlabel("predicted α (min over the patches; 1e-9: zero)")
    axes.set_ylabel("global α (1e-9: zero)")
    axes.set_title(f"local α predictor against the global α: {total['configurations']} configurations")
    axes.legend(fontsize=7, loc="lower center", ncol=2)  # the empty corner: no point has α ≪ its prediction
    figure.tight_layout()
    save_figure(figure, out / "predictor_check.png")
    if total["false_stable"]:
        sys.exit(f"{total['false_stable']} configurations predicted stable with α < {ALPHA_MIN}")


if __name__ == "__main__":
    main()
