#!/usr/bin/env python3
"""The paper's experiment (specimen/README.md): for each mission x version x method, N flights in
which V0 flies to a preselected random point, is checkpointed and killed (SIGKILL), and the
patched build Vk is started, restores, and must finish the mission.

Methods: baseline (V0 flies the whole mission, no checkpoint), symcr (the autopilot calls
symcr's store), symcr-points (builds whose sources carry no symcr call: the program points of an
annotation file save and restore), raw-image (the root
object's bytes restored with memcpy, standing for whole-memory C/R), criu (the autopilot's
process dumped and restored by CRIU, which checks the executable as it always does) and
criu-unchecked (CRIU with that check reduced to sizes, which the world makes equal: the old
memory under the new code); both only where `criu check` passes, with criu taken from $CRIU or
PATH; symcr-live (no checkpoint, no kill: the live host flies V0's vehicle module and, at the
point, loads Vk's and moves the state into it with symcr::transfer between two loops; its
"restore" is the gap from that loop boundary to Vk's first motor outputs). Red team: the
vulnerable build is checkpointed periodically, the exploit frame crashes it, and the latest
checkpoint is restored into the repaired build.

Prints Table 1 and writes results.json, one SVG per mission and every flight's track and log
under --out. Usage: experiment.py [--runs 50] [--out DIR] [--build-dir DIR]
"""
import argparse
import concurrent.futures
import json
import os
import random
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import report  # noqa: E402
import trajectory_svg  # noqa: E402

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
MISSIONS_DIR = os.path.join(ROOT, "specimen", "missions")
DEFAULT_MISSIONS = ("istar.waypoints", "busroute.waypoints")
MISSION_NAMES = {"istar.waypoints": "ISTAR", "busroute.waypoints": "BusRoute"}


def parse_args():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--runs", type=int, default=5, help="flights per cell (paper: 50)")
    p.add_argument("--build-dir", default=os.path.join(ROOT, "build", "specimen"))
    p.add_argument("--out", default=os.path.join(ROOT, "out", "experiment"))
    p.add_argument("--missions", nargs="+", help="mission files (default: ISTAR and BusRoute)")
    # V0 -> V0 (the same build restored) is the control: every method must succeed there.
    p.add_argument("--versions", nargs="+", default=["V0", "V1", "V2", "V3", "V4"])
    p.add_argument("--methods", nargs="+",
                   default=["symcr", "symcr-points", "symcr-live", "raw-image", "criu",
                            "criu-unchecked"])
    p.add_argument("--no-redteam", action="store_true")
    p.add_argument("--seed", type=int, default=2020)
    p.add_argument("--outage", type=float, default=0.2, help="seconds without autopilot")
    p.add_argument("--jobs", type=int, default=1,
                   help="flights in parallel (each flight is two processes in lock-step)")
    p.add_argument("--check", action="store_true",
                   help="exit 1 unless every baseline flight succeeded (for CI)")
    return p.parse_args()


def find_build(build_dir):
    """Executables by name; the specimen lives in <build>/specimen."""
    base = os.path.join(build_dir, "specimen")
    found = {}
    for name in ("copter_v0", "copter_v1", "copter_v2", "copter_v3", "copter_v4",
                 "copter_redteam", "copter_redteam_repaired"):
        for variant in (name, name + "_symcr", name + "_points"):
            path = os.path.join(base, variant)
            if os.access(path, os.X_OK):
                found[variant] = path
        module = os.path.join(base, name + "_live.so")  # a vehicle module (symcr-live)
        if os.path.exists(module):
            found[name + "_live"] = module
    for tool in ("sitl_world", "copter_live"):
        if os.access(os.path.join(base, tool), os.X_OK):
            found[tool] = os.path.join(base, tool)
    config = {}
    config_path = os.path.join(base, "specimen_config.json")
    if os.path.exists(config_path):
        with open(config_path) as f:
            config = json.load(f)
    return found, config


CRIU_METHODS = ("criu", "criu-unchecked")
LIVE_METHOD = "symcr-live"


def find_criu():
    """The criu binary: $CRIU, else criu on PATH (or in /usr/sbin, where Debian puts it)."""
    if os.environ.get("CRIU"):
        return os.environ["CRIU"]
    return shutil.which("criu") or (os.path.exists("/usr/sbin/criu") and "/usr/sbin/criu") or None


def criu_status():
    """(criu binary or None, reason it cannot be used)."""
    criu = find_criu()
    if not criu:
        return None, "criu is not installed (apt-get install criu, or CRIU=<binary>)"
    try:
        r = subprocess.run([criu, "check"], capture_output=True, text=True, timeout=60)
    except OSError as e:
        return None, "%s check could not run: %s" % (criu, e)
    if r.returncode != 0:
        lines = [l for l in (r.stderr + r.stdout).splitlines() if l.strip()]
        return None, "`%s check` failed: %s" % (
            criu, lines[-1] if lines else "exit %d" % r.returncode)
    return criu, ""


