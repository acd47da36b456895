// Migration hooks (docs/resolution.md): symcr::OldValues over real payloads, and restore calling
// TypeInfo::migrate — after the mechanical rules, nested objects first, per element, never when
// the type did not change, on a validator's staged copy, never when the restore fails — and the
// report's entries.
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "engine_test_util.hpp"
#include "handwritten_schemas.hpp"
#include "old_values_view.hpp"
#include "parsed_schema.hpp"
#include "payload_grammar.hpp"
#include "restore_payload.hpp"

#define SYMCR_COUNT(array) static_cast<std::uint32_t>(sizeof(array) / sizeof((array)[0]))

namespace engine_tests {
namespace {

using symcr::Decision;
using symcr::EnumeratorInfo;
using symcr::OldValues;
using symcr::RootInfo;
using symcr::Schema;
using symcr::ops::offset_of;

// ---- A writer world holding every kind OldValues reads ---------------------------------------
namespace ov {
enum class Mode : std::uint8_t { Manual = 0, Auto = 3 };
struct Inner {
  std::int32_t x;
};
struct OldBase {
  std::int32_t base_value;
};
struct Old : OldBase {
  bool on;
  std::int8_t small;
  std::int32_t neg;
  std::uint64_t big;
  float f;
  double d;
  Mode mode;
  Mode stray;  // holds a value that is no enumerator
  std::string name;
  char tag[8];
  std::vector<std::int16_t> samples;
  std::int32_t after;  // at a variable payload position: after a string and a vector
  std::int32_t grid[3];
  Inner inner;
  std::optional<Inner> maybe;
  std::optional<Inner> none;
  std::vector<Inner> inners;
};
Old old;

enum : std::uint32_t {
  kBool, kInt8, kInt32, kUInt64, kFloat, kDouble, kUInt8, kMode, kString, kTag, kInt16,
  kSamples, kGrid, kInner, kOptional, kInners, kBase, kOld
};

const Schema& schema() {
  static const EnumeratorInfo modes[] = {{"Manual", 0}, {"Auto", 3}};
  static const FieldInfo inner_fields[] = {field("x", kInt32, offsetof(Inner, x))};
  static const FieldInfo base_fields[] = {field("base_value", kInt32, offsetof(OldBase, base_value))};
  static const FieldInfo old_fields[] = {
      base("OldBase", kBase, base_offset<Old, OldBase>()),
      field("on", kBool, offset_of(&Old::on)),
      field("small", kInt8, offset_of(&Old::small)),
      field("neg", kInt32, offset_of(&Old::neg)),
      field("big", kUInt64, offset_of(&Old::big)),
      field("f", kFloat, offset_of(&Old::f)),
      field("d", kDouble, offset_of(&Old::d)),
      field("mode", kMode, offset_of(&Old::mode)),
      field("stray", kMode, offset_of(&Old::stray)),
      field("name", kString, offset_of(&Old::name)),
      field("tag", kTag, offset_of(&Old::tag)),
      field("samples", kSamples, offset_of(&Old::samples)),
      field("after", kInt32, offset_of(&Old::after)),
      field("grid", kGrid, offset_of(&Old::grid)),
      field("inner", kInner, offset_of(&Old::inner)),
      field("maybe", kOptional, offset_of(&Old::maybe)),
      field("none", kOptional, offset_of(&Old::none)),
      field("inners", kInners, offset_of(&Old::inners)),
  };
  static const TypeInfo types[] = {
      scalar("bool", Kind::Bool, 1),
      scalar("int8", Kind::Int, 1),
      scalar("int32", Kind::Int, 4),
      scalar("uint64", Kind::UInt, 8),
      scalar("float32", Kind::Float, 4),
      scalar("float64", Kind::Float, 8),
      scalar("uint8", Kind::UInt, 1),
      enumeration("Mode", 1, kUInt8, modes, SYMCR_COUNT(modes)),
      holder("std::string", Kind::String, sizeof(std::string), alignof(std::string), kInt8,
             &symcr::ops::string<std::string>::table),
      array("int8[8]", kInt8, 8, 8, 1),
      scalar("int16", Kind::Int, 2),
      holder("std::vector<int16>", Kind::Container, sizeof(std::vector<std::int16_t>),
             alignof(std::vector<std::int16_t>), kInt16,
             &symcr::ops::container<std::vector<std::int16_t>>::table),
      array("int32[3]", kInt32, 3, 12, 4),
      record("Inner", sizeof(Inner), alignof(Inner), inner_fields, SYMCR_COUNT(inner_fields)),
      holder("std::optional<Inner>", Kind::Optional, sizeof(std::optional<Inner>),
             alignof(std::optional<Inner>), kInner,
             &symcr::ops::optional<std::optional<Inner>>::table),
      holder("std::vector<Inner>", Kind::Container, sizeof(std::vector<Inner>),
             alignof(std::vector<Inner>), kInner,
             &symcr::ops::container<std::vector<Inner>>::table),
      record("OldBase", sizeof(OldBase), alignof(OldBase), base_fields, SYMCR_COUNT(base_fields)),
      record("Old", sizeof(Old), alignof(Old), old_fields, SYMCR_COUNT(old_fields)),
  };
  static const RootInfo roots[] = {{"old", kOld, &old, 0, nullptr}};
  static const Schema schema{types, SYMCR_COUNT(types), roots, SYMCR_COUNT(roots), nullptr};
  return schema;
}
}  // namespace ov

// The saved world, parsed back as restore sees it; the root's value starts the payload.
class OldValuesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ov::old.base_value = 77;
    ov::old.on = true;
    ov::old.small = -5;
    ov::old.neg = -70000;
    ov::old.big = 0xF000000000000001ull;
    ov::old.f = 2.5f;
    ov::old.d = -1.25;
    ov::old.mode = ov::Mode::Auto;
    std::uint8_t stray = 7;
    std::memcpy(&ov::old.stray, &stray, 1);
    ov::old.name = "writer";
    std::memcpy(ov::old.tag, "abc\0zzzz", 8);
    ov::old.samples = {10, 20, -30};
    ov::old.after = 4242;
    ov::old.grid[0] = 1, ov::old.grid[1] = 2, ov::old.grid[2] = 3;
    ov::old.inner.x = 9;
    ov::old.maybe = ov::Inner{11};
    ov::old.none.reset();
    ov::old.inners = {ov::Inner{100}, ov::Inner{200}};
    saved_ = save(ov::schema());
    ASSERT_TRUE(symcr::detail::parse_schema(saved_.schema.data(), saved_.schema.size(), parsed_)
                    .ok());
    sizes_ = symcr::detail::wire_sizes(parsed_.schema());
    view_ = view(ov::kOld, saved_.payload.data(), saved_.payload.size());
  }

