"""3-D CalculiX case: a parallel key pressed between two keyway walls (surfaces/planar's law).

The planar law (surfaces/planar/planar_law.h) takes a key of width b pressed over its flank height
h and engaged length L between two walls with an interference delta per face: the key a block
compressed across its width in plane strain (free to bulge in height), each wall a half-space
loaded over the strip h x L, p = 2 delta / (c_key + 2 c_wall). This case is that contact without
its closed forms: the key an elastic block b x h x L, each wall an elastic body far larger than the
strip, frictionless penalty contact resolving the overlap.

An eighth is meshed: the planes x = 0 (the key's middle), y = 0 (the middle of the engaged length)
and z = 0 (the middle of the flank height) are symmetry planes. The key is x in [0, b/2], y in
[0, L/2], z in [0, h/2], drawn delta wider per face; the wall fills x in [b/2, b/2 + D],
y in [0, D], z in [0, D] with D = 200 mm and its far face x = b/2 + D held (a half-space cut at
D: what lies beyond carries about strip / D of the compliance, under 2 % here). Quadratic
hexahedra (C3D20R) graded towards the strip's edges. The flank's normal force is the far face's
reaction, times 4 (the quarter of one flank).
"""

import io
import math
import tempfile

import numpy as np

import axisymmetric as axi
from solid import print_totals, quadratic_cell, with_midpoints, write_csv

E = axi.E
NU = axi.NU
PENALTY = axi.PENALTY
WIDTH, HEIGHT = 8.0, 2.6   # DIN 6885-1 8 x 7 key, its flat flank height in the hub keyway (mm)
FAR = 200.0                # the wall's extent (mm)
DELTA = 5e-3               # interference per face (mm)
# (case, engaged length L in mm, the key's Young's modulus over the walls'): the key-parallel
# scenario at full engagement and a quarter of it, and a rigid key (1000 times stiffer), whose
# flank force is the wall's alone: delta h L / c_wall, the law's lateral stiffness per flank.
KEY_CASES = [("key-8x2.6-L40", 40.0, 1.0), ("key-8x2.6-L10", 10.0, 1.0),
             ("key-rigid-8x2.6-L40", 40.0, 1000.0)]


class BoxGrid:
    """Quadratic serendipity nodes of a structured hexahedral grid on corner stations xs, ys, zs."""

    def __init__(self, xs, ys, zs, first_node):
        self.xs, self.ys, self.zs = xs, ys, zs
        self.ids = {}
        self.nodes = []
        nid = first_node
        for i, x in enumerate(with_midpoints(xs)):
            for j, y in enumerate(with_midpoints(ys)):
                for k, z in enumerate(with_midpoints(zs)):
                    if (i % 2) + (j % 2) + (k % 2) > 1:
                        continue  # serendipity: edge midpoints only
                    self.ids[(i, j, k)] = nid
                    self.nodes.append((nid, x, y, z))
                    nid += 1
        self.next_node = nid

    def cells(self, first_elem):
        """(element id, node ids in ccx's C3D20 order, (i, j, k) cell index) of every cell."""
        out = []
        g = self.ids
        eid = first_elem
        for i in range(len(self.xs) - 1):
            for j in range(len(self.ys) - 1):
                for k in range(len(self.zs) - 1):
                    i0, im, i1 = 2 * i, 2 * i + 1, 2 * i + 2
                    j0, jm, j1 = 2 * j, 2 * j + 1, 2 * j + 2
                    corners = [(i0, j0), (i1, j0), (i1, j1), (i0, j1)]
                    mids = [(im, j0), (i1, jm), (im, j1), (i0, jm)]
                    out.append((eid, quadratic_cell(g, corners, mids, k), (i, j, k)))
                    eid += 1
        return out


