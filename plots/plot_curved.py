#!/usr/bin/env python3
"""Plots the convergence study on a curved domain (studies/curved/convergence.toml): the H¹ error
against p with cells following the arcs and on the polygonal domain through the same vertices
(left), and against h for the curved geometry (right).

Reads DIR/convergence.csv (written by `hpcontact convergence`) and writes DIR/curved.png.
Usage: plot_curved.py DIR
"""
import math
import sys
from collections import defaultdict
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from figure_file import save_figure  # noqa: E402
from plot_convergence import read_rows  # noqa: E402  (the same convergence.csv)


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    folder = Path(sys.argv[1])
    rows = read_rows(folder / "convergence.csv")
    series = defaultdict(list)
    for row in rows:
        series[(row["geometry"], row["cells"])].append(row)

    figure, (left, right) = plt.subplots(1, 2, figsize=(11.5, 4.6))
    styles = {"curved": ("tab:blue", "o", "-"), "polygonal": ("tab:red", "s", "--")}
    for (geometry, cells), points in sorted(series.items()):
        points.sort(key=lambda r: r["p"])
        if len(points) < 5:
            continue
        colour, marker, line = styles[geometry]
        shade = 1.0 if cells == min(c for g, c in series if g == geometry) else 0.55
        left.semilogy([r["p"] for r in points], [r["error_h1"] for r in points], marker=marker, linestyle=line,
                      color=colour, alpha=shade, label=f"{geometry}, {cells} cells")
    left.set_xlabel("polynomial degree p")
    left.set_ylabel(r"$\|u - u_h\|_{H^1(\Omega)}$")
    left.set_title("p-refinement: exact arcs vs. polygon")
    left.grid(True, which="both", alpha=0.3)
    left.legend(fontsize=8)

    by_p = defaultdict(list)
    for row in rows:
        if row["geometry"] == "curved":
            by_p[row["p"]].append(row)
    markers = "o^sDv<>p"
    for index, (p, points) in enumerate(sorted(by_p.items())):
        points.sort(key=lambda r: -r["h"])
        if len(points) < 3 or p > 4:
            continue
        h = [r["h"] for r in points]
        error = [r["error_h1"] for r in points]
        rate = math.log(error[-2] / error[-1]) / math.log(h[-2] / h[-1])
        right.loglog(h, error, marker=markers[index % len(markers)], label=f"p = {p} (rate {rate:.2f})")
    right.set_xlabel("h (longest edge)")
    right.set_ylabel(r"$\|u - u_h\|_{H^1(\Omega)}$")
    right.set_title("h-refinement, curved cells")
    right.grid(True, which="both", alpha=0.3)
    right.legend(fontsize=8)

    figure.suptitle(r"Quarter annulus $1<r<2$, $u = (r^2-1)(4-r^2)\,e^x$, $u_D = 0$ on the inner arc")
    figure.tight_layout()
    save_figure(figure, folder / "curved.png")


if __name__ == "__main__":
    main()