  OldValues view(std::uint32_t type, const std::uint8_t* bytes, std::size_t size) const {
    return symcr::detail::old_values_view(parsed_.schema(), sizes_, type, bytes, size);
  }

  Saved saved_;
  symcr::detail::ParsedSchema parsed_;
  symcr::detail::WireSizes sizes_;
  OldValues view_;
};

TEST_F(OldValuesTest, ViewsTheRootValue) {
  EXPECT_TRUE(view_.valid());
  EXPECT_STREQ(view_.type_name(), "Old");
  EXPECT_TRUE(view_.has("on"));
  EXPECT_TRUE(view_.has("inners"));
  EXPECT_TRUE(view_.has(nullptr));
  EXPECT_FALSE(view_.has("missing"));
}

TEST_F(OldValuesTest, SignedIntegers) {
  std::int64_t value = 0;
  EXPECT_TRUE(view_.get("small", value));
  EXPECT_EQ(value, -5);
  EXPECT_TRUE(view_.get("neg", value));
  EXPECT_EQ(value, -70000);
  EXPECT_TRUE(view_.get("on", value));  // bool as 0/1
  EXPECT_EQ(value, 1);
  EXPECT_TRUE(view_.get("mode", value));  // an enum as its underlying value
  EXPECT_EQ(value, 3);
  EXPECT_TRUE(view_.get("d", value) == false);  // -1.25 is not integral
  EXPECT_FALSE(view_.get("big", value));        // beyond int64
  EXPECT_EQ(value, 3);                          // untouched by the failures
}

