#!/usr/bin/env python3
"""The experiment harness's output, without flying: which failures the progress lines call
expected, the table's legend of version names, and the SVG's labels not covering each other."""
import os
import re
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "specimen", "harness"))
import experiment  # noqa: E402
import report  # noqa: E402
import trajectory_svg  # noqa: E402


class ProgressStatus(unittest.TestCase):
    crash = {"success": False, "reason": "autopilot stopped (signal 11)"}

    def test_a_byte_image_into_a_patched_build_fails_as_expected(self):
        why = experiment.expected_failure("V3", "raw-image")
        self.assertEqual(experiment.flight_status(self.crash, why),
                         "failed as expected (a byte image holds the old build's addresses and "
                         "layout): autopilot stopped (signal 11)")

    def test_the_expected_failures(self):
        for version, method in (("V1", "raw-image"), ("RT", "raw-image"), ("V2", "criu"),
                                ("RT", "criu"), ("RT0", "criu"), ("V4", "criu-unchecked")):
            self.assertIsNotNone(experiment.expected_failure(version, method), (version, method))
        for version, method in (("V0", "raw-image"), ("V0", "criu"), ("V3", "symcr"),
                                ("RT", "symcr-points"), ("V1", "symcr-live")):
            self.assertIsNone(experiment.expected_failure(version, method), (version, method))

    def test_a_method_that_should_succeed_still_fails_loudly(self):
        why = experiment.expected_failure("V3", "symcr")
        self.assertEqual(experiment.flight_status(self.crash, why),
                         "FAIL: autopilot stopped (signal 11)")
        self.assertEqual(experiment.flight_status({"success": True}, why), "ok")

    def test_an_expected_failure_that_succeeds_is_pointed_out(self):
        why = experiment.expected_failure("V1", "raw-image")
        self.assertTrue(experiment.flight_status({"success": True}, why)
                        .startswith("ok, although expected to fail"))


class TableLegend(unittest.TestCase):
    def row(self, version):
        return report.make_row("ISTAR", version, "symcr", [])

    def test_red_team_names_are_explained(self):
        table = report.format_table([self.row("V0"), self.row("RT"), self.row("RT0")], [])
        self.assertIn("version RT: red team: the vulnerable build, crashed by an exploit frame, "
                      "restored into its one-line repair", table)
        self.assertIn("version RT0: red team, CRIU only", table)
        self.assertIn("version V0: the released build; baseline: it flies the whole mission", table)
        self.assertNotIn("V1-V4", table)

    def test_only_names_in_the_table_are_explained(self):
        table = report.format_table([self.row("V2")], [])
        self.assertIn("version V1-V4: the patched builds", table)
        self.assertNotIn("version RT", table)


def label_box(x, y, text):
    """What a 12 px sans-serif label at baseline (x, y) covers, generously (7 px a character)."""
    return (x, y - 11, x + 7 * len(text), y + 3)


def overlaps(a, b):
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


class TrajectoryLabels(unittest.TestCase):
    def test_marker_labels_cover_no_waypoint_label(self):
        with tempfile.TemporaryDirectory() as work:
            mission = os.path.join(work, "m.waypoints")
            with open(mission, "w") as f:
                f.write("QGC WPL 110\n")
                # home, then waypoints 1..4; the markers sit on waypoint 2, next to 3
                for i, (lat, lng) in enumerate([(0, 0), (0.001, 0), (0.001, 0.001),
                                                (0.00103, 0.0011), (0, 0.001)]):
                    f.write("%d 0 3 16 0 0 0 0 %.6f %.6f 20 1\n" % (i, lat, lng))
            track = os.path.join(work, "track.csv")
            with open(track, "w") as f:
                f.write("t,north,east,segment\n0,0,0,0\n1,111,111,0\n2,111,112,1\n3,112,113,2\n")
            here = {"north": 111.3, "east": 111.3, "t": 12.5}
            flight = {"checkpoint_point": here, "resume_point": dict(here, t=12.7),
                      "exploit_point": dict(here, t=12.6), "reason": "mission complete"}
            out = os.path.join(work, "m.svg")
            trajectory_svg.draw(mission, track, flight, "test", out)
            with open(out) as f:
                svg = f.read()
        labels = [(float(x), float(y), text) for x, y, text in
                  re.findall(r'<text x="([0-9.-]+)" y="([0-9.-]+)"[^>]*>([^<]*)</text>', svg)]
        waypoints = [label_box(x, y, t) for x, y, t in labels if re.fullmatch(r"\d+|home", t)]
        markers = [label_box(x, y, t) for x, y, t in labels if "(t=" in t]
        self.assertEqual(len(waypoints), 5)
        self.assertEqual(len(markers), 3)
        for i, box in enumerate(markers):
            for other in waypoints + markers[:i]:
                self.assertFalse(overlaps(box, other), (box, other))


if __name__ == "__main__":
    unittest.main()
