// The small vector/quaternion toolkit the autopilot needs (ArduPilot's AP_Math, reduced).
#ifndef AUTOPILOT_AP_MATH_HPP
#define AUTOPILOT_AP_MATH_HPP

#include <cmath>
#include <cstdint>

constexpr float GRAVITY_MSS = 9.80665f;
constexpr float M_PI_F = 3.14159265f;

template <class T>
T constrain_value(T value, T low, T high) {
  return value < low ? low : (value > high ? high : value);
}

inline float sq(float v) { return v * v; }

inline float wrap_PI(float angle) {
  while (angle > M_PI_F) angle -= 2 * M_PI_F;
  while (angle < -M_PI_F) angle += 2 * M_PI_F;
  return angle;
}

struct Vector2f {
  float x, y;
  float length() const { return std::sqrt(x * x + y * y); }
  Vector2f operator+(const Vector2f& o) const { return {x + o.x, y + o.y}; }
  Vector2f operator-(const Vector2f& o) const { return {x - o.x, y - o.y}; }
  Vector2f operator*(float s) const { return {x * s, y * s}; }
  float operator*(const Vector2f& o) const { return x * o.x + y * o.y; }
};

struct Vector3f {
  float x, y, z;
  Vector3f operator+(const Vector3f& o) const { return {x + o.x, y + o.y, z + o.z}; }
  Vector3f operator-(const Vector3f& o) const { return {x - o.x, y - o.y, z - o.z}; }
  Vector3f operator*(float s) const { return {x * s, y * s, z * s}; }
  Vector3f& operator+=(const Vector3f& o) { x += o.x; y += o.y; z += o.z; return *this; }
  float operator*(const Vector3f& o) const { return x * o.x + y * o.y + z * o.z; }
  Vector3f operator%(const Vector3f& o) const {  // cross product
    return {y * o.z - z * o.y, z * o.x - x * o.z, x * o.y - y * o.x};
  }
  float length() const { return std::sqrt(x * x + y * y + z * z); }
  Vector2f xy() const { return {x, y}; }
};

// Body-to-earth rotation (q1 = w). Kept normalised by its users.
struct Quaternion {
  float q1, q2, q3, q4;

  static Quaternion from_euler(float roll, float pitch, float yaw);
  void to_euler(float& roll, float& pitch, float& yaw) const;
  // Integrates a body-frame rotation vector (rad).
  void rotate(const Vector3f& v);
  void normalize();
  Vector3f body_to_earth(const Vector3f& v) const;
  Vector3f earth_to_body(const Vector3f& v) const;
};

// ArduPilot's sqrt_controller: P control near the target, constant deceleration far from it.
float sqrt_controller(float error, float p, float second_ord_lim, float dt);

#endif  // AUTOPILOT_AP_MATH_HPP
