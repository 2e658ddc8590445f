#!/usr/bin/env python3
"""Plots the performance benchmark: seconds against primal dofs per kind (log-log, fitted
exponents in the legend; dashed: the assembled matrices) and the ratio to one linear solve of the
same matrix, with the peak memory per size (condensed path, and assembled matrices if measured).

Reads only DIR/benchmark.csv and DIR/scaling.csv (written by `hpcontact benchmark`) and writes
DIR/benchmark.png.
Usage: plot_benchmark.py DIR
"""
import csv
import sys
from collections import defaultdict
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from figure_file import save_figure  # noqa: E402

STYLE = {
    "linear_K": ("k", "o", "one linear solve of K"),
    "linear_AG": ("0.5", "o", "one linear solve of A_G"),
    "linear_K_assembled": ("k", "x", "K assembled, CHOLMOD on all dofs"),
    "linear_AG_assembled": ("0.5", "x", "A_G assembled, CHOLMOD on all dofs"),
    "signorini": ("C0", "s", "contact (9)"),
    "friction": ("C1", "^", "friction (13)"),
    "friction_s": ("C2", "v", "friction (15)"),
    "alpha": ("C3", "D", "α (interpolation norm)"),
}


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    folder = Path(sys.argv[1])
    with open(folder / "benchmark.csv", newline="") as handle:
        rows = list(csv.DictReader(handle))
    with open(folder / "scaling.csv", newline="") as handle:
        exponents = {row["kind"]: float(row["exponent"]) for row in csv.DictReader(handle)}
    by_kind = defaultdict(list)
    for row in rows:
        by_kind[row["kind"]].append(row)

    figure, (times, ratios) = plt.subplots(1, 2, figsize=(12, 4.8))
    for kind, series in by_kind.items():
        colour, marker, label = STYLE.get(kind, ("C7", "x", kind))
        ndofs = [int(r["ndofs"]) for r in series]
        seconds = [float(r["seconds"]) for r in series]
        fit = f", slope {exponents[kind]:.2f}" if kind in exponents else ""
        style = "--" if kind.endswith("_assembled") else "-"
        times.loglog(ndofs, seconds, marker=marker, color=colour, ls=style, label=label + fit)
        if not kind.startswith("linear"):
            ratios.semilogx(ndofs, [float(r["ratio"]) for r in series], marker=marker, color=colour, label=label)
    times.set_xlabel("primal dofs")
    times.set_ylabel("seconds (assembly excluded)")
    times.set_title(f"p = {rows[0]['p']}, p_C = {rows[0]['pC']}: time against size")
    times.grid(True, which="both", alpha=0.3)
    times.legend(fontsize=8)
    ratios.axhline(1.5, color="C0", ls=":", lw=1, label="target contact ≤ 1.5")
    ratios.axhline(2.0, color="C3", ls=":", lw=1, label="target α ≤ 2")
    ratios.set_xlabel("primal dofs")
    ratios.set_ylabel("seconds / one linear solve of the same matrix")
    ratios.set_title("cost relative to one linear solve")
    ratios.grid(True, which="both", alpha=0.3)
    memory = ratios.twinx()
    for assembled, style, label in ((False, "--", "peak memory (GB, right)"),
                                    (True, ":", "peak memory, assembled (GB, right)")):
        peak = defaultdict(float)
        for row in rows:
            if row["kind"].endswith("_assembled") == assembled:
                peak[int(row["ndofs"])] = max(peak[int(row["ndofs"])], float(row["peak_rss_mb"]) / 1024)
        if peak:
            sizes = sorted(peak)
            memory.semilogx(sizes, [peak[size] for size in sizes], color="0.6", ls=style, label=label)
    memory.set_ylabel("peak resident memory, GB")
    lines = ratios.get_legend_handles_labels()
    extra = memory.get_legend_handles_labels()
    ratios.legend(lines[0] + extra[0], lines[1] + extra[1], fontsize=8, loc="upper left")
    figure.tight_layout()
    save_figure(figure, folder / "benchmark.png")


if __name__ == "__main__":
    main()
