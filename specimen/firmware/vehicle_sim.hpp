// What the firmware's vehicle senses and is told, without a world or a ground station: it
// stands level at the field with a 3D GPS fix, is given a mission, is armed in AUTO, and flies
// loops of 10 ms.
#ifndef SPECIMEN_FIRMWARE_VEHICLE_SIM_HPP
#define SPECIMEN_FIRMWARE_VEHICLE_SIM_HPP

namespace firmware {

// Takeoff to 10 m, two waypoints, land; then arms in AUTO. False if the vehicle refused.
bool start_mission();
// `loops` loops of the vehicle (sensors, copter.loop(), its scheduler's checkpoint task).
void fly(unsigned loops);

}  // namespace firmware

#endif  // SPECIMEN_FIRMWARE_VEHICLE_SIM_HPP
