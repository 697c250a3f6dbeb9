#!/usr/bin/python3
"""The pieces of a slave surface's VTU file, as a plot over arc_length sees
them (Debian's /usr/bin/python3 with python3-vtk9).

    /usr/bin/python3 slave_pieces.py FILE.vtu

ParaView's Plot Data joins the points in the file's order. A piece is a run
of line cells, each starting at the point where the one before ended. For
each piece the script checks, and prints what it found:
- arc_length starts at 0 and increases from each point to the next;
- each increase is at least the distance between the two points (an arc is
  no shorter than its chord) and at most 1 % more (neighbours along the
  surface, not points of its other end), to the single precision of the
  file's points and arc lengths;
- a piece that ends where it started is a closed surface: its last step,
  back to the start's position, is checked as the others (the arc length
  there is the surface's length, not the start's 0).
Exits with 1, printing FAILED and the reason, on the first violation.
"""
import math
import sys


def fail(message):
    print("FAILED: " + message)
    sys.exit(1)


def main():
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader

    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(sys.argv[1])
    reader.Update()
    grid = reader.GetOutput()
    arc = grid.GetPointData().GetArray("arc_length")
    if arc is None or grid.GetNumberOfCells() == 0:
        fail(f"{sys.argv[1]}: no arc_length or no cells")
    pieces = []
    for c in range(grid.GetNumberOfCells()):
        ids = grid.GetCell(c).GetPointIds()
        if ids.GetNumberOfIds() != 2:
            fail(f"cell {c} is not a line")
        a, b = ids.GetId(0), ids.GetId(1)
        if not pieces or pieces[-1][-1] != a:
            pieces.append([a])
        pieces[-1].append(b)
    for k, piece in enumerate(pieces, start=1):
        s = [arc.GetValue(i) for i in piece]
        x = [grid.GetPoint(i) for i in piece]
        if abs(s[0]) > 1e-12:
            fail(f"piece {k} starts at arc_length {s[0]}")
        for i in range(len(piece) - 1):
            step, chord = s[i + 1] - s[i], math.dist(x[i], x[i + 1])
            # The points and the arc length are stored in single precision
            # (a relative 6e-8 of the largest coordinate or length).
            slack = 1e-6 * max(1.0, abs(s[i + 1]), *map(abs, x[i + 1]))
            if not (step > 0 and chord - slack <= step <= 1.01 * chord + slack):
                fail(f"piece {k}, point {i}: arc_length goes from {s[i]} "
                     f"to {s[i + 1]} over a chord of {chord}")
        closed = math.dist(x[0], x[-1]) < 1e-9 * max(1.0, s[-1])
        print(f"piece {k}: {'closed' if closed else 'open'}, "
              f"{len(piece)} points, arc_length increasing from 0 to "
              f"{s[-1]:.6g}, each step its chord to 1 %")


if __name__ == "__main__":
    main()
