#ifndef CONSUMER_STATE_HPP
#define CONSUMER_STATE_HPP

#include <string>
#include <vector>

#include <symcr/symcr.hpp>

struct Greeting {
  std::string text;
  std::vector<int> counts;
  // MARKER: the test appends a field here to check that editing a header regenerates.
};

#endif
