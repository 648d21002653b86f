#!/usr/bin/python3
"""Generated-input campaign against the fitfeel CLI.

Cases are drawn from a seeded generator over three families and each is run as a user would run
it, as a process:

  scenario     a shipped scenario, shrunk to a tiny run (milliseconds of virtual time, a coarse
               grid; three of them also with the scripted hand and a safety section, which no
               shipped scenario has), then mutated: values replaced by absurd, negative, non-finite, unit-swapped
               or malformed ones, lines deleted, duplicated or truncated, indentation broken, line
               endings changed, bytes inserted. Both `fitfeel validate F` and `fitfeel run F`.
  recording    a valid recording made once by `fitfeel run`, mutated (fields made huge, non-finite
               or malformed, lines dropped or swapped, header and end line damaged, quaternions
               denormalised, time reversed), replayed by the replay device: validate and run.
  command      a command line built from the CLI's grammar with mutated option values (signs,
               overflow, empty, units, device paths as outputs, unknown options).

Every case is checked for:
  - no crash and no hang: the process exits by itself within the timeout;
  - exit code 0 or 2 only;
  - every refusal located: the message names the file with line and column (scenarios), the
    recording's file and line, or one of the command line's own words (the argument);
  - every message in the project's format: each line on standard error is fitfeel's ("fitfeel:
    error: ...", "fitfeel: note: ...", an indented continuation) or a command's usage line, and
    none is in the argument library's own words ("At least 2 required but received 1");
  - validate and run agree (both accept or both refuse) on scenario and recording cases;
  - no non-finite number in trace.csv, summary.json or recording.csv of a run that succeeded,
    and no file at all in the output folder of a run that failed (no partial outputs).

Usage: tools/campaign/run.py [--cases N] [--seed S] [--jobs J] [--fitfeel PATH] [--keep DIR]
Exit code 0 when every case passes, 1 otherwise (the failing cases are kept under --keep).
"""

import argparse
import json
import math
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
TIMEOUT_S = 60

# Shipped scenarios whose tiny runs are cheap (the knuckle bearing settles a conformal contact each
# tick and the taper pin presses to 10 kN: both stay, at a coarse grid).
SCENARIOS = sorted(f for f in os.listdir(os.path.join(ROOT, "scenarios")) if f.endswith(".yaml"))

ABSURD_VALUES = [
    "0", "-1", "-0", "1e308", "-1e308", "1e-320", "nan", "NaN", "inf", "-inf", ".inf", ".nan",
    "''", '""', "~", "null", "[]", "{}", "[1, 2]", "{a: 1}", "18446744073709551616",
    "9223372036854775807", "-9223372036854775808", "0x10", "1_000", "+5", "5e", "e5", "1..2",
    "20 mm mm", "20mm", "20 kg", "20 N", "20 Hz", "20 s", "20 um", "20 km", "20 nm", "1e9 mm",
    "3 GPa", "0.5", "0.4999", "-0.5", "1.5", "2", "10000", "100000", "4000000", "2000",
    "true", "false", "yes", "H7", "g6", "Z9", "20 mm H7", "20 mm zz", "abc", "\"\\u0000\"",
    "!!binary aGVsbG8=", "&a 1", "*a", "|", ">", "- 1", "0 s", "1 ns", "1 us", "3600 s", "3601 s",
    "1 kHz", "100 kHz", "99 Hz", "1e-9 m", "360 deg", "1e6 rad/s",
]
NUMBER = re.compile(r"(?<![\w.])[-+]?\d+(?:\.\d+)?(?:[eE][-+]?\d+)?")


def shrink(text):
    """A shipped scenario as a run of a few milliseconds on a coarse grid, with every output."""
    text = re.sub(r"(?m)^(\s*duration:\s*).*$", r"\g<1>20 ms", text)
    text = re.sub(r"(?m)^(\s*resolution:\s*)\{[^}]*\}", r"\g<1>{rows: 8, columns: 36}", text)
    text = re.sub(r"(?m)^(\s*outputs:\s*).*$", r"\g<1>[trace, summary, recording]", text)
    return text


