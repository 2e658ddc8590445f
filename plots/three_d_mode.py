#!/usr/bin/env python3
"""Plots spurious inf-sup modes of 3-D pairings written by `hpcontact infsup --scene S --mode F.vtu`
(the mode on the cells of T_{C,H} of a flat Γ_C, each cut into linear quadrilaterals): one panel
per file, the mode over Γ_C's in-plane coordinates (x, y for a face z = const), scaled to its
largest magnitude.

Usage: three_d_mode.py OUT.png TITLE=MODE.vtu [TITLE=MODE.vtu ...]
"""
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import meshio  # noqa: E402
import numpy as np  # noqa: E402
from figure_file import save_figure  # noqa: E402


def main():
    if len(sys.argv) < 3 or any("=" not in argument for argument in sys.argv[2:]):
        sys.exit(__doc__)
    panels = [argument.rsplit("=", 1) for argument in sys.argv[2:]]
    figure, axes = plt.subplots(1, len(panels), figsize=(4.4 * len(panels) + 1.2, 4.2), squeeze=False)
    for axis, (title, file) in zip(axes[0], panels):
        grid = meshio.read(file)
        points, quads = grid.points, grid.cells_dict["quad"]
        mode = np.asarray(grid.point_data["mode"]).reshape(-1)
        scale = np.abs(mode).max() or 1.0
        # Each quadrilateral as two triangles, shaded between its corner values (no point is
        # shared between cells of T_{C,H}: the jumps of the multiplier show).
        triangles = np.concatenate([quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]])
        shaded = axis.tripcolor(points[:, 0], points[:, 1], triangles, mode / scale, shading="gouraud",
                                cmap="RdBu_r", vmin=-1.0, vmax=1.0)
        axis.set_xlim(points[:, 0].min(), points[:, 0].max())
        axis.set_ylim(points[:, 1].min(), points[:, 1].max())
        axis.set_aspect("equal")
        axis.set_title(title, fontsize=9)
        axis.set_xlabel("x")
    axes[0][0].set_ylabel("y")
    figure.colorbar(shaded, ax=axes[0].tolist(), label="mode / max |mode|", shrink=0.85)
    figure.suptitle("spurious multiplier modes of 3-D pairings (Γ_C: z = -1)")
    save_figure(figure, Path(sys.argv[1]))


if __name__ == "__main__":
    main()
