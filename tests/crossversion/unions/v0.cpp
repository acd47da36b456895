// v0: unions restored as raw bytes of the largest member.
#include <cstdint>

#include "check.hpp"

union Reading {
  std::int32_t raw;
  float value;
};
union Packet {
  std::uint32_t word;
  std::uint8_t bytes[4];
};

struct Radio {
  Reading reading;
  Packet packet;
};

SYMCR_CHECKPOINT Radio radio;

int main(int argc, char** argv) {
  radio.reading.value = 3.25f;
  radio.packet.word = 0xA1B2C3D4u;
  return xv::save(argc, argv);
}