TEST_F(OldValuesTest, UnsignedIntegers) {
  std::uint64_t value = 5;
  EXPECT_TRUE(view_.get("big", value));
  EXPECT_EQ(value, 0xF000000000000001ull);
  EXPECT_FALSE(view_.get("neg", value));    // negative
  EXPECT_FALSE(view_.get("f", value));      // 2.5 is not integral
  EXPECT_EQ(value, 0xF000000000000001ull);  // untouched
  EXPECT_TRUE(view_.get("after", value));   // after a string and a vector in the payload
  EXPECT_EQ(value, 4242u);
}

TEST_F(OldValuesTest, Doubles) {
  double value = 0;
  EXPECT_TRUE(view_.get("f", value));
  EXPECT_EQ(value, 2.5);
  EXPECT_TRUE(view_.get("d", value));
  EXPECT_EQ(value, -1.25);
  EXPECT_TRUE(view_.get("neg", value));
  EXPECT_EQ(value, -70000.0);
  EXPECT_TRUE(view_.get("big", value));  // rounds
  EXPECT_EQ(value, static_cast<double>(0xF000000000000001ull));
  EXPECT_TRUE(view_.get("on", value));
  EXPECT_EQ(value, 1.0);
}

TEST_F(OldValuesTest, Bools) {
  bool value = false;
  EXPECT_TRUE(view_.get("on", value));
  EXPECT_TRUE(value);
  EXPECT_FALSE(view_.get("small", value));  // -5 is no bool
  EXPECT_TRUE(value);
}

TEST_F(OldValuesTest, Strings) {
  std::string text = "untouched";
  EXPECT_TRUE(view_.get("name", text));
  EXPECT_EQ(text, "writer");
  EXPECT_TRUE(view_.get("tag", text));  // char[8] up to its NUL
  EXPECT_EQ(text, "abc");
  EXPECT_FALSE(view_.get("neg", text));
  EXPECT_FALSE(view_.get("grid", text));  // int32 elements are not characters
  EXPECT_FALSE(view_.get("inner", text));
  EXPECT_EQ(text, "abc");
}

TEST_F(OldValuesTest, Enumerators) {
  const char* name = nullptr;
  EXPECT_TRUE(view_.enumerator("mode", name));
  EXPECT_STREQ(name, "Auto");
  EXPECT_FALSE(view_.enumerator("stray", name));  // 7 has no name
  EXPECT_FALSE(view_.enumerator("small", name));  // not an enum
  EXPECT_FALSE(view_.enumerator("missing", name));
  EXPECT_STREQ(name, "Auto");
}

TEST_F(OldValuesTest, WrongKindsFail) {
  double number = 42;
  std::int64_t integer = 42;
  EXPECT_FALSE(view_.get("name", number));
  EXPECT_FALSE(view_.get("inner", number));
  EXPECT_FALSE(view_.get("samples", integer));
  EXPECT_FALSE(view_.get("maybe", integer));
  EXPECT_FALSE(view_.get(nullptr, number));  // the view itself is a struct
  EXPECT_EQ(number, 42);
  EXPECT_EQ(integer, 42);
  EXPECT_EQ(view_.count("inner"), 0u);
  EXPECT_FALSE(view_.element("inner", 0).valid());
}

TEST_F(OldValuesTest, AbsentFieldsFail) {
  double number = 42;
  std::string text = "x";
  const char* name = "y";
  EXPECT_FALSE(view_.get("alt_m", number));
  EXPECT_FALSE(view_.get("alt_m", text));
  EXPECT_FALSE(view_.enumerator("alt_m", name));
  EXPECT_FALSE(view_.child("alt_m").valid());
  EXPECT_EQ(view_.count("alt_m"), 0u);
  EXPECT_FALSE(view_.element("alt_m", 0).valid());
  EXPECT_EQ(number, 42);
  EXPECT_EQ(text, "x");
  EXPECT_STREQ(name, "y");
}

TEST_F(OldValuesTest, NestedChildren) {
  std::int64_t value = 0;
  const OldValues inner = view_.child("inner");
  ASSERT_TRUE(inner.valid());
  EXPECT_STREQ(inner.type_name(), "Inner");
  EXPECT_TRUE(inner.get("x", value));
  EXPECT_EQ(value, 9);
  EXPECT_FALSE(inner.has("on"));  // only the child's own fields
  const OldValues maybe = view_.child("maybe");  // an engaged optional: its value
  ASSERT_TRUE(maybe.valid());
  EXPECT_TRUE(maybe.get("x", value));
  EXPECT_EQ(value, 11);
  EXPECT_FALSE(view_.child("none").valid());  // empty
  const OldValues scalar_child = view_.child("neg");
  EXPECT_TRUE(scalar_child.get(nullptr, value));
  EXPECT_EQ(value, -70000);
}