def text_bytes(path):
    """.text size of an executable (binutils `size -A`), or None."""
    try:
        r = subprocess.run(["size", "-A", path], capture_output=True, text=True, check=True)
    except (OSError, subprocess.CalledProcessError):
        return None
    for line in r.stdout.splitlines():
        parts = line.split()
        if parts and parts[0] == ".text":
            return int(parts[1])
    return None


def expected_failure(version, method):
    """Why every flight of a cell is meant to fail, or None. A byte image and CRIU carry the old
    executable's memory: into any other build they fail, which is the point of the comparison;
    into the vulnerable build itself (RT0) the attacker's second exploit crashes it again."""
    if version == "V0":
        return None
    if method == "raw-image":
        return "a byte image holds the old build's addresses and layout"
    if method == "criu":
        return ("the vulnerable build, restored, falls to the second exploit" if version == "RT0"
                else "CRIU restores only the executable it dumped")
    if method == "criu-unchecked":
        return "the old memory runs under the new code"
    return None


def flight_status(flight, expected_failure=None):
    """A flight's outcome for the progress lines: FAIL only where the method should succeed."""
    if flight["success"]:
        return "ok" if not expected_failure else "ok, although expected to fail (%s)" % (
            expected_failure)
    if expected_failure:
        return "failed as expected (%s): %s" % (expected_failure, flight["reason"])
    return "FAIL: " + flight["reason"]


class Progress:
    def __init__(self, total):
        self.total, self.done, self.start = total, 0, time.monotonic()
        self.tty = sys.stderr.isatty()

    def step(self, label, flight, expected_failure=None):
        self.done += 1
        status = flight_status(flight, expected_failure)
        line = "[%3d/%d %5.0fs] %s: %s" % (self.done, self.total, time.monotonic() - self.start,
                                            label, status)
        if self.tty:
            sys.stderr.write("\r\033[K" + line[:150])
        else:
            sys.stderr.write(line + "\n")
        sys.stderr.flush()

    def finish(self):
        if self.tty:
            sys.stderr.write("\n")


def autopilot(exe, name, method):
    """The build of `name` for `method`: symcr flies the builds that call symcr, symcr-points
    the builds checkpointed by program points alone (no symcr call in their sources),
    symcr-live the vehicle modules of the live host."""
    suffix = {"symcr": "_symcr", "symcr-points": "_points", "symcr-live": "_live"}
    return exe[name + suffix.get(method, "")]


def fly(exe, mission_path, workdir, seed, autopilot, resume=None, method="none",
        checkpoint_at=None, exploit_at=None, outage=0.2, criu=None):
    """One flight. A red-team flight (exploit_at) sends the exploit again 5 s after the restart:
    the attacker tries twice, so a restore into a build that is still vulnerable falls again."""
    os.makedirs(workdir, exist_ok=True)
    for stale in ("checkpoint.img", "checkpoint.store", "autopilot.log"):
        if os.path.exists(os.path.join(workdir, stale)):
            os.remove(os.path.join(workdir, stale))
    track = os.path.join(workdir, "track.csv")
    cmd = [exe["sitl_world"], "--autopilot", autopilot, "--mission", mission_path,
           "--workdir", workdir, "--seed", str(seed), "--track", track, "--method", method,
           "--outage", str(outage)]
    if resume:
        cmd += ["--resume-autopilot", resume]
    if checkpoint_at is not None:
        cmd += ["--checkpoint-at", "%.2f" % checkpoint_at]
    if exploit_at is not None:
        cmd += ["--exploit-at", "%.2f" % exploit_at, "--exploit-again", "5"]
    if method in CRIU_METHODS:
        cmd += ["--criu", criu]
    if method == LIVE_METHOD:
        cmd += ["--live-host", exe["copter_live"]]
    r = subprocess.run(cmd, capture_output=True, text=True)
    try:
        flight = json.loads(r.stdout.strip().splitlines()[-1])
    except (IndexError, json.JSONDecodeError):
        flight = {"success": False, "reason": "sitl_world failed: " + r.stderr.strip()[-200:],
                  "mission_time_s": 0, "checkpoints_saved": 0, "checkpoint_bytes": 0}
    flight["track"] = track
    flight["command"] = " ".join(cmd)
    with open(os.path.join(workdir, "flight.json"), "w") as f:
        json.dump(flight, f, indent=2)
    return flight


def restore_report_entry(log_path, path):
    """The restore report's line for `path` in a flight's autopilot.log, or None."""
    if not os.path.exists(log_path):
        return None
    with open(log_path) as f:
        for line in f:
            fields = line.split(None, 1)
            if fields and fields[0] == path:
                return " ".join(line.split())
    return None


