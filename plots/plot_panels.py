#!/usr/bin/env python3
"""Multiplier panels like the paper's Figures 2, 3, 5 and 7: λ_H against arc length on Γ_C for
several pairings, each panel with its axis labels.

Reads DIR/<name>/boundary_<problem>.csv for every sub-folder DIR/<name> written by `hpcontact solve`,
where <name> = <problem>_p<p>_pC<pc>_hH<ratio with '-' for '/'>; writes DIR/panels_<problem>.png.
Usage: plot_panels.py DIR
"""
import csv
import sys
from collections import defaultdict
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from figure_file import save_figure  # noqa: E402


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    folder = Path(sys.argv[1])
    by_problem = defaultdict(list)
    for sub in sorted(p for p in folder.iterdir() if p.is_dir()):
        problem, p, pc, ratio = sub.name.rsplit("_", 3)
        if not (sub / f"boundary_{problem}.csv").exists():
            continue
        by_problem[problem].append((sub, p[1:], pc[2:], ratio[2:].replace("-", "/")))
    for problem, panels in by_problem.items():
        columns = 2 if len(panels) <= 4 else 3
        rows = (len(panels) + columns - 1) // columns
        figure, axes = plt.subplots(rows, columns, figsize=(4.2 * columns, 2.8 * rows), squeeze=False)
        for axis, (sub, p, pc, ratio) in zip(axes.flat, panels):
            with open(sub / f"boundary_{problem}.csv", newline="") as handle:
                data = list(csv.DictReader(handle))
            axis.plot([float(r["s_arc"]) for r in data], [float(r["lambda"]) for r in data], linewidth=1)
            axis.set_title(f"p = {p}, $p_C$ = {pc}, h/H = {ratio}", fontsize=9)
            axis.set_xlabel(r"arc length $s$ along $\Gamma_C$", fontsize=8)
            axis.set_ylabel(r"$\lambda_H$", fontsize=9)
            axis.grid(True, alpha=0.3)
        for axis in list(axes.flat)[len(panels):]:
            axis.set_visible(False)
        figure.suptitle(rf"$\lambda_H$ on $\Gamma_C$, problem {problem}")
        figure.tight_layout()
        save_figure(figure, folder / f"panels_{problem}.png", dpi=110)


if __name__ == "__main__":
    main()
