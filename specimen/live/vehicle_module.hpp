// The entry points of a vehicle module (copter_vK_live): one version of the autopilot's vehicle
// code (what holds `copter` and its classes) built as a loadable module, for the live host
// (copter_live.cpp), which loads V0's, flies it, and switches to Vk's while flying. Each module
// has its own globals, its own symcr runtime and generated schema (symcr_program_schema), and
// is loaded RTLD_LOCAL; the two links to the world are handed from module to module.
#ifndef SPECIMEN_LIVE_VEHICLE_MODULE_HPP
#define SPECIMEN_LIVE_VEHICLE_MODULE_HPP

#include "channel.hpp"
#include "messages.hpp"

extern "C" {
// Start-up that touches no link: the scheduler, parameters, an empty mission.
void specimen_vehicle_setup();
// The module's ends of the links (0: sim, 1: gcs): the host sets them, and copies them from the
// old module to the new at a switch (a frame half-received stays received).
mav::Channel* specimen_vehicle_link(int which);
// One loop: this frame's sensors, the vehicle's loop, the motor outputs sent. False when the
// world is gone.
bool specimen_vehicle_step(const mav::SimSensors* sensors);
// After the state was transferred in: rebuilds what is derived from it (as after a restore),
// with this frame's sensors.
void specimen_vehicle_resume(const mav::SimSensors* sensors);
}

#endif  // SPECIMEN_LIVE_VEHICLE_MODULE_HPP
