#!/usr/bin/env python3
"""What accuracy costs in time: error against wall time, log-log, one curve per family.

Reads DIR/work_precision.csv, DIR/reference.csv and DIR/cheapest.csv written by
`hpcontact work-precision`; writes DIR/work_precision.png with one row per contact problem:
the energy error |E(u_h) - E_ref| (left) and the multiplier error (right) against seconds. The
grey band is the reference's own estimated accuracy: errors inside it are not resolved. An adaptive
family (black stars) has one point per step at the time of every solve and estimate up to it.
Usage: plot_work_precision.py DIR
"""
import csv
import sys
from collections import defaultdict
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from figure_file import save_figure  # noqa: E402

LAMBDA_NORM = {
    "signorini": r"$\|\lambda_H-\lambda_{ref}\|_{L^2(\Gamma_C)}$",
    "friction": r"$\|s(\lambda_H-\lambda_{ref})\|_{L^2(\Gamma_C)}$",
    "friction_s": r"$\|\lambda_H-\lambda_{ref}\|_{L^2(\Gamma_C)}$",
}
TITLE = {"signorini": "(9) Signorini", "friction": "(13) friction, $M_1$", "friction_s": "(15) friction, $M_s$"}


def read(path):
    with open(path, newline="") as handle:
        return list(csv.DictReader(handle))


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    folder = Path(sys.argv[1])
    rows = read(folder / "work_precision.csv")
    references = {r["problem"]: r for r in read(folder / "reference.csv")}
    problems = list(dict.fromkeys(r["problem"] for r in rows))
    figure, axes = plt.subplots(len(problems), 2, figsize=(12, 4.0 * len(problems)), squeeze=False)
    for row_axes, problem in zip(axes, problems):
        curves = defaultdict(list)
        for r in rows:
            if r["problem"] == problem:
                curves[r["family"]].append((float(r["seconds"]), float(r["error_energy"]), float(r["error_lambda"])))
        reference = references[problem]
        for column, (axis, key, label) in enumerate(
            zip(row_axes, ("accuracy_energy", "accuracy_lambda"), (r"$|E(u_h)-E_{ref}|$", LAMBDA_NORM[problem]))
        ):
            for family, points in curves.items():
                points.sort()
                errors = [max(p[1 + column], 1e-16) for p in points]
                if family.startswith("adaptive"):  # each step at the time spent to reach it
                    axis.loglog([p[0] for p in points], errors, "k*-", markersize=5, linewidth=1.5, label=family)
                    continue
                style = "o-" if family.startswith("h,") else ("s-" if family.startswith("p") else "D-")
                axis.loglog([p[0] for p in points], errors, style, markersize=3.5, linewidth=1.2, label=family)
            accuracy = float(reference[key])
            axis.axhspan(1e-16, accuracy, color="grey", alpha=0.18, label="below reference accuracy")
            axis.set_xlabel("seconds (meshes, assembly, factorization, contact solve, u)")
            axis.set_ylabel(label)
            axis.set_title(f"{TITLE.get(problem, problem)}: {label}", fontsize=10)
            axis.grid(True, which="both", alpha=0.25)
            lowest = min(min(max(p[1 + column], 1e-16) for p in points) for points in curves.values())
            axis.set_ylim(bottom=max(lowest / 3, accuracy / 30, 1e-12))
        row_axes[0].legend(fontsize=7, ncol=2)
    figure.tight_layout()
    save_figure(figure, folder / "work_precision.png", dpi=100)


if __name__ == "__main__":
    main()
