"""The ParaView outputs read back by independent readers: meshio (cell types, shared points, arrays)
and VTK itself (python3-vtk9), whose own Lagrange-cell interpolation must give u_h at the boundary
samples the library evaluates on its own, to round-off. Run by CTest (Python.Module)."""

import os
import subprocess
import xml.etree.ElementTree as ET

import meshio
import numpy as np
import pytest
import vtk
from vtk.util.numpy_support import numpy_to_vtk, vtk_to_numpy

import hpcontact

SOURCE = os.environ["HPCONTACT_SOURCE_DIR"]
FIGURE1 = os.path.join(SOURCE, "studies", "paper", "figure1_signorini.toml")
TRIANGLES = os.path.join(SOURCE, "studies", "triangles", "signorini.toml")
ELASTIC = os.path.join(SOURCE, "studies", "elasticity", "hertz.toml")
VTK_TYPES = {"VTK_LAGRANGE_QUADRILATERAL": 70, "VTK_LAGRANGE_TRIANGLE": 69}


def solve_to(tmp_path, scene, p, effects, extra=None):
    overrides = {"discretization.p": p, "run.outputs": ["summary", "boundary", "vtu"], **(extra or {})}
    hpcontact.solve(scene, overrides, effects=effects, out=tmp_path)
    return tmp_path


def nodes_of(cell_type, k):
    return (k + 1) ** 2 if cell_type == "VTK_LAGRANGE_QUADRILATERAL" else (k + 1) * (k + 2) // 2


def probe(vtu_path, points, array):
    """VTK's own interpolation of `array` of the VTU (or PVTU) at 2D points."""
    reader = vtk.vtkXMLPUnstructuredGridReader() if str(vtu_path).endswith(".pvtu") else vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(str(vtu_path))
    polydata = vtk.vtkPolyData()
    xyz = np.column_stack([points, np.zeros(len(points))])
    vtk_points = vtk.vtkPoints()
    vtk_points.SetData(numpy_to_vtk(np.ascontiguousarray(xyz), deep=True))
    polydata.SetPoints(vtk_points)
    prober = vtk.vtkProbeFilter()
    prober.SetInputData(polydata)
    prober.SetSourceConnection(reader.GetOutputPort())
    prober.SetTolerance(1e-10)
    prober.Update()
    output = prober.GetOutput()
    found = vtk_to_numpy(output.GetPointData().GetArray(prober.GetValidPointMaskArrayName()))
    return vtk_to_numpy(output.GetPointData().GetArray(array)), found.astype(bool)


@pytest.mark.parametrize("scene, p", [(FIGURE1, 4), (TRIANGLES, 5)])
def test_vtu_holds_lagrange_cells_of_degree_p_with_shared_points(tmp_path, scene, p):
    out = solve_to(tmp_path, scene, p, ["signorini"])
    mesh = meshio.read(out / "solution_signorini.vtu")
    for block in mesh.cells:
        assert block.type in VTK_TYPES
        assert block.data.shape[1] == nodes_of(block.type, p)
    # Shared points: no two points at the same place, every point used.
    rounded = np.round(mesh.points[:, :2], 12)
    assert len(np.unique(rounded, axis=0)) == len(mesh.points)
    used = np.unique(np.concatenate([block.data.ravel() for block in mesh.cells]))
    assert len(used) == len(mesh.points)
    assert set(mesh.point_data) == {"u", "grad_u"} and mesh.point_data["grad_u"].shape[1] == 3
    assert np.all(np.concatenate(mesh.cell_data["p"]) == p)
    # Appended raw binary with 64-bit headers.
    header = (out / "solution_signorini.vtu").read_bytes().split(b"<AppendedData")[0].decode()
    assert 'header_type="UInt64"' in header and 'format="appended"' in header and "ascii" not in header


@pytest.mark.parametrize("scene, p", [(FIGURE1, 4), (TRIANGLES, 5)])
def test_vtk_interpolation_of_the_lagrange_cells_gives_u_on_the_contact_boundary(tmp_path, scene, p):
    out = solve_to(tmp_path, scene, p, ["signorini"])
    samples = np.genfromtxt(out / "boundary_signorini.csv", delimiter=",", names=True)
    points = np.column_stack([samples["x"], samples["y"]])
    u, found = probe(out / "solution_signorini.vtu", points, "u")
    assert found.all()
    # The cells carry u_h exactly (degree k = p), so VTK's node order and ours agree iff this holds.
    np.testing.assert_allclose(u, samples["u"], rtol=0, atol=1e-10 * np.abs(samples["u"]).max())


