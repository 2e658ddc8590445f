#!/usr/bin/env python3
"""Plots contact solutions written by `hpcontact solve` like the paper's Figures 1, 4 and 6:
u on Γ_C with the obstacle g (or the bound s) and the multiplier λ, next to a colour view of u on Ω.

Reads DIR/boundary_<problem>.csv and DIR/solution_<problem>.vtu for every contact problem a run
wrote into each DIR given; writes DIR/figure_<problem>.png.
Usage: plot_paper.py DIR [DIR ...]
"""
import csv
import re
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.tri as mtri  # noqa: E402


def read_vtu(path):
    text = path.read_text()

    def array(name):
        match = re.search(rf'Name="{name}"[^>]*>(.*?)</DataArray>', text, re.S)
        return [float(v) for v in match.group(1).split()]

    points = re.search(r"<Points>\s*<DataArray[^>]*>(.*?)</DataArray>", text, re.S).group(1).split()
    xyz = [float(v) for v in points]
    x, y = xyz[0::3], xyz[1::3]
    cells = [int(v) for v in array("connectivity")]
    triangles = []
    for k in range(0, len(cells), 4):
        a, b, c, d = cells[k:k + 4]
        triangles += [(a, b, c), (a, c, d)]
    return x, y, triangles, array("u")


def plot(folder, problem):
    with open(folder / f"boundary_{problem}.csv", newline="") as handle:
        rows = list(csv.DictReader(handle))
    data_key = "obstacle" if "obstacle" in rows[0] else "s"
    x = [float(r["x"]) for r in rows]
    figure, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2))
    left.plot(x, [float(r["u"]) for r in rows], label=r"$u_h$ on $\Gamma_C$")
    left.plot(x, [float(r[data_key]) for r in rows], "--",
              label="obstacle g" if data_key == "obstacle" else "bound s")
    if problem == "friction":
        left.plot(x, [1.0] * len(x), ":", color="grey", label="1")
    left.plot(x, [float(r["lambda"]) for r in rows], label=r"$\lambda_H$")
    left.set_xlabel(r"x on $\Gamma_C$")
    left.grid(True, alpha=0.3)
    left.legend(fontsize=8)
    px, py, triangles, u = read_vtu(folder / f"solution_{problem}.vtu")
    picture = right.tripcolor(mtri.Triangulation(px, py, triangles), u, shading="gouraud", cmap="viridis")
    figure.colorbar(picture, ax=right, label=r"$u_h$")
    right.set_aspect("equal")
    right.set_title(r"$u_h$ on $\Omega$")
    figure.suptitle(f"{folder.name.replace('_', ' ')}: problem {problem}")
    figure.tight_layout()
    output = folder / f"figure_{problem}.png"
    temporary = output.with_suffix(".tmp.png")
    figure.savefig(temporary, dpi=110)
    temporary.replace(output)
    plt.close(figure)
    print(f"wrote {output}")


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    for folder in map(Path, sys.argv[1:]):
        problems = [p.stem[len("boundary_"):] for p in sorted(folder.glob("boundary_*.csv"))]
        if not problems:
            sys.exit(f"plot_paper.py: no boundary_<problem>.csv in {folder}")
        for problem in problems:
            plot(folder, problem)


if __name__ == "__main__":
    main()
