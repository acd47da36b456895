#include "Location.hpp"

namespace {
constexpr double kLatLonToM = 6378100.0 * 3.14159265358979323846 / 180.0 * 1e-7;

double longitude_scale(std::int32_t lat) {
  const double scale = std::cos(lat * 1e-7 * 3.14159265358979323846 / 180.0);
  return scale < 0.01 ? 0.01 : scale;
}
}  // namespace

Location Location::make(std::int32_t lat, std::int32_t lng, std::int32_t alt_cm) {
  Location loc{};
  loc.relative_alt = 1;
  loc.lat = lat;
  loc.lng = lng;
  loc.alt = alt_cm;
  return loc;
}

Vector2f Location::get_distance_NE(const Location& other) const {
  return {static_cast<float>((static_cast<double>(other.lat) - lat) * kLatLonToM),
          static_cast<float>((static_cast<double>(other.lng) - lng) * kLatLonToM *
                             longitude_scale(lat))};
}

void Location::offset(float north_m, float east_m) {
  lat += static_cast<std::int32_t>(std::lround(north_m / kLatLonToM));
  lng += static_cast<std::int32_t>(std::lround(east_m / (kLatLonToM * longitude_scale(lat))));
}
