// The C test program's schema, in the form symcr-gen emits (tables over offsetof/sizeof), and
// its symcr_program_schema(), so the C program can use the argument-less API.
#include <cstddef>

#include "c_api_test_state.h"
#include "schema_tables.hpp"
#include "symcr/generated.hpp"

namespace {

using namespace schema_tables;  // scalar(), record(), field(), ...: tests/support

enum : std::uint32_t { kInt16, kInt32, kUInt16, kUInt32, kFloat64, kTrims, kVehicle, kTypes };

const FieldInfo vehicle_fields[] = {
    field("altitude_cm", kInt32, offsetof(c_vehicle, altitude_cm)),
    field("waypoint", kUInt16, offsetof(c_vehicle, waypoint)),
    field("heading", kFloat64, offsetof(c_vehicle, heading)),
    field("trims", kTrims, offsetof(c_vehicle, trims)),
};

const TypeInfo types[] = {
    scalar("int16", Kind::Int, 2),
    scalar("int32", Kind::Int, 4),
    scalar("uint16", Kind::UInt, 2),
    scalar("uint32", Kind::UInt, 4),
    scalar("float64", Kind::Float, 8),
    array("int16[3]", kInt16, 3, sizeof(c_vehicle::trims), alignof(std::int16_t)),
    record("c_vehicle", sizeof(c_vehicle), alignof(c_vehicle), vehicle_fields, 4),
};

const symcr::RootInfo roots[] = {
    {"c_vehicle_state", kVehicle, &c_vehicle_state, 0, nullptr},
    {"c_tick_count", kUInt32, &c_tick_count, 0, nullptr},
};

const symcr::Schema schema{types, kTypes, roots, 2, nullptr};

}  // namespace

extern "C" const symcr::Schema* symcr_program_schema(void) { return &schema; }
