"""Aggregates flights into the rows of the paper's Table 1, prints the table, writes JSON."""
import collections
import json
import statistics

ROW_FIELDS = ("mission", "version", "method", "runs", "successes", "time_s_mean", "time_s_sd",
              "checkpoint_bytes", "checkpoint_us_mean", "restore_us_mean", "failures")


def _mean(values):
    return statistics.fmean(values) if values else None


def make_row(mission, version, method, flights):
    """One table row from the sitl_world results of one mission x version x method cell."""
    ok = [f for f in flights if f["success"]]
    times = [f["mission_time_s"] for f in ok]
    saved = [f for f in flights if f.get("checkpoints_saved", 0) > 0]
    restored = [f for f in flights if f.get("restored") and f.get("restore_us", -1) >= 0]
    return {
        "mission": mission,
        "version": version,
        "method": method,
        "runs": len(flights),
        "successes": len(ok),
        "time_s_mean": _mean(times),
        "time_s_sd": statistics.stdev(times) if len(times) > 1 else (0.0 if times else None),
        "checkpoint_bytes": max((f["checkpoint_bytes"] for f in saved), default=None),
        "checkpoint_us_mean": _mean([f["checkpoint_us_mean"] for f in saved]),
        "restore_us_mean": _mean([f["restore_us"] for f in restored]),
        "failures": dict(collections.Counter(f["reason"] for f in flights if not f["success"])),
    }


def _fmt(value, spec):
    return "-" if value is None else format(value, spec)


# What the Version column's names mean, printed under the table for those that appear.
VERSION_LEGEND = (
    ({"V0"}, "V0: the released build; baseline: it flies the whole mission without a stop; with "
             "a method: its checkpoint restored into V0 itself (the control)"),
    ({"V1", "V2", "V3", "V4"}, "V1-V4: the patched builds (specimen/README.md, versions)"),
    ({"RT"}, "RT: red team: the vulnerable build, crashed by an exploit frame, restored into "
             "its one-line repair"),
    ({"RT0"}, "RT0: red team, CRIU only: restored into the vulnerable build itself (the only "
              "executable CRIU accepts), which the exploit's second try crashes again"),
)


def format_table(rows, notes):
    header = ("Mission", "Version", "Method", "Runs", "Time (s)", "Ckpt (B)", "Ckpt (us)",
              "Restore (us)", "Success")
    lines = []
    for r in rows:
        time = "-" if r["time_s_mean"] is None else "%.1f ± %.1f" % (r["time_s_mean"], r["time_s_sd"])
        success = "n/a" if r["runs"] == 0 else "%d%%" % round(100.0 * r["successes"] / r["runs"])
        lines.append((r["mission"], r["version"], r["method"], str(r["runs"]), time,
                      _fmt(r["checkpoint_bytes"], "d"), _fmt(r["checkpoint_us_mean"], ".2f"),
                      _fmt(r["restore_us_mean"], ".1f"), success))
    widths = [max(len(h), *(len(l[i]) for l in lines)) if lines else len(h)
              for i, h in enumerate(header)]

    def render(cells):
        return "  ".join(c.ljust(w) if i < 3 else c.rjust(w) for i, (c, w) in enumerate(zip(cells, widths)))

    out = ["Table 1: resuming a mission after a checkpoint, kill -9 and restart into a patched build",
           render(header), render(["-" * w for w in widths])]
    out += [render(l) for l in lines]
    versions = {r["version"] for r in rows}
    out += ["version " + text for names, text in VERSION_LEGEND if names & versions]
    out += ["note: " + n for n in notes]
    return "\n".join(out)


def write_json(rows, path):
    with open(path, "w") as f:
        json.dump([{k: r[k] for k in ROW_FIELDS} for r in rows], f, indent=2)
        f.write("\n")
