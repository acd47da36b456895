// v1: fields reordered, one removed, one added, one renamed.
#include "check.hpp"

struct Config {
  char tag;
  float b;
  int a;
  int added = 7;
  int new_name SYMCR_RENAMED_FROM("old_name");
};

SYMCR_CHECKPOINT Config config;

int main(int argc, char** argv) {
  config = Config{};
  config.added = 7;
  symcr::Report report = xv::restore(argc, argv);
  XV_CHECK(report.ok());
  XV_CHECK(config.a == 1);
  XV_CHECK(config.b == 3.5f);
  XV_CHECK(config.tag == 'x');
  XV_CHECK(config.new_name == 42);
  XV_CHECK(config.added == 7);
  XV_CHECK(xv::decided(report, "config.removed", symcr::Decision::Dropped));
  XV_CHECK(xv::decided(report, "config.added", symcr::Decision::Kept));
  XV_CHECK(xv::decided(report, "config.new_name", symcr::Decision::Converted));
  XV_CHECK(xv::restored(report, "config.a"));
  return xv::verdict();
}
