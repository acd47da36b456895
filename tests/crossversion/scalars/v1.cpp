// v1: integers widened and narrowed, int -> double, float -> double, double -> int.
#include <cstdint>

#include "check.hpp"

struct Sensors {
  std::int32_t widened;
  std::int16_t narrowed_fits;
  std::int8_t narrowed_overflows = 5;  // 300 does not fit: rejected, keeps 5
  double to_double;
  double float_to_double;
  std::int32_t double_to_int;
  std::int16_t unsigned_to_signed;
  bool flag;
  long double precise;
};

SYMCR_CHECKPOINT Sensors sensors;

int main(int argc, char** argv) {
  sensors = Sensors{};
  sensors.narrowed_overflows = 5;
  symcr::Report report = xv::restore(argc, argv);
  XV_CHECK(report.ok());
  XV_CHECK(sensors.widened == -1234);
  XV_CHECK(sensors.narrowed_fits == 1000);
  XV_CHECK(sensors.narrowed_overflows == 5);
  XV_CHECK(sensors.to_double == 77.0);
  XV_CHECK(sensors.float_to_double == 1.25);
  XV_CHECK(sensors.double_to_int == 41);
  XV_CHECK(sensors.unsigned_to_signed == 200);
  XV_CHECK(sensors.flag);
  XV_CHECK(sensors.precise == 2.5L);
  XV_CHECK(xv::decided(report, "sensors.widened", symcr::Decision::Converted));
  XV_CHECK(xv::decided(report, "sensors.narrowed_fits", symcr::Decision::Converted));
  XV_CHECK(xv::decided(report, "sensors.narrowed_overflows", symcr::Decision::Rejected));
  XV_CHECK(xv::decided(report, "sensors.to_double", symcr::Decision::Converted));
  XV_CHECK(xv::decided(report, "sensors.float_to_double", symcr::Decision::Converted));
  XV_CHECK(xv::restored(report, "sensors.flag"));
  // Strict mode refuses the lossy narrowing and writes nothing.
  sensors.widened = 9;
  symcr::Report strict = xv::restore(argc, argv, /*strict=*/true);
  XV_CHECK(!strict.ok());
  XV_CHECK(sensors.widened == 9);
  return xv::verdict();
}
