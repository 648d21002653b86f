#!/usr/bin/python3
"""FEM reference for fitfeel's elastic contact model, computed with CalculiX (ccx).

Writes CalculiX input decks for a shaft-in-hub cross-section (2-D plane stress, quadratic
elements on a polar mesh), runs ccx, parses its output and writes small CSV files that the C++
tests compare the model against (docs/contact-mechanics.md says what each case checks).

  /usr/bin/python3 tools/fem/fem.py harmonic OUT.csv    stiffness per circumferential harmonic
  /usr/bin/python3 tools/fem/fem.py contact OUT.csv     contact cases (ccx surface-to-surface
                                                        contact from overlapping geometry)
  /usr/bin/python3 tools/fem/fem.py axisymmetric OUT.csv  finite hubs, a taper pin, a ball in its ring
                                                        (tools/fem/axisymmetric.py)
  /usr/bin/python3 tools/fem/fem.py solid OUT.csv       bent and lobed shafts in 3-D
                                                        (tools/fem/solid.py; 1 to 40 minutes a
                                                        case)
  /usr/bin/python3 tools/fem/fem.py bearing OUT.csv     a loaded plain bearing in 3-D
                                                        (tools/fem/solid.py; minutes a case)
  /usr/bin/python3 tools/fem/fem.py key OUT.csv         a parallel key between two keyway walls
                                                        in 3-D (tools/fem/key.py; a minute a
                                                        case)
  /usr/bin/python3 tools/fem/fem.py all DIR             all six, into DIR/harmonic.csv,
                                                        DIR/contact.csv, DIR/axisymmetric.csv,
                                                        DIR/solid.csv, DIR/bearing.csv,
                                                        DIR/key.csv
  /usr/bin/python3 tools/fem/fem.py compare NEW OLD      every number of two such CSV files
                                                        within 0.5 % (of 1e-3 for smaller ones;
                                                        exit 1 otherwise)

Units inside the decks: mm, N, MPa. Needs ccx on PATH (Debian: calculix-ccx) and numpy
(Debian: python3-numpy, loaded by /usr/bin/python3).
"""

import io
import math
import os
import subprocess
import sys
import tempfile

import numpy as np

import axisymmetric as axi
import key
import solid

# The reference section: solid steel shaft d1 = 20 mm in a steel hub d2 = 30 mm (the paper's
# case-study pair), one millimetre thick (plane stress: results per unit thickness scale).
D1 = 20.0
D2 = 30.0
E = 210000.0  # MPa
NU = 0.3
THICKNESS = 1.0


