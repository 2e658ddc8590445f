"""Figure 1 of the paper from Python, as a notebook would: the simplified Signorini problem (9) on
the §7 square solved through the module (`import hpcontact`), u_h, the obstacle g and λ_H along
Γ_C at p = 2 and p = 6, and α of the pairing on quadrilaterals and on triangles.

    PYTHONPATH=build/python /usr/bin/python3 plots/notebook_figure1.py results/notebook_figure1.png
"""
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import hpcontact  # noqa: E402
from figure_file import save_figure  # noqa: E402

SCENE = Path(__file__).resolve().parent.parent / "studies" / "paper" / "figure1_signorini.toml"


def main(output):
    figure, (left, right) = plt.subplots(1, 2, figsize=(12, 5.2))
    multiplier_axis = left.twinx()
    for p, style in ((2, ":"), (6, "-")):
        result = hpcontact.solve(SCENE, {"discretization.p": p}, effects=["signorini"])
        b = result.boundary["signorini"]
        energy = result.summary["signorini"]["energy"]
        left.plot(b["s_arc"] - 1, b["u"], style, color="tab:blue", label=rf"$u_h$, p = {p} (E = {energy:.6f})")
        multiplier_axis.plot(b["s_arc"] - 1, b["lambda"], style, color="tab:red", label=rf"$\lambda_H$, p = {p}")
    left.plot(b["s_arc"] - 1, b["obstacle"], "--", color="tab:green", label="obstacle g")
    left.set_xlabel(r"x on $\Gamma_C$ (y = -1)")
    left.set_ylabel(r"$u_h$ and g")
    multiplier_axis.set_ylabel(r"multiplier $\lambda_H$", color="tab:red")
    multiplier_axis.tick_params(axis="y", colors="tab:red")
    handles, labels = left.get_legend_handles_labels()
    more_handles, more_labels = multiplier_axis.get_legend_handles_labels()
    left.legend(handles + more_handles, labels + more_labels, fontsize=8, loc="upper center",
                bbox_to_anchor=(0.5, -0.14), ncol=3)
    left.grid(True, alpha=0.3)
    left.set_title(r"Figure 1: $u_h$, g and $\lambda_H$ (16 × 16 cells, h/H = 1/2, $p_C$ = 1)")

    degrees = [1, 2, 3, 4, 5, 6]
    for cells, marker in (("quadrilaterals", "o"), ("triangles", "s")):
        alphas = [hpcontact.infsup(SCENE, {"discretization.p": p, "domain.cells": cells}).alpha for p in degrees]
        right.plot(degrees, alphas, marker=marker, label=cells)
    right.set_xlabel("p")
    right.set_ylabel(r"$\alpha$")
    right.set_ylim(0, 1.05)
    right.grid(True, alpha=0.3)
    right.legend(title=r"cells ($p_C$ = 1, h/H = 1/2)")
    right.set_title(r"inf-sup constant $\alpha$ of the pairing")
    figure.tight_layout()
    save_figure(figure, Path(output))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "notebook_figure1.png")