def mutate_value(rng, line):
    """Replaces a scalar in `line` (after a key or a list dash) with an absurd one."""
    m = re.match(r"^(\s*(?:-\s+)?[\w.]+:\s*)(.*)$", line)
    if m and m.group(2) and not m.group(2).startswith("#"):
        return m.group(1) + rng.choice(ABSURD_VALUES)
    numbers = list(NUMBER.finditer(line))
    if numbers:
        n = rng.choice(numbers)
        repl = rng.choice(["-" + n.group(0), n.group(0) + "e300", "0", "nan", n.group(0) * 3,
                           str(rng.uniform(-1e6, 1e6)), "1e-300"])
        return line[:n.start()] + repl + line[n.end():]
    return line + " " + rng.choice(ABSURD_VALUES)


def mutate_text(rng, text, rounds):
    lines = text.split("\n")
    for _ in range(rounds):
        op = rng.random()
        i = rng.randrange(len(lines)) if lines else 0
        if not lines:
            lines = [""]
        if op < 0.45:
            lines[i] = mutate_value(rng, lines[i])
        elif op < 0.55:
            del lines[i]
        elif op < 0.62:
            lines.insert(i, lines[i])
        elif op < 0.69:
            lines[i] = " " * rng.choice([1, 3, 8]) + lines[i]
        elif op < 0.74:
            lines[i] = lines[i].lstrip()
        elif op < 0.79:
            j = rng.randrange(len(lines))
            lines[i], lines[j] = lines[j], lines[i]
        elif op < 0.84:
            k = max(1, len(lines[i]))
            p = rng.randrange(k)
            lines[i] = lines[i][:p] + rng.choice(["\t", ":", "{", "[", "#", "'", '"', "\x00",
                                                   "\xff", "é", "%", "&", "*", ",", "- "]) + lines[i][p:]
        elif op < 0.88:
            m = re.match(r"^(\s*)(\w+)(:.*)$", lines[i])
            if m:
                lines[i] = m.group(1) + m.group(2)[:-1] + rng.choice("xyz_") + m.group(3)
        elif op < 0.91:
            lines = lines[: rng.randrange(len(lines) + 1)]
        else:
            lines[i] = mutate_value(rng, lines[i])
    out = "\n".join(lines)
    r = rng.random()
    if r < 0.04:
        out = out.replace("\n", "\r")
    elif r < 0.08:
        out = out.replace("\n", "\r\n")
    elif r < 0.10:
        out = out[: rng.randrange(len(out) + 1)]
    return out


def run(fitfeel, args, cwd):
    try:
        p = subprocess.run([fitfeel] + args, cwd=cwd, capture_output=True, timeout=TIMEOUT_S)
    except subprocess.TimeoutExpired:
        return None, "", "timeout"
    return p.returncode, p.stdout.decode("utf-8", "replace"), p.stderr.decode("utf-8", "replace")


NON_FINITE_WORDS = {"nan", "-nan", "+nan", "inf", "-inf", "+inf", "infinity", "-infinity",
                    "+infinity"}


def non_finite_field(text, separator):
    """Whether a data row of a CSV (trace: ',', recording: ' ') holds a non-finite number."""
    for line in text.split("\n"):
        for field in line.split(separator):
            if field.strip().lower() in NON_FINITE_WORDS:
                return True
    return False


def non_finite_json(text):
    """Whether summary.json holds NaN or Infinity (never valid JSON; Python's parser admits it)."""
    found = []
    json.loads(text, parse_constant=lambda c: found.append(c))
    return bool(found)


