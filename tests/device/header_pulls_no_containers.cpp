// The device profile's header promises no standard containers (a firmware may not have them):
// including it, and through it the generated-code contract, must pull in none of them, nor the
// other heavy standard headers (algorithms, streams, vocabulary types). Compiled by
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
#if defined(_GLIBCXX_MAP) || defined(_LIBCPP_MAP)
#error "<symcr/device.hpp> pulls in <map>"
#endif
#if defined(_GLIBCXX_SET) || defined(_LIBCPP_SET)
#error "<symcr/device.hpp> pulls in <set>"
#endif
#if defined(_GLIBCXX_UNORDERED_MAP) || defined(_LIBCPP_UNORDERED_MAP)
#error "<symcr/device.hpp> pulls in <unordered_map>"
#endif
#if defined(_GLIBCXX_UNORDERED_SET) || defined(_LIBCPP_UNORDERED_SET)
#error "<symcr/device.hpp> pulls in <unordered_set>"
#endif
#if defined(_GLIBCXX_DEQUE) || defined(_LIBCPP_DEQUE)
#error "<symcr/device.hpp> pulls in <deque>"
#endif
#if defined(_GLIBCXX_LIST) || defined(_LIBCPP_LIST)
#error "<symcr/device.hpp> pulls in <list>"
#endif
#if defined(_GLIBCXX_FORWARD_LIST) || defined(_LIBCPP_FORWARD_LIST)
#error "<symcr/device.hpp> pulls in <forward_list>"
#endif
#if defined(_GLIBCXX_ARRAY) || defined(_LIBCPP_ARRAY)
#error "<symcr/device.hpp> pulls in <array>"
#endif
#if defined(_GLIBCXX_QUEUE) || defined(_LIBCPP_QUEUE)
#error "<symcr/device.hpp> pulls in <queue>"
#endif
#if defined(_GLIBCXX_STACK) || defined(_LIBCPP_STACK)
#error "<symcr/device.hpp> pulls in <stack>"
#endif
#if defined(_GLIBCXX_BITSET) || defined(_LIBCPP_BITSET)
#error "<symcr/device.hpp> pulls in <bitset>"
#endif
#if defined(_GLIBCXX_STRING_VIEW) || defined(_LIBCPP_STRING_VIEW)
#error "<symcr/device.hpp> pulls in <string_view>"
#endif
#if defined(_GLIBCXX_OPTIONAL) || defined(_LIBCPP_OPTIONAL)
#error "<symcr/device.hpp> pulls in <optional>"
#endif
#if defined(_GLIBCXX_VARIANT) || defined(_LIBCPP_VARIANT)
#error "<symcr/device.hpp> pulls in <variant>"
#endif
#if defined(_GLIBCXX_ANY) || defined(_LIBCPP_ANY)
#error "<symcr/device.hpp> pulls in <any>"
#endif
#if defined(_GLIBCXX_ALGORITHM) || defined(_LIBCPP_ALGORITHM)
#error "<symcr/device.hpp> pulls in <algorithm>"
#endif
#if defined(_GLIBCXX_IOSTREAM) || defined(_LIBCPP_IOSTREAM)
#error "<symcr/device.hpp> pulls in <iostream>"
#endif
#if defined(_GLIBCXX_SSTREAM) || defined(_LIBCPP_SSTREAM)
#error "<symcr/device.hpp> pulls in <sstream>"
#endif
