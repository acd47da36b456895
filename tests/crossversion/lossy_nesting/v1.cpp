// v1 of lossy_nesting: strict mode refuses the checkpoint and writes nothing; the default mode
// restores what can be restored and reports every lossy decision at the level it happens.
#include <string>
#include <vector>

#include "check.hpp"

struct Gain {
  int id;
  double k;
};
bool symcr_validate(const Gain& gain);
bool symcr_validate(const Gain& gain) { return gain.k >= 0; }

struct Calibration {
  double m[2][2];  // each row loses its third value
  std::vector<Gain> gains;
  std::u32string label;
  std::string callsign;
  std::u16string raw;
};

SYMCR_CHECKPOINT Calibration cal;

namespace {

void set_initial() {
  cal.m[0][0] = cal.m[0][1] = cal.m[1][0] = cal.m[1][1] = -1;
  cal.gains = {{9, 9}};
  cal.label = U"initial";
  cal.callsign = "initial";
  cal.raw = u"initial";
}

bool initial() {
  return cal.m[0][0] == -1 && cal.m[1][1] == -1 && cal.gains.size() == 1 &&
         cal.gains[0].id == 9 && cal.label == U"initial" && cal.callsign == "initial" &&
         cal.raw == u"initial";
}

bool lossy(const symcr::Report& report, const char* path) {
  for (const symcr::ReportEntry& e : report.entries()) {
    if (e.path == path && e.lossy) return true;
  }
  std::fprintf(stderr, "no lossy entry for '%s'\n", path);
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  set_initial();
  const symcr::Report strict = xv::restore(argc, argv, /*strict=*/true);
  XV_CHECK(!strict.ok());
  XV_CHECK(strict.status().error() == symcr::Error::Strict);
  XV_CHECK(initial());

  set_initial();
  const symcr::Report report = xv::restore(argc, argv);
  XV_CHECK(report.ok());
  // [2][3] -> [2][2]: the common prefix of each row, and the loss is said.
  XV_CHECK(cal.m[0][0] == 1 && cal.m[0][1] == 2 && cal.m[1][0] == 4 && cal.m[1][1] == 5);
  XV_CHECK(xv::decided(report, "cal.m", symcr::Decision::Converted));
  XV_CHECK(lossy(report, "cal.m"));
  // The refused gain is left out, not inserted value-initialised.
  XV_CHECK(cal.gains.size() == 2);
  XV_CHECK(cal.gains.size() == 2 && cal.gains[0].id == 1 && cal.gains[1].id == 3);
  XV_CHECK(xv::decided(report, "cal.gains[1]", symcr::Decision::Rejected));
  XV_CHECK(lossy(report, "cal.gains[1]"));
  // Re-encoded by code point, not copied unit by unit.
  XV_CHECK(cal.label == U"Z\u00fcrich \u2192 \U0001F681");
  XV_CHECK(cal.callsign == "N\xc3\xa9o-\xf0\x9f\x9a\x81");
  XV_CHECK(xv::decided(report, "cal.label", symcr::Decision::Converted));
  // Bytes that are not UTF-8 cannot become UTF-16: rejected, v1's value kept.
  XV_CHECK(cal.raw == u"initial");
  XV_CHECK(xv::decided(report, "cal.raw", symcr::Decision::Rejected));
  XV_CHECK(lossy(report, "cal.raw"));
  return xv::verdict();
}
