"""VTU files of VTK Lagrange cells (as `hpcontact solve` writes them) read with meshio and cut into
triangles along each cell's node lattice, for matplotlib's tripcolor/tricontour.

VTK's node order (the same as lib/io/vtk_lagrange_nodes.hpp): quadrilateral vertices, edge nodes of
edges 0→1, 1→2, 3→2, 0→3, then interior nodes row by row; triangle vertices, edge nodes of 0→1,
1→2, 2→0, then the interior nodes as the order k − 3 triangle one step inside, recursively."""
import math
import pathlib
import xml.etree.ElementTree as ET

import meshio
import numpy as np


def _triangle_lattice(k, o=0):
    if k < 0:
        return []
    if k == 0:
        return [(o, o)]
    nodes = [(o, o), (o + k, o), (o, o + k)]
    nodes += [(o + t, o) for t in range(1, k)]
    nodes += [(o + k - t, o + t) for t in range(1, k)]
    nodes += [(o, o + k - t) for t in range(1, k)]
    return nodes + _triangle_lattice(k - 3, o + 1)


def _quadrilateral_lattice(k):
    nodes = [(0, 0), (k, 0), (k, k), (0, k)]
    nodes += [(t, 0) for t in range(1, k)] + [(k, t) for t in range(1, k)]
    nodes += [(t, k) for t in range(1, k)] + [(0, t) for t in range(1, k)]
    return nodes + [(i, j) for j in range(1, k) for i in range(1, k)]


def _lattice_triangles(cell_type, n_nodes):
    """Sub-triangles of one cell as node positions in VTK's order."""
    if cell_type == "VTK_LAGRANGE_QUADRILATERAL":
        k = math.isqrt(n_nodes) - 1
        position = {node: n for n, node in enumerate(_quadrilateral_lattice(k))}
        squares = [(i, j) for j in range(k) for i in range(k)]
        return [t for i, j in squares for t in (
            (position[i, j], position[i + 1, j], position[i + 1, j + 1]),
            (position[i, j], position[i + 1, j + 1], position[i, j + 1]))]
    if cell_type == "VTK_LAGRANGE_TRIANGLE":
        k = (math.isqrt(8 * n_nodes + 1) - 3) // 2
        position = {node: n for n, node in enumerate(_triangle_lattice(k))}
        out = []
        for j in range(k):
            for i in range(k - j):
                out.append((position[i, j], position[i + 1, j], position[i, j + 1]))
                if i + j + 2 <= k:
                    out.append((position[i + 1, j], position[i + 1, j + 1], position[i, j + 1]))
        return out
    raise ValueError(f"not a VTK Lagrange cell: {cell_type}")


def read_lagrange_vtu(path):
    """(x, y, triangles, point_data) of a VTU of Lagrange cells; triangles index the points. A PVTU
    (an mpirun run's: one piece per rank) is read piece by piece and joined."""
    if str(path).endswith(".pvtu"):
        return _join(read_lagrange_vtu(pathlib.Path(path).parent / piece.get("Source"))
                     for piece in ET.parse(path).getroot().iter("Piece"))
    mesh = meshio.read(path)
    triangles = []
    for block in mesh.cells:
        pattern = np.array(_lattice_triangles(block.type, block.data.shape[1]))
        triangles.append(block.data[:, pattern].reshape(-1, 3))
    # One-component arrays as vectors (meshio may keep them as (n, 1) columns).
    fields = {name: values[:, 0] if values.ndim == 2 and values.shape[1] == 1 else values
              for name, values in mesh.point_data.items()}
    return mesh.points[:, 0], mesh.points[:, 1], np.concatenate(triangles), fields


def _join(pieces):
    xs, ys, triangles, fields, offset = [], [], [], {}, 0
    for x, y, piece_triangles, piece_fields in pieces:
        xs.append(x)
        ys.append(y)
        triangles.append(piece_triangles + offset)
        for name, values in piece_fields.items():
            fields.setdefault(name, []).append(values)
        offset += len(x)
    return (np.concatenate(xs), np.concatenate(ys), np.concatenate(triangles),
            {name: np.concatenate(values) for name, values in fields.items()})


def solution_file(folder, name):
    """folder/name.vtu, or the PVTU an mpirun run writes in its place."""
    serial = pathlib.Path(folder) / f"{name}.vtu"
    return serial if serial.exists() else pathlib.Path(folder) / f"{name}.pvtu"
