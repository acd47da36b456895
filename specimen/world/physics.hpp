// The real world of the simulation: a rigid quadcopter with four motors, gravity, aerodynamic
// drag, wind with gusts, and the ground. Not part of the autopilot; it does not restart when
// the autopilot does.
#ifndef WORLD_PHYSICS_HPP
#define WORLD_PHYSICS_HPP

#include <array>
#include <random>

namespace world {

struct Vec3 {
  double x = 0, y = 0, z = 0;
  Vec3 operator+(const Vec3& o) const { return {x + o.x, y + o.y, z + o.z}; }
  Vec3 operator-(const Vec3& o) const { return {x - o.x, y - o.y, z - o.z}; }
  Vec3 operator*(double s) const { return {x * s, y * s, z * s}; }
  double dot(const Vec3& o) const { return x * o.x + y * o.y + z * o.z; }
  Vec3 cross(const Vec3& o) const { return {y * o.z - z * o.y, z * o.x - x * o.z, x * o.y - y * o.x}; }
  double norm() const;
};

struct Quat {  // body -> earth, w first
  double w = 1, x = 0, y = 0, z = 0;
  Vec3 rotate(const Vec3& v) const;          // body to earth
  Vec3 inverse_rotate(const Vec3& v) const;  // earth to body
  void integrate(const Vec3& omega_body, double dt);
  void euler(double& roll, double& pitch, double& yaw) const;
  static Quat from_yaw(double yaw);
};

struct Airframe {
  double mass = 1.5;                 // kg
  double motor_thrust_max = 7.5;     // N per motor
  double arm_length = 0.25;          // m
  double yaw_torque_per_n = 0.016;   // m
  Vec3 inertia{0.015, 0.015, 0.028};
  double motor_time_constant = 0.02;  // s
  double drag_linear = 0.08;         // N per m/s
  double drag_quadratic = 0.02;      // N per (m/s)^2
  double rotational_damping = 0.002;  // N m per rad/s
};

struct WindModel {
  Vec3 mean;            // m/s NED
  double gust_sigma = 0.5;
  double gust_tau = 2.0;
};

struct BodyState {
  Vec3 position;  // m NED from the home point (z = 0 is the ground)
  Vec3 velocity;
  Vec3 acceleration;  // of the last step, for the accelerometer
  Quat attitude;
  Vec3 rates;         // body rad/s
  std::array<double, 4> motor{};  // actual thrust fractions (lagging the commands)
  bool on_ground = true;
};

class Physics {
 public:
  Physics(const Airframe& airframe, const WindModel& wind, unsigned seed);

  void step(const std::array<double, 4>& command, double dt);
  const BodyState& state() const { return state_; }
  const Vec3& wind() const { return wind_now_; }
  // Set when the vehicle hit the ground too hard or tipped over.
  bool crashed() const { return crashed_; }
  const char* crash_reason() const { return crash_reason_; }
  double last_touchdown_speed() const { return touchdown_speed_; }

 private:
  Airframe airframe_;
  WindModel wind_;
  BodyState state_;
  Vec3 gust_;
  Vec3 wind_now_;
  std::mt19937_64 rng_;
  std::normal_distribution<double> normal_{0.0, 1.0};
  bool crashed_ = false;
  const char* crash_reason_ = "";
  double touchdown_speed_ = 0;
};

}  // namespace world

#endif  // WORLD_PHYSICS_HPP
