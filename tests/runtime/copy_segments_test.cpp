// Copy segments: a struct that is not copy-only as a whole (it holds a pointer, a time of a
// clock) restores its runs of copy-only fields by bulk copies and only the other fields one
// by one. Values, faults and rebased times must be exactly those of the field-by-field path.
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

#include "clocks.hpp"
#include "engine_test_util.hpp"
#include "handwritten_schemas.hpp"
#include "plan.hpp"
#include "schema_blob.hpp"

namespace engine_tests {
namespace {

struct Segmented {
  std::int32_t a;
  double b;
  bool flag;
  std::uint32_t stamp;  // a time of the `ticks` clock
  std::int16_t c;
  std::int32_t* target;  // -> a
  std::int64_t d[4];
};
Segmented segmented;

std::int64_t ticks_now = 5000;
std::int64_t read_ticks() { return ticks_now; }
const symcr::ClockInfo ticks{"ticks", &read_ticks, 0};
const symcr::FieldTime stamp_time{&ticks, 0};

const symcr::Schema& segmented_schema() {
  static const symcr::FieldInfo fields[] = {
      field("a", 0, offsetof(Segmented, a)),
      field("b", 1, offsetof(Segmented, b)),
      field("flag", 2, offsetof(Segmented, flag)),
      schema_tables::timed("stamp", 3, offsetof(Segmented, stamp), stamp_time),
      field("c", 4, offsetof(Segmented, c)),
      field("target", 5, offsetof(Segmented, target)),
      field("d", 7, offsetof(Segmented, d))};
  static const symcr::TypeInfo types[] = {
      scalar("int32", Kind::Int, 4),
      scalar("double", Kind::Float, 8),
      scalar("bool", Kind::Bool, 1),
      scalar("uint32", Kind::UInt, 4),
      scalar("int16", Kind::Int, 2),
      holder("int32*", Kind::Pointer, sizeof(void*), alignof(void*), 0, nullptr),
      scalar("int64", Kind::Int, 8),
      array("int64[4]", 6, 4, 32, 8),
      record("Segmented", sizeof(Segmented), alignof(Segmented), fields, 7),
  };
  static const symcr::RootInfo roots[] = {{"segmented", 8, &segmented, 0, nullptr}};
  static const symcr::Schema schema{types, 9, roots, 1, nullptr};
  return schema;
}

void set_values() {
  segmented.a = -7;
  segmented.b = 2.5;
  segmented.flag = true;
  segmented.stamp = 1200;
  segmented.c = 300;
  segmented.target = &segmented.a;
  for (int i = 0; i < 4; ++i) segmented.d[i] = 1000 + i;
}

void scramble() {
  segmented.a = 1;
  segmented.b = -1.0;
  segmented.flag = false;
  segmented.stamp = 9;
  segmented.c = -1;
  segmented.target = nullptr;
  for (int i = 0; i < 4; ++i) segmented.d[i] = -1;
}

// Wire offsets of the saved values (docs/format.md §3: values back to back, no padding).
constexpr std::size_t kFlagWire = 4 + 8;

std::shared_ptr<const symcr::detail::Plan> same_build_plan() {
  const symcr::Schema& schema = segmented_schema();
  symcr::Status status;
  return symcr::detail::plan_for(schema, symcr::detail::schema_blob(schema).hash, schema, status);
}

TEST(CopySegments, AStructWithAPointerAndATimeIsCopiedAroundThem) {
  const auto plan = same_build_plan();
  ASSERT_NE(plan, nullptr);
  ASSERT_EQ(plan->roots.size(), 1u);
  const symcr::detail::PlanNode& root = *plan->roots[0].node;
  EXPECT_FALSE(root.copy_only);
  EXPECT_FALSE(plan->copy_only_payload);
  // [a b flag] stamp [c] target [d]: the time and the pointer in place, the rest copied.
  ASSERT_EQ(root.copy_segments.size(), 5u);
  const std::uint32_t bounds[5][2] = {{0, 3}, {3, 4}, {4, 5}, {5, 6}, {6, 7}};
  const bool copied[5] = {true, false, true, false, true};
  for (std::size_t s = 0; s < 5; ++s) {
    const symcr::detail::CopySegment& segment = root.copy_segments[s];
    EXPECT_EQ(segment.first_field, bounds[s][0]) << s;
    EXPECT_EQ(segment.end_field, bounds[s][1]) << s;
    EXPECT_EQ(segment.copy != nullptr, copied[s]) << s;
  }
  // The first segment: a, b and flag in one program over their 13 wire bytes, the bool checked.
  const symcr::detail::PlanNode& first = *root.copy_segments[0].copy;
  EXPECT_EQ(first.copy_wire, 4u + 8u + 1u);
  ASSERT_EQ(first.copy_bools.size(), 1u);
  EXPECT_EQ(first.copy_bools[0], kFlagWire);
  // No copy run reaches the time's bytes in the reader.
  for (const symcr::detail::CopySegment& segment : root.copy_segments) {
    if (!segment.copy) continue;
    for (const symcr::detail::CopyRun& run : segment.copy->copy_runs) {
      const bool below = run.dst + run.length <= offsetof(Segmented, stamp);
      const bool above = run.dst >= offsetof(Segmented, stamp) + sizeof(std::uint32_t);
      EXPECT_TRUE(below || above) << run.dst << "+" << run.length;
    }
  }
}

TEST(CopySegments, EveryValueAndThePointerRoundTrip) {
  set_values();
  const Saved saved = save(segmented_schema());
  scramble();
  const symcr::Report report = load(saved, segmented_schema(), true);
  ASSERT_TRUE(report.ok()) << report.to_text();
  EXPECT_EQ(segmented.a, -7);
  EXPECT_EQ(segmented.b, 2.5);
  EXPECT_TRUE(segmented.flag);
  EXPECT_EQ(segmented.stamp, 1200u);  // the same process: not rebased
  EXPECT_EQ(segmented.c, 300);
  EXPECT_EQ(segmented.target, &segmented.a);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(segmented.d[i], 1000 + i) << i;
}

TEST(CopySegments, AnInvalidBoolInASegmentIsNamedAndNothingIsWritten) {
  set_values();
  Saved saved = save(segmented_schema());
  saved.payload[kFlagWire] = 2;
  scramble();
  const symcr::Report report = load(saved, segmented_schema());
  EXPECT_FALSE(report.ok());
  EXPECT_NE(std::string(report.status().message()).find("bool value 2"), std::string::npos)
      << report.status().message();
  EXPECT_EQ(segmented.a, 1);  // nothing written
  EXPECT_EQ(segmented.d[0], -1);
  EXPECT_EQ(segmented.target, nullptr);
}

TEST(CopySegments, ATimeBetweenSegmentsIsRebasedInAnotherProcess) {
  set_values();
  ticks_now = 5000;
  Saved saved = save(segmented_schema());
  // The payload ends with the writing process's epoch and the clock's reading (format.md §3):
  // made another process's, whose clock read 1000 ticks less than this one's now.
  const std::size_t readings = saved.payload.size() - 16;
  const std::uint64_t other_epoch = symcr::detail::process_epoch() + 1;
  const std::int64_t earlier = ticks_now - 1000;
  std::memcpy(&saved.payload[readings], &other_epoch, 8);
  std::memcpy(&saved.payload[readings + 8], &earlier, 8);
  scramble();
  const symcr::Report report = load(saved, segmented_schema());
  ASSERT_TRUE(report.ok()) << report.to_text();
  EXPECT_EQ(segmented.stamp, 2200u);  // moved by the clock's advance
  EXPECT_EQ(segmented.a, -7);         // its neighbours copied as they were
  EXPECT_TRUE(segmented.flag);
  EXPECT_EQ(segmented.c, 300);
  EXPECT_EQ(segmented.target, &segmented.a);
  EXPECT_EQ(segmented.d[3], 1003);
}

// An array whose elements are copy-only but too many to be one copy program (each padded
// element is two runs): its elements are checked, then copied, in one loop each.
struct Cell {
  std::int32_t id;
  bool on;
  double level;  // after 3 bytes of padding: a second run
};
template <std::size_t kCount>
struct GridOf {
  std::int32_t head;
  Cell cells[kCount];
};
template <std::size_t kCount>
GridOf<kCount> grid_of;

constexpr std::size_t kCells = 600;  // 1,200 runs: more than one copy program holds

// The build of `grid_of<kCount>`, root "grid", whose array type is named `array_name`.
template <std::size_t kCount>
const symcr::Schema& grid_schema(const char* array_name) {
  static const symcr::FieldInfo cell_fields[] = {field("id", 0, offsetof(Cell, id)),
                                                 field("on", 1, offsetof(Cell, on)),
                                                 field("level", 2, offsetof(Cell, level))};
  static const symcr::FieldInfo grid_fields[] = {
      field("head", 0, offsetof(GridOf<kCount>, head)),
      field("cells", 4, offsetof(GridOf<kCount>, cells))};
  static const symcr::TypeInfo types[] = {
      scalar("int32", Kind::Int, 4),
      scalar("bool", Kind::Bool, 1),
      scalar("double", Kind::Float, 8),
      record("Cell", sizeof(Cell), alignof(Cell), cell_fields, 3),
      array(array_name, 3, kCount, sizeof(Cell) * kCount, alignof(Cell)),
      record("Grid", sizeof(GridOf<kCount>), alignof(GridOf<kCount>), grid_fields, 2),
  };
  static const symcr::RootInfo roots[] = {{"grid", 5, &grid_of<kCount>, 0, nullptr}};
  static const symcr::Schema schema{types, 6, roots, 1, nullptr};
  return schema;
}
const symcr::Schema& cells_schema() { return grid_schema<kCells>("Cell[600]"); }

template <std::size_t kCount>
void fill_grid(std::int32_t head, std::int32_t first_id, double level_scale) {
  grid_of<kCount>.head = head;
  for (std::size_t i = 0; i < kCount; ++i) {
    Cell& cell = grid_of<kCount>.cells[i];
    cell.id = first_id + static_cast<std::int32_t>(i);
    cell.on = i % 3 == 0;
    cell.level = level_scale * static_cast<double>(i);
  }
}

// Wire bytes (values back to back): head, then each cell's id, on and level.
constexpr std::size_t kCellWire = 4 + 1 + 8;
constexpr std::size_t cell_on_wire(std::size_t i) { return 4 + i * kCellWire + 4; }

TEST(CopySegments, ArrayElementsTooManyForOneProgramAreCopiedAndChecked) {
  const symcr::Schema& schema = cells_schema();
  symcr::Status status;
  const auto plan =
      symcr::detail::plan_for(schema, symcr::detail::schema_blob(schema).hash, schema, status);
  ASSERT_NE(plan, nullptr) << status.message();
  const symcr::detail::PlanNode& cells = *plan->roots[0].node->fields[1].node;
  EXPECT_FALSE(cells.copy_only);  // the array as a whole: too many runs
  ASSERT_NE(cells.element, nullptr);
  EXPECT_TRUE(cells.element->copy_only);
  EXPECT_EQ(cells.element->copy_runs.size(), 2u);

  fill_grid<kCells>(-5, 100, 0.5);
  const Saved saved = save(schema);
  fill_grid<kCells>(7, -1, -1.0);
  const symcr::Report report = load(saved, schema, true);
  ASSERT_TRUE(report.ok()) << report.to_text();
  EXPECT_EQ(grid_of<kCells>.head, -5);
  for (std::size_t i = 0; i < kCells; ++i) {
    const Cell& cell = grid_of<kCells>.cells[i];
    ASSERT_EQ(cell.id, 100 + static_cast<std::int32_t>(i)) << i;
    ASSERT_EQ(cell.on, i % 3 == 0) << i;
    ASSERT_EQ(cell.level, 0.5 * static_cast<double>(i)) << i;
  }
}

TEST(CopySegments, AnInvalidBoolInALaterElementIsFoundAndNoElementIsWritten) {
  fill_grid<kCells>(-5, 100, 0.5);
  Saved saved = save(cells_schema());
  saved.payload[cell_on_wire(457)] = 2;
  fill_grid<kCells>(7, -1, -1.0);
  const symcr::Report report = load(saved, cells_schema());
  EXPECT_FALSE(report.ok());
  EXPECT_NE(std::string(report.status().message()).find("bool value 2"), std::string::npos)
      << report.status().message();
  EXPECT_EQ(grid_of<kCells>.head, 7);  // nothing written
  EXPECT_EQ(grid_of<kCells>.cells[0].id, -1);
  EXPECT_EQ(grid_of<kCells>.cells[599].level, -599.0);
}

TEST(CopySegments, AShorterArrayInThisBuildTakesTheFirstElements) {
  constexpr std::size_t kFewer = 500;
  fill_grid<kCells>(-5, 100, 0.5);
  const Saved saved = save(cells_schema());
  fill_grid<kFewer>(7, -1, -1.0);
  const symcr::Report report = load(saved, grid_schema<kFewer>("Cell[500]"));
  ASSERT_TRUE(report.ok()) << report.to_text();
  EXPECT_EQ(grid_of<kFewer>.head, -5);
  for (std::size_t i = 0; i < kFewer; ++i) {
    ASSERT_EQ(grid_of<kFewer>.cells[i].id, 100 + static_cast<std::int32_t>(i)) << i;
    ASSERT_EQ(grid_of<kFewer>.cells[i].on, i % 3 == 0) << i;
    ASSERT_EQ(grid_of<kFewer>.cells[i].level, 0.5 * static_cast<double>(i)) << i;
  }
}

TEST(CopySegments, ALongerArrayInThisBuildKeepsItsLastElements) {
  constexpr std::size_t kMore = 700;
  fill_grid<kCells>(-5, 100, 0.5);
  const Saved saved = save(cells_schema());
  fill_grid<kMore>(7, -1, -1.0);
  const symcr::Report report = load(saved, grid_schema<kMore>("Cell[700]"));
  ASSERT_TRUE(report.ok()) << report.to_text();
  for (std::size_t i = 0; i < kMore; ++i) {
    const bool saved_one = i < kCells;
    ASSERT_EQ(grid_of<kMore>.cells[i].id,
              saved_one ? 100 + static_cast<std::int32_t>(i) : -1 + static_cast<std::int32_t>(i))
        << i;
    ASSERT_EQ(grid_of<kMore>.cells[i].level, (saved_one ? 0.5 : -1.0) * static_cast<double>(i))
        << i;
  }
}

}  // namespace
}  // namespace engine_tests
