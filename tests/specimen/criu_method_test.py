#!/usr/bin/env python3
"""The experiment's criu method, flown for real where CRIU works: a V0 -> V0 dump and restore
succeeds with an image of some size, and V0 -> V1 (another executable) is refused by CRIU, the
refusal recorded as the flight's outcome. Where `criu check` fails (or criu is missing) the test
says why and exits 77, which ctest reports as skipped.

Usage: criu_method_test.py <build dir> <scratch dir>"""
import json
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "specimen", "harness"))
import experiment  # noqa: E402

SKIP = 77
MISSION = os.path.join(experiment.MISSIONS_DIR, "istar.waypoints")


def fly(exe, work, criu, resume, method="criu"):
    flight = experiment.fly(exe, MISSION, work, 31, exe["copter_v0"], exe[resume], method,
                            checkpoint_at=20.0, criu=criu)
    print("%s -> %s (%s): %s" % ("copter_v0", resume, method, json.dumps(
        {k: flight.get(k) for k in ("success", "reason", "checkpoint_bytes", "restored",
                                    "restore_us", "checkpoint_us_mean")})))
    return flight


def main():
    build_dir, scratch = sys.argv[1], sys.argv[2]
    criu, why = experiment.criu_status()
    if criu is None:
        print("criu method not tested here: " + why)
        return SKIP
    exe, _ = experiment.find_build(build_dir)
    shutil.rmtree(scratch, ignore_errors=True)
    failures = []

    same = fly(exe, os.path.join(scratch, "v0-v0"), criu, "copter_v0")
    if not same["success"] or not same["restored"]:
        failures.append("V0 -> V0 must restore and finish the mission: " + same["reason"])
    if same["checkpoint_bytes"] <= 0:
        failures.append("the dump's images must have a size")
    images = os.path.join(scratch, "v0-v0", "criu-images")
    if not os.path.isdir(images) or not os.listdir(images):
        failures.append("no images in " + images)

    changed = fly(exe, os.path.join(scratch, "v0-v1"), criu, "copter_v1")
    if changed["success"] or changed["restored"]:
        failures.append("CRIU must refuse V1's executable in place of V0's")
    if not changed["reason"].startswith("criu refused the restore: "):
        failures.append("the refusal must be the outcome, with CRIU's reason: " + changed["reason"])

    for failure in failures:
        print("FAIL: " + failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