def check_outputs(out_dir, ok, problems):
    if not ok:
        if os.path.exists(out_dir) and os.listdir(out_dir):
            problems.append("a failed run left " + ", ".join(sorted(os.listdir(out_dir))))
        return
    if not os.path.exists(out_dir):
        return  # `run.outputs: []`: a run that writes nothing makes no folder
    for name in ("trace.csv", "summary.json", "recording.csv"):
        path = os.path.join(out_dir, name)
        if not os.path.exists(path):
            continue
        with open(path, encoding="utf-8", errors="replace") as f:
            text = f.read()
        if name == "summary.json":
            try:
                if non_finite_json(text):
                    problems.append("summary.json holds a non-finite number")
            except ValueError:
                problems.append("summary.json does not parse")
            continue
        if name == "trace.csv":
            rows = text.split("\n", 1)[1] if "\n" in text else ""
            bad = non_finite_field(rows, ",")
        else:
            rows = "\n".join(l for l in text.split("\n")
                             if not l.startswith("#") and not l.startswith("t_s"))
            bad = non_finite_field(rows, " ")
        if bad:
            problems.append(name + " holds a non-finite number")
    for name in os.listdir(out_dir):
        if ".tmp-" in name or name.endswith(".partial"):
            problems.append("temporary left behind: " + name)


# The project's message format (framework/cli/command_line_errors.h): an error, note or warning of
# fitfeel's or of one of its commands ("fitfeel run: interrupted ..."), an indented continuation,
# or a usage line.
MESSAGE_LINE = re.compile(r"^(?:fitfeel(?: [a-z]+)*: |usage: fitfeel\b|  )")
LIBRARY_WORDS = ["At least", "At Most", "required but received", "The following argument",
                 "Run with --help", "is required", "Could not convert", "Expected exactly",
                 "A subcommand", "not in {"]


def check_format(name, stderr, problems):
    # Lines end at newlines only (splitlines would also cut at a form feed inside a quoted key).
    for line in stderr.split("\n"):
        if line.strip() and not MESSAGE_LINE.match(line):
            problems.append(name + ": message outside the project's format: " + line[:200])
    for words in LIBRARY_WORDS:
        if words in stderr:
            problems.append(name + ": in the argument library's words: " + stderr.strip()[:200])
            break


def located(stderr, places):
    """Whether an error message names one of `places` (regexes) at its start or anywhere."""
    return any(re.search(p, stderr) for p in places)


def check_exit(name, code, stderr, problems):
    if code is None:
        problems.append(name + ": hang (no exit within %d s)" % TIMEOUT_S)
    elif code < 0:
        problems.append(name + ": killed by signal %d" % -code)
    elif code not in (0, 2):
        problems.append(name + ": exit code %d: %s" % (code, stderr.strip()[-300:]))


def file_places(path):
    q = re.escape(path)
    return [q + r":\d+:\d+: ", q + r": ", q + r":\d+: "]


def scenario_case(rng, fitfeel, work, base_texts, recording_file=None, recording_text=None):
    problems = []
    if recording_text is not None:
        rec = os.path.join(work, "rec.csv")
        with open(rec, "w", encoding="utf-8", errors="surrogateescape") as f:
            f.write(recording_text)
        text = base_texts["replay"]
    else:
        name = rng.choice(SCENARIOS)
        text = mutate_text(rng, base_texts[name], rng.randint(1, 3))
    scenario = os.path.join(work, "case.yaml")
    with open(scenario, "w", encoding="utf-8", errors="surrogateescape") as f:
        f.write(text)
    places = file_places(scenario)
    if recording_text is not None:
        places += file_places(os.path.join(work, "rec.csv"))
    v_code, _, v_err = run(fitfeel, ["validate", scenario], work)
    out_dir = os.path.join(work, "out")
    r_code, _, r_err = run(fitfeel, ["run", scenario, "--out", out_dir], work)
    check_exit("validate", v_code, v_err, problems)
    check_exit("run", r_code, r_err, problems)
    check_format("validate", v_err, problems)
    check_format("run", r_err, problems)
    if v_code == 2 and not located(v_err, places):
        problems.append("validate refusal not located: " + v_err.strip()[:300])
    if r_code == 2 and not located(r_err, places):
        problems.append("run refusal not located: " + r_err.strip()[:300])
    if v_code in (0, 2) and r_code in (0, 2) and v_code != r_code:
        problems.append("validate exit %d but run exit %d: %s" % (v_code, r_code,
                                                                  (v_err + r_err).strip()[:300]))
    check_outputs(out_dir, r_code == 0, problems)
    return ("accepted" if r_code == 0 else "refused"), problems