def run_cell(pool, progress, label, runs, fly_one, expected=None):
    """Flies `fly_one(i)` for every run i, in parallel on `pool`; results in run order.
    `expected`: why the cell's flights are meant to fail (expected_failure), or None."""
    futures = [pool.submit(fly_one, i) for i in range(runs)]
    flights = []
    for i, future in enumerate(futures):
        flight = future.result()
        progress.step("%s %d/%d" % (label, i + 1, runs), flight, expected)
        flights.append(flight)
    return flights


def main():
    args = parse_args()
    exe, config = find_build(args.build_dir)
    if "sitl_world" not in exe or "copter_v0" not in exe:
        sys.exit("experiment: build the specimen first (missing sitl_world/copter_v0 in %s)"
                 % args.build_dir)
    missions = args.missions or [os.path.join(MISSIONS_DIR, m) for m in DEFAULT_MISSIONS]
    symcr_built = bool(config.get("symcr")) and "copter_v0_symcr" in exe
    wants_criu = any(m in CRIU_METHODS for m in args.methods)
    criu, criu_reason = criu_status() if wants_criu else (None, "")
    criu_ok = criu is not None
    notes = []
    if any(m.startswith("symcr") for m in args.methods) and not symcr_built:
        notes.append("symcr: not measured: the autopilots of this build have no symcr-generated "
                     "code (no symcr_add_checkpointing or no working symcr-gen at build time)")
    if wants_criu and not criu_ok:
        notes.append("criu: unavailable on this machine: " + criu_reason)
    methods = [m for m in args.methods
               if (not m.startswith("symcr") or symcr_built) and (m not in CRIU_METHODS or criu_ok)
               and (m != LIVE_METHOD or ("copter_live" in exe and "copter_v0_live" in exe))]
    # The red team's builds have no vehicle modules: a live update does not restart anything.
    redteam_methods = [m for m in methods if m != LIVE_METHOD]
    if LIVE_METHOD in methods:
        notes.append("symcr-live: no checkpoint, no kill, no restart; its Restore (us) is the gap "
                     "from the loop boundary where V0's code stops to Vk's first motor outputs "
                     "(transfer, links handed over, resume, one loop)")
    versions = [v for v in args.versions if "copter_" + v.lower() in exe]
    if symcr_built:
        versions = [v for v in versions if "copter_%s_symcr" % v.lower() in exe]
    redteam = (not args.no_redteam and "copter_redteam" in exe
               and "copter_redteam_repaired" in exe)

    per_mission = 1 + len(versions) * len(methods) + (
        len(redteam_methods) + ("criu" in methods) if redteam else 0)
    progress = Progress(len(missions) * args.runs * per_mission)
    os.makedirs(args.out, exist_ok=True)
    rows, pictures = [], {}
    rng_root = random.Random(args.seed)
    pool = concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs))
    for mission_path in missions:
        base = os.path.basename(mission_path)
        name = MISSION_NAMES.get(base, os.path.splitext(base)[0])
        run_dir = os.path.join(args.out, "runs", name)
        seeds = [rng_root.randrange(1, 2**31) for _ in range(args.runs)]

        # Baseline: V0 flies the whole mission; its times fix where the checkpoints go.
        flights = run_cell(pool, progress, "%s V0 baseline" % name, args.runs, lambda i: fly(
            exe, mission_path, os.path.join(run_dir, "V0-baseline-%d" % i), seeds[i],
            exe["copter_v0"], outage=args.outage))
        rows.append(report.make_row(name, "V0", "baseline", flights))
        ok_times = [f["mission_time_s"] for f in flights if f["success"]]
        if not ok_times:
            notes.append("%s: no baseline flight succeeded; checkpoint points cannot be chosen"
                         % name)
            continue
        horizon = min(ok_times)
        # The same preselected point for every version and method of run i (paired runs).
        point_rng = random.Random("%d/%s" % (args.seed, name))
        points = [point_rng.uniform(0.1, 0.8) * horizon for _ in seeds]

        for version in versions:
            for method in methods:
                def fly_version(i, version=version, method=method):
                    return fly(exe, mission_path,
                               os.path.join(run_dir, "%s-%s-%d" % (version, method, i)), seeds[i],
                               autopilot(exe, "copter_v0", method),
                               autopilot(exe, "copter_" + version.lower(), method), method,
                               checkpoint_at=points[i], outage=args.outage, criu=criu)
                flights = run_cell(pool, progress, "%s %s %s" % (name, version, method), args.runs,
                                   fly_version, expected_failure(version, method))
                for i, f in enumerate(flights):
                    if f["success"] and f.get("checkpoint_point") and (
                            name not in pictures or (method == "symcr" and version == "V3")):
                        pictures[name] = (f, "%s %s, %s, run %d" % (name, version, method, i + 1))
                rows.append(report.make_row(name, version, method, flights))
        if redteam:
            for method in redteam_methods:
                def fly_redteam(i, method=method):
                    return fly(exe, mission_path, os.path.join(run_dir, "RT-%s-%d" % (method, i)),
                               seeds[i], autopilot(exe, "copter_redteam", method),
                               autopilot(exe, "copter_redteam_repaired", method), method,
                               exploit_at=points[i], outage=args.outage, criu=criu)
                flights = run_cell(pool, progress, "%s red team %s" % (name, method), args.runs,
                                   fly_redteam, expected_failure("RT", method))
                rows.append(report.make_row(name, "RT", method, flights))
            if "criu" in methods:
                # CRIU accepts only the executable it dumped: the vulnerable build itself (RT0).
                def fly_unrepaired(i):
                    return fly(exe, mission_path, os.path.join(run_dir, "RT0-criu-%d" % i),
                               seeds[i], exe["copter_redteam"], exe["copter_redteam"], "criu",
                               exploit_at=points[i], outage=args.outage, criu=criu)
                flights = run_cell(pool, progress, "%s red team criu, unrepaired" % name,
                                   args.runs, fly_unrepaired, expected_failure("RT0", "criu"))
                rows.append(report.make_row(name, "RT0", "criu", flights))
        if name not in pictures:
            ok = [f for f in flights if f["success"]] or flights
            pictures[name] = (ok[0], "%s, %s" % (name, "baseline"))
        flight, title = pictures[name]
        svg = os.path.join(args.out, "%s.svg" % name)
        trajectory_svg.draw(mission_path, flight["track"], flight, title, svg)
    progress.finish()
    pool.shutdown()

    for method in [m for m in args.methods if m.startswith("symcr") and not symcr_built]:
        for mission_path in missions:
            base = os.path.basename(mission_path)
            name = MISSION_NAMES.get(base, os.path.splitext(base)[0])
            for version in versions:
                rows.append(report.make_row(name, version, method, []))
    for method in [m for m in args.methods if m in CRIU_METHODS and not criu_ok]:
        for mission_path in missions:
            base = os.path.basename(mission_path)
            name = MISSION_NAMES.get(base, os.path.splitext(base)[0])
            for version in versions:
                rows.append(report.make_row(name, version, method, []))
    # What CRIU said when it refused (or what became of the restored process), per cell.
    for r in rows:
        if r["method"] in CRIU_METHODS and r["runs"] > r["successes"]:
            reasons = "; ".join("%d× %s" % (n, why) for why, n in r["failures"].items())
            notes.append("%s, %s %s: %s" % (r["method"], r["mission"], r["version"], reasons))
    order = {"baseline": 0, "symcr": 1, "symcr-points": 2, "symcr-live": 3, "raw-image": 4,
             "criu": 5, "criu-unchecked": 6}
    mission_order = {MISSION_NAMES.get(os.path.basename(m), os.path.splitext(os.path.basename(m))[0]): i
                     for i, m in enumerate(missions)}
    rows.sort(key=lambda r: (mission_order.get(r["mission"], 99), r["version"].startswith("RT"),
                             r["version"], order.get(r["method"], 9)))
    if symcr_built:
        gen_report = os.path.join(args.build_dir, "specimen", "symcr", "copter_v0_symcr",
                                  "report.txt")
        if os.path.exists(gen_report):
            with open(gen_report) as f:
                reach = [l.strip() for l in f if l.strip().startswith("reaches ")]
            if reach:
                notes.append("symcr-gen on V0's root copter: " + reach[0])
        # How the flight mode came back in the newest version (a pointer, saved as a reference).
        first = MISSION_NAMES.get(os.path.basename(missions[0]),
                                  os.path.splitext(os.path.basename(missions[0]))[0])
        if versions and "symcr" in methods:
            newest = versions[-1]
            log = os.path.join(args.out, "runs", first, "%s-symcr-0" % newest, "autopilot.log")
            entry = restore_report_entry(log, "copter.flightmode")
            if entry:
                notes.append("restore report, %s V0 -> %s (symcr, run 1): %s" % (first, newest, entry))
        plain, generated = text_bytes(exe["copter_v0"]), text_bytes(exe["copter_v0_symcr"])
        if plain and generated:
            notes.append("symcr adds %d bytes of .text to the V0 autopilot (runtime + generated "
                         "code; %d -> %d)" % (generated - plain, plain, generated))
    print(report.format_table(rows, notes))
    report.write_json(rows, os.path.join(args.out, "results.json"))
    print("results: %s; pictures: %s" % (os.path.join(args.out, "results.json"),
                                         ", ".join(os.path.join(args.out, n + ".svg") for n in pictures)))
    if args.check:
        baseline_ok = all(r["successes"] == r["runs"] for r in rows if r["method"] == "baseline")
        return 0 if baseline_ok else 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
