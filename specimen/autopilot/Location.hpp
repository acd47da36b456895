// A point on the earth, as ArduPilot stores it: 1e-7 degrees and centimetres above home.
// Trivially constructible on purpose: it lives inside AP_Mission's command union.
#ifndef AUTOPILOT_LOCATION_HPP
#define AUTOPILOT_LOCATION_HPP

#include <cstdint>

#include "AP_Math.hpp"

struct Location {
  std::uint8_t relative_alt : 1;  // alt is relative to home (always, in this autopilot)
  std::uint8_t loiter_ccw : 1;    // loiter direction, kept for mission compatibility
  std::int32_t alt;               // cm
  std::int32_t lat;               // 1e-7 degrees
  std::int32_t lng;               // 1e-7 degrees

  static Location make(std::int32_t lat, std::int32_t lng, std::int32_t alt_cm);
  bool is_zero() const { return lat == 0 && lng == 0; }
  // North/east metres from this location to `other`.
  Vector2f get_distance_NE(const Location& other) const;
  float get_distance(const Location& other) const { return get_distance_NE(other).length(); }
  // Moves this location by north/east metres.
  void offset(float north_m, float east_m);
};

#endif  // AUTOPILOT_LOCATION_HPP