@pytest.mark.parametrize("scene, p", [(FIGURE1, 5), (TRIANGLES, 6)])
def test_vtk_geometry_of_every_node_matches_the_affine_cells(tmp_path, scene, p):
    """Inside the cells: on affine cells VTK's Lagrange map of the nodes must be the affine map of
    the corners at every parametric point; any node (edge or interior) out of VTK's order breaks it."""
    out = solve_to(tmp_path, scene, p, ["signorini"])
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(str(out / "solution_signorini.vtu"))
    reader.Update()
    grid = reader.GetOutput()
    rng = np.random.default_rng(7)
    worst = 0.0
    for c in range(grid.GetNumberOfCells()):
        cell = grid.GetCell(c)
        corners = np.array([cell.GetPoints().GetPoint(v)[:2] for v in range(4 if cell.GetCellType() == 70 else 3)])
        for _ in range(3):
            r, s = rng.random(2)
            if cell.GetCellType() == 69:
                r, s = (r, s) if r + s <= 1 else (1 - r, 1 - s)
                expected = (1 - r - s) * corners[0] + r * corners[1] + s * corners[2]
            else:
                expected = ((1 - r) * (1 - s) * corners[0] + r * (1 - s) * corners[1] + r * s * corners[2]
                            + (1 - r) * s * corners[3])
            x = [0.0, 0.0, 0.0]
            weights = [0.0] * cell.GetNumberOfPoints()
            cell.EvaluateLocation(vtk.mutable(0), [r, s, 0.0], x, weights)
            worst = max(worst, np.abs(np.array(x[:2]) - expected).max())
    assert worst < 1e-12


def test_contact_vtu_carries_lambda_and_the_obstacle_for_vtk_and_meshio(tmp_path):
    out = solve_to(tmp_path, FIGURE1, 3, ["signorini"])
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(str(out / "contact_signorini.vtu"))
    reader.Update()
    grid = reader.GetOutput()
    samples = np.genfromtxt(out / "boundary_signorini.csv", delimiter=",", names=True)
    assert grid.GetNumberOfCells() == len(samples) - 1 and grid.GetNumberOfPoints() == len(samples)
    for name in ("lambda", "obstacle", "u", "s_arc"):
        np.testing.assert_array_equal(vtk_to_numpy(grid.GetPointData().GetArray(name)), samples[name])
    np.testing.assert_array_equal(vtk_to_numpy(grid.GetPoints().GetData())[:, 0], samples["x"])
    # meshio (which reads no PolyData) reads the same samples as line cells.
    lines = meshio.read(out / "contact_signorini.vtu")
    assert [block.type for block in lines.cells] == ["line"]
    np.testing.assert_array_equal(lines.point_data["lambda"].ravel(), samples["lambda"])


def test_convergence_writes_one_vtu_per_level_and_a_pvd(tmp_path):
    out = solve_to(tmp_path, FIGURE1, 2, ["signorini", "convergence"], {"convergence.refinements": 2})
    collection = ET.parse(out / "solution_signorini.pvd").getroot()
    files = [(float(d.get("timestep")), d.get("file")) for d in collection.iter("DataSet")]
    assert [t for t, _ in files] == [0.0, 1.0, 2.0]
    cells = [sum(len(b.data) for b in meshio.read(out / f).cells) for _, f in files]
    assert cells[1] == 4 * cells[0] and cells[2] == 4 * cells[1]


def test_elastic_vtu_carries_the_displacement_and_von_mises_per_level(tmp_path):
    out = solve_to(tmp_path, ELASTIC, 3, ["frictionless", "convergence"], {"convergence.refinements": 1})
    mesh = meshio.read(out / "solution_frictionless.vtu")
    assert mesh.point_data["displacement"].shape == (len(mesh.points), 3)
    assert np.all(mesh.point_data["displacement"][:, 2] == 0)
    assert np.all(mesh.point_data["von_mises"] >= 0)
    assert "pressure" in meshio.read(out / "contact_frictionless.vtu").point_data
    collection = ET.parse(out / "solution_frictionless.pvd").getroot()
    levels = [meshio.read(out / d.get("file")) for d in collection.iter("DataSet")]
    assert [sum(len(b.data) for b in m.cells) for m in levels][1] == 4 * len(mesh.cells[0].data)


