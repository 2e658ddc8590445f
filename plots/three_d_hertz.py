#!/usr/bin/env python3
"""Plots the 3-D Hertz run (studies/three_d/hertz.toml): the contact pressure at every sample of
Γ_C against its radius r, the ring averages of the samples, and the Hertz pressure of the run's
total force P (four times the quarter's), with a from the moment Σ w p r² / Σ w p = 2a²/5 and from
Hertz's a³ = 3PR/(4E*).

Reads DIR/boundary_frictionless.csv and writes DIR/hertz3d.png.
Usage: three_d_hertz.py DIR
"""
import csv
import math
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from figure_file import save_figure  # noqa: E402

RADIUS, YOUNG, POISSON, QUARTERS = 1.0, 1.0, 0.3, 4


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    folder = Path(sys.argv[1])
    with open(folder / "boundary_frictionless.csv", newline="") as handle:
        rows = [{k: float(v) for k, v in row.items()} for row in csv.DictReader(handle)]
    r = [math.hypot(row["x"], row["y"]) for row in rows]
    w = [row["w"] for row in rows]
    p = [row["pressure"] for row in rows]
    force = QUARTERS * sum(wi * pi for wi, pi in zip(w, p))
    modulus = YOUNG / (1.0 - POISSON**2)
    a_hertz = (3.0 * force * RADIUS / (4.0 * modulus)) ** (1.0 / 3.0)
    a_moment = math.sqrt(2.5 * sum(wi * pi * ri * ri for wi, pi, ri in zip(w, p, r)) / sum(wi * pi for wi, pi in zip(w, p)))
    p0 = 3.0 * force / (2.0 * math.pi * a_hertz**2)

    def hertz(radius):
        return p0 * math.sqrt(max(0.0, 1.0 - (radius / a_hertz) ** 2))

    width = 0.02
    rings = {}
    for ri, wi, pi in zip(r, w, p):
        k = int(ri / width)
        total = rings.setdefault(k, [0.0, 0.0])
        total[0] += wi * pi
        total[1] += wi
    ring_r = [(k + 0.5) * width for k in sorted(rings)]
    ring_p = [rings[k][0] / rings[k][1] for k in sorted(rings)]

    figure, axes = plt.subplots(figsize=(7.5, 4.6))
    axes.scatter(r, p, s=2, color="tab:blue", alpha=0.35, label="samples of the discrete pressure")
    axes.plot(ring_r, ring_p, "o", color="tab:orange", markersize=4, label=f"ring averages (width {width})")
    fine = [i * 0.5 / 400 for i in range(401)]
    axes.plot(fine, [hertz(x) for x in fine], color="black", label="Hertz for the run's P")
    axes.set_xlim(0.0, 0.48)
    axes.set_xlabel("r")
    axes.set_ylabel("contact pressure")
    axes.set_title(
        f"3-D Hertz: P = {force:.5g}, a (Hertz) = {a_hertz:.5f}, a (moment) = {a_moment:.5f} "
        f"({100 * abs(a_moment / a_hertz - 1):.2f} %)",
        fontsize=9,
    )
    axes.legend(fontsize=8)
    figure.tight_layout()
    save_figure(figure, folder / "hertz3d.png")


if __name__ == "__main__":
    main()
