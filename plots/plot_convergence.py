#!/usr/bin/env python3
"""Plots the convergence study: H¹ error against h per p (log-log), and against p per n (semi-log).

Reads only DIR/convergence.csv (written by `hpcontact convergence`) and writes DIR/convergence.png.
Usage: plot_convergence.py DIR
"""
import csv
import math
import sys
from collections import defaultdict
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from figure_file import save_figure  # noqa: E402


# Below this the H¹ error is dominated by round-off (cond(K) ~ h⁻² times machine epsilon).
ROUND_OFF_FLOOR = 1e-11


def read_rows(path):
    with open(path, newline="") as handle:
        return [
            {k: (v if k == "geometry" else int(v) if k in ("p", "n", "refinements", "cells", "ndofs") else float(v))
             for k, v in row.items()}
            for row in csv.DictReader(handle)
        ]


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    folder = Path(sys.argv[1])
    rows = read_rows(folder / "convergence.csv")
    by_p, by_n = defaultdict(list), defaultdict(list)
    for row in rows:
        by_p[row["p"]].append(row)
        by_n[row["n"]].append(row)

    figure, (left, right) = plt.subplots(1, 2, figsize=(11, 4.5))
    for p, series in sorted(by_p.items()):
        series.sort(key=lambda r: -r["h"])
        if len(series) < 3:
            continue
        h = [r["h"] for r in series]
        error = [r["error_h1"] for r in series]
        # Rate from the finest pair still above the round-off floor.
        above = [k for k in range(len(error)) if error[k] > ROUND_OFF_FLOOR]
        label = f"p = {p}"
        if len(above) >= 2:
            a, b = above[-2], above[-1]
            label += f" (rate {math.log(error[a] / error[b]) / math.log(h[a] / h[b]):.2f})"
        left.loglog(h, error, "o-", label=label)
    left.axhline(ROUND_OFF_FLOOR, color="grey", linestyle=":", linewidth=1)
    left.set_xlabel("h")
    left.set_ylabel(r"$\|u - u_h\|_1$")
    left.set_title("h-refinement")
    left.grid(True, which="both", alpha=0.3)
    left.legend(fontsize=8)

    for n, series in sorted(by_n.items()):
        series.sort(key=lambda r: r["p"])
        if len(series) < 3:
            continue
        right.semilogy([r["p"] for r in series], [r["error_h1"] for r in series], "s-",
                       label=f"n = {n} ({n}×{n} cells)")
    right.set_xlabel("p")
    right.set_ylabel(r"$\|u - u_h\|_1$")
    right.set_title("p-refinement")
    right.grid(True, which="both", alpha=0.3)
    right.legend(fontsize=8)

    figure.suptitle(r"S$^p$(T$_h$) on the §7 square, u = sin(1-x) sin(1-y) e$^{(x+y)/2}$")
    figure.tight_layout()
    save_figure(figure, folder / "convergence.png")


if __name__ == "__main__":
    main()
