// Lat/lon <-> local north/east metres, as ArduPilot's Location does it (equirectangular around
// the reference point; exact enough for routes of a few kilometres), and great-circle lengths.
#ifndef SPECIMEN_LINK_GEO_HPP
#define SPECIMEN_LINK_GEO_HPP

#include <cmath>
#include <cstdint>

namespace geo {

constexpr double kEarthRadius = 6378100.0;                    // ArduPilot's RADIUS_OF_EARTH
constexpr double kDegToRad = 3.14159265358979323846 / 180.0;
constexpr double kLatLonToM = kEarthRadius * kDegToRad * 1e-7;  // metres per 1e-7 degree

inline double longitude_scale(std::int32_t lat_e7) {
  const double scale = std::cos(lat_e7 * 1e-7 * kDegToRad);
  return scale < 0.01 ? 0.01 : scale;
}

// North/east metres from (lat0, lng0) to (lat, lng).
inline void offset_ne(std::int32_t lat0, std::int32_t lng0, std::int32_t lat, std::int32_t lng,
                      double& north, double& east) {
  north = (static_cast<double>(lat) - lat0) * kLatLonToM;
  east = (static_cast<double>(lng) - lng0) * kLatLonToM * longitude_scale(lat0);
}

inline void add_ne(std::int32_t lat0, std::int32_t lng0, double north, double east,
                   std::int32_t& lat, std::int32_t& lng) {
  lat = static_cast<std::int32_t>(std::lround(lat0 + north / kLatLonToM));
  lng = static_cast<std::int32_t>(std::lround(lng0 + east / (kLatLonToM * longitude_scale(lat0))));
}

// Great-circle distance in metres (haversine), the "true" length of a route leg.
inline double haversine(double lat1_deg, double lng1_deg, double lat2_deg, double lng2_deg) {
  const double p1 = lat1_deg * kDegToRad, p2 = lat2_deg * kDegToRad;
  const double dp = p2 - p1, dl = (lng2_deg - lng1_deg) * kDegToRad;
  const double a = std::sin(dp / 2) * std::sin(dp / 2) +
                   std::cos(p1) * std::cos(p2) * std::sin(dl / 2) * std::sin(dl / 2);
  return 2 * kEarthRadius * std::atan2(std::sqrt(a), std::sqrt(1 - a));
}

}  // namespace geo

#endif  // SPECIMEN_LINK_GEO_HPP