class Mesh:
    """Quadratic polar mesh of a disc (inner radius 0) or a ring, nodes numbered from `first`."""

    def __init__(self, r_in, r_out, radial, columns, first_node, first_elem, radial_bias=1.0):
        self.nodes = []  # (id, x, y)
        self.quads = []  # (id, 8 node ids), CPS8 ordering
        self.tris = []   # (id, 6 node ids), CPS6 ordering
        self.columns = columns
        ids = {}
        nid = first_node
        # Radii of corner rings, graded towards the interface when radial_bias != 1.
        t = np.linspace(0.0, 1.0, radial + 1)
        if r_in == 0.0:
            t = 1.0 - (1.0 - t) ** radial_bias if radial_bias != 1.0 else t
        else:
            t = t ** radial_bias if radial_bias != 1.0 else t
        radii = r_in + (r_out - r_in) * t
        half = np.empty(2 * radial + 1)
        half[0::2] = radii
        half[1::2] = 0.5 * (radii[:-1] + radii[1:])
        self.radii = radii
        for i, r in enumerate(half):
            if r == 0.0:
                ids[(i, 0)] = nid
                self.nodes.append((nid, 0.0, 0.0))
                nid += 1
                continue
            for j in range(2 * columns):
                if i % 2 == 1 and j % 2 == 1:
                    continue  # serendipity elements have no centre node
                th = math.pi * j / columns
                ids[(i, j)] = nid
                self.nodes.append((nid, r * math.cos(th), r * math.sin(th)))
                nid += 1
        self.ids = ids
        eid = first_elem
        n2 = 2 * columns
        for k in range(radial):
            for c in range(columns):
                j0, j1, jm = 2 * c, (2 * c + 2) % n2, 2 * c + 1
                i0, i1, im = 2 * k, 2 * k + 2, 2 * k + 1
                if r_in == 0.0 and k == 0:
                    centre = ids[(0, 0)]
                    self.tris.append((eid, [centre, ids[(i1, j0)], ids[(i1, j1)],
                                            ids[(im, j0)], ids[(i1, jm)], ids[(im, j1)]]))
                else:
                    self.quads.append((eid, [ids[(i0, j0)], ids[(i1, j0)], ids[(i1, j1)],
                                             ids[(i0, j1)], ids[(im, j0)], ids[(i1, jm)],
                                             ids[(im, j1)], ids[(i0, jm)]]))
                eid += 1
        self.next_node = nid
        self.next_elem = eid
        self.outer_ring = 2 * radial

    def ring_nodes(self, i):
        """Node ids of radial index i in angular order, with their angles."""
        out = []
        for j in range(2 * self.columns):
            if (i, j) in self.ids:
                out.append((self.ids[(i, j)], math.pi * j / self.columns))
        return out

    def boundary_elements(self, outer):
        """(element id, face label, mid angle) of the elements on the outer or inner boundary.
        Elements are numbered ring by ring; a quad's face 2 is its outer edge, face 4 its inner
        one, and a centre triangle's face 2 its outer edge."""
        first = min([e for e, _ in self.tris] + [e for e, _ in self.quads])
        k = len(self.radii) - 2 if outer else 0
        face = "P2" if outer else "P4"
        return [(first + k * self.columns + c, face, 2 * math.pi * (c + 0.5) / self.columns)
                for c in range(self.columns)]


def write_mesh(f, mesh, elset):
    f.write("*NODE\n")
    for nid, x, y in mesh.nodes:
        f.write(f"{nid}, {x:.12g}, {y:.12g}\n")
    if mesh.tris:
        f.write(f"*ELEMENT, TYPE=CPS6, ELSET={elset}\n")
        for eid, n in mesh.tris:
            f.write(f"{eid}, " + ", ".join(str(v) for v in n) + "\n")
    if mesh.quads:
        f.write(f"*ELEMENT, TYPE=CPS8, ELSET={elset}\n")
        for eid, n in mesh.quads:
            f.write(f"{eid}, " + ", ".join(str(v) for v in n) + "\n")


def material(f, elsets):
    f.write("*MATERIAL, NAME=STEEL\n*ELASTIC\n" + f"{E}, {NU}\n")
    for s in elsets:
        f.write(f"*SOLID SECTION, ELSET={s}, MATERIAL=STEEL\n{THICKNESS}\n")


def run_ccx(deck_text, workdir, name):
    path = os.path.join(workdir, name + ".inp")
    with open(path, "w") as f:
        f.write(deck_text)
    proc = subprocess.run(["ccx", "-i", name], cwd=workdir, capture_output=True, text=True,
                          env=dict(os.environ, OMP_NUM_THREADS="1"))
    if proc.returncode != 0 or "Job finished" not in proc.stdout:
        sys.stderr.write(proc.stdout[-3000:] + proc.stderr[-2000:])
        raise RuntimeError(f"ccx failed on {name}")
    with open(os.path.join(workdir, name + ".dat")) as f:
        return f.read()


def parse_blocks(dat, keyword):
    """Every block of the .dat whose header contains `keyword`: list of {id: [values]}."""
    blocks = []
    current = None
    for line in dat.splitlines():
        s = line.strip()
        if not s:
            continue
        if keyword in s and "for set" in s or keyword in s and "time" in s:
            current = {}
            blocks.append(current)
            continue
        if current is None:
            continue
        parts = s.split()
        try:
            vals = [float(v) for v in parts]
        except ValueError:
            current = None
            continue
        key = tuple(int(v) for v in vals[:2]) if keyword.startswith("contact") else int(vals[0])
        current[key] = vals[1:] if not keyword.startswith("contact") else vals[2:]
    return blocks


