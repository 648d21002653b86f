"""Axisymmetric CalculiX cases: finite hubs, a taper pin and a ball in its ring (tools/fem/fem.py
runs them; docs/contact-mechanics.md says what each checks).

Every case is a pair of solids of revolution about the y axis (CalculiX's axisymmetric elements:
x is the radius, y the axis), meshed as mapped blocks of quadratic quadrilaterals (CAX8R) between
an inner and an outer profile r_lo(y) <= r <= r_hi(y). The inner part is drawn oversize by a
uniform radial interference; frictionless surface-to-surface penalty contact resolves it.

The result is the radial ("bursting") force B = integral of p n_r over the contact, taken from
equilibrium rather than from the printed contact stresses (which ccx gives only at slave
integration points in contact, unweighted): cut either part by a plane through the axis; the
radial components of the contact pressure on one half are carried by the hoop stress across the
cut, so B = 2 pi * integral of sigma_theta over the part's meridian section (outer part; minus
that for the inner part). Both parts give it; the two agree to the FEM's discretisation error,
which the CSV reports. For a cylinder B is the normal force, for a taper N cos(alpha), for a
sphere integral p cos(latitude) dA.
"""

import io
import math
import tempfile

import numpy as np

E = 210000.0  # MPa
NU = 0.3
PENALTY = 1e8  # MPa/mm: 2000 times the stiffest interface (its compliance below 0.05 %)


