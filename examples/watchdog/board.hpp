// A simulated flight controller for the example: backup RAM that keeps its bytes across a
// reset (here a file mapped into memory), a watchdog whose reset ends the program without
// warning, and the loop both firmware versions run. Each version defines `vehicle` (its
// checkpointed state), `fly_one_loop()` and `print_state()`.
#ifndef EXAMPLES_WATCHDOG_BOARD_HPP
#define EXAMPLES_WATCHDOG_BOARD_HPP

#include <cstdint>

namespace board {

// What the firmware version provides.
extern const char* const kVersion;
void fly_one_loop();  // one control loop of the vehicle
void print_state();   // "state: ..." on one line
std::uint64_t loop_count();

// Runs the firmware: boots, restores, flies, checkpoints, and is reset by the watchdog.
int run(int argc, char** argv);

}  // namespace board

#endif  // EXAMPLES_WATCHDOG_BOARD_HPP
