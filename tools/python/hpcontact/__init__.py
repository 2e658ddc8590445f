"""hpcontact: higher-order mixed finite element methods for contact problems and their inf-sup
stability analysis (the paper "Mixed finite element methods of higher-order for model contact
problems" by A. Schröder, and linear elasticity), from Python.

Scenes are the TOML scenes of the command-line tool (docs/scene_keys.md), from a file or a dict,
with dotted-key overrides::

    import hpcontact
    result = hpcontact.solve("studies/paper/figure1_signorini.toml", {"discretization.p": 4})
    result.run.contact("signorini").energy         # the typed result (RunResult)
    result.summary["signorini"]["energy"]          # the same as summary.json's dict
    b = result.boundary["signorini"]               # numpy arrays along Γ_C
    b["s_arc"], b["u"], b["obstacle"], b["lambda"]
    f = result.fields["signorini"]                 # the solution on Ω, the VTU's arrays
    f["points"], f["u"], f["triangles"]            # (elastic: "displacement", "stress", "von_mises")
    hpcontact.infsup("studies/paper/figure1_signorini.toml").alpha

Errors in the input raise hpcontact.InputError (a ValueError) with the command-line tool's message.
"""

# Imported under private names, so that the module's namespace holds its API alone.
import csv as _csv
import os as _os
import tempfile as _tempfile
import warnings as _warnings
from dataclasses import dataclass as _dataclass, field as _field

import numpy as _np

from ._hpcontact import InputError, Scene, read_scene, scene_from_dict, scene_keys
from . import _hpcontact

__all__ = ["InputError", "Scene", "read_scene", "scene_from_dict", "scene_keys", "scene", "solve", "infsup",
           "sweep", "advise", "Result", "InfSup", "Advice", "StabilityWarning"]


class StabilityWarning(UserWarning):
    """A solve's pairing is predicted unstable ([solve] stability = "warn"): the message names the
    predicted α, where, and a stable alternative."""


def scene(source, overrides=None, path=None):
    """A checked Scene from a scene file (str or os.PathLike), a dict of tables, or a Scene.

    `overrides` maps dotted keys ("discretization.p", "run.effects") to values; `path` names a dict
    scene in messages and anchors its relative mesh files (default: "<dict>" in the working folder).
    """
    overrides = dict(overrides or {})
    if isinstance(source, Scene):
        if overrides:
            raise InputError("overrides apply to a scene file or dict, not to an already checked Scene")
        return source
    if isinstance(source, dict):
        return scene_from_dict(source, path or _os.path.join(_os.getcwd(), "<dict>"), overrides)
    return read_scene(_os.fspath(source), overrides)


@_dataclass
class Result:
    """What a run computed: the typed result (`run`, a RunResult: run.contacts, run.contact(name),
    run.infsup), the same as summary.json's dict, its tables and its solutions on Ω as numpy
    arrays."""

    run: object
    summary: dict
    tables: dict = _field(default_factory=dict)
    fields: dict = _field(default_factory=dict)
    """The solutions on Ω per problem (and body: "frictionless_bottom"), the arrays of the VTU files
    (output "vtu"): "points" (n, 3); the VTK Lagrange cells "connectivity", "offsets", "types" and
    their degrees "p"; "triangles" (m, 3), the cells cut into linear triangles through their nodes
    (matplotlib's tripcolor(points[:, 0], points[:, 1], triangles, values)); and the point fields:
    "u" and "grad_u" (scalar model), "displacement" (n, 3), "stress" (n, 6: xx, yy, zz, xy, yz, xz)
    and "von_mises" (elastic)."""

    @property
    def boundary(self):
        """Samples along Γ_C per contact problem: {problem: {column: array}} (x, u, obstacle or
        bound, lambda, y, s_arc, zone for the scalar problems; docs/user_guide.md for the elastic ones)."""
        return {name[len("boundary_"):]: columns for name, columns in self.tables.items()
                if name.startswith("boundary_")}

    @property
    def mode(self):
        """The eigenvector of α sampled along Γ_C (effect infsup), or None."""
        return self.tables.get("mode")

    @property
    def convergence(self):
        """The rows of the effect convergence as columns, or None."""
        return self.tables.get("convergence")