TEST_F(OldValuesTest, BaseClassFields) {
  std::int64_t value = 0;
  EXPECT_TRUE(view_.get("base_value", value));  // found through the base
  EXPECT_EQ(value, 77);
  const OldValues base = view_.child("OldBase");
  ASSERT_TRUE(base.valid());
  EXPECT_TRUE(base.get("base_value", value));
  EXPECT_EQ(value, 77);
}

TEST_F(OldValuesTest, ArraysAndContainers) {
  std::int64_t value = 0;
  EXPECT_EQ(view_.count("samples"), 3u);
  EXPECT_TRUE(view_.element("samples", 2).get(nullptr, value));
  EXPECT_EQ(value, -30);
  EXPECT_FALSE(view_.element("samples", 3).valid());
  EXPECT_EQ(view_.count("grid"), 3u);
  EXPECT_TRUE(view_.element("grid", 1).get(nullptr, value));
  EXPECT_EQ(value, 2);
  EXPECT_EQ(view_.count("inners"), 2u);
  EXPECT_TRUE(view_.element("inners", 1).get("x", value));
  EXPECT_EQ(value, 200);
  EXPECT_EQ(view_.count("tag"), 8u);
  EXPECT_EQ(view_.count("on"), 0u);
}

TEST_F(OldValuesTest, InvalidAndTruncatedViewsFail) {
  const OldValues empty;
  double number = 1;
  EXPECT_FALSE(empty.valid());
  EXPECT_STREQ(empty.type_name(), "");
  EXPECT_FALSE(empty.has("on"));
  EXPECT_FALSE(empty.get(nullptr, number));
  EXPECT_FALSE(empty.child("inner").valid());
  EXPECT_EQ(empty.count("samples"), 0u);
  // A type index beyond the schema: invalid.
  EXPECT_FALSE(view(1000, saved_.payload.data(), saved_.payload.size()).valid());
  // Every prefix of the value: queries fail or succeed, never read past the bytes given.
  for (std::size_t size = 0; size < 64; ++size) {
    std::vector<std::uint8_t> prefix(saved_.payload.begin(),
                                     saved_.payload.begin() + static_cast<std::ptrdiff_t>(size));
    const OldValues cut = view(ov::kOld, prefix.data(), prefix.size());
    std::int64_t value = 0;
    std::string text;
    (void)cut.get("after", value);
    (void)cut.get("name", text);
    (void)cut.element("inners", 1).get("x", value);
    EXPECT_FALSE(cut.get("after", value)) << size;  // 'after' lies beyond 64 bytes' reach
  }
}

// ---- Restore with hooks: a writer build m0 and a reader build m1 ------------------------------
namespace m0 {
struct Reading {
  float alt_m;
  std::int32_t id;
};
struct Batch {
  std::vector<Reading> list;
  Reading one;
  std::int16_t narrow;
};
struct Same {
  std::int32_t a;
};
Batch batch;
Same same;

const Schema& schema() {
  static const FieldInfo reading_fields[] = {field("alt_m", 1, offsetof(Reading, alt_m)),
                                             field("id", 0, offsetof(Reading, id))};
  static const FieldInfo batch_fields[] = {field("list", 3, offset_of(&Batch::list)),
                                            field("one", 2, offset_of(&Batch::one)),
                                            field("narrow", 6, offset_of(&Batch::narrow))};
  static const FieldInfo same_fields[] = {field("a", 0, offsetof(Same, a))};
  static const TypeInfo types[] = {
      scalar("int32", Kind::Int, 4),
      scalar("float32", Kind::Float, 4),
      record("Reading", sizeof(Reading), alignof(Reading), reading_fields, 2),
      holder("std::vector<Reading>", Kind::Container, sizeof(std::vector<Reading>),
             alignof(std::vector<Reading>), 2,
             &symcr::ops::container<std::vector<Reading>>::table),
      record("Batch", sizeof(Batch), alignof(Batch), batch_fields, 3),
      record("Same", sizeof(Same), alignof(Same), same_fields, 1),
      scalar("int16", Kind::Int, 2),
  };
  static const RootInfo roots[] = {{"batch", 4, &batch, 0, nullptr},
                                   {"same", 5, &same, 0, nullptr}};
  static const Schema schema{types, SYMCR_COUNT(types), roots, SYMCR_COUNT(roots), nullptr};
  return schema;
}
}  // namespace m0

