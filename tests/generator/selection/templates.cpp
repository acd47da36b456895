// Directives naming typedefs (one specialisation) and class templates (all of them).
#include <symcr/symcr.hpp>

template <typename T>
struct AP_Param {
  T value;
  T backup;
};
typedef AP_Param<signed char> AP_Int8;
using AP_Float = AP_Param<float>;

struct Copter {
  AP_Int8 gain;
  AP_Float rate;
  AP_Param<int> count;
  AP_Param<short> trim;
};
SYMCR_CHECKPOINT Copter copter;

#pragma symcr skip(AP_Int8::backup)
#pragma symcr renamed(AP_Param::value, val)
#pragma symcr skip(AP_Param<int16>)
