// A vehicle module's entry points (vehicle_module.hpp), compiled with one version's sources.
#include "vehicle_module.hpp"

#include "AP_HAL.hpp"
#include "AP_Motors.hpp"
#include "Copter.hpp"

extern "C" {

void specimen_vehicle_setup() { copter.setup(); }

mav::Channel* specimen_vehicle_link(int which) { return which == 0 ? &hal.sim : &hal.gcs; }

bool specimen_vehicle_step(const mav::SimSensors* sensors) {
  hal.apply_sensors(*sensors);
  copter.loop();
  return hal.send_motors(motors.outputs());
}

void specimen_vehicle_resume(const mav::SimSensors* sensors) {
  hal.apply_sensors(*sensors);
  copter.resume_after_restore();
}

}  // extern "C"