def mpirun_solve(out, ranks, scene, arguments):
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    command = ["mpirun", "-n", str(ranks), "--oversubscribe", os.environ["HPCONTACT_CLI"], "solve", scene, *arguments,
               "--out", str(out)]
    result = subprocess.run(command, env=env, capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stdout + result.stderr


def read_grid(path):
    reader = vtk.vtkXMLPUnstructuredGridReader() if str(path).endswith(".pvtu") else vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(str(path))
    reader.Update()
    return reader.GetOutput()


@pytest.mark.parametrize("scene, problem, array", [(FIGURE1, "signorini", "u"), (ELASTIC, "frictionless", "displacement")])
def test_under_mpirun_each_rank_writes_its_cells_as_a_piece_of_a_pvtu(tmp_path, scene, problem, array):
    """Under mpirun no rank gathers u: each writes its own cells; the PVTU's pieces together are the
    serial file's cells, and VTK's interpolation of them gives the serial u at the boundary samples
    and at points inside."""
    with open(scene) as original:  # the scene with the convergence effect, one refinement, every output
        text = original.read().split("[run]")[0]
    scene = tmp_path / "scene.toml"
    scene.write_text(text + f'[run]\neffects = ["{problem}", "convergence"]\noutputs = ["summary", "boundary", "vtu"]\n'
                     "[convergence]\nrefinements = 1\n")
    arguments = ["--p", "3"]
    subprocess.run([os.environ["HPCONTACT_CLI"], "solve", str(scene), *arguments, "--out", str(tmp_path / "serial")],
                   check=True, capture_output=True)
    mpirun_solve(tmp_path / "parallel", 3, str(scene), arguments)
    serial, parallel = tmp_path / "serial", tmp_path / "parallel"
    assert not (parallel / f"solution_{problem}.vtu").exists()
    collection = ET.parse(parallel / f"solution_{problem}.pvd").getroot()
    assert [d.get("file") for d in collection.iter("DataSet")] == [f"solution_{problem}_level0.pvtu",
                                                                   f"solution_{problem}_level1.pvtu"]
    for name in (f"solution_{problem}", f"solution_{problem}_level1"):
        pieces = [p.get("Source") for p in ET.parse(parallel / f"{name}.pvtu").getroot().iter("Piece")]
        assert pieces == [f"{name}_rank{r:04d}.vtu" for r in range(3)]
        cells = [read_grid(parallel / piece).GetNumberOfCells() for piece in pieces]
        assert min(cells) > 0 and sum(cells) == read_grid(serial / f"{name}.vtu").GetNumberOfCells()
    samples = np.genfromtxt(serial / f"boundary_{problem}.csv", delimiter=",", names=True)
    rng = np.random.default_rng(3)
    inside = rng.uniform(-0.9, 0.9, (50, 2)) if problem == "signorini" else None
    points = np.column_stack([samples["x"], samples["y"]])
    if inside is not None:
        points = np.vstack([points, inside])
    values = {}
    for label, path in (("serial", serial / f"solution_{problem}.vtu"),
                        ("parallel", parallel / f"solution_{problem}.pvtu")):
        value, found = probe(path, points, array)
        assert found.all(), label
        values[label] = value
    scale = np.abs(values["serial"]).max()
    assert scale > 0
    np.testing.assert_allclose(values["parallel"], values["serial"], rtol=0, atol=1e-10 * scale)


def test_result_fields_are_the_vtu_arrays_with_the_stress_tensor(tmp_path):
    """Result.fields holds what solution_<problem>.vtu holds (points, cells, displacement, stress,
    von Mises), bit for bit, and von Mises is that of the stress tensor."""
    overrides = {"discretization.p": 2, "domain.n_x": 16, "domain.n_y": 8, "domain.grading_layers": 0,
                 "run.outputs": ["summary", "vtu"]}
    result = hpcontact.solve(ELASTIC, overrides, effects=["frictionless"], out=tmp_path)
    fields = result.fields["frictionless"]
    mesh = meshio.read(tmp_path / "solution_frictionless.vtu")
    np.testing.assert_array_equal(fields["points"], mesh.points)
    for name in ("displacement", "stress", "von_mises"):  # (meshio keeps one component as (n, 1))
        np.testing.assert_array_equal(fields[name], mesh.point_data[name].reshape(fields[name].shape))
    assert fields["stress"].shape == (len(mesh.points), 6) and np.all(fields["stress"][:, 4:] == 0)
    sxx, syy, szz, sxy = (fields["stress"][:, k] for k in range(4))
    von_mises = np.sqrt(0.5 * ((sxx - syy) ** 2 + (syy - szz) ** 2 + (szz - sxx) ** 2) + 3 * sxy ** 2)
    # At a cell's interior node (the last of an order-2 quadrilateral) one cell gives both values;
    # where cells meet both are averages, and von Mises, a norm, of the mean is at most the mean.
    interior = fields["connectivity"][fields["offsets"] - 1]
    np.testing.assert_allclose(fields["von_mises"][interior], von_mises[interior], rtol=1e-12, atol=1e-15)
    assert np.all(von_mises <= fields["von_mises"] * (1 + 1e-12) + 1e-15)
    # The cells as meshio sees them, and 2k² linear triangles per quadrilateral of order k.
    (cells,) = mesh.cells
    np.testing.assert_array_equal(fields["connectivity"], cells.data.ravel())
    assert fields["types"].tolist() == [70] * len(cells.data) and fields["p"].tolist() == [2] * len(cells.data)
    assert fields["triangles"].shape == (8 * len(cells.data), 3) and fields["triangles"].max() < len(mesh.points)
    # Without out= no file is written, and the fields are there all the same.
    assert "u" in hpcontact.solve(FIGURE1, {"discretization.p": 2}, effects=["signorini"]).fields["signorini"]
