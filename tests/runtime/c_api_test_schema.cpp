// The C test program's schema, in the form symcr-gen emits (tables over offsetof/sizeof), and
// its symcr_program_schema(), so the C program can use the argument-less API.
#include <cstddef>

#include "c_api_test_state.h"
#include "symcr/generated.hpp"

namespace {

using symcr::Kind;
using symcr::kNoType;

enum : std::uint32_t { kInt16, kInt32, kUInt16, kUInt32, kFloat64, kTrims, kVehicle, kTypes };

const symcr::FieldInfo vehicle_fields[] = {
    {"altitude_cm", kInt32, offsetof(c_vehicle, altitude_cm), 0, 0, 0, nullptr, 0, 0},
    {"waypoint", kUInt16, offsetof(c_vehicle, waypoint), 0, 0, 0, nullptr, 0, 0},
    {"heading", kFloat64, offsetof(c_vehicle, heading), 0, 0, 0, nullptr, 0, 0},
    {"trims", kTrims, offsetof(c_vehicle, trims), 0, 0, 0, nullptr, 0, 0},
};

const symcr::TypeInfo types[] = {
    {"int16", Kind::Int, 0, 2, 2, nullptr, 0, nullptr, 0, kNoType, 0, nullptr, 0, 0, nullptr,
     nullptr, nullptr, nullptr, nullptr, nullptr},
    {"int32", Kind::Int, 0, 4, 4, nullptr, 0, nullptr, 0, kNoType, 0, nullptr, 0, 0, nullptr,
     nullptr, nullptr, nullptr, nullptr, nullptr},
    {"uint16", Kind::UInt, 0, 2, 2, nullptr, 0, nullptr, 0, kNoType, 0, nullptr, 0, 0, nullptr,
     nullptr, nullptr, nullptr, nullptr, nullptr},
    {"uint32", Kind::UInt, 0, 4, 4, nullptr, 0, nullptr, 0, kNoType, 0, nullptr, 0, 0, nullptr,
     nullptr, nullptr, nullptr, nullptr, nullptr},
    {"float64", Kind::Float, 0, 8, 8, nullptr, 0, nullptr, 0, kNoType, 0, nullptr, 0, 0,
     nullptr, nullptr, nullptr, nullptr, nullptr, nullptr},
    {"int16[3]", Kind::Array, 0, sizeof(c_vehicle::trims), alignof(std::int16_t), nullptr, 0,
     nullptr, 0, kInt16, 3, nullptr, 0, 0, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr},
    {"c_vehicle", Kind::Struct, 0, sizeof(c_vehicle), alignof(c_vehicle), vehicle_fields, 4,
     nullptr, 0, kNoType, 0, nullptr, 0, 0, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr},
};

const symcr::RootInfo roots[] = {
    {"c_vehicle_state", kVehicle, &c_vehicle_state, 0, nullptr},
    {"c_tick_count", kUInt32, &c_tick_count, 0, nullptr},
};

const symcr::Schema schema{types, kTypes, roots, 2, nullptr};

}  // namespace

extern "C" const symcr::Schema* symcr_program_schema(void) { return &schema; }