def recording_case(rng, fitfeel, work, base_texts):
    lines = base_texts["recording"].split("\n")
    for _ in range(rng.randint(1, 3)):
        if not lines:
            lines = [""]
        op = rng.random()
        data = [i for i, l in enumerate(lines) if l and not l.startswith("#") and not l.startswith("t_s")]
        if op < 0.5 and data:
            i = rng.choice(data)
            fields = lines[i].split(" ")
            j = rng.randrange(len(fields))
            fields[j] = rng.choice(["1e308", "-1e308", "nan", "inf", "", "x", "1e5", "0",
                                    "-" + fields[j], fields[j] + "0", "4294967296", "-1",
                                    "1e-320", "12", "0.7"])
            lines[i] = " ".join(fields)
        elif op < 0.6 and data:
            del lines[rng.choice(data)]
        elif op < 0.7 and len(data) > 1:
            a, b = rng.sample(data, 2)
            lines[a], lines[b] = lines[b], lines[a]
        elif op < 0.8:
            i = rng.randrange(len(lines))
            lines[i] = lines[i][: rng.randrange(len(lines[i]) + 1)]
        elif op < 0.9:
            k = rng.choice([0, 1, 2, len(lines) - 2])
            if 0 <= k < len(lines):
                lines[k] = rng.choice(["# fitfeel-recording 1", "# fitfeel-recording 3", "",
                                       "# end: 1 samples", "# end: x samples", lines[k] + " extra",
                                       lines[k].replace("_m ", "_mm ", 1)])
        else:
            lines = lines[: rng.randrange(len(lines) + 1)]
    return scenario_case(rng, fitfeel, work, base_texts, recording_text="\n".join(lines))


SEEDS = ["0", "1", "42", "-1", "", "18446744073709551616", "9223372036854775807",
         "9223372036854775808", "1e3", "abc", "+7", " 5", "0x1f", "1.5", "--", "-0"]
OUTS = ["out", "/dev/null", "/dev/null/x", "/proc/self", "", "case.yaml", "a/b/c", ".", "\x01",
        "nested/" * 20 + "x"]
FIT_CODES = ["H7/g6", "h7/G6", "H7", "g6", "H7/", "/g6", "H7/g6/h6", "ZC7/zc7", "H18/h18",
             "H1/h1", "A11/a11", "JS6/js6", "H7/js6", "", "H7 g6", "H07/g6", "H7/g99"]
SIZES = ["20", "0", "-1", "3150", "3151", "1e308", "nan", "20 mm", "0.5", "abc", "", "500"]


