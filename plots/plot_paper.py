#!/usr/bin/env python3
"""Plots contact solutions written by `hpcontact solve` like the paper's Figures 1, 4 and 6:
u on Γ_C with the obstacle g (or the bound s) against arc length, the multiplier λ on its own
axis, next to a colour view of u on Ω; the title names the scene (summary.json).

Reads DIR/boundary_<problem>.csv and DIR/solution_<problem>.vtu (or .pvtu) for every contact problem a run
wrote into each DIR given; writes DIR/figure_<problem>.png.
Usage: plot_paper.py DIR [DIR ...]
"""
import csv
import json
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.tri as mtri  # noqa: E402
from figure_file import save_figure  # noqa: E402
from vtk_lagrange import read_lagrange_vtu, solution_file  # noqa: E402


def scene_title(folder, problem):
    """The scene file's name (from summary.json) and the problem, else the folder's name."""
    try:
        scene = json.loads((folder / "summary.json").read_text())["scene"]
        name = Path(scene).stem.replace("_", " ")
    except (OSError, KeyError, ValueError):
        name = folder.name.replace("_", " ")
    return f"{name}: problem {problem}"


def plot(folder, problem):
    with open(folder / f"boundary_{problem}.csv", newline="") as handle:
        rows = list(csv.DictReader(handle))
    data_key = "obstacle" if "obstacle" in rows[0] else "s"
    # Along Γ_C by arc length (a vertical or curved Γ_C would collapse in x), one piece per zone.
    zones = sorted({r.get("zone", "0") for r in rows}, key=int)
    figure, (left, right) = plt.subplots(1, 2, figsize=(12, 4.4))
    multiplier_axis = left.twinx()
    for index, zone in enumerate(zones):
        part = [r for r in rows if r.get("zone", "0") == zone]
        s = [float(r["s_arc"]) for r in part]
        first = index == 0
        left.plot(s, [float(r["u"]) for r in part], color="tab:blue", label=r"$u_h$" if first else None)
        left.plot(s, [float(r[data_key]) for r in part], "--", color="tab:green",
                  label=("obstacle g" if data_key == "obstacle" else "bound s") if first else None)
        multiplier_axis.plot(s, [float(r["lambda"]) for r in part], color="tab:red",
                             label=r"$\lambda_H$ (right axis)" if first else None)
        if index > 0:
            left.axvline(s[0], color="grey", linewidth=0.8, linestyle=":")
    if problem == "friction":  # problem (13): |λ| ≤ 1
        for bound in (-1.0, 1.0):
            multiplier_axis.axhline(bound, color="tab:red", linestyle=":", linewidth=1,
                                    label=r"$|\lambda| \leq 1$" if bound > 0 else None)
    left.set_xlabel(r"arc length $s$ along $\Gamma_C$" + (" (dotted: start of a zone)" if len(zones) > 1 else ""))
    left.set_ylabel(r"$u_h$ and " + ("g" if data_key == "obstacle" else "s") + r" on $\Gamma_C$")
    multiplier_axis.set_ylabel(r"multiplier $\lambda_H$", color="tab:red")
    multiplier_axis.tick_params(axis="y", colors="tab:red")
    left.grid(True, alpha=0.3)
    handles = left.get_legend_handles_labels()
    extra = multiplier_axis.get_legend_handles_labels()
    # Below the axes: inside, the legend would hide part of the curves (λ runs everywhere).
    left.legend(handles[0] + extra[0], handles[1] + extra[1], fontsize=8, loc="upper center",
                bbox_to_anchor=(0.5, -0.16), ncol=4)
    px, py, triangles, fields = read_lagrange_vtu(solution_file(folder, f"solution_{problem}"))
    picture = right.tripcolor(mtri.Triangulation(px, py, triangles), fields["u"], shading="gouraud", cmap="viridis")
    figure.colorbar(picture, ax=right, label=r"$u_h$")
    right.set_aspect("equal")
    right.set_xlabel("x")
    right.set_ylabel("y")
    right.set_title(r"$u_h$ on $\Omega$")
    figure.suptitle(scene_title(folder, problem))
    figure.tight_layout()
    save_figure(figure, folder / f"figure_{problem}.png", dpi=110)


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    for folder in map(Path, sys.argv[1:]):
        problems = [p.stem[len("boundary_"):] for p in sorted(folder.glob("boundary_*.csv"))]
        if not problems:
            sys.exit(f"plot_paper.py: no boundary_<problem>.csv in {folder}")
        for problem in problems:
            with open(folder / f"boundary_{problem}.csv", newline="") as handle:
                if "u" not in next(csv.reader(handle), []):
                    print(f"plot_paper.py: {problem} in {folder} is an elastic problem: plots/plot_run.py draws it")
                    continue
            plot(folder, problem)


if __name__ == "__main__":
    main()