namespace m1 {
struct Reading {
  std::int32_t alt_cm;
  std::int32_t id;
};
struct Batch {
  std::vector<Reading> list;
  Reading one;
  std::int8_t narrow;  // int16 -> int8: lossy in strict mode
  std::int32_t readings_done;  // how many Reading hooks had run when Batch's ran
};
struct Same {
  std::int32_t a;
};
Batch batch;
Same same;

std::vector<std::string> calls;  // hooks in call order: "Reading", "Batch", "Same"
int reading_calls = 0;
std::int64_t old_narrow = 0;  // what Batch's hook read of the old `narrow`

void migrate_reading(void* object, const OldValues& old) {
  auto* reading = static_cast<Reading*>(object);
  ++reading_calls;
  calls.push_back("Reading");
  double alt_m = 0;
  if (old.get("alt_m", alt_m)) reading->alt_cm = static_cast<std::int32_t>(alt_m * 100.0);
}
void migrate_batch(void* object, const OldValues& old) {
  auto* batch = static_cast<Batch*>(object);
  calls.push_back("Batch");
  batch->readings_done = reading_calls;
  EXPECT_EQ(old.count("list"), batch->list.size());
  old.get("narrow", old_narrow);
}
void migrate_same(void* object, const OldValues&) {
  calls.push_back("Same");
  static_cast<Same*>(object)->a = -1;
}
bool validate_reading(const void* object) {
  // Passes only on the migrated value: before the hook, alt_cm is this build's default 0.
  return static_cast<const Reading*>(object)->alt_cm != 0;
}

enum class Variant { Plain, Validated, FlagOnly };

const Schema& schema(Variant variant) {
  static const FieldInfo reading_fields[] = {field("alt_cm", 0, offsetof(Reading, alt_cm)),
                                             field("id", 0, offsetof(Reading, id))};
  static const FieldInfo batch_fields[] = {
      field("list", 2, offset_of(&Batch::list)), field("one", 1, offset_of(&Batch::one)),
      field("narrow", 5, offset_of(&Batch::narrow)),
      field("readings_done", 0, offset_of(&Batch::readings_done))};
  static const FieldInfo same_fields[] = {field("a", 0, offsetof(Same, a))};
  auto types_for = [&](Variant v) {
    const bool code = v != Variant::FlagOnly;
    std::vector<TypeInfo> types = {
        scalar("int32", Kind::Int, 4),
        record("Reading", sizeof(Reading), alignof(Reading), reading_fields, 2,
               &symcr::ops::lifecycle<Reading>::table,
               v == Variant::Validated ? &validate_reading : nullptr, nullptr,
               code ? &migrate_reading : nullptr),
        holder("std::vector<Reading>", Kind::Container, sizeof(std::vector<Reading>),
               alignof(std::vector<Reading>), 1,
               &symcr::ops::container<std::vector<Reading>>::table),
        record("Batch", sizeof(Batch), alignof(Batch), batch_fields, 4, nullptr, nullptr,
               nullptr, code ? &migrate_batch : nullptr),
        record("Same", sizeof(Same), alignof(Same), same_fields, 1, nullptr, nullptr, nullptr,
               code ? &migrate_same : nullptr),
        scalar("int8", Kind::Int, 1),
    };
    // A schema file carries no code, only the flag (what `symcr plan` reads).
    for (TypeInfo& type : types) {
      if (type.kind == Kind::Struct) type.flags |= symcr::kTypeMigrated;
    }
    return types;
  };
  static const std::vector<TypeInfo> plain = types_for(Variant::Plain);
  static const std::vector<TypeInfo> validated = types_for(Variant::Validated);
  static const std::vector<TypeInfo> flag_only = types_for(Variant::FlagOnly);
  const std::vector<TypeInfo>& types = variant == Variant::Plain       ? plain
                                       : variant == Variant::Validated ? validated
                                                                       : flag_only;
  static const RootInfo roots[] = {{"batch", 3, &batch, 0, nullptr},
                                   {"same", 4, &same, 0, nullptr}};
  static Schema schemas[3];
  Schema& schema = schemas[static_cast<int>(variant)];
  schema = Schema{types.data(), static_cast<std::uint32_t>(types.size()), roots,
                  SYMCR_COUNT(roots), nullptr};
  return schema;
}
}  // namespace m1

