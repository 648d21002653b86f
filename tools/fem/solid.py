"""3-D CalculiX cases: bent and lobed shafts in a straight bore, and a spherical plain bearing
loaded across its clearance (tools/fem/fem.py runs them; docs/contact-mechanics.md and
docs/friction.md say what each checks).

The paper's pair, a solid steel shaft d1 = 20 mm flush in a hub d2 = 30 mm, both L = 20 mm long,
with the shaft's rim drawn at radius a + delta(theta, z) over a bore of radius a:

    delta(theta, z) = delta0 + h (2 z / L)^2 cos(n theta),   -L/2 <= z <= L/2,

a uniform interference delta0 and, for n = 1, a shaft whose axis is bent in a parabola of
sagitta h (ends h off the middle), for n >= 2 lobes growing from the middle to the ends. Where
contact is partial, the sections carry loads that change along the axis: for n = 1 net radial
loads that balance only over the length. How the parts carry them (in the model, each section on
its own but for the breathing mode; in 3-D, the parts' deformation along the axis) is what these
cases check. The loads are self-equilibrated, so the answer does not depend on how the parts are
held: each is held only against rigid motion, the shaft floats radially.

A quarter is meshed (0 <= theta <= pi, 0 <= z <= L/2: the field is symmetric about the planes y = 0
and z = 0, which become symmetry planes), in quadratic hexahedra (C3D20R; the shaft's core in
quadratic wedges, C3D15) on a polar grid graded towards the interface and the free ends.
Frictionless surface-to-surface penalty contact resolves the overlap.

The normal force N = integral of p dA comes from equilibrium, as in axisymmetric.py: a plane
through the axis at angle alpha cuts the hub in two walls; the half on one side balances the
contact pressure's component normal to the plane with the hoop forces W in its walls, and
averaged over alpha this gives N = integral of W(alpha) d alpha = integral of sigma_theta dr dtheta dz
over the hub. The uniform case is also computed in axisymmetry (cylinder-flush): the two meshes'
agreement is reported beside it.
"""

import io
import math
import tempfile

import numpy as np

import axisymmetric as axi

E = axi.E
NU = axi.NU
PENALTY = axi.PENALTY
A = 10.0     # interface radius, mm
B = 15.0     # hub outer radius, mm
LENGTH = 20.0  # hub and shaft, mm


def with_midpoints(v):
    """Corner stations with their midpoints between: a quadratic grid's node stations."""
    return np.concatenate([np.ravel(np.column_stack([v[:-1], 0.5 * (v[:-1] + v[1:])])), v[-1:]])


def quadratic_cell(ids, corners, mids, k):
    """Node ids of a quadratic cell in ccx's order: the cross-section's corners in layer k's
    lower and upper plane, its midsides in both, then the corners' edges across the layer; `ids`
    maps the node indices (i, j, k) of the midpoint-refined grid to node ids."""
    k0, km, k1 = 2 * k, 2 * k + 1, 2 * k + 2
    return [ids[(a, b, kz)] for points, kz in ((corners, k0), (corners, k1), (mids, k0),
                                               (mids, k1), (corners, km))
            for a, b in points]


class PolarGrid:
    """Quadratic serendipity nodes of r in radii, theta in angles, z in zs (corner stations), in a
    polar cell grid; a grid starting at r = 0 has one node per axial station on the axis. With a
    `profile`, radii are parameters t in [0, 1] and a node lies at r = profile(t, z) (a ring
    between two surfaces of revolution)."""

    def __init__(self, radii, angles, zs, first_node, profile=None):
        self.radii, self.angles, self.zs, self.profile = radii, angles, zs, profile
        rr, tt, zz = with_midpoints(radii), with_midpoints(angles), with_midpoints(zs)
        self.ids = {}
        self.nodes = []  # (id, x, y, z)
        nid = first_node
        axis = {}
        for i, r in enumerate(rr):
            for j, t in enumerate(tt):
                for k, z in enumerate(zz):
                    if (i % 2) + (j % 2) + (k % 2) > 1:
                        continue  # serendipity: edge midpoints only
                    if profile is None and r == 0.0:
                        if j % 2 == 1:
                            continue  # collapsed edge
                        if k not in axis:
                            axis[k] = nid
                            self.nodes.append((nid, 0.0, 0.0, z))
                            nid += 1
                        self.ids[(i, j, k)] = axis[k]
                        continue
                    radius = r if profile is None else profile(r, z)
                    self.ids[(i, j, k)] = nid
                    self.nodes.append((nid, radius * math.cos(t), radius * math.sin(t), z))
                    nid += 1
        self.next_node = nid

    def cells(self, first_elem):
        """(element id, type, node ids, (i, j, k) cell index) of every cell."""
        out = []
        eid = first_elem
        g = self.ids
        for i in range(len(self.radii) - 1):
            for j in range(len(self.angles) - 1):
                for k in range(len(self.zs) - 1):
                    i0, im, i1 = 2 * i, 2 * i + 1, 2 * i + 2
                    j0, jm, j1 = 2 * j, 2 * j + 1, 2 * j + 2
                    # The cross-section's corners and midside nodes (a wedge at the axis).
                    if self.profile is None and self.radii[i] == 0.0:
                        etype = "C3D15"
                        corners = [(i0, j0), (i1, j0), (i1, j1)]
                        mids = [(im, j0), (i1, jm), (im, j1)]
                    else:
                        etype = "C3D20R"
                        corners = [(i0, j0), (i1, j0), (i1, j1), (i0, j1)]
                        mids = [(im, j0), (i1, jm), (im, j1), (i0, jm)]
                    out.append((eid, etype, quadratic_cell(g, corners, mids, k), (i, j, k)))
                    eid += 1
        return out