def key_deck(length, key_stiffening=1.0):
    """The eighth model's deck for an engaged length `length` (mm), the key's Young's modulus
    `key_stiffening` times the walls'."""
    b2, h2, l2 = WIDTH / 2, HEIGHT / 2, length / 2
    # Near the strip: its edges graded (the pressure concentrates there); beyond: growing to FAR.
    ys = np.unique(np.concatenate([axi.stations(l2, 10, bias_hi=1.5),
                                   l2 + (FAR - l2) * axi.graded(10, bias_lo=2.5)]))
    zs = np.unique(np.concatenate([axi.stations(h2, 4, bias_hi=1.5),
                                   h2 + (FAR - h2) * axi.graded(12, bias_lo=3.0)]))
    xs = b2 + FAR * axi.graded(14, bias_lo=3.0)
    key = BoxGrid(axi.stations(b2, 4), axi.stations(l2, 10, bias_hi=1.5),
                  axi.stations(h2, 4, bias_hi=1.5), 1)
    wall = BoxGrid(xs, ys, zs, key.next_node)
    key_cells = key.cells(1)
    wall_cells = wall.cells(len(key_cells) + 1)
    f = io.StringIO()
    f.write("*HEADING\nfitfeel key between two walls\n*NODE\n")
    scale = (b2 + DELTA) / b2  # the key drawn DELTA wider per face
    for nid, x, y, z in key.nodes:
        f.write(f"{nid}, {x * scale:.15g}, {y:.15g}, {z:.15g}\n")
    for nid, x, y, z in wall.nodes:
        f.write(f"{nid}, {x:.15g}, {y:.15g}, {z:.15g}\n")
    for name, cells in (("KEY", key_cells), ("WALL", wall_cells)):
        f.write(f"*ELEMENT, TYPE=C3D20R, ELSET={name}\n")
        for eid, conn, _ in cells:
            f.write(f"{eid}, " + ", ".join(str(v) for v in conn[:15]) + ",\n" +
                    ", ".join(str(v) for v in conn[15:]) + "\n")
    f.write("*MATERIAL, NAME=STEEL\n*ELASTIC\n" + f"{E}, {NU}\n")
    f.write("*MATERIAL, NAME=KEYSTEEL\n*ELASTIC\n" + f"{E * key_stiffening}, {NU}\n")
    f.write("*SOLID SECTION, ELSET=KEY, MATERIAL=KEYSTEEL\n*SOLID SECTION, ELSET=WALL, "
            "MATERIAL=STEEL\n")
    # ccx's C3D20 faces: S4 the cell's x-max face, S6 its x-min face.
    f.write("*SURFACE, NAME=SKEY, TYPE=ELEMENT\n")
    f.write("".join(f"{c[0]}, S4\n" for c in key_cells if c[2][0] == len(key.xs) - 2))
    f.write("*SURFACE, NAME=SWALL, TYPE=ELEMENT\n")
    f.write("".join(f"{c[0]}, S6\n" for c in wall_cells if c[2][0] == 0))
    f.write(f"*SURFACE INTERACTION, NAME=SI\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n"
            f"{PENALTY:g}, 3.\n")
    f.write("*CONTACT PAIR, INTERACTION=SI, TYPE=SURFACE TO SURFACE\nSKEY, SWALL\n")
    f.write("*BOUNDARY\n")
    far_i = 2 * (len(wall.xs) - 1)
    far = []
    for grid, is_key in ((key, True), (wall, False)):
        for (i, j, k), nid in sorted(grid.ids.items()):
            if is_key and i == 0:
                f.write(f"{nid}, 1, 1\n")
            if j == 0:
                f.write(f"{nid}, 2, 2\n")
            if k == 0:
                f.write(f"{nid}, 3, 3\n")
            if not is_key and i == far_i:
                f.write(f"{nid}, 1, 3\n")
                far.append(nid)
    f.write("*NSET, NSET=FAR\n" + "\n".join(str(n) for n in far) + "\n")
    f.write("*STEP, INC=200\n*STATIC\n1., 1.\n*NODE PRINT, NSET=FAR, TOTALS=ONLY\nRF\n*END STEP\n")
    return f.getvalue()


def key(out_csv, run_ccx, only=()):
    rows = []
    for name, length, stiffening in KEY_CASES:
        if only and name not in only:
            continue
        with tempfile.TemporaryDirectory() as work:
            dat = run_ccx(key_deck(length, stiffening), work, "key")
        force = 4.0 * abs(print_totals(dat)[0])  # the quarter of one flank
        rows.append((name, WIDTH, HEIGHT, length, 1e3 * DELTA, stiffening, force))
        print(name, force, flush=True)
    write_csv(out_csv, "a steel key pressed between two steel walls far larger than its flank "
              "strip, interference per face delta, frictionless; normal force on one flank; "
              "regenerate: /usr/bin/python3 tools/fem/fem.py key <this file>",
              "case,width_mm,height_mm,length_mm,delta_um,key_stiffening,flank_force_N", rows,
              model="eighth model")
    return rows