class MigrationTest : public ::testing::Test {
 protected:
  void SetUp() override {
    m0::batch.list = {m0::Reading{1.5f, 1}, m0::Reading{2.25f, 2}};
    m0::batch.one = m0::Reading{-3.0f, 3};
    m0::batch.narrow = 5;
    m0::same.a = 44;
    m1::batch = m1::Batch{};
    m1::batch.one.alt_cm = 7;
    m1::same.a = 0;
    m1::calls.clear();
    m1::reading_calls = 0;
    m1::old_narrow = 0;
  }
};

TEST_F(MigrationTest, HooksRunAfterTheRulesNestedFirstPerElement) {
  const symcr::Report report = load(save(m0::schema()), m1::schema(m1::Variant::Plain));
  ASSERT_TRUE(report.ok()) << report.to_text();
  ASSERT_EQ(m1::batch.list.size(), 2u);
  EXPECT_EQ(m1::batch.list[0].alt_cm, 150);
  EXPECT_EQ(m1::batch.list[0].id, 1);  // by the mechanical rules
  EXPECT_EQ(m1::batch.list[1].alt_cm, 225);
  EXPECT_EQ(m1::batch.one.alt_cm, -300);
  EXPECT_EQ(m1::batch.one.id, 3);
  EXPECT_EQ(m1::batch.narrow, 5);
  EXPECT_EQ(m1::batch.readings_done, 3);  // every Reading's hook ran before Batch's
  EXPECT_EQ(m1::calls, (std::vector<std::string>{"Reading", "Reading", "Reading", "Batch"}));
  EXPECT_EQ(m1::same.a, 44);  // Same did not change: restored, its hook not called

  expect_entry(report, "batch", Decision::Converted, "migrated by symcr_migrate(Batch)", 0);
  expect_entry(report, "batch.list[]", Decision::Converted, "migrated by symcr_migrate(Reading)",
               0);
  expect_entry(report, "batch.one", Decision::Converted, "migrated by symcr_migrate(Reading)", 0);
  expect_entry(report, "batch.one.alt_m", Decision::Dropped, "goes to symcr_migrate(Reading)", 0);
  expect_entry(report, "batch.one.alt_cm", Decision::Kept, "field added");
  expect_entry(report, "same", Decision::Restored);
  for (const symcr::ReportEntry& e : report.entries()) {
    EXPECT_EQ(e.detail.find("symcr_migrate(Same)"), std::string::npos) << e.path;
  }
}

TEST_F(MigrationTest, NoHookRunsWhenTheTypesAreTheSame) {
  // The reader's own checkpoint: every plan node is a plain restore.
  m1::batch.list = {m1::Reading{10, 1}};
  m1::batch.one = m1::Reading{20, 2};
  m1::batch.readings_done = 9;
  m1::same.a = 8;
  const Saved own = save(m1::schema(m1::Variant::Plain));
  m1::batch = m1::Batch{};
  m1::same.a = 0;
  const symcr::Report report = load(own, m1::schema(m1::Variant::Plain));
  ASSERT_TRUE(report.ok()) << report.to_text();
  EXPECT_TRUE(m1::calls.empty());
  ASSERT_EQ(m1::batch.list.size(), 1u);
  EXPECT_EQ(m1::batch.list[0].alt_cm, 10);
  EXPECT_EQ(m1::batch.one.alt_cm, 20);
  EXPECT_EQ(m1::batch.readings_done, 9);
  EXPECT_EQ(m1::same.a, 8);
  EXPECT_EQ(report.count(Decision::Converted), 0u) << report.to_text();
}

TEST_F(MigrationTest, AFailedRestoreRunsNoHook) {
  // The payload ends inside batch.narrow: pass 1 fails, nothing is written.
  const Saved saved = save(m0::schema());
  const symcr::Report report =
      load(saved, m1::schema(m1::Variant::Plain), false, saved.payload.size() - 5);
  EXPECT_FALSE(report.ok());
  EXPECT_TRUE(m1::calls.empty());
  EXPECT_TRUE(m1::batch.list.empty());
  EXPECT_EQ(m1::batch.one.alt_cm, 7);
}