def meshes(columns, shaft_rings, hub_rings, axial):
    """The shaft and hub grids of the quarter model, graded towards the interface and the ends."""
    angles = np.linspace(0.0, math.pi, columns + 1)
    zs = axi.stations(LENGTH / 2, axial, bias_hi=1.5)
    shaft = PolarGrid(A * axi.graded(shaft_rings, bias_hi=1.5), angles, zs, 1)
    hub = PolarGrid(A + (B - A) * axi.graded(hub_rings, bias_lo=1.5), angles, zs, shaft.next_node)
    return shaft, hub


def pair_deck(inner, outer, inner_radius=lambda x, y, z: 1.0):
    """The deck's model part for two grids in frictionless contact (the inner grid's outer face
    the slave surface, the outer grid's inner face the master), with the symmetry planes y = 0
    and z = 0: nodes (the inner grid's scaled radially by inner_radius(x, y, z)), elements,
    material, contact, and a *BOUNDARY block left open for the caller's holds. Returns the deck
    (a StringIO the caller appends its holds and step to) and both grids' cells."""
    inner_cells = inner.cells(1)
    outer_cells = outer.cells(len(inner_cells) + 1)
    f = io.StringIO()
    f.write("*HEADING\nfitfeel 3-D case\n*NODE\n")
    for grid, scale in ((inner, inner_radius), (outer, lambda x, y, z: 1.0)):
        for nid, x, y, z in grid.nodes:
            k = scale(x, y, z)
            f.write(f"{nid}, {x * k:.15g}, {y * k:.15g}, {z:.15g}\n")
    for name, cells in (("INNER", inner_cells), ("OUTER", outer_cells)):
        for etype in ("C3D15", "C3D20R"):
            group = [c for c in cells if c[1] == etype]
            if not group:
                continue
            f.write(f"*ELEMENT, TYPE={etype}, ELSET={name}\n")
            for eid, _, conn, _ in group:
                # 16 ids per line at most in a deck: continue on a second line.
                head = ", ".join(str(v) for v in conn[:15])
                tail = ", ".join(str(v) for v in conn[15:])
                f.write(f"{eid}, {head}" + (f",\n{tail}\n" if tail else "\n"))
    f.write("*MATERIAL, NAME=STEEL\n*ELASTIC\n" + f"{E}, {NU}\n")
    f.write("*SOLID SECTION, ELSET=INNER, MATERIAL=STEEL\n*SOLID SECTION, ELSET=OUTER, "
            "MATERIAL=STEEL\n")
    face = len(inner.radii) - 2
    f.write("*SURFACE, NAME=SINNER, TYPE=ELEMENT\n")
    f.write("".join(f"{c[0]}, S4\n" for c in inner_cells if c[3][0] == face))
    f.write("*SURFACE, NAME=SOUTER, TYPE=ELEMENT\n")
    f.write("".join(f"{c[0]}, S6\n" for c in outer_cells if c[3][0] == 0))
    f.write(f"*SURFACE INTERACTION, NAME=SI\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n"
            f"{PENALTY:g}, 3.\n")
    f.write("*CONTACT PAIR, INTERACTION=SI, TYPE=SURFACE TO SURFACE\nSINNER, SOUTER\n")
    f.write("*BOUNDARY\n")
    for grid in (inner, outer):
        last_j = 2 * (len(grid.angles) - 1)
        for (i, j, k), nid in sorted(grid.ids.items()):
            if j in (0, last_j):
                f.write(f"{nid}, 2, 2\n")
            if k == 0:
                f.write(f"{nid}, 3, 3\n")
    return f, inner_cells, outer_cells