def solve(source, overrides=None, effects=None, out=None, path=None):
    """Runs a scene's effects (or `effects`, a list of names) and returns a Result.

    With `out` (a folder) the run also writes the command-line tool's files there.
    """
    overrides = dict(overrides or {})
    if effects is not None:
        # (one name is one effect: list("signorini") would be its letters)
        overrides["run.effects"] = [effects] if isinstance(effects, str) else list(effects)
    checked = scene(source, overrides, path)
    run, summary, tables, fields = _hpcontact.run_scene(checked, _os.fspath(out) if out is not None else "")
    stability = summary.get("stability", {})
    if stability.get("warned"):
        _warnings.warn(stability["warning"], StabilityWarning, stacklevel=2)
    return Result(run, summary, tables, fields)


@_dataclass
class InfSup:
    """The discrete inf-sup constant of a scene's pairing."""

    alpha: float
    alpha_error: float
    converged: bool
    unique: bool
    mode: dict
    summary: dict


def infsup(source, overrides=None, path=None):
    """α of the scene's pairing (effect infsup alone), its error estimate and the mode along Γ_C."""
    overrides = dict(overrides or {})
    overrides["run.effects"] = ["infsup"]
    overrides.setdefault("run.outputs", ["summary", "mode"])
    result = solve(source, overrides, path=path)
    info = result.run.infsup
    return InfSup(info.alpha, info.alpha_error, info.alpha_converged, info.lambda_unique, result.mode, result.summary)


def _read_columns(path):
    with open(path, newline="") as handle:
        rows = list(_csv.DictReader(handle))
    columns = {}
    for name in (rows[0].keys() if rows else []):
        values = [row[name] for row in rows]
        try:
            columns[name] = _np.array([float(v) for v in values])
        except ValueError:
            columns[name] = values
    return columns


def sweep(study, out=None, restart=False):
    """Runs a stability sweep (a study file, as `hpcontact sweep`) and returns (alpha, verdicts), each
    {column: array}. With `out` the resumable alpha.csv and verdicts.csv stay there; `restart`
    replaces the rows stored there (as --restart)."""
    if out is None:
        # An interrupted sweep may still be stopping in the folder when it is removed.
        with _tempfile.TemporaryDirectory(prefix="hpcontact_sweep_", ignore_cleanup_errors=True) as folder:
            return sweep(study, folder)
    alpha_csv, verdicts_csv = _hpcontact.run_sweep(_os.fspath(study), _os.fspath(out), bool(restart))
    return _read_columns(alpha_csv), _read_columns(verdicts_csv)


@_dataclass
class Advice:
    """What `hpcontact advise` finds for a scene's mesh and p: every candidate (advice.csv's
    columns as arrays: zone, p, pC, ratio, family, constraint_points, alpha_predicted, alpha,
    unknowns, recommended), the recommended row, the scene edits that apply it, and alpha_min."""

    candidates: dict
    recommended: dict
    edits: list
    alpha_min: float


def advise(source, overrides=None, alpha_min=None, out=None, path=None):
    """Ranks the multiplier discretizations (p_C, h/H, family) for the scene's T_h and p by predicted
    α and multipliers, with the global α of the recommended one and its runner-up. With `out` the
    candidates are also written to out/advice.csv."""
    checked = scene(source, overrides, path)
    columns, edits, minimum = _hpcontact.run_advice(checked, alpha_min, _os.fspath(out) if out is not None else "")
    rows = [dict(zip(columns, values)) for values in zip(*columns.values())]
    recommended = next((row for row in rows if row["recommended"] == "yes"), None)
    return Advice(columns, recommended, list(edits), minimum)