def sections(columns=240, shaft_rings=24, hub_rings=12):
    """The shaft disc and the hub ring, graded towards the interface."""
    shaft = Mesh(0.0, D1 / 2, shaft_rings, columns, 1, 1, radial_bias=1.6)
    hub = Mesh(D1 / 2, D2 / 2, hub_rings, columns, shaft.next_node, shaft.next_elem,
               radial_bias=1.4)
    return shaft, hub


def radial_harmonic(disp, ring, n):
    """Amplitude of cos(n theta) in the radial displacement of a ring of nodes."""
    ur = np.array([disp[nid][0] * math.cos(th) + disp[nid][1] * math.sin(th) for nid, th in ring])
    th = np.array([t for _, t in ring])
    return 2.0 / len(th) * float(np.sum(ur * np.cos(n * th))) / (2.0 if n == 0 else 1.0)


def mean_displacement(mesh, disp):
    """Area-weighted mean displacement (x, y) of a mesh: each element's area (the polygon of its
    corner and midside nodes, which lie on the polar grid's arcs) times the mean of its nodes'."""
    coords = {nid: (x, y) for nid, x, y in mesh.nodes}
    total, area = np.zeros(2), 0.0
    # Boundary order of the nodes: corners and midsides alternating (CPS8, CPS6).
    for elements, order in ((mesh.quads, [0, 4, 1, 5, 2, 6, 3, 7]),
                            (mesh.tris, [0, 3, 1, 4, 2, 5])):
        for _, conn in elements:
            xy = np.array([coords[conn[i]] for i in order])
            a = 0.5 * abs(np.dot(xy[:, 0], np.roll(xy[:, 1], -1)) -
                          np.dot(xy[:, 1], np.roll(xy[:, 0], -1)))
            total += a * np.mean([disp[n][:2] for n in conn], axis=0)
            area += a
    return total / area


