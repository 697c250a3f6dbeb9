#!/usr/bin/python3
"""Read a ring_contact output folder back and check that every file is whole.

    /usr/bin/python3 check_results.py FOLDER [options]

(Debian's /usr/bin/python3 with python3-vtk9; where ParaView's Python is
installed instead, python3-paraview, which conflicts with python3-vtk9, the
script runs itself again under pvpython: both give VTK 9's vtkmodules.)
Checks:
- history.csv: a header that starts with scheme, step, time, holds the
  solver's columns and ends with the invariants (equilibrium_error,
  action_reaction_error), rows of as many fields, every number parses;
- verdicts.csv (if present): rows of 10 fields;
- every .pvd parses and every file it lists exists; every listed .vtu (or
  .pvtu of an MPI run, with its pieces) is read
  with VTK's own XML reader without error or warning, has cells, every cell's
  point ids are in range, every point is referenced by a cell, every point and
  cell data array has one finite value (tuple) per point or cell;
- no temporary file is left, and (--all-listed) every .vtu is listed in a pvd.
Options add expectations: --rows N (history rows), --bulk-cells N,
--surface-cells N, --bulk-area A --surface-length L with --tolerance T
(relative; area and length from VTK's own triangulation of each cell, so a
wrongly numbered high-order cell shows up as folded or overlapping area).
Prints one line per file and exits with 1 on the first failure.
"""
import argparse
import csv
import glob
import math
import os
import shutil
import sys
import xml.etree.ElementTree as ET

VERDICT_FIELDS = 10
LEADING = ["scheme", "step", "time"]
SOLVER = ["newton_iterations", "step_cuts", "active_nodes", "wall_time", "cells",
          "unknowns"]
INVARIANTS = ["equilibrium_error", "action_reaction_error"]


def fail(message):
    print("FAILED: " + message)
    sys.exit(1)


def check_csv(path, n_fields):
    with open(path, newline="") as f:
        text = f.read()
    if not text.endswith("\n"):
        fail(f"{path}: the last line is not complete")
    rows = list(csv.reader(text.splitlines()))
    if not rows or len(rows[0]) != n_fields:
        fail(f"{path}: header of {len(rows[0]) if rows else 0} fields")
    for i, row in enumerate(rows[1:], start=2):
        if len(row) != n_fields:
            fail(f"{path}: line {i} has {len(row)} fields, not {n_fields}")
    return rows[1:]


def history_fields(path):
    """scheme, step, time, the scenario's leading columns, the solver's,
    the scenario's trailing ones, and the invariants last: the number of
    fields of the header, whose names must be unique."""
    with open(path, newline="") as f:
        header = next(csv.reader(f), [])
    if header[:len(LEADING)] != LEADING:
        fail(f"{path}: the header does not start with {LEADING}")
    if header[-len(INVARIANTS):] != INVARIANTS:
        fail(f"{path}: the header does not end with {INVARIANTS}")
    position = [header.index(name) if name in header else -1 for name in SOLVER]
    if -1 in position or position != sorted(position) or \
            position[-1] - position[0] != len(SOLVER) - 1:
        fail(f"{path}: the header lacks the solver's columns {SOLVER} in order")
    if len(set(header)) != len(header):
        fail(f"{path}: the header repeats a name")
    return len(header)


def check_history(path):
    rows = check_csv(path, history_fields(path))
    for i, row in enumerate(rows, start=2):
        for value in row[1:]:
            try:
                float(value)
            except ValueError:
                fail(f"{path}: line {i}: '{value}' is not a number")
    return rows


def scheme_tag(name):
    """The file name tag of a scheme name ("Gauss 3" -> "gauss-3")."""
    return name.lower().replace(" ", "-")


def triangulated_measure(cell, points):
    """Signed area (2d cells) or length (1d cells) of VTK's triangulation of
    one cell, and the same with absolute values."""
    from vtkmodules.vtkCommonCore import vtkIdList, vtkPoints

    ids = vtkIdList()
    pts = vtkPoints()
    cell.Triangulate(0, ids, pts)
    signed, absolute = 0.0, 0.0
    if cell.GetCellDimension() == 2:
        for t in range(0, pts.GetNumberOfPoints(), 3):
            a, b, c = (pts.GetPoint(t + k) for k in range(3))
            area = 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) -
                          (c[0] - a[0]) * (b[1] - a[1]))
            signed += area
            absolute += abs(area)
    else:
        for s in range(0, pts.GetNumberOfPoints(), 2):
            a, b = pts.GetPoint(s), pts.GetPoint(s + 1)
            length = math.dist(a, b)
            signed += length
            absolute += length
    return signed, absolute