def graded(n, bias_lo=1.0, bias_hi=1.0):
    """n + 1 points on [0, 1], finer towards 0 by bias_lo and towards 1 by bias_hi (> 1 grades)."""
    t = np.linspace(0.0, 1.0, n + 1)
    if bias_lo != 1.0 and bias_hi != 1.0:
        half = graded(n // 2, bias_lo, 1.0) * 0.5
        rest = 0.5 + graded(n - n // 2, 1.0, bias_hi) * 0.5
        return np.concatenate([half, rest[1:]])
    if bias_lo != 1.0:
        return t ** bias_lo
    if bias_hi != 1.0:
        return 1.0 - (1.0 - t) ** bias_hi
    return t


class Block:
    """Mapped CAX8R mesh of r_lo(y) <= r <= r_hi(y), y in ys (corner stations), with radial
    corner parameters ts in [0, 1]. Nodes and elements numbered from first_node / first_elem."""

    def __init__(self, r_lo, r_hi, ys, ts, first_node, first_elem):
        self.nodes = []
        self.quads = []
        ny, nt = len(ys) - 1, len(ts) - 1
        yy = np.empty(2 * ny + 1)
        yy[0::2] = ys
        yy[1::2] = 0.5 * (ys[:-1] + ys[1:])
        tt = np.empty(2 * nt + 1)
        tt[0::2] = ts
        tt[1::2] = 0.5 * (ts[:-1] + ts[1:])
        ids = {}
        nid = first_node
        for i, t in enumerate(tt):
            for j, y in enumerate(yy):
                if i % 2 == 1 and j % 2 == 1:
                    continue  # serendipity: no centre node
                lo, hi = r_lo(y), r_hi(y)
                ids[(i, j)] = nid
                self.nodes.append((nid, lo + t * (hi - lo), y))
                nid += 1
        self.ids = ids
        eid = first_elem
        self.outer_faces, self.inner_faces = [], []
        for k in range(nt):
            for m in range(ny):
                i0, im, i1 = 2 * k, 2 * k + 1, 2 * k + 2
                j0, jm, j1 = 2 * m, 2 * m + 1, 2 * m + 2
                # Counterclockwise in (r, y): face 2 is the outer profile side, face 4 the inner.
                self.quads.append((eid, [ids[(i0, j0)], ids[(i1, j0)], ids[(i1, j1)],
                                         ids[(i0, j1)], ids[(im, j0)], ids[(i1, jm)],
                                         ids[(im, j1)], ids[(i0, jm)]]))
                if k == nt - 1:
                    self.outer_faces.append(eid)
                if k == 0:
                    self.inner_faces.append(eid)
                eid += 1
        self.next_node, self.next_elem = nid, eid
        self.coords = {n: (x, y) for n, x, y in self.nodes}

    def nodes_where(self, predicate):
        return [n for n, x, y in self.nodes if predicate(x, y)]

    def areas(self):
        """Meridian area of every element (3 x 3 Gauss on the serendipity map)."""
        g = [(-math.sqrt(0.6), 5 / 9), (0.0, 8 / 9), (math.sqrt(0.6), 5 / 9)]
        corners = [(-1, -1), (1, -1), (1, 1), (-1, 1)]
        mids = [(0, -1), (1, 0), (0, 1), (-1, 0)]
        out = {}
        for eid, conn in self.quads:
            xy = np.array([self.coords[n] for n in conn])
            area = 0.0
            for xi, wx in g:
                for eta, wy in g:
                    dxi = np.zeros(8)
                    deta = np.zeros(8)
                    for k, (a, b) in enumerate(corners):
                        dxi[k] = 0.25 * a * (1 + eta * b) * (2 * xi * a + eta * b)
                        deta[k] = 0.25 * b * (1 + xi * a) * (xi * a + 2 * eta * b)
                    for k, (a, b) in enumerate(mids):
                        if a == 0:
                            dxi[4 + k] = -xi * (1 + eta * b)
                            deta[4 + k] = 0.5 * b * (1 - xi * xi)
                        else:
                            dxi[4 + k] = 0.5 * a * (1 - eta * eta)
                            deta[4 + k] = -eta * (1 + xi * a)
                    jac = np.array([dxi @ xy, deta @ xy])
                    area += wx * wy * abs(np.linalg.det(jac))
            out[eid] = area
        return out


def write_block(f, block, elset):
    f.write("*NODE\n")
    for nid, x, y in block.nodes:
        f.write(f"{nid}, {x:.15g}, {y:.15g}\n")
    f.write(f"*ELEMENT, TYPE=CAX8R, ELSET={elset}\n")
    for eid, n in block.quads:
        f.write(f"{eid}, " + ", ".join(str(v) for v in n) + "\n")


def point_stresses(dat):
    """The integration point stresses of *EL PRINT S in a .dat: {element: [[sxx, syy, szz, sxy,
    sxz, syz] per point]}."""
    stresses = {}
    for line in dat.splitlines():
        parts = line.split()
        if len(parts) != 8:
            continue
        try:
            eid = int(parts[0])
            vals = [float(v) for v in parts[2:]]
        except ValueError:
            continue
        stresses.setdefault(eid, []).append(vals)
    return stresses


def hoop_integral(dat, elset, areas):
    """2 pi * integral of sigma_theta over the meridian section of the elements in `areas` (the
    elset's), from the integration point stresses of *EL PRINT (the mean of a CAX8R's points
    times its area)."""
    stresses = point_stresses(dat)
    missing = set(areas) - set(stresses)
    if missing:
        raise RuntimeError(f"no stresses printed for {len(missing)} elements of {elset}")
    # szz: the hoop component
    return 2.0 * math.pi * sum(float(np.mean([v[2] for v in stresses[e]])) * areas[e]
                               for e in areas)


def pair_deck(inner, outer, holds, heading):
    """Deck of two blocks in frictionless contact: the inner block's outer faces are the slave
    surface, the outer block's inner faces the master."""
    f = io.StringIO()
    f.write(f"*HEADING\n{heading}\n")
    write_block(f, inner, "INNER")
    write_block(f, outer, "OUTER")
    f.write("*MATERIAL, NAME=STEEL\n*ELASTIC\n" + f"{E}, {NU}\n")
    f.write("*SOLID SECTION, ELSET=INNER, MATERIAL=STEEL\n")
    f.write("*SOLID SECTION, ELSET=OUTER, MATERIAL=STEEL\n")
    f.write("*SURFACE, NAME=SINNER, TYPE=ELEMENT\n")
    f.write("".join(f"{e}, S2\n" for e in inner.outer_faces))
    f.write("*SURFACE, NAME=SOUTER, TYPE=ELEMENT\n")
    f.write("".join(f"{e}, S4\n" for e in outer.inner_faces))
    f.write(f"*SURFACE INTERACTION, NAME=SI\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n"
            f"{PENALTY:g}, 3.\n")
    f.write("*CONTACT PAIR, INTERACTION=SI, TYPE=SURFACE TO SURFACE\nSINNER, SOUTER\n")
    f.write("*BOUNDARY\n")
    for node, dof in holds:
        f.write(f"{node}, {dof}, {dof}\n")
    f.write("*STEP, INC=200\n*STATIC\n1., 1.\n*EL PRINT, ELSET=INNER\nS\n"
            "*EL PRINT, ELSET=OUTER\nS\n*END STEP\n")
    return f.getvalue()


def holds_for(inner, outer, inner_axial_node, outer_axial_node, plane_strain_ends=None):
    """Axis nodes held radially (r = 0), one node of each part axially (rigid motion only), or
    every node of the listed end planes axially (a plane-strain slice)."""
    holds = [(n, 1) for n in inner.nodes_where(lambda x, y: x == 0.0)]
    if plane_strain_ends is None:
        holds += [(inner_axial_node, 2), (outer_axial_node, 2)]
    else:
        for block in (inner, outer):
            holds += [(n, 2) for n in block.nodes_where(
                lambda x, y: any(abs(y - e) < 1e-12 for e in plane_strain_ends))]
    return holds


def run_pair(run_ccx, inner, outer, holds, name):
    deck = pair_deck(inner, outer, holds, f"fitfeel axisymmetric case {name}")
    with tempfile.TemporaryDirectory() as work:
        dat = run_ccx(deck, work, "axisym")
    b_outer = hoop_integral(dat, "OUTER", outer.areas())
    b_inner = -hoop_integral(dat, "INNER", inner.areas())
    return b_outer, b_inner


def stations(length, n, bias_lo=1.0, bias_hi=1.0, start=0.0):
    return start + length * graded(n, bias_lo, bias_hi)


def merge(*parts):
    return np.unique(np.round(np.concatenate(parts), 12))


# Cylinder: steel shaft d = 20 mm in a hub d2 = 30 mm, 20 mm long (the paper's pair), uniform
# radial interference of 5 um (the DIN 7190 case). y = 0 is the hub's entrance face.
CYL_A, CYL_B, CYL_L, CYL_DELTA = 10.0, 15.0, 20.0, 5e-3


def cylinder_case(run_ccx, shaft_from, shaft_to, plane_strain=False, hub_diameter=2 * CYL_B):
    """Shaft over y in [shaft_from, shaft_to], hub over [0, L] with outer diameter hub_diameter.
    Axial stations are graded towards the hub's faces and the shaft's end, where the pressure
    concentrates."""
    a, b, length, delta = CYL_A, hub_diameter / 2, CYL_L, CYL_DELTA
    hub_y = stations(length, 80, 1.8, 1.8)
    shaft_parts = [hub_y[(hub_y >= shaft_from - 1e-12) & (hub_y <= shaft_to + 1e-12)]]
    if shaft_from < 0.0:
        shaft_parts.append(stations(-shaft_from, 16, 1.0, 1.8, shaft_from))
    if shaft_to > length:
        shaft_parts.append(stations(shaft_to - length, 16, 1.8, 1.0, length))
    if 0.0 < shaft_to < length:  # the shaft ends inside the hub: grade the hub towards it too
        inside = max(20, int(round(100 * shaft_to / length)))
        hub_y = merge(stations(shaft_to, inside, 1.8, 1.8),
                      stations(length - shaft_to, max(20, 100 - inside), 1.8, 1.8, shaft_to))
        shaft_parts = [hub_y[hub_y <= shaft_to + 1e-12]]
        if shaft_from < 0.0:  # and runs on outside the entrance, as a shaft being pressed in does
            shaft_parts.append(stations(-shaft_from, 16, 1.0, 1.8, shaft_from))
    shaft_y = merge(*shaft_parts)
    inner = Block(lambda y: 0.0, lambda y: a + delta, shaft_y, graded(16, 1.0, 1.6), 1, 1)
    outer = Block(lambda y: a, lambda y: b, hub_y, graded(12, 1.6, 1.0), inner.next_node,
                  inner.next_elem)
    inner_hold = inner.nodes_where(lambda x, y: x == 0.0 and abs(y - shaft_from) < 1e-12)[0]
    outer_hold = outer.nodes_where(lambda x, y: abs(x - b) < 1e-12 and y == 0.0)[0]
    holds = holds_for(inner, outer, inner_hold, outer_hold,
                      (shaft_from, shaft_to) if plane_strain else None)
    return run_pair(run_ccx, inner, outer, holds, "cylinder")


# Taper pin ISO 2339 d = 8 mm, 1:50, 40 mm long, in a 20 mm reamed hole of a d2 = 24 mm collar
# (scenarios/taper-pin.yaml); 1 um radial interference. y = 0 is the hole's small end (where the
# pin's small end sits), the hole's entrance (large end) at y = 20 mm.
TAPER_D, TAPER_C, TAPER_PIN, TAPER_HOLE, TAPER_D2, TAPER_DELTA = 8.0, 1 / 50, 40.0, 20.0, 24.0, 1e-3


def taper_case(run_ccx):
    r0, c = TAPER_D / 2, TAPER_C / 2  # radius at the small end, radius growth per mm
    hole_y = stations(TAPER_HOLE, 80, 1.8, 1.8)
    pin_y = merge(hole_y, stations(TAPER_PIN - TAPER_HOLE, 16, 1.8, 1.0, TAPER_HOLE))
    delta = TAPER_DELTA
    inner = Block(lambda y: 0.0, lambda y: r0 + c * y + delta, pin_y, graded(12, 1.0, 1.6), 1, 1)
    outer = Block(lambda y: r0 + c * y, lambda y: TAPER_D2 / 2, hole_y, graded(12, 1.6, 1.0),
                  inner.next_node, inner.next_elem)
    # The wedge pushes the pin out along +y with N sin(alpha) (about 1 % of N). A point hold would
    # carry it as a singular load whose local give grows with every refinement and, times the
    # taper, eats the interference (1 um of axial give is 1 % of it); so, as a press does, the
    # pin's large end face rests on a flat punch and the collar's small end face on a flat support
    # (both frictionless: u_y = 0 on the face, radial motion free).
    holds = [(n, 1) for n in inner.nodes_where(lambda x, y: x == 0.0)]
    holds += [(n, 2) for n in inner.nodes_where(lambda x, y: abs(y - TAPER_PIN) < 1e-12)]
    holds += [(n, 2) for n in outer.nodes_where(lambda x, y: y == 0.0)]
    return run_pair(run_ccx, inner, outer, holds, "taper")


# Spherical plain bearing GE 20 E (ISO 12240-1): sphere dk = 29 mm, inner ring width B = 16 mm
# and bore d = 20 mm, outer ring width C = 12 mm and outer diameter D = 35 mm
# (scenarios/knuckle-bearing.yaml); 1 um radial interference. y = 0 is the equator.
BALL_DK, BALL_B, BALL_BORE, RING_C, RING_D, BALL_DELTA = 29.0, 16.0, 20.0, 12.0, 35.0, 1e-3


def ball_case(run_ccx, bore):
    a, delta = BALL_DK / 2, BALL_DELTA
    ring_y = stations(RING_C, 60, 1.8, 1.8, -RING_C / 2)
    half_out = (BALL_B - RING_C) / 2
    ball_y = merge(ring_y, stations(half_out, 8, 1.0, 1.8, -BALL_B / 2),
                   stations(half_out, 8, 1.8, 1.0, RING_C / 2))
    r_in = (lambda y: BALL_BORE / 2) if bore else (lambda y: 0.0)
    inner = Block(r_in, lambda y: math.sqrt((a + delta) ** 2 - y * y), ball_y,
                  graded(10 if bore else 14, 1.0, 1.6), 1, 1)
    outer = Block(lambda y: math.sqrt(a * a - y * y), lambda y: RING_D / 2, ring_y,
                  graded(10, 1.6, 1.0), inner.next_node, inner.next_elem)
    inner_hold = inner.nodes_where(lambda x, y: abs(y + BALL_B / 2) < 1e-12)[0]
    outer_hold = outer.nodes_where(lambda x, y: abs(x - RING_D / 2) < 1e-12 and
                                   abs(y + RING_C / 2) < 1e-12)[0]
    return run_pair(run_ccx, inner, outer, holds_for(inner, outer, inner_hold, outer_hold), "ball")


def cases():
    """(name, callable(run_ccx) -> (B from the outer part, from the inner part)); the C++ tests
    build the same geometry from the name (docs/contact-mechanics.md, section 6)."""
    return [
        ("cylinder-plane-strain", lambda r: cylinder_case(r, 0.0, CYL_L, plane_strain=True)),
        ("cylinder-flush", lambda r: cylinder_case(r, 0.0, CYL_L)),
        ("cylinder-through", lambda r: cylinder_case(r, -10.0, CYL_L + 10.0)),
        # A shaft 20 mm long pressed in part way: the rest of it still outside the entrance.
        ("cylinder-half-engaged", lambda r: cylinder_case(r, -10.0, 10.0)),
        ("cylinder-entry-0.5mm", lambda r: cylinder_case(r, -19.5, 0.5)),
        ("cylinder-entry-1mm", lambda r: cylinder_case(r, -19.0, 1.0)),
        ("cylinder-entry-2mm", lambda r: cylinder_case(r, -18.0, 2.0)),
        ("cylinder-quarter-engaged", lambda r: cylinder_case(r, -15.0, 5.0)),
        ("cylinder-three-quarters-engaged", lambda r: cylinder_case(r, -5.0, 15.0)),
        ("cylinder-thin-hub-half-engaged",
         lambda r: cylinder_case(r, -10.0, 10.0, hub_diameter=24.0)),
        ("cylinder-thick-hub-half-engaged",
         lambda r: cylinder_case(r, -10.0, 10.0, hub_diameter=40.0)),
        ("taper", taper_case),
        ("ball-solid", lambda r: ball_case(r, bore=False)),
        ("ball-bore", lambda r: ball_case(r, bore=True)),
    ]


def axisymmetric(out_csv, run_ccx, only=None):
    rows = []
    for name, run in cases():
        if only and name not in only:
            continue
        b_outer, b_inner = run(run_ccx)
        rows.append((name, 0.5 * (b_outer + b_inner), abs(b_outer - b_inner) /
                     (0.5 * abs(b_outer + b_inner))))
        print(name, b_outer, b_inner, flush=True)
    with open(out_csv, "w") as out:
        out.write("# CalculiX axisymmetric (CAX8R), steel E = 210 GPa, nu = 0.3, frictionless "
                  "penalty contact; bursting force B = integral of p n_r dA from the hoop stress of "
                  "either part (the mean; their relative difference beside it); "
                  "regenerate: /usr/bin/python3 tools/fem/fem.py axisymmetric <this file>\n")
        out.write("case,bursting_force_N,inner_outer_difference\n")
        for name, force, diff in rows:
            out.write(f"{name},{force:.6g},{diff:.3g}\n")
    return rows
