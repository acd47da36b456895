// Runs the vehicle's tasks at their rates from the main loop (ArduPilot's AP_Scheduler,
// without time slicing: the lock-step world waits for every loop to finish).
#ifndef AUTOPILOT_AP_SCHEDULER_HPP
#define AUTOPILOT_AP_SCHEDULER_HPP

#include <cstdint>

class AP_Scheduler {
 public:
  struct Task {
    void (*function)();
    std::uint16_t rate_hz;
    const char* name;
  };

  static constexpr std::uint16_t kLoopRateHz = 100;

  void init(const Task* tasks, std::uint8_t count) {
    _tasks = tasks;
    _task_count = count;
  }
  void run();
  std::uint32_t ticks() const { return _tick_counter; }

 private:
  const Task* _tasks = nullptr;
  std::uint8_t _task_count = 0;
  std::uint32_t _tick_counter = 0;
};

extern AP_Scheduler scheduler;

#endif  // AUTOPILOT_AP_SCHEDULER_HPP
