// The device profile's header promises no standard containers (a firmware may not have them):
// including it, and through it the generated-code contract, must pull in none. Compiled by
// ctest as C++11; each check names the header that leaked (libstdc++'s and libc++'s guards).
#include "symcr/device.hpp"

#if defined(_GLIBCXX_STRING) || defined(_LIBCPP_STRING)
#error "<symcr/device.hpp> pulls in <string>"
#endif
#if defined(_GLIBCXX_VECTOR) || defined(_LIBCPP_VECTOR)
#error "<symcr/device.hpp> pulls in <vector>"
#endif
#if defined(_GLIBCXX_MEMORY) || defined(_LIBCPP_MEMORY)
#error "<symcr/device.hpp> pulls in <memory>"
#endif
#if defined(_GLIBCXX_FUNCTIONAL) || defined(_LIBCPP_FUNCTIONAL)
#error "<symcr/device.hpp> pulls in <functional>"
#endif
