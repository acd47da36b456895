#include "AP_Math.hpp"

Quaternion Quaternion::from_euler(float roll, float pitch, float yaw) {
  const float cr = std::cos(roll * 0.5f), sr = std::sin(roll * 0.5f);
  const float cp = std::cos(pitch * 0.5f), sp = std::sin(pitch * 0.5f);
  const float cy = std::cos(yaw * 0.5f), sy = std::sin(yaw * 0.5f);
  return {cr * cp * cy + sr * sp * sy, sr * cp * cy - cr * sp * sy,
          cr * sp * cy + sr * cp * sy, cr * cp * sy - sr * sp * cy};
}

void Quaternion::to_euler(float& roll, float& pitch, float& yaw) const {
  roll = std::atan2(2.0f * (q1 * q2 + q3 * q4), 1.0f - 2.0f * (q2 * q2 + q3 * q3));
  pitch = std::asin(constrain_value(2.0f * (q1 * q3 - q4 * q2), -1.0f, 1.0f));
  yaw = std::atan2(2.0f * (q1 * q4 + q2 * q3), 1.0f - 2.0f * (q3 * q3 + q4 * q4));
}

void Quaternion::rotate(const Vector3f& v) {
  const float angle = v.length();
  if (angle < 1e-9f) return;
  const float s = std::sin(angle * 0.5f) / angle;
  const float d1 = std::cos(angle * 0.5f), d2 = v.x * s, d3 = v.y * s, d4 = v.z * s;
  const Quaternion r{q1 * d1 - q2 * d2 - q3 * d3 - q4 * d4, q1 * d2 + q2 * d1 + q3 * d4 - q4 * d3,
                     q1 * d3 - q2 * d4 + q3 * d1 + q4 * d2, q1 * d4 + q2 * d3 - q3 * d2 + q4 * d1};
  *this = r;
  normalize();
}

void Quaternion::normalize() {
  const float n = std::sqrt(q1 * q1 + q2 * q2 + q3 * q3 + q4 * q4);
  if (n < 1e-6f) {
    *this = {1, 0, 0, 0};
    return;
  }
  q1 /= n; q2 /= n; q3 /= n; q4 /= n;
}

Vector3f Quaternion::body_to_earth(const Vector3f& v) const {
  const float a = q1, b = q2, c = q3, d = q4;
  return {(a * a + b * b - c * c - d * d) * v.x + 2 * (b * c - a * d) * v.y + 2 * (a * c + b * d) * v.z,
          2 * (b * c + a * d) * v.x + (a * a - b * b + c * c - d * d) * v.y + 2 * (c * d - a * b) * v.z,
          2 * (b * d - a * c) * v.x + 2 * (a * b + c * d) * v.y + (a * a - b * b - c * c + d * d) * v.z};
}

Vector3f Quaternion::earth_to_body(const Vector3f& v) const {
  const Quaternion inverse{q1, -q2, -q3, -q4};
  return inverse.body_to_earth(v);
}

float sqrt_controller(float error, float p, float second_ord_lim, float dt) {
  float correction;
  if (second_ord_lim <= 0.0f || p <= 0.0f) {
    correction = error * p;
  } else {
    const float linear_dist = second_ord_lim / sq(p);
    if (error > linear_dist) {
      correction = std::sqrt(2.0f * second_ord_lim * (error - linear_dist / 2.0f));
    } else if (error < -linear_dist) {
      correction = -std::sqrt(2.0f * second_ord_lim * (-error - linear_dist / 2.0f));
    } else {
      correction = error * p;
    }
  }
  if (dt > 0.0f) {
    // Never ask for more than closes the error in one step.
    const float limit = std::fabs(error) / dt;
    correction = constrain_value(correction, -limit, limit);
  }
  return correction;
}
