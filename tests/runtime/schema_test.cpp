// Schema serialisation, hashing and the validating parser (docs/format.md §2).
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "handwritten_schemas.hpp"
#include "parsed_schema.hpp"
#include "schema_blob.hpp"
#include "schema_facts.hpp"
#include "symcr/format/hashes.hpp"

namespace engine_tests {
namespace {

using symcr::detail::ParsedSchema;
using symcr::detail::parse_schema;
using symcr::detail::schema_blob;

TEST(EngineSchema, Fnv1aMatchesReferenceVectors) {
  EXPECT_EQ(symcr::format::fnv1a64(nullptr, 0), 0xcbf29ce484222325ull);
  const std::uint8_t a[] = {'a'};
  EXPECT_EQ(symcr::format::fnv1a64(a, 1), 0xaf63dc4c8601ec8cull);
  const std::uint8_t foobar[] = {'f', 'o', 'o', 'b', 'a', 'r'};
  EXPECT_EQ(symcr::format::fnv1a64(foobar, 6), 0x85944171f73967e8ull);
}

TEST(EngineSchema, BlobIsCachedAndHashed) {
  const auto& first = schema_blob(b0::schema());
  const auto& second = schema_blob(b0::schema());
  EXPECT_EQ(&first, &second);
  EXPECT_EQ(first.hash, symcr::format::fnv1a64(first.data, first.size));
  EXPECT_NE(first.hash, schema_blob(b1::schema()).hash);
}

TEST(EngineSchema, RoundTripsThroughTheParser) {
  for (const symcr::Schema* schema : {&a0::schema(), &a1::schema(), &b0::schema(), &c1::schema(),
                                      &d1::schema(), &e1::schema()}) {
    const auto& blob = schema_blob(*schema);
    ParsedSchema parsed;
    const symcr::Status status = parse_schema(blob.data, blob.size, parsed);
    ASSERT_TRUE(status.ok()) << status.message();
    EXPECT_EQ(parsed.hash(), blob.hash);
    const symcr::Schema& copy = parsed.schema();
    ASSERT_EQ(copy.type_count, schema->type_count);
    ASSERT_EQ(copy.root_count, schema->root_count);
    for (std::uint32_t t = 0; t < copy.type_count; ++t) {
      EXPECT_STREQ(copy.types[t].name, schema->types[t].name);
      EXPECT_EQ(copy.types[t].kind, schema->types[t].kind);
      EXPECT_EQ(copy.types[t].size, schema->types[t].size);
      EXPECT_EQ(copy.types[t].field_count, schema->types[t].field_count);
      for (std::uint32_t f = 0; f < copy.types[t].field_count; ++f) {
        EXPECT_STREQ(copy.types[t].fields[f].name, schema->types[t].fields[f].name);
        EXPECT_EQ(copy.types[t].fields[f].offset, schema->types[t].fields[f].offset);
        EXPECT_EQ(copy.types[t].fields[f].bit_width, schema->types[t].fields[f].bit_width);
      }
    }
    EXPECT_STREQ(copy.roots[0].name, schema->roots[0].name);
    EXPECT_EQ(copy.roots[0].address, nullptr);
    // A parsed schema serialises to the same bytes.
    std::vector<std::uint8_t> again;
    symcr::detail::serialise_schema(copy, again);
    EXPECT_EQ(again, std::vector<std::uint8_t>(blob.data, blob.data + blob.size));
  }
}

TEST(EngineSchema, ParsedAliasesAndRangesSurvive) {
  const auto& blob = schema_blob(a1::schema());
  ParsedSchema parsed;
  ASSERT_TRUE(parse_schema(blob.data, blob.size, parsed).ok());
  const symcr::TypeInfo& basic = parsed.schema().types[13];
  EXPECT_STREQ(basic.fields[3].name, "yaw");
  ASSERT_NE(basic.fields[3].renamed_from, nullptr);
  EXPECT_STREQ(basic.fields[3].renamed_from[0], "heading");
  EXPECT_EQ(basic.fields[3].renamed_from[1], nullptr);
  EXPECT_TRUE(basic.fields[20].flags & symcr::kFieldHasRange);
  EXPECT_EQ(basic.fields[20].range->max, 100.0);
  EXPECT_STREQ(parsed.schema().roots[1].renamed_from[0], "old_counter");
  EXPECT_STREQ(parsed.schema().types[5].enumerators[3].name, "RTL");
}

TEST(EngineSchema, EveryTruncationIsRefused) {
  const auto& blob = schema_blob(c0::schema());
  for (std::size_t size = 0; size < blob.size; ++size) {
    ParsedSchema parsed;
    const symcr::Status status = parse_schema(blob.data, size, parsed);
    EXPECT_FALSE(status.ok()) << size;
    EXPECT_EQ(status.error(), symcr::Error::Corrupt);
  }
  std::vector<std::uint8_t> longer(blob.data, blob.data + blob.size);
  longer.push_back(0);
  ParsedSchema parsed;
  EXPECT_EQ(parse_schema(longer.data(), longer.size(), parsed).error(), symcr::Error::Corrupt);
}

// A tiny hand-made schema: u32 types, u32 roots, then types.
struct Bytes {
  std::vector<std::uint8_t> data;
  template <typename T>
  Bytes& put(T value) {
    std::uint8_t raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    data.insert(data.end(), raw, raw + sizeof(T));
    return *this;
  }
  Bytes& str(const char* text) {
    put(static_cast<std::uint16_t>(std::strlen(text)));
    data.insert(data.end(), text, text + std::strlen(text));
    return *this;
  }
  Bytes& type(symcr::Kind kind, std::uint32_t size, const char* name) {
    return put(static_cast<std::uint8_t>(kind)).put(std::uint32_t{0}).put(size).put(size).str(name).put(std::uint8_t{0});
  }
};

symcr::Status parse(const Bytes& bytes) {
  ParsedSchema parsed;
  return parse_schema(bytes.data.data(), bytes.data.size(), parsed);
}

TEST(EngineSchema, RefusesHostileSchemas) {
  // A struct containing itself by value.
  Bytes self;
  self.put(std::uint32_t{1}).put(std::uint32_t{0});
  self.type(symcr::Kind::Struct, 8, "Loop").put(std::uint32_t{1}).str("me").put(std::uint32_t{0})
      .put(std::uint32_t{0}).put(std::uint16_t{0}).put(std::uint16_t{0}).put(std::uint32_t{0})
      .put(std::uint8_t{0});
  symcr::Status status = parse(self);
  EXPECT_EQ(status.error(), symcr::Error::Corrupt);
  EXPECT_NE(std::string(status.message()).find("contains itself"), std::string::npos) << status.message();

  // A field whose type index is out of range.
  Bytes index;
  index.put(std::uint32_t{1}).put(std::uint32_t{0});
  index.type(symcr::Kind::Struct, 8, "S").put(std::uint32_t{1}).str("f").put(std::uint32_t{7})
      .put(std::uint32_t{0}).put(std::uint16_t{0}).put(std::uint16_t{0}).put(std::uint32_t{0})
      .put(std::uint8_t{0});
  EXPECT_NE(std::string(parse(index).message()).find("out of range"), std::string::npos);

  // Scalar sizes the kind does not allow.
  Bytes size;
  size.put(std::uint32_t{1}).put(std::uint32_t{0}).type(symcr::Kind::Int, 3, "int24");
  EXPECT_EQ(parse(size).error(), symcr::Error::Corrupt);
  Bytes boolean;
  boolean.put(std::uint32_t{1}).put(std::uint32_t{0}).type(symcr::Kind::Bool, 4, "bool");
  EXPECT_EQ(parse(boolean).error(), symcr::Error::Corrupt);

  // Counts far beyond the bytes: refused before allocating.
  Bytes counts;
  counts.put(std::uint32_t{0xFFFFFFFF}).put(std::uint32_t{0});
  EXPECT_NE(std::string(parse(counts).message()).find("exceeds"), std::string::npos);
  Bytes fields;
  fields.put(std::uint32_t{1}).put(std::uint32_t{0}).type(symcr::Kind::Struct, 8, "S")
      .put(std::uint32_t{0x10000000});
  EXPECT_NE(std::string(parse(fields).message()).find("exceeds"), std::string::npos);

  // An array claiming more elements than bytes, and an unknown kind.
  Bytes array;
  array.put(std::uint32_t{2}).put(std::uint32_t{0}).type(symcr::Kind::Int, 1, "int8")
      .type(symcr::Kind::Array, 4, "int8[big]").put(std::uint32_t{0}).put(std::uint64_t{1} << 40);
  EXPECT_EQ(parse(array).error(), symcr::Error::Corrupt);
  Bytes kind;
  kind.put(std::uint32_t{1}).put(std::uint32_t{0}).type(static_cast<symcr::Kind>(99), 1, "x");
  EXPECT_EQ(parse(kind).error(), symcr::Error::Corrupt);

  // A root naming a type that does not exist.
  Bytes root;
  root.put(std::uint32_t{1}).put(std::uint32_t{1}).type(symcr::Kind::Int, 4, "int32")
      .str("r").put(std::uint32_t{5}).put(std::uint32_t{0}).put(std::uint8_t{0});
  EXPECT_EQ(parse(root).error(), symcr::Error::Corrupt);
  // ...and the same root with a valid type parses.
  Bytes good;
  good.put(std::uint32_t{1}).put(std::uint32_t{1}).type(symcr::Kind::Int, 4, "int32")
      .str("r").put(std::uint32_t{0}).put(std::uint32_t{0}).put(std::uint8_t{0});
  EXPECT_TRUE(parse(good).ok()) << parse(good).message();
}

}  // namespace
}  // namespace engine_tests