def command_case(rng, fitfeel, work, base_texts):
    problems = []
    scenario = os.path.join(work, "case.yaml")
    with open(scenario, "w") as f:
        f.write(base_texts[rng.choice(SCENARIOS)])
    kind = rng.random()
    if kind < 0.35:
        args = ["run", rng.choice([scenario, "missing.yaml", "", work])]
        if rng.random() < 0.7:
            args += ["--seed", rng.choice(SEEDS)]
        if rng.random() < 0.6:
            args += ["--out", rng.choice(OUTS)]
        if rng.random() < 0.2:
            args += [rng.choice(["--realtime", "--virtual", "--allow-large", "--bogus", "-x"])]
        if rng.random() < 0.1:
            args += ["--realtime", "--virtual"]
    elif kind < 0.5:
        args = ["validate", rng.choice([scenario, "missing.yaml", "", "/dev/null", work])]
        if rng.random() < 0.2:
            args += [rng.choice(["--allow-large", "--seed", "extra"])]
    elif kind < 0.75:
        args = ["fit", rng.choice(SIZES), rng.choice(FIT_CODES)]
        if rng.random() < 0.1:
            args = args[:rng.randint(1, 2)]
    elif kind < 0.9:
        args = ["sms", scenario, "-o", rng.choice(["sms.csv", "/dev/null", "", "/proc/self/x"]),
                "--seed", rng.choice(SEEDS)]
        if rng.random() < 0.3:
            args += ["--part", rng.choice(["shaft", "bushing", "nothing", ""])]
    else:
        args = rng.choice([["plugins"], ["plugins", "--json"], ["--version"], ["bogus"], [],
                           ["run", "--help"], ["plugins", "--seed", "1"]])
    out_dir = os.path.join(work, "out")
    code, _, err = run(fitfeel, args, work)
    check_exit(" ".join(args), code, err, problems)
    check_format(" ".join(args), err, problems)
    if code == 2:
        # The argument: one of the command line's own words (an option or its value), a file
        # location, or the list of commands when none was given.
        words = [w for w in args if w.strip()]
        # An empty word is named as nothing: "fitfeel: error: : ..." or "found nothing".
        empty = "" in args and ("error: : " in err or "nothing" in err or "''" in err)
        ok = empty or any(w in err for w in words) or located(err, file_places(scenario)) \
            or "expected a command" in err or "no scenario file given" in err
        if not ok:
            problems.append("refusal names no argument: " + err.strip()[:300])
    if args and args[0] == "run" and "--out" in args:
        target = args[args.index("--out") + 1] if args.index("--out") + 1 < len(args) else ""
        if target.startswith("/dev") or target.startswith("/proc"):
            if code == 0:
                problems.append("run wrote into " + target)
    if args and args[0] == "run" and "--out" in args and code == 0:
        target = args[args.index("--out") + 1]
        check_outputs(os.path.join(work, target), True, problems)
    return ("accepted" if code == 0 else "refused"), problems


