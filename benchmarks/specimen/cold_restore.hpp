// The restore a user does: once, in a build that has just started. Each repetition is a fresh
// process (fork + exec of the benchmark program itself) that opens a copy of the V0 build's
// store and restores its newest checkpoint, next to the raw-image method in the same condition
// (open a file, read sizeof(Copter) bytes, copy them over `copter`), as the experiment's
// autopilot does. The parent prints one line per method with the median, min and max of the
// children's timings; benchmarks/run reports them beside the warm rows.
//
//   <program> --cold-restore N STORE        the parent: N fresh processes per method
//   <program> --cold-restore-child METHOD STORE    one child (internal)
//
// With SYMCR_COLD_COUNTERS=1 in the environment each child also counts its restore call's
// instructions, cycles, iTLB, dTLB and L1i misses (user mode, perf_event_open), and the parent
// prints their medians on a line of its own per method.
#ifndef SYMCR_BENCHMARKS_SPECIMEN_COLD_RESTORE_HPP
#define SYMCR_BENCHMARKS_SPECIMEN_COLD_RESTORE_HPP

namespace specimen_bench {

// Runs the mode named by argv[1] when it is one of the two above; returns -1 otherwise.
// `restored` tells whether the state after a restore is the V0 build's in-flight state.
int run_cold_restore_mode(int argc, char** argv, bool (*restored)());

}  // namespace specimen_bench

#endif  // SYMCR_BENCHMARKS_SPECIMEN_COLD_RESTORE_HPP