def deck(delta, columns, shaft_rings, hub_rings, axial):
    """A shaft drawn at A + delta(theta, z) in the hub: the hub held in x at one node, the shaft
    free in x (the contact holds it)."""
    shaft, hub = meshes(columns, shaft_rings, hub_rings, axial)

    def rim(x, y, z):  # the section scaled radially: rim exact
        return 1.0 + delta(math.atan2(y, x), z) / A if (x, y) != (0.0, 0.0) else 1.0
    f, _, hub_cells = pair_deck(shaft, hub, rim)
    f.write(f"{hub.ids[(2 * (len(hub.radii) - 1), 0, 0)]}, 1, 1\n")
    f.write("*STEP, INC=200\n*STATIC\n1., 1.\n*EL PRINT, ELSET=OUTER\nS\n*END STEP\n")
    return f.getvalue(), hub, hub_cells


def hoop_integral(dat, grid, cells):
    """Integral of sigma_theta dr dtheta dz over the hub's quarter: per element the mean of its
    integration points' hoop stress (taken at the element's mid angle) times the cell's extent."""
    stress = axi.point_stresses(dat)
    total = 0.0
    for eid, _, _, (i, j, k) in cells:
        if eid not in stress:
            raise RuntimeError(f"no stresses printed for hub element {eid}")
        t = 0.5 * (grid.angles[j] + grid.angles[j + 1])
        c, s = math.cos(t), math.sin(t)
        sxx, syy, _, sxy = (np.mean([v[q] for v in stress[eid]]) for q in range(4))
        hoop = sxx * s * s + syy * c * c - 2.0 * sxy * s * c
        total += hoop * ((grid.radii[i + 1] - grid.radii[i]) * (grid.angles[j + 1] - grid.angles[j])
                         * (grid.zs[k + 1] - grid.zs[k]))
    return 4.0 * total  # the four quarters


# (case, order n, delta0 um, h um) of delta0 + h (2 z / L)^2 cos(n theta): the uniform press fit
# (the axisymmetric cylinder-flush case in 3-D); a bent shaft (n = 1, h the sagitta) in full
# contact (its normal force is the uniform one's: the bend's order-1 load adds nothing to the
# mean), in partial contact, and on a clearance; an oval (n = 2) and a three-lobed (n = 3) shaft
# whose lobes grow from the middle to the ends, round and in full contact in the middle, touching
# in bands at the ends (full contact there would need delta0 >= (K_n / K_0) h = 1.16 and 3.1 um).
CASES = [
    ("uniform-flush", 1, 5.0, 0.0),
    ("bent-full", 1, 5.0, 2.0),
    ("bent-partial", 1, 1.0, 4.0),
    ("bent-clearance", 1, -1.0, 6.0),
    ("oval-ends-partial", 2, 0.5, 8.0),
    ("lobed3-ends-partial", 3, 1.0, 4.0),
]

MESH = dict(columns=36, shaft_rings=8, hub_rings=5, axial=10)


def solid(out_csv, run_ccx, only=()):
    rows = []
    for name, n, d0, h in CASES:
        if only and name not in only:
            continue
        delta = lambda t, z, n=n, d0=d0, h=h: 1e-3 * (d0 + h * (2.0 * z / LENGTH) ** 2 *
                                                       math.cos(n * t))
        text, hub, cells = deck(delta, **MESH)
        with tempfile.TemporaryDirectory() as work:
            dat = run_ccx(text, work, "solid")
        force = hoop_integral(dat, hub, cells)
        rows.append((name, n, d0, h, force))
        print(name, force, flush=True)
    write_csv(out_csv, "steel shaft d1 = 20 mm flush in a hub d2 = 30 mm, L = 20 mm, rim "
              "interference delta0 + h (2z/L)^2 cos(n theta), frictionless; normal force from the "
              "hub's hoop stress; regenerate: /usr/bin/python3 tools/fem/fem.py solid <this file>",
              "case,order,delta0_um,amplitude_um,normal_force_N", rows)
    return rows


def write_csv(out_csv, about, header, rows, model="quarter model"):
    """The cases' rows under a comment line saying what they are and how to regenerate them."""
    with open(out_csv, "w") as out:
        out.write(f"# CalculiX 3-D (C3D20R, {model}), {about}\n{header}\n")
        for r in rows:
            out.write(",".join(f"{v:.6g}" if isinstance(v, float) else str(v) for v in r) + "\n")


