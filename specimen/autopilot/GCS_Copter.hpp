// The ground-control side of the vehicle: mission upload protocol, mode and arming commands,
// heartbeats and mission progress reports, over hal.gcs.
#ifndef AUTOPILOT_GCS_COPTER_HPP
#define AUTOPILOT_GCS_COPTER_HPP

#include <cstdint>

#include "frame.hpp"

class GCS_Copter {
 public:
  // Handles every frame that arrived since the last loop.
  void update_receive();
  void send_heartbeat();
  void send_mission_current(std::uint16_t seq);
  void send_mission_item_reached(std::uint16_t seq);
  void send_text(const char* text);

 private:
  void handle_message(const mav::Frame& frame);
  void handle_mission_count(const mav::Frame& frame);
  void handle_mission_item(const mav::Frame& frame);
  void handle_command_long(const mav::Frame& frame);
  void handle_set_mode(const mav::Frame& frame);
  void request_next_item();

  // Mission upload in progress.
  bool _receiving_mission = false;
  std::uint16_t _upload_count = 0;
  std::uint16_t _upload_next = 0;
  std::uint32_t _frames_received = 0;
};

#endif  // AUTOPILOT_GCS_COPTER_HPP