def listed_files(path, element, attribute):
    """The files an XML index (.pvd, .pvtu) lists in `attribute` of its
    `element`s, each checked to exist beside it."""
    try:
        root = ET.parse(path).getroot()
    except ET.ParseError as e:
        fail(f"{path}: not whole XML ({e})")
    files = [e.get(attribute) for e in root.iter(element)]
    if not files:
        fail(f"{path}: lists no {element.lower()}")
    for name in files:
        if not os.path.isfile(os.path.join(os.path.dirname(path), name)):
            fail(f"{path}: lists {name}, which does not exist")
    return files


def pvtu_pieces(path):
    """The piece files a .pvtu lists (an MPI run's pieces)."""
    return listed_files(path, "Piece", "Source")


def check_vtu(path):
    """A .vtu, or a .pvtu with its pieces read as one grid."""
    from vtkmodules.vtkIOXML import (vtkXMLPUnstructuredGridReader,
                                     vtkXMLUnstructuredGridReader)

    class Errors:
        messages = []

        def __call__(self, caller, event):
            self.messages.append(event)

    errors = Errors()
    parallel = path.endswith(".pvtu")
    if parallel:
        pvtu_pieces(path)
    reader = (vtkXMLPUnstructuredGridReader() if parallel else
              vtkXMLUnstructuredGridReader())
    reader.AddObserver("ErrorEvent", errors)
    reader.AddObserver("WarningEvent", errors)
    reader.SetFileName(path)
    reader.Update()
    if errors.messages or reader.GetErrorCode() != 0:
        fail(f"{path}: VTK reader reports {errors.messages or reader.GetErrorCode()}")
    grid = reader.GetOutput()
    n_points, n_cells = grid.GetNumberOfPoints(), grid.GetNumberOfCells()
    if n_cells == 0 or n_points == 0:
        fail(f"{path}: {n_cells} cells, {n_points} points")
    referenced = [False] * n_points
    signed, absolute = 0.0, 0.0
    cell_types = set()
    for c in range(n_cells):
        cell = grid.GetCell(c)
        cell_types.add(cell.GetClassName())
        ids = cell.GetPointIds()
        for k in range(ids.GetNumberOfIds()):
            i = ids.GetId(k)
            if i < 0 or i >= n_points:
                fail(f"{path}: cell {c} references point {i} of {n_points}")
            referenced[i] = True
        s, a = triangulated_measure(cell, grid.GetPoints())
        signed += s
        absolute += a
    unreferenced = referenced.count(False)
    if unreferenced:
        fail(f"{path}: {unreferenced} of {n_points} points belong to no cell")
    for data, n, what in ((grid.GetPointData(), n_points, "point"),
                          (grid.GetCellData(), n_cells, "cell")):
        for a in range(data.GetNumberOfArrays()):
            array = data.GetArray(a)
            if array.GetNumberOfTuples() != n:
                fail(f"{path}: {what} array {array.GetName()} has "
                     f"{array.GetNumberOfTuples()} values for {n} {what}s")
            for t in range(array.GetNumberOfTuples()):
                for k in range(array.GetNumberOfComponents()):
                    if not math.isfinite(array.GetComponent(t, k)):
                        fail(f"{path}: {what} array {array.GetName()} value "
                             f"{t} is not finite")
    # The Cauchy stress is a tensor (9 components, as ParaView reads
    # tensors), symmetric; in a 2D run (cells of dimension 2) with nothing
    # out of the plane but sigma_33.
    stress = grid.GetPointData().GetArray("cauchy_stress")
    if stress is not None:
        if stress.GetNumberOfComponents() != 9:
            fail(f"{path}: cauchy_stress has {stress.GetNumberOfComponents()} "
                 "components, not the 9 of a tensor")
        solid = grid.GetCell(0).GetCellDimension() == 3
        for t in range(stress.GetNumberOfTuples()):
            s_ = [stress.GetComponent(t, k) for k in range(9)]
            scale = max(1.0, max(abs(v) for v in s_))
            asymmetry = max(abs(s_[1] - s_[3]), abs(s_[2] - s_[6]),
                            abs(s_[5] - s_[7]))
            out_of_plane = 0 if solid else max(abs(s_[2]), abs(s_[5]),
                                               abs(s_[6]), abs(s_[7]))
            if asymmetry > 1e-6 * scale or out_of_plane > 0:
                fail(f"{path}: cauchy_stress at point {t} is not a symmetric "
                     f"{'' if solid else 'in-plane '}tensor: {s_}")
    return {"cells": n_cells, "points": n_points, "signed": signed,
            "absolute": absolute, "types": sorted(cell_types),
            "arrays": grid.GetPointData().GetNumberOfArrays()}


