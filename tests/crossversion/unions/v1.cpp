// v1: Reading is unchanged in size; Packet grew to 8 bytes (rejected, kept).
#include <cstdint>

#include "check.hpp"

union Reading {
  float value;
  std::int32_t raw;
};
union Packet {
  std::uint64_t word;
  std::uint8_t bytes[8];
};

struct Radio {
  Reading reading;
  Packet packet;
};

SYMCR_CHECKPOINT Radio radio;

int main(int argc, char** argv) {
  radio.reading.raw = 0;
  radio.packet.word = 77;
  symcr::Report report = xv::restore(argc, argv);
  XV_CHECK(report.ok());
  XV_CHECK(radio.reading.value == 3.25f);
  XV_CHECK(radio.packet.word == 77);
  XV_CHECK(xv::decided(report, "radio.packet", symcr::Decision::Rejected));
  return xv::verdict();
}
