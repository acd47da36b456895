// The operator's ground station: uploads the mission, selects AUTO, arms, sends heartbeats,
// and follows the vehicle's reports. In red-team runs it is also the attacker's radio.
#ifndef WORLD_GROUND_STATION_HPP
#define WORLD_GROUND_STATION_HPP

#include <cstdint>
#include <string>
#include <vector>

#include "channel.hpp"
#include "mission_file.hpp"

namespace world {

class GroundStation {
 public:
  explicit GroundStation(const Mission& mission) : mission_(mission) {}

  // Called once per loop after the autopilot answered. `link` is the current process's link.
  void update(mav::Channel& link, double time_s);
  // After a restart the new autopilot already has the mission (restored): just keep talking.
  void on_autopilot_restarted() { last_heartbeat_s_ = -1; }
  // Sends the crafted NAMED_VALUE_FLOAT frame of the red-team exploit.
  void send_exploit(mav::Channel& link);
  // The operator switches the flight mode (mav::MODE_LOITER to pause, MODE_AUTO to resume).
  void send_mode(mav::Channel& link, std::uint32_t mode);

  bool armed() const { return armed_; }
  bool mission_started() const { return started_; }
  double arm_time_s() const { return arm_time_s_; }
  std::uint32_t mode() const { return mode_; }
  int mission_current() const { return mission_current_; }
  const std::vector<int>& items_reached() const { return items_reached_; }
  const std::vector<std::string>& texts() const { return texts_; }

 private:
  enum class Phase { WaitHeartbeat, Uploading, SetAuto, Arming, Flying };

  void handle(mav::Channel& link, const mav::Frame& frame, double time_s);
  void send_item(mav::Channel& link, int seq);

  const Mission& mission_;
  Phase phase_ = Phase::WaitHeartbeat;
  double last_heartbeat_s_ = -1;
  double last_request_s_ = -1;
  bool armed_ = false;
  bool started_ = false;
  double arm_time_s_ = 0;
  std::uint32_t mode_ = 0;
  int mission_current_ = -1;
  std::vector<int> items_reached_;
  std::vector<std::string> texts_;
};

}  // namespace world

#endif  // WORLD_GROUND_STATION_HPP