def check_pvd(path):
    return listed_files(path, "DataSet", "file")


def check_measure(path, info, expected, tolerance, what):
    for key in ("signed", "absolute"):
        if abs(info[key] - expected) > tolerance * expected:
            fail(f"{path}: {what} ({key}) {info[key]:.6g}, expected "
                 f"{expected:.6g} within {tolerance:g}")


def ensure_vtk():
    """VTK 9's Python modules, from python3-vtk9 or from ParaView: without
    the former, the script runs itself again under pvpython (once)."""
    try:
        import vtkmodules.vtkCommonDataModel  # noqa: F401
        import vtkmodules.vtkIOXML  # noqa: F401
        return
    except ImportError:
        pass
    pvpython = shutil.which("pvpython")
    if pvpython and os.environ.get("RING_CONTACT_UNDER_PVPYTHON") != "1":
        os.environ["RING_CONTACT_UNDER_PVPYTHON"] = "1"
        sys.stdout.flush()
        os.execv(pvpython, [pvpython, os.path.abspath(__file__)] + sys.argv[1:])
    fail("no VTK for Python: install python3-vtk9, or ParaView's "
         "python3-paraview (pvpython)")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("folder")
    parser.add_argument("--rows", type=int)
    parser.add_argument("--no-history", action="store_true")
    parser.add_argument("--all-listed", action="store_true")
    parser.add_argument("--allow-temporaries", action="store_true")
    parser.add_argument("--vtu-every-step", action="store_true")
    parser.add_argument("--bulk-cells", type=int)
    parser.add_argument("--surface-cells", type=int)
    parser.add_argument("--bulk-area", type=float)
    parser.add_argument("--surface-length", type=float)
    parser.add_argument("--tolerance", type=float, default=1e-3)
    parser.add_argument("--quiet", action="store_true")
    args = parser.parse_args()
    ensure_vtk()

    def say(text):
        if not args.quiet:
            print(text)

    folder = args.folder
    leftovers = glob.glob(os.path.join(folder, ".*.tmp"))
    if leftovers and not args.allow_temporaries:
        fail(f"temporary files left: {sorted(leftovers)}")
    history = os.path.join(folder, "history.csv")
    rows = []
    if not args.no_history:
        if not os.path.isfile(history):
            fail(f"{history} does not exist")
        rows = check_history(history)
        if args.rows is not None and len(rows) != args.rows:
            fail(f"{history}: {len(rows)} rows, expected {args.rows}")
        say(f"history.csv: {len(rows)} rows of {history_fields(history)} "
            "fields")
    verdicts = os.path.join(folder, "verdicts.csv")
    if os.path.isfile(verdicts):
        say(f"verdicts.csv: {len(check_csv(verdicts, VERDICT_FIELDS))} rows")
    listed = set()
    for pvd in sorted(glob.glob(os.path.join(folder, "*.pvd"))):
        files = check_pvd(pvd)
        listed.update(files)
        surface = os.path.basename(pvd).startswith("slave-")
        if args.vtu_every_step:
            tag = os.path.basename(pvd).split("-", 1)[1][:-len(".pvd")]
            # The undeformed state (step 0), then every converged step.
            steps = ["0"] + [r[1] for r in rows if scheme_tag(r[0]) == tag]
            listed_steps = [str(int(os.path.splitext(f)[0].rsplit("-", 1)[1]))
                            for f in files]
            if listed_steps != steps:
                fail(f"{pvd}: lists steps {listed_steps}, history.csv has "
                     f"{steps}")
        for name in files:
            path = os.path.join(folder, name)
            if name.endswith(".pvtu"):
                listed.update(pvtu_pieces(path))
            info = check_vtu(path)
            cells = args.surface_cells if surface else args.bulk_cells
            if cells is not None and info["cells"] != cells:
                fail(f"{path}: {info['cells']} cells, expected {cells}")
            measure = args.surface_length if surface else args.bulk_area
            if measure is not None:
                check_measure(path, info, measure, args.tolerance,
                              "length" if surface else "area")
        say(f"{os.path.basename(pvd)}: {len(files)} files, last "
            f"{info['cells']} cells ({', '.join(info['types'])}), "
            f"{info['points']} points, {info['arrays']} point arrays, "
            f"{'length' if surface else 'area'} {info['absolute']:.6f}")
    if args.all_listed:
        for vtu in glob.glob(os.path.join(folder, "*.vtu")):
            if os.path.basename(vtu) not in listed:
                fail(f"{vtu} is listed in no .pvd")
    say("OK")


if __name__ == "__main__":
    main()
