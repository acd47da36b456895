#include "AP_Scheduler.hpp"

AP_Scheduler scheduler;

void AP_Scheduler::run() {
  for (std::uint8_t i = 0; i < _task_count; ++i) {
    const Task& task = _tasks[i];
    const std::uint32_t interval = task.rate_hz >= kLoopRateHz ? 1 : kLoopRateHz / task.rate_hz;
    if (_tick_counter % interval == 0) task.function();
  }
  ++_tick_counter;
}
