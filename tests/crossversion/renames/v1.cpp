// v1: the root, its type and a field renamed, with both the macro and the pragma forms.
#include "check.hpp"

struct SYMCR_RENAMED_FROM("Settings") Parameters {
  int gain;
  int max_limit;
};
#pragma symcr renamed(Parameters::max_limit, limit)

Parameters parameters;
#pragma symcr checkpoint(parameters)
#pragma symcr renamed(parameters, tuning)

int main(int argc, char** argv) {
  symcr::Report report = xv::restore(argc, argv);
  XV_CHECK(report.ok());
  XV_CHECK(parameters.gain == 12);
  XV_CHECK(parameters.max_limit == 300);
  XV_CHECK(xv::decided(report, "parameters.max_limit", symcr::Decision::Converted));
  return xv::verdict();
}
