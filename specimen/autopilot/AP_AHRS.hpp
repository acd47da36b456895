// Attitude and position estimation: a Mahony complementary filter for attitude (gyro
// integration corrected by the accelerometer's gravity vector and the compass heading) and a
// complementary position/velocity filter (accelerometer prediction corrected by GPS and baro).
#ifndef AUTOPILOT_AP_AHRS_HPP
#define AUTOPILOT_AP_AHRS_HPP

#include <cstdint>

#include <symcr/symcr.hpp>

#include "AP_HAL.hpp"
#include "AP_Math.hpp"
#include "Location.hpp"

class AP_AHRS {
 public:
  enum class Status : std::uint8_t {
    NOT_INITIALISED = 0,  // collecting samples for the initial alignment
    ALIGNED = 1,          // attitude known, waiting for a GPS origin
    HEALTHY = 2,          // attitude and position known
  };

  void update(const SensorSample& sample, float dt);

  bool healthy() const { return _status == Status::HEALTHY; }
  Status status() const { return _status; }
  const Vector3f& get_gyro() const { return _omega; }
  // Position in metres north/east/down of the origin, velocity NED in m/s.
  const Vector3f& get_position_NED() const { return _position_ned; }
  const Vector3f& get_velocity_NED() const { return _velocity_ned; }
  float get_altitude() const { return -_position_ned.z; }  // m above the origin
  bool get_location(Location& out) const;
  const Location& get_origin() const { return _origin; }
  // North/east/down metres of `loc` relative to the origin (alt relative to home = origin).
  Vector3f location_to_NED(const Location& loc) const;

  // Euler angles (rad) of the current estimate, public as in ArduPilot.
  float roll = 0;
  float pitch = 0;
  float yaw = 0;

 private:
  void align(const SensorSample& sample);
  void update_attitude(const SensorSample& sample, float dt);
  void update_position(const SensorSample& sample, float dt);

  Status _status = Status::NOT_INITIALISED;
  Quaternion _q{1, 0, 0, 0};         // body -> earth
  Vector3f _omega_I{0, 0, 0};        // gyro bias estimate (rad/s)
  Vector3f _omega{0, 0, 0};          // bias-corrected body rates
  Vector3f _accel_ef{0, 0, 0};       // earth-frame acceleration, from GPS velocity changes
  float _error_rp = 0;               // attitude filter health: mean correction magnitudes
  float _error_yaw = 0;
  Location _origin{};                // position origin: the first good GPS fix
  Vector3f _position_ned{0, 0, 0};
  Vector3f _velocity_ned{0, 0, 0};
  float _baro_offset = 0;            // baro reading at the origin
  std::uint32_t _gps_fix_count = 0;
  std::uint32_t _last_gps_ms = 0;

  // Alignment accumulators and raw readings: re-acquired after a restart, never restored.
  std::uint16_t _align_count SYMCR_SKIP = 0;
  Vector3f _align_accel_sum SYMCR_SKIP{0, 0, 0};
  Vector2f _align_heading_sum SYMCR_SKIP{0, 0};  // unit vectors: averages across +-pi
  Vector3f _last_gps_vel SYMCR_SKIP{0, 0, 0};
  SensorSample _last_sample SYMCR_SKIP{};
};

#endif  // AUTOPILOT_AP_AHRS_HPP
