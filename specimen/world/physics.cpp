#include "physics.hpp"

#include <algorithm>
#include <cmath>

namespace world {

namespace {
constexpr double kGravity = 9.80665;
constexpr double kCrashSpeed = 3.0;  // m/s at touchdown
constexpr double kCrashTilt = 0.8;   // rad (46 deg) on the ground
// Motor positions (x forward, y right, per unit arm) and spin: ArduPilot's quad-X order.
constexpr double kMotorX[4] = {0.7071, -0.7071, 0.7071, -0.7071};
constexpr double kMotorY[4] = {0.7071, -0.7071, -0.7071, 0.7071};
constexpr double kMotorSpin[4] = {1, 1, -1, -1};  // +1: counter-clockwise seen from above
}  // namespace

double Vec3::norm() const { return std::sqrt(x * x + y * y + z * z); }

Vec3 Quat::rotate(const Vec3& v) const {
  const Vec3 u{x, y, z};
  const Vec3 t = u.cross(v) * 2.0;
  return v + t * w + u.cross(t);
}

Vec3 Quat::inverse_rotate(const Vec3& v) const {
  const Quat c{w, -x, -y, -z};
  return c.rotate(v);
}

void Quat::integrate(const Vec3& omega, double dt) {
  const double angle = omega.norm() * dt;
  if (angle < 1e-12) return;
  const Vec3 axis = omega * (1.0 / omega.norm());
  const double s = std::sin(angle / 2), c = std::cos(angle / 2);
  const Quat d{c, axis.x * s, axis.y * s, axis.z * s};
  const Quat r{w * d.w - x * d.x - y * d.y - z * d.z, w * d.x + x * d.w + y * d.z - z * d.y,
               w * d.y - x * d.z + y * d.w + z * d.x, w * d.z + x * d.y - y * d.x + z * d.w};
  const double n = std::sqrt(r.w * r.w + r.x * r.x + r.y * r.y + r.z * r.z);
  *this = {r.w / n, r.x / n, r.y / n, r.z / n};
}

void Quat::euler(double& roll, double& pitch, double& yaw) const {
  roll = std::atan2(2 * (w * x + y * z), 1 - 2 * (x * x + y * y));
  pitch = std::asin(std::clamp(2 * (w * y - z * x), -1.0, 1.0));
  yaw = std::atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z));
}

Quat Quat::from_yaw(double yaw) { return {std::cos(yaw / 2), 0, 0, std::sin(yaw / 2)}; }

Physics::Physics(const Airframe& airframe, const WindModel& wind, unsigned seed)
    : airframe_(airframe), wind_(wind), rng_(seed) {}

void Physics::step(const std::array<double, 4>& command, double dt) {
  BodyState& s = state_;
  // Motors follow their commands with a first-order lag.
  double thrust[4];
  double total = 0;
  Vec3 torque;
  const double alpha = dt / (airframe_.motor_time_constant + dt);
  for (int i = 0; i < 4; ++i) {
    s.motor[i] += (std::clamp(command[i], 0.0, 1.0) - s.motor[i]) * alpha;
    thrust[i] = s.motor[i] * airframe_.motor_thrust_max;
    total += thrust[i];
    torque.x += -kMotorY[i] * airframe_.arm_length * thrust[i];
    torque.y += kMotorX[i] * airframe_.arm_length * thrust[i];
    torque.z += kMotorSpin[i] * airframe_.yaw_torque_per_n * thrust[i];
  }
  torque = torque - s.rates * airframe_.rotational_damping;

  // Wind: a mean plus first-order Gauss-Markov gusts.
  const double decay = std::exp(-dt / wind_.gust_tau);
  const double drive = wind_.gust_sigma * std::sqrt(1 - decay * decay);
  gust_ = gust_ * decay + Vec3{normal_(rng_), normal_(rng_), 0.3 * normal_(rng_)} * drive;
  wind_now_ = wind_.mean + gust_;

  const Vec3 air = s.velocity - wind_now_;
  const Vec3 drag = air * (-airframe_.drag_linear - airframe_.drag_quadratic * air.norm());
  const Vec3 force = s.attitude.rotate(Vec3{0, 0, -total}) + Vec3{0, 0, airframe_.mass * kGravity} + drag;
  Vec3 accel = force * (1.0 / airframe_.mass);

  // Rotational dynamics: I w' = tau - w x I w.
  const Vec3& I = airframe_.inertia;
  const Vec3 Iw{I.x * s.rates.x, I.y * s.rates.y, I.z * s.rates.z};
  const Vec3 net = torque - s.rates.cross(Iw);
  Vec3 rates = s.rates + Vec3{net.x / I.x, net.y / I.y, net.z / I.z} * dt;

  Vec3 velocity = s.velocity + accel * dt;
  Vec3 position = s.position + velocity * dt;

  // The ground: z = 0. Touching it stops the fall; touching it hard or tilted is a crash.
  if (position.z >= 0.0) {
    double roll, pitch, yaw;
    s.attitude.euler(roll, pitch, yaw);
    if (!s.on_ground) {
      touchdown_speed_ = velocity.norm();
      if (touchdown_speed_ > kCrashSpeed && !crashed_) {
        crashed_ = true;
        crash_reason_ = "hit the ground too fast";
      }
      if ((std::fabs(roll) > kCrashTilt || std::fabs(pitch) > kCrashTilt) && !crashed_) {
        crashed_ = true;
        crash_reason_ = "touched down tilted";
      }
    }
    const bool lifting = total > airframe_.mass * kGravity * 1.0001;
    if (!lifting) {
      position.z = 0.0;
      velocity = Vec3{};
      accel = Vec3{};
      rates = Vec3{};
      s.attitude = Quat::from_yaw(yaw);  // the landing gear levels the frame
      s.on_ground = true;
    } else {
      position.z = std::min(position.z, 0.0);
      s.on_ground = false;
    }
  } else {
    s.on_ground = false;
  }
  s.attitude.integrate(rates, dt);
  s.rates = rates;
  s.velocity = velocity;
  s.position = position;
  s.acceleration = accel;
}

}  // namespace world