TEST_F(MigrationTest, AValueTheRulesRejectGoesToTheHook) {
  // 300 does not fit batch.narrow (int8): this build keeps its value, and Batch's hook reads
  // the old one by name. Not a loss (the hook decides), so strict mode restores.
  m0::batch.narrow = 300;
  const symcr::Report report = load(save(m0::schema()), m1::schema(m1::Variant::Plain),
                                    /*strict=*/true);
  ASSERT_TRUE(report.ok()) << report.to_text();
  EXPECT_TRUE(report.lossless()) << report.to_text();
  EXPECT_EQ(m1::batch.narrow, 0);
  EXPECT_EQ(m1::old_narrow, 300);
  EXPECT_EQ(m1::calls.back(), "Batch");
  EXPECT_EQ(report.count(Decision::Rejected), 0u) << report.to_text();
  // The value's own entry, besides the field's (converted int16 -> int8).
  const auto handed = [](const symcr::Report& r) {
    for (const symcr::ReportEntry& e : r.entries()) {
      if (e.path == "batch.narrow" && e.decision == Decision::Converted && !e.lossy &&
          e.detail == "300 out of range of int8; the old value goes to symcr_migrate(Batch)") {
        return true;
      }
    }
    return false;
  };
  EXPECT_TRUE(handed(report)) << report.to_text();
  // The same from the schema alone (`symcr plan`): the hook is known by its flag.
  const Saved saved = save(m0::schema());
  symcr::detail::ParsedSchema writer;
  ASSERT_TRUE(symcr::detail::parse_schema(saved.schema.data(), saved.schema.size(), writer).ok());
  symcr::RestoreOptions strict;
  strict.strict = true;
  const symcr::Report plan =
      symcr::detail::plan_payload(writer.schema(), saved.hash, saved.payload.data(),
                                  saved.payload.size(), m1::schema(m1::Variant::FlagOnly), strict);
  ASSERT_TRUE(plan.ok()) << plan.to_text();
  EXPECT_TRUE(handed(plan)) << plan.to_text();
}

TEST_F(MigrationTest, AValueItsValidatorRefusesStaysRejected) {
  // The hook makes alt_cm 0 from alt_m 0, which Reading's symcr_validate refuses: a rejection
  // even inside migrated objects, so strict mode refuses and writes nothing.
  m0::batch.one.alt_m = 0.0f;
  const symcr::Report report = load(save(m0::schema()), m1::schema(m1::Variant::Validated),
                                    /*strict=*/true);
  EXPECT_FALSE(report.ok());
  expect_entry(report, "batch.one", Decision::Rejected, "symcr_validate", 1);
  EXPECT_TRUE(m1::batch.list.empty());
  EXPECT_EQ(m1::batch.one.alt_cm, 7);
  for (const std::string& call : m1::calls) EXPECT_NE(call, "Batch");  // only staged copies
}

TEST_F(MigrationTest, ValidatorsJudgeTheMigratedValue) {
  const symcr::Report report = load(save(m0::schema()), m1::schema(m1::Variant::Validated));
  ASSERT_TRUE(report.ok()) << report.to_text();
  // Each Reading passed symcr_validate only because its hook ran on the staged copy first.
  EXPECT_EQ(report.count(Decision::Rejected), 0u) << report.to_text();
  ASSERT_EQ(m1::batch.list.size(), 2u);
  EXPECT_EQ(m1::batch.list[1].alt_cm, 225);
  EXPECT_EQ(m1::batch.one.alt_cm, -300);
}