def harmonic(out_csv, orders=(0, 1, 2, 3, 5, 10)):
    """Interface compliance per harmonic: pressure p cos(n theta) on the shaft's rim and on the
    hub's bore (two separate bodies, each held only against rigid motion), radial displacement
    amplitude of order n at the interface, K_n = p / (u_shaft + u_hub). Order 1 carries a net
    force: each body's is balanced by a uniform body force (gravity at unit density), and the
    face's amplitude is taken relative to the body's area-mean displacement (its centroid's
    motion), as the model defines it (docs/contact-mechanics.md section 1)."""
    shaft, hub = sections()
    p = 10.0  # MPa amplitude; linear, any value
    a, b = D1 / 2, D2 / 2
    f = io.StringIO()
    f.write("*HEADING\nfitfeel harmonic compliance\n")
    write_mesh(f, shaft, "SHAFT")
    write_mesh(f, hub, "HUB")
    material(f, ["SHAFT", "HUB"])
    f.write("*DENSITY\n1.\n")  # for the body force of order 1 (tonne/mm^3: g in N/mm^3)
    rim = shaft.ring_nodes(shaft.outer_ring)
    bore = hub.ring_nodes(0)
    f.write("*NSET, NSET=RIM\n" + "\n".join(str(n) for n, _ in rim) + "\n")
    f.write("*NSET, NSET=BORE\n" + "\n".join(str(n) for n, _ in bore) + "\n")
    f.write("*NSET, NSET=SHAFTN\n" + "\n".join(str(n) for n, _, _ in shaft.nodes) + "\n")
    f.write("*NSET, NSET=HUBN\n" + "\n".join(str(n) for n, _, _ in hub.nodes) + "\n")
    # Rigid-body holds only (statically determinate, so self-equilibrated loads leave them
    # unloaded): shaft centre in x, y and a rim node in y; hub outer node at 0 deg in x, y, the
    # one at 180 deg in y.
    centre = shaft.ids[(0, 0)]
    s0 = rim[0][0]
    hub_out = hub.ring_nodes(hub.outer_ring)
    h0 = hub_out[0][0]
    h180 = hub_out[len(hub_out) // 2][0]
    f.write(f"*BOUNDARY\n{centre}, 1, 2\n{s0}, 2, 2\n{h0}, 1, 2\n{h180}, 2, 2\n")
    dtheta = 2 * math.pi / shaft.columns
    # A piecewise-constant load per element carries sinc(n dtheta / 2) of the cosine.
    applied = {n: p * (1.0 if n == 0 else math.sin(n * dtheta / 2) / (n * dtheta / 2))
               for n in orders}
    for n in orders:
        f.write("*STEP\n*STATIC\n*DLOAD, OP=NEW\n")
        for eid, face, th in shaft.boundary_elements(outer=True):
            f.write(f"{eid}, {face}, {p * math.cos(n * th):.12g}\n")
        for eid, face, th in hub.boundary_elements(outer=False):
            f.write(f"{eid}, {face}, {p * math.cos(n * th):.12g}\n")
        if n == 1:
            # Net forces -pi a p1 and +pi a p1 per mm (p1 the applied amplitude), spread over
            # each body's area.
            f.write(f"SHAFT, GRAV, {applied[1] / a:.12g}, 1., 0., 0.\n"
                    f"HUB, GRAV, {applied[1] * a / (b * b - a * a):.12g}, -1., 0., 0.\n")
        f.write("*NODE PRINT, NSET=RIM\nU\n*NODE PRINT, NSET=BORE\nU\n")
        if n == 1:
            f.write("*NODE PRINT, NSET=SHAFTN\nU\n*NODE PRINT, NSET=HUBN\nU\n")
        f.write("*END STEP\n")
    with tempfile.TemporaryDirectory() as work:
        dat = run_ccx(f.getvalue(), work, "harmonic")
    blocks = iter(parse_blocks(dat, "displacements"))
    rows = []
    for n in orders:
        u_rim, u_bore = next(blocks), next(blocks)
        closure = -radial_harmonic(u_rim, rim, n) + radial_harmonic(u_bore, bore, n)
        if n == 1:  # relative to each body's centroid: its mean x displacement
            closure += mean_displacement(shaft, next(blocks))[0]
            closure -= mean_displacement(hub, next(blocks))[0]
        rows.append((n, applied[n] / closure * 1e9))  # MPa/mm -> Pa/m
    p0 = rows[0][1]
    with open(out_csv, "w") as out:
        out.write("# CalculiX 2-D plane stress, steel d1 = 20 mm, d2 = 30 mm; "
                  "regenerate: /usr/bin/python3 tools/fem/fem.py harmonic <this file>\n")
        out.write("n,stiffness_MPa_per_um,ratio_to_n0\n")
        for n, k in rows:
            out.write(f"{n},{k / 1e12:.6g},{k / p0:.6g}\n")
    return rows


def contact_deck(delta, columns, penalty=1e8):
    """Shaft rim at radius a + delta(theta) (mm) overlapping a bore of radius a: the contact
    resolves the overlap. Frictionless, the shaft floats (only its rotation is held)."""
    shaft, hub = sections(columns, *RINGS[columns])
    a = D1 / 2
    nodes = []
    for nid, x, y in shaft.nodes:
        r = math.hypot(x, y)
        th = math.atan2(y, x)
        k = 1.0 + delta(th) / a  # the whole disc scaled radially: smooth, rim exact
        nodes.append((nid, x * k, y * k))
    shaft.nodes = nodes
    f = io.StringIO()
    f.write("*HEADING\nfitfeel contact case\n")
    write_mesh(f, shaft, "SHAFT")
    write_mesh(f, hub, "HUB")
    material(f, ["SHAFT", "HUB"])
    rim = shaft.ring_nodes(shaft.outer_ring)
    f.write("*NSET, NSET=RIM\n" + "\n".join(str(n) for n, _ in rim) + "\n")
    f.write("*SURFACE, NAME=SRIM, TYPE=ELEMENT\n")
    for eid, face, _ in shaft.boundary_elements(outer=True):
        f.write(f"{eid}, S{face[1]}\n")
    f.write("*SURFACE, NAME=SBORE, TYPE=ELEMENT\n")
    for eid, face, _ in hub.boundary_elements(outer=False):
        f.write(f"{eid}, S{face[1]}\n")
    f.write(f"*SURFACE INTERACTION, NAME=SI\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n"
            f"{penalty:g}, 3.\n")
    f.write("*CONTACT PAIR, INTERACTION=SI, TYPE=SURFACE TO SURFACE\nSRIM, SBORE\n")
    hub_out = hub.ring_nodes(hub.outer_ring)
    f.write(f"*BOUNDARY\n{rim[0][0]}, 2, 2\n{hub_out[0][0]}, 1, 2\n"
            f"{hub_out[len(hub_out) // 2][0]}, 2, 2\n")
    f.write("*STEP, INC=200\n*STATIC\n1., 1.\n*NODE PRINT, NSET=RIM\nU\n"
            "*CONTACT PRINT\nCSTR\n*NODE FILE\nU\n*CONTACT FILE\nCDIS, CSTR\n*END STEP\n")
    return f.getvalue(), shaft, rim


# Contact cases: radial interference fields delta(theta) of the shaft's rim over the bore, um.
# Lobed: delta0 + deltan cos(n theta) with deltan = 2 um; full contact needs delta0 >= (K_n/K_0)
# deltan, so "full" puts delta0 at 1.5 times that and "partial" at 0.3 times. Bump: a Gaussian of
# 3 um and standard deviation w (arc length) at theta = 0 on a 1 um radial clearance.
LOBE_RATIO = {2: 0.1455, 3: 0.778, 5: 3.16, 10: 8.83}


# Elements around, and rings in shaft and hub. The cases whose contact set takes many iterations
# to settle (ten lobes, bumps) use the coarser mesh so that each runs in minutes; 160 quadratic
# elements still put 16 on a lobe of order 10 and node pitch 0.2 mm under the narrowest bump.
RINGS = {240: (24, 12), 160: (16, 8)}


def contact_cases():
    cases = [("uniform", "uniform", 0, 2.0, 0.0, 0.0, 240)]
    for n in (2, 3, 5, 10):
        for kind, factor in (("full", 1.5), ("partial", 0.3)):
            cases.append((f"lobed{n}-{kind}", "lobed", n, factor * LOBE_RATIO[n] * 2.0, 2.0, 0.0,
                          240 if n < 10 else 160))
    for w in (0.5, 1.5, 4.5):
        cases.append((f"bump{w:g}mm", "bump", 0, -1.0, 3.0, w, 160))
    return cases


def interference(kind, n, d0, dn, width):
    """delta(theta) in mm for one case (the C++ tests rebuild it from the same parameters)."""
    a = D1 / 2
    if kind == "bump":
        def f(th):
            t = math.remainder(th, 2 * math.pi)
            return 1e-3 * (d0 + dn * math.exp(-0.5 * (a * t / width) ** 2))
        return f
    return lambda th: 1e-3 * (d0 + dn * math.cos(n * th))


def normal_force(disp, rim):
    """Total normal force per mm of length from the shaft rim's mean radial displacement.

    Only the mean pressure p0 moves the rim's mean radius (every other harmonic, and the rigid
    offset, averages out over the equally spaced rim nodes), and for a solid disc in plane stress
    u_r(a) = -p0 a (1 - nu) / E (Lame). So N = 2 pi a p0 follows from displacements, which the
    FEM resolves to its discretisation error, whereas summing the printed contact stresses does
    not: ccx prints them only at the slave integration points in contact, without weights, and
    an element partly in contact (narrow bumps, the edges of partial contact) would be counted
    whole (the 0.5 mm bump summed to 72 N/mm against 11.7 N/mm from the displacements, with a
    net force of 59 N/mm on a floating shaft)."""
    a = D1 / 2
    p0 = -radial_harmonic(disp, rim, 0) * E / (a * (1.0 - NU))
    return 2.0 * math.pi * a * p0 * THICKNESS


def contact(out_csv, only=None):
    rows = []
    for name, kind, n, d0, dn, width, columns in contact_cases():
        if only and name not in only:
            continue
        deck, shaft, rim = contact_deck(interference(kind, n, d0, dn, width), columns)
        with tempfile.TemporaryDirectory() as work:
            dat = run_ccx(deck, work, "contact")
        press = {}
        for line in dat[dat.index("contact stress"):].splitlines()[1:]:
            parts = line.split()
            if len(parts) == 5:
                press.setdefault(int(parts[0]), []).append(float(parts[2]))
        first = min(e for e, _, _ in shaft.boundary_elements(outer=True))
        cols = shaft.columns
        profile = np.zeros(cols)
        for e, values in press.items():
            profile[e - first] = max(0.0, float(np.mean(values)))
        force = normal_force(parse_blocks(dat, "displacements")[0], rim)
        rows.append((name, kind, n, d0, dn, width, force, float(profile.max()), columns))
        print(name, force, profile.max(), flush=True)
    with open(out_csv, "w") as out:
        out.write("# CalculiX 2-D plane stress, steel shaft d1 = 20 mm in hub d2 = 30 mm, "
                  "frictionless surface-to-surface contact; "
                  "regenerate: /usr/bin/python3 tools/fem/fem.py contact <this file>\n")
        out.write("case,kind,n,delta0_um,deltan_um,width_mm,normal_force_N_per_mm,"
                  "max_pressure_MPa,fem_elements_around\n")
        for r in rows:
            out.write(",".join(f"{v:.6g}" if isinstance(v, float) else str(v) for v in r) + "\n")
    return rows


def compare(new_csv, old_csv, tolerance=0.005):
    def rows(path):
        with open(path) as f:
            return [line.strip().split(",") for line in f if line.strip() and line[0] != "#"]
    new, old = rows(new_csv), rows(old_csv)
    bad = []
    if len(new) != len(old):
        bad.append(f"{len(new)} rows against {len(old)}")
    for a, b in zip(new, old):
        for x, y in zip(a, b):
            try:
                fx, fy = float(x), float(y)
            except ValueError:
                if x != y:
                    bad.append(f"{x} != {y}")
                continue
            # Numbers below 1e-3 (the axisymmetric cases' part-to-part differences, ~1e-4) are
            # discretisation residues: compared absolutely.
            if abs(fx - fy) > tolerance * max(abs(fx), abs(fy), 1e-3):
                bad.append(f"{a[0]}: {fx} against {fy}")
    for b in bad:
        print(f"{new_csv}: {b}")
    return not bad


if __name__ == "__main__":
    if sys.argv[1:2] == ["compare"] and len(sys.argv) == 4:
        sys.exit(0 if compare(sys.argv[2], sys.argv[3]) else 1)
    if len(sys.argv) < 3 or sys.argv[1] not in ("harmonic", "contact", "axisymmetric", "solid",
                                                "bearing", "key", "all"):
        sys.stderr.write(__doc__)
        sys.exit(2)
    if sys.argv[1] == "contact":
        contact(sys.argv[2])
    if sys.argv[1] == "axisymmetric":  # optional case names after the file: only those
        axi.axisymmetric(sys.argv[2], run_ccx, sys.argv[3:])
    if sys.argv[1] == "solid":  # optional case names after the file: only those
        solid.solid(sys.argv[2], run_ccx, sys.argv[3:])
    if sys.argv[1] == "bearing":  # optional case names after the file: only those
        solid.bearing(sys.argv[2], run_ccx, sys.argv[3:])
    if sys.argv[1] == "key":  # optional case names after the file: only those
        key.key(sys.argv[2], run_ccx, sys.argv[3:])
    if sys.argv[1] == "all":
        harmonic(os.path.join(sys.argv[2], "harmonic.csv"))
        contact(os.path.join(sys.argv[2], "contact.csv"))
        axi.axisymmetric(os.path.join(sys.argv[2], "axisymmetric.csv"), run_ccx)
        solid.solid(os.path.join(sys.argv[2], "solid.csv"), run_ccx)
        solid.bearing(os.path.join(sys.argv[2], "bearing.csv"), run_ccx)
        key.key(os.path.join(sys.argv[2], "key.csv"), run_ccx)
    if sys.argv[1] == "harmonic":
        for n, k in harmonic(sys.argv[2]):
            print(n, k)
