"""A foreign runtime drives fitfeel's C library through ctypes, as C#'s DllImport would: it runs
`fitfeel run` on a shipped scenario with a recording, feeds every recorded device state to
fitfeel_step (the scenario opened from YAML text) and requires the wrench each step returns to
equal, bit for bit, what the run commanded the device.

ctypes_host_test.py LIBFITFEEL_C FITFEEL SCENARIO
"""
import ctypes
import pathlib
import subprocess
import sys
import tempfile

lib_path, fitfeel, scenario = sys.argv[1:4]


class DeviceState(ctypes.Structure):
    _fields_ = [("time", ctypes.c_double), ("position", ctypes.c_double * 3),
                ("orientation", ctypes.c_double * 4), ("velocity", ctypes.c_double * 3),
                ("angular_velocity", ctypes.c_double * 3),
                ("buttons", ctypes.c_uint32)]


class Wrench(ctypes.Structure):
    _fields_ = [("force", ctypes.c_double * 3), ("torque", ctypes.c_double * 3)]


lib = ctypes.CDLL(lib_path)
lib.fitfeel_open_yaml.argtypes = [ctypes.c_char_p, ctypes.c_char_p, ctypes.c_uint64,
                                  ctypes.POINTER(ctypes.c_void_p)]
lib.fitfeel_step.argtypes = [ctypes.c_void_p, ctypes.POINTER(DeviceState), ctypes.POINTER(Wrench)]
lib.fitfeel_close.argtypes = [ctypes.c_void_p]
lib.fitfeel_write_outputs.argtypes = [ctypes.c_void_p, ctypes.c_char_p]
lib.fitfeel_pressure_map.argtypes = [ctypes.c_void_p, ctypes.POINTER(ctypes.c_double), ctypes.c_int,
                                     ctypes.POINTER(ctypes.c_int), ctypes.POINTER(ctypes.c_int)]
lib.fitfeel_last_error.argtypes = [ctypes.c_void_p]
lib.fitfeel_last_error.restype = ctypes.c_char_p
lib.fitfeel_thread_last_error.restype = ctypes.c_char_p
assert lib.fitfeel_abi_version() == 2

text = pathlib.Path(scenario).read_text()
assert "outputs: [trace, summary]" in text, "the scenario's outputs line changed"
text = text.replace("outputs: [trace, summary]", "outputs: [trace, summary, recording]")

with tempfile.TemporaryDirectory() as work:
    scene = pathlib.Path(work) / "scene.yaml"
    scene.write_text(text)
    subprocess.run([fitfeel, "run", str(scene), "--out", work], check=True,
                   stdout=subprocess.DEVNULL)
    lines = [l for l in (pathlib.Path(work) / "recording.csv").read_text().splitlines()
             if not l.startswith("#")]
    header, rows = lines[0].split(), [l.split() for l in lines[1:]]
    run_trace = (pathlib.Path(work) / "trace.csv").read_text()

col = {name: i for i, name in enumerate(header)}
handle = ctypes.c_void_p()
status = lib.fitfeel_open_yaml(text.encode(), b"scene.yaml", 0, ctypes.byref(handle))
assert status == 0, lib.fitfeel_thread_last_error().decode()

d, w = DeviceState(), Wrench()
mismatches = 0
loaded = 0
for n, row in enumerate(rows):
    v = lambda name: float(row[col[name]])
    d.time = v("t_s")
    d.position[:] = [v("x_m"), v("y_m"), v("z_m")]
    d.orientation[:] = [v("qw_1"), v("qx_1"), v("qy_1"), v("qz_1")]
    d.velocity[:] = [v("vx_m/s"), v("vy_m/s"), v("vz_m/s")]
    d.angular_velocity[:] = [v("wx_rad/s"), v("wy_rad/s"), v("wz_rad/s")]
    d.buttons = int(row[col["buttons_bits"]])
    assert lib.fitfeel_step(handle, ctypes.byref(d), ctypes.byref(w)) == 0, f"tick {n}"
    want = [v(f"f{a}_cmd_N") for a in "xyz"] + [v(f"t{a}_cmd_N*m") for a in "xyz"]
    got = list(w.force) + list(w.torque)
    loaded += any(x != 0.0 for x in want)
    if got != want:
        mismatches += 1
        if mismatches <= 5:
            print(f"tick {n}: C API {got} != fitfeel run {want}")


def without_timings(trace):
    # tick_us (the 7th column) is a measurement, the only value not fixed in virtual time.
    return [",".join(l.split(",")[:6] + l.split(",")[7:]) for l in trace.splitlines()]


# The host's run written by the library: the same trace as fitfeel run's, row for row.
with tempfile.TemporaryDirectory() as work:
    assert lib.fitfeel_write_outputs(handle, work.encode()) == 0, lib.fitfeel_last_error(handle)
    host_trace = (pathlib.Path(work) / "trace.csv").read_text()
    assert (pathlib.Path(work) / "summary.json").is_file()
trace_ok = without_timings(host_trace) == without_timings(run_trace)
print(f"fitfeel_write_outputs: trace {'equal to' if trace_ok else 'DIFFERENT from'} fitfeel run's")
assert lib.fitfeel_write_outputs(handle, b"/dev/null/x") != 0
assert b"/dev/null" in lib.fitfeel_last_error(handle), lib.fitfeel_last_error(handle)

# The pressure map: ask its size, then fetch it.
rows_n, cols_n = ctypes.c_int(), ctypes.c_int()
assert lib.fitfeel_pressure_map(handle, None, 0, ctypes.byref(rows_n), ctypes.byref(cols_n)) == -1
assert rows_n.value > 0 and cols_n.value > 0, (rows_n.value, cols_n.value)
cells = (ctypes.c_double * (rows_n.value * cols_n.value))()
status = lib.fitfeel_pressure_map(handle, cells, len(cells), ctypes.byref(rows_n),
                                  ctypes.byref(cols_n))
assert status == 0, lib.fitfeel_last_error(handle)
assert all(p >= 0.0 for p in cells)
print(f"pressure map {rows_n.value} x {cols_n.value}, max {max(cells):.4g} Pa")
lib.fitfeel_close(handle)
if not trace_ok:
    sys.exit(1)
print(f"{len(rows)} ticks through ctypes ({loaded} with a non-zero wrench), "
      f"{mismatches} differing from fitfeel run")
# A run that renders nothing would compare zeros with zeros: most of the insertion is loaded.
sys.exit(1 if mismatches or len(rows) < 1000 or loaded < len(rows) // 2 else 0)