def make_bases(fitfeel, scratch):
    bases = {}
    for name in SCENARIOS:
        with open(os.path.join(ROOT, "scenarios", name)) as f:
            bases[name] = shrink(f.read())
    # A recording of a tiny run, and a replay scenario that plays it (`rec.csv` beside it).
    src = os.path.join(scratch, "base.yaml")
    with open(src, "w") as f:
        f.write(bases["paper-case1-h7g6.yaml"])
    code, _, err = run(fitfeel, ["run", src, "--out", os.path.join(scratch, "base")], scratch)
    if code != 0:
        sys.exit("campaign: the base run failed: " + err)
    with open(os.path.join(scratch, "base", "recording.csv")) as f:
        bases["recording"] = f.read()
    replay = re.sub(r"(?m)^device:\n(?:  .*\n)+", "device:\n  plugin: fitfeel.device.replay\n"
                    "  file: rec.csv\n  model: PHANTOM Desktop\n", bases["paper-case1-h7g6.yaml"])
    bases["replay"] = replay
    # Sections no shipped scenario has: the scripted hand (tremor, aim, waypoints) and a safety
    # section (the chain's keys), on three surfaces with lead-ins, so that mutations reach them.
    hand_and_safety = (
        "device:\n  plugin: fitfeel.device.simulated\n  mode: scripted\n"
        "  hand: {mass: 0.5 kg, stiffness: 2000 N/m, damping: 20 N*s/m, tremor: true,"
        " aim_error: [1 mm, 0 mm]}\n"
        "  waypoints:\n"
        "    - {time: 0 s, position: [0 mm, -2 mm, 0 mm]}\n"
        "    - {time: 20 ms, position: [0 mm, 5 mm, 0 mm]}\n"
        "safety:\n  force_scale: 0.5\n  coupling: spring_damper\n"
        "  coupling_stiffness: 800 N/m\n  passivity_controller: true\n")
    for name in ("paper-case1-h7g6.yaml", "key-parallel.yaml", "taper-pin.yaml"):
        variant = name.replace(".yaml", "+hand.yaml")
        bases[variant] = re.sub(r"(?m)^device:\n(?:  .*\n|\s*#.*\n)+", hand_and_safety,
                                bases[name])
        SCENARIOS.append(variant)
    # A hand starting the part crooked and giving in tilt, rendered as a Touch with the perceptual
    # force map: the tilt, tilt_stiffness, model and mapping keys.
    tilted_hand = (
        "device:\n  plugin: fitfeel.device.simulated\n  mode: scripted\n  model: touch\n"
        "  force_mapping: perceptual\n"
        "  hand: {mass: 0.5 kg, stiffness: 2000 N/m, damping: 20 N*s/m, tilt_stiffness: 2 N*m/rad}\n"
        "  waypoints:\n"
        "    - {time: 0 s, position: [0 mm, -2 mm, 0 mm], tilt: [0.3 deg, 0 deg]}\n"
        "    - {time: 20 ms, position: [0 mm, 5 mm, 0 mm], tilt: [0.3 deg, 0 deg]}\n"
        "safety:\n  mapping_knee: 0.1 N\n  mapping_top: 20 kN\n")
    variant = "paper-case1-h7g6-paper+tilted-hand.yaml"
    bases[variant] = re.sub(r"(?m)^device:\n(?:  .*\n|\s*#.*\n)+", tilted_hand,
                            bases["paper-case1-h7g6-paper.yaml"])
    SCENARIOS.append(variant)
    return bases


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--cases", type=int, default=10000)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--fitfeel", default=os.path.join(ROOT, "build", "bin", "fitfeel"))
    parser.add_argument("--only", default="",
                        help="comma-separated case numbers to rerun (a case depends only on the "
                             "seed and its number)")
    parser.add_argument("--keep", default=os.path.join(ROOT, "build", "campaign-failures"))
    args = parser.parse_args()
    fitfeel = os.path.abspath(args.fitfeel)
    scratch = tempfile.mkdtemp(prefix="fitfeel-campaign-")
    bases = make_bases(fitfeel, scratch)
    # Sanity: the replay base itself runs (otherwise every recording case is refused for it).
    families = [("scenario", scenario_case, 0.55), ("recording", recording_case, 0.2),
                ("command", command_case, 0.25)]

    def one(index):
        rng = random.Random(args.seed * 1000003 + index)
        r = rng.random()
        for family, fn, share in families:
            if r < share:
                break
            r -= share
        work = os.path.join(scratch, "case-%d" % index)
        os.makedirs(work)
        outcome, problems = fn(rng, fitfeel, work, bases)
        if problems:
            keep = os.path.join(args.keep, "%s-%d" % (family, index))
            shutil.rmtree(keep, ignore_errors=True)
            shutil.copytree(work, keep)
            with open(os.path.join(keep, "problems.txt"), "w") as f:
                f.write("\n".join(problems) + "\n")
        shutil.rmtree(work, ignore_errors=True)
        return family, outcome, problems

    counts = {}
    failures = []
    with ThreadPoolExecutor(max_workers=args.jobs) as pool:
        indices = [int(i) for i in args.only.split(",")] if args.only else range(args.cases)
        for index, (family, outcome, problems) in zip(indices, pool.map(one, indices)):
            counts.setdefault(family, {"accepted": 0, "refused": 0, "failed": 0})
            counts[family][outcome] += 1
            if problems:
                counts[family]["failed"] += 1
                failures.append((family, index, problems))
    shutil.rmtree(scratch, ignore_errors=True)
    total = sum(sum(c[k] for k in ("accepted", "refused")) for c in counts.values())
    print("campaign: %d cases, seed %d" % (total, args.seed))
    for family in sorted(counts):
        c = counts[family]
        print("  %-9s %5d accepted, %5d refused, %d failing" % (family, c["accepted"], c["refused"],
                                                               c["failed"]))
    for family, index, problems in failures[:40]:
        print("FAIL %s-%d: %s" % (family, index, "; ".join(problems)))
    if failures:
        print("campaign: %d failing cases kept in %s" % (len(failures), args.keep))
        return 1
    print("campaign: no crash, exit codes 0 or 2 only, every refusal located and in the project's "
          "format, validate and run agree, no non-finite output")
    return 0


if __name__ == "__main__":
    sys.exit(main())
