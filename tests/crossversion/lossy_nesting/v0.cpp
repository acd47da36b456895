// v0: lossy decisions below the top level, each of which v1's restore must report (and strict
// mode refuse): an inner array dimension that shrinks, container elements a validator refuses,
// and strings whose character width changes.
#include <string>
#include <vector>

#include "check.hpp"

struct Gain {
  int id;
  double k;
};

struct Calibration {
  double m[2][3];
  std::vector<Gain> gains;
  std::string label;        // UTF-8; v1: std::u32string
  std::u16string callsign;  // UTF-16 with a surrogate pair; v1: std::string
  std::string raw;          // not UTF-8; v1: std::u16string, so it cannot be re-encoded
};

SYMCR_CHECKPOINT Calibration cal;

int main(int argc, char** argv) {
  double v = 1;
  for (auto& row : cal.m) {
    for (double& x : row) x = v++;
  }
  cal.gains = {{1, 0.5}, {2, -7.0}, {3, 1.5}};  // v1 refuses negative gains
  cal.label = "Z\xc3\xbcrich \xe2\x86\x92 \xf0\x9f\x9a\x81";  // "Zürich → 🚁"
  cal.callsign = u"N\u00e9o-\U0001F681";
  cal.raw = std::string("\xff\xfe\x01", 3);
  return xv::save(argc, argv);
}
