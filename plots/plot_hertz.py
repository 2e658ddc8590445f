#!/usr/bin/env python3
"""Plots the Hertz validation: the contact pressure of the finest run against the 2-D Hertz
solution, and the errors of the half-width a and of the pressure profile against the number of
unknowns for each refinement sequence.

Reads DIR/hertz.csv and DIR/hertz_profiles.csv (written by `hpcontact hertz`) and writes
DIR/hertz.png.
Usage: plot_hertz.py DIR
"""
import csv
import sys
from collections import defaultdict
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from figure_file import save_figure  # noqa: E402

STYLES = {"h": ("tab:blue", "o"), "p": ("tab:orange", "s"), "hp": ("tab:green", "^"), "block": ("tab:red", "D")}
NAMES = {
    "h": "h (uniform mesh, p = 2)",
    "p": "p = 1…8 (graded mesh)",
    "hp": "hp (layers and p together)",
    "block": "block 8, 16, 32 wide (p = 6)",
}


def read(path):
    with open(path, newline="") as handle:
        return list(csv.DictReader(handle))


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    folder = Path(sys.argv[1])
    rows = read(folder / "hertz.csv")
    profiles = defaultdict(list)
    for row in read(folder / "hertz_profiles.csv"):
        profiles[row["sequence"]].append((float(row["x"]), float(row["pressure"]), float(row["hertz"])))

    figure, (left, middle, right) = plt.subplots(1, 3, figsize=(15, 4.6))
    shown = "hp" if "hp" in profiles else next(iter(profiles))
    x, pressure, hertz = zip(*profiles[shown])
    left.plot(x, hertz, "-", color="black", linewidth=2.5, alpha=0.35, label="Hertz (same total force P)")
    left.plot(x, pressure, "-", color=STYLES.get(shown, ("tab:green", ""))[0], linewidth=1.2,
              label=f"hpcontact, finest {shown} run")
    left.set_xlabel("x on Γ_C (the top edge y = 0)")
    left.set_ylabel("contact pressure  p = −σ_nn")
    left.set_title("Pressure under the cylinder (R = 1, E = 1, ν = 0.3)")
    left.grid(True, alpha=0.3)
    left.legend(fontsize=8, loc="upper right")

    by_sequence = defaultdict(list)
    for row in rows:
        by_sequence[row["sequence"]].append(row)
    for axis, column, title in ((middle, "a_error", "contact half-width a"),
                                (right, "profile_error", "pressure profile")):
        for name, series in by_sequence.items():
            colour, marker = STYLES.get(name, ("tab:grey", "x"))
            ndofs = [int(r["ndofs"]) for r in series]
            error = [max(float(r[column]), 1e-6) for r in series]
            axis.loglog(ndofs, error, marker=marker, color=colour, label=NAMES.get(name, name))
        axis.axhline(0.01, color="grey", linestyle=":", linewidth=1)
        axis.text(axis.get_xlim()[0] * 1.1, 0.0105, "1 %", color="grey", fontsize=8)
        axis.set_xlabel("unknowns (displacement)")
        axis.set_ylabel("relative error against Hertz" if column == "profile_error" else "|a − a_Hertz| / a_Hertz")
        axis.set_title(f"Error of the {title}")
        axis.grid(True, which="both", alpha=0.3)
        axis.legend(fontsize=8)
    figure.tight_layout()
    save_figure(figure, folder / "hertz.png")


if __name__ == "__main__":
    main()