TEST_F(MigrationTest, SchemaWithoutCodeReportsTheSameMigrations) {
  const Saved saved = save(m0::schema());
  symcr::detail::ParsedSchema writer;
  ASSERT_TRUE(symcr::detail::parse_schema(saved.schema.data(), saved.schema.size(), writer).ok());
  const symcr::Report plan =
      symcr::detail::plan_payload(writer.schema(), saved.hash, saved.payload.data(),
                                  saved.payload.size(), m1::schema(m1::Variant::FlagOnly), {});
  ASSERT_TRUE(plan.ok()) << plan.to_text();
  expect_entry(plan, "batch", Decision::Converted, "migrated by symcr_migrate(Batch)", 0);
  expect_entry(plan, "batch.list[]", Decision::Converted, "migrated by symcr_migrate(Reading)");
  expect_entry(plan, "same", Decision::Restored);
  // Restoring into it writes by the rules and calls nothing.
  const symcr::Report report = load(saved, m1::schema(m1::Variant::FlagOnly));
  ASSERT_TRUE(report.ok()) << report.to_text();
  EXPECT_TRUE(m1::calls.empty());
  ASSERT_EQ(m1::batch.list.size(), 2u);
  EXPECT_EQ(m1::batch.list[0].alt_cm, 0);
  EXPECT_EQ(m1::batch.list[0].id, 1);
}

// ---- A recursive type: whether it changed depends on itself ---------------------------------
namespace r0 {
struct Node {
  std::vector<Node> kids;  // first: the recursion is met before the change
  float v;
};
struct Tree {
  std::vector<Node> nodes;
};
Tree tree;
const Schema& schema() {
  static const FieldInfo node_fields[] = {field("kids", 1, offset_of(&Node::kids)),
                                          field("v", 2, offset_of(&Node::v))};
  static const FieldInfo tree_fields[] = {field("nodes", 1, offset_of(&Tree::nodes))};
  static const TypeInfo types[] = {
      record("Node", sizeof(Node), alignof(Node), node_fields, 2),
      holder("std::vector<Node>", Kind::Container, sizeof(std::vector<Node>),
             alignof(std::vector<Node>), 0, &symcr::ops::container<std::vector<Node>>::table),
      scalar("float32", Kind::Float, 4),
      record("Tree", sizeof(Tree), alignof(Tree), tree_fields, 1),
  };
  static const RootInfo roots[] = {{"tree", 3, &tree, 0, nullptr}};
  static const Schema schema{types, SYMCR_COUNT(types), roots, SYMCR_COUNT(roots), nullptr};
  return schema;
}
}  // namespace r0

namespace r1 {
struct Node {
  std::vector<Node> kids;
  double v;  // float -> double: Node, vector<Node> and Tree all differ
};
struct Tree {
  std::vector<Node> nodes;
};
Tree tree;
int tree_calls = 0;
void migrate_tree(void*, const OldValues&) { ++tree_calls; }
const Schema& schema() {
  static const FieldInfo node_fields[] = {field("kids", 1, offset_of(&Node::kids)),
                                          field("v", 2, offset_of(&Node::v))};
  static const FieldInfo tree_fields[] = {field("nodes", 1, offset_of(&Tree::nodes))};
  static const TypeInfo types[] = {
      record("Node", sizeof(Node), alignof(Node), node_fields, 2),
      holder("std::vector<Node>", Kind::Container, sizeof(std::vector<Node>),
             alignof(std::vector<Node>), 0, &symcr::ops::container<std::vector<Node>>::table),
      scalar("float64", Kind::Float, 8),
      record("Tree", sizeof(Tree), alignof(Tree), tree_fields, 1, nullptr, nullptr, nullptr,
             &migrate_tree),
  };
  static const RootInfo roots[] = {{"tree", 3, &tree, 0, nullptr}};
  static const Schema schema{types, SYMCR_COUNT(types), roots, SYMCR_COUNT(roots), nullptr};
  return schema;
}
}  // namespace r1

TEST(MigrationRecursion, AChangeInsideARecursiveTypeIsAChange) {
  r0::tree.nodes = {r0::Node{{r0::Node{{}, 2.5f}}, 1.5f}};
  const symcr::Report report = load(save(r0::schema()), r1::schema());
  ASSERT_TRUE(report.ok()) << report.to_text();
  EXPECT_EQ(r1::tree_calls, 1);
  ASSERT_EQ(r1::tree.nodes.size(), 1u);
  EXPECT_EQ(r1::tree.nodes[0].v, 1.5);
  ASSERT_EQ(r1::tree.nodes[0].kids.size(), 1u);
  EXPECT_EQ(r1::tree.nodes[0].kids[0].v, 2.5);
  expect_entry(report, "tree", Decision::Converted, "migrated by symcr_migrate(Tree)", 0);
}

}  // namespace
}  // namespace engine_tests