# GE 20 E (ISO 12240-1) loaded across its radial clearance: the inner ring's sphere (dk = 29 mm,
# 16 mm wide, 20 mm bore) in the outer ring (12 mm wide, 35 mm outer diameter), a radial
# clearance of 30 um (the middle of h7 in E7's 20-41 um). The outer ring sits in a rigid housing
# (its outer surface held), the inner ring on a rigid shaft (its bore moved by the clearance plus
# the approach and otherwise held: both rings fixed to what holds them, as a fit holds them; with
# the bore free along the axis the loads are 3.7 to 4.6 % lower); the radial load is the bore's
# reaction.
BALL_RADIUS = 14.5
CLEARANCE = 0.030
BEARING_MESH = dict(columns=36, ball_rings=6, ring_rings=4, ball_axial=10, ring_axial=8)
# (case, approach um, changes to the mesh or the bands' half widths): the law's cases, and two
# checks of the 2 um one, a finer mesh and both bands widened to +-10 mm (the rings' free edges
# moved away from the patch).
BEARING_CASES = [
    ("bearing-approach-1um", 1.0, {}),
    ("bearing-approach-2um", 2.0, {}),
    ("bearing-approach-3um", 3.0, {}),
    ("bearing-fine-mesh-2um", 2.0,
     dict(columns=48, ball_rings=8, ring_rings=6, ball_axial=14, ring_axial=12)),
    ("bearing-wide-bands-2um", 2.0, dict(ball_half=10.0, ring_half=10.0, ball_axial=12,
                                         ring_axial=12)),
]


def bearing_deck(approach, columns, ball_rings, ring_rings, ball_axial, ring_axial, ball_half=8.0,
                 ring_half=6.0):
    """Quarter of the loaded bearing (symmetry planes y = 0 and z = 0), elements graded towards
    the contact at theta = 0 and towards the contact surfaces; the ball's band +-ball_half (GE 20
    E: B / 2 = 8 mm), the outer ring's +-ring_half (C / 2 = 6 mm)."""
    r1, r2 = BALL_RADIUS, BALL_RADIUS + CLEARANCE
    angles = math.pi * axi.graded(columns, bias_lo=1.6)
    ball = PolarGrid(axi.graded(ball_rings, bias_hi=1.5), angles,
                     axi.stations(ball_half, ball_axial),
                     1, profile=lambda t, z: 10.0 + t * (math.sqrt(r1 * r1 - z * z) - 10.0))
    ring = PolarGrid(axi.graded(ring_rings, bias_lo=1.5), angles,
                     axi.stations(ring_half, ring_axial),
                     ball.next_node,
                     profile=lambda t, z: math.sqrt(r2 * r2 - z * z) + t * (
                         17.5 - math.sqrt(r2 * r2 - z * z)))
    f, _, _ = pair_deck(ball, ring)
    outer = 2 * (len(ring.radii) - 1)
    f.write("".join(f"{nid}, 1, 3\n" for (i, _, _), nid in sorted(ring.ids.items())
                    if i == outer))
    bore = sorted({nid for (i, _, _), nid in ball.ids.items() if i == 0})
    f.write("*NSET, NSET=BORE\n" + "\n".join(str(n) for n in bore) + "\n")
    f.write("*STEP, INC=200\n*STATIC\n1., 1.\n*BOUNDARY\n")
    shift = CLEARANCE + 1e-3 * approach
    f.write("".join(f"{n}, 1, 1, {shift:.12g}\n{n}, 2, 3, 0.\n" for n in bore))
    f.write("*NODE PRINT, NSET=BORE, TOTALS=ONLY\nRF\n*END STEP\n")
    return f.getvalue()


def print_totals(dat):
    """(fx, fy, fz) of the *NODE PRINT ..., TOTALS=ONLY that closes a deck's .dat."""
    return [float(v) for v in [line for line in dat.splitlines() if line.strip()][-1].split()]


def bearing(out_csv, run_ccx, only=()):
    rows = []
    for name, approach, changes in BEARING_CASES:
        if only and name not in only:
            continue
        with tempfile.TemporaryDirectory() as work:
            dat = run_ccx(bearing_deck(approach, **{**BEARING_MESH, **changes}), work, "bearing")
        load = 4.0 * print_totals(dat)[0]  # the quarter's reaction
        rows.append((name, 1e3 * CLEARANCE, approach, load))
        print(name, load, flush=True)
    write_csv(out_csv, "GE 20 E: sphere 29 mm, radial clearance 30 um, outer ring held in a rigid "
              "housing, inner ring held on a rigid shaft moved by the clearance plus the approach; "
              "frictionless; radial load = the bore's reaction; regenerate: /usr/bin/python3 "
              "tools/fem/fem.py bearing <this file>", "case,clearance_um,approach_um,radial_load_N",
              rows)
    return rows
