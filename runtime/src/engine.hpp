// The seam between the file layer (records, single files, the store, the C API) and the
// payload engine (schema serialisation, save traversal, resolution, two-pass restore).
// Internal to the runtime; the CLI and fuzzers may include it too.
#ifndef SYMCR_SRC_ENGINE_HPP
#define SYMCR_SRC_ENGINE_HPP

#include <cstdarg>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "symcr/generated.hpp"
#include "symcr/symcr.hpp"

namespace symcr::detail {

// The scratch memory of the calling thread's engine, in bytes of capacity: what its last
// checkpoint's memo tables, region index and reference and heap lists hold (kept between
// checkpoints for reuse), and what the decoding tables of its last restore that got as far as
// writing held (freed on return; 0 after the copy-only fast path).
// Rebuilt objects and the output buffer are not scratch. For benchmarks and tools.
struct ScratchBytes {
  std::size_t checkpoint = 0;
  std::size_t restore = 0;
};
ScratchBytes thread_scratch_bytes();
std::size_t encode_scratch_bytes();  // its checkpoint part (encode.cpp)

// For the payload decoders: sets `error`, unless it already holds one, to Corrupt "invalid
// payload: <format...>", and returns it. Out of line and cold, so that its message buffer is
// not in the frames of the recursive decoders (their depth is bounded, their frames not).
__attribute__((format(printf, 2, 0), noinline, cold)) const Status& set_corrupt_payload(
    Status& error, const char* format, va_list args);

// The serialised form (docs/format.md §2) of a running build's schema and its FNV-1a 64 hash:
// symcr-gen's (Schema::serialised), or serialised once per Schema object and cached.
// Thread-compatible (compute before sharing).
struct SchemaBlob {
  SchemaBlob() = default;
  SchemaBlob(const SchemaBlob&) = delete;  // `data` may point into `storage`
  SchemaBlob& operator=(const SchemaBlob&) = delete;
  const std::uint8_t* data = nullptr;  // the generated constant, or storage's bytes
  std::size_t size = 0;
  std::uint64_t hash = 0;
  std::uint32_t program_id = 0;  // format::program_id(schema.program)
  std::vector<std::uint8_t> storage;
};
// Serialises `schema` into `blob` (its storage) and hashes it.
void serialise_blob(const Schema& schema, SchemaBlob& blob);

const SchemaBlob& schema_blob(const Schema& schema);

// A writer schema parsed from checkpoint bytes: owns its strings and tables and exposes them
// as a symcr::Schema (roots have null addresses). Validated on parse (docs/format.md §2).
class ParsedSchema {
 public:
  ParsedSchema();
  ~ParsedSchema();
  ParsedSchema(ParsedSchema&&) noexcept;
  ParsedSchema& operator=(ParsedSchema&&) noexcept;
  const Schema& schema() const;
  std::uint64_t hash() const;
  const std::vector<std::uint8_t>& bytes() const;  // the serialised form it was parsed from

  struct Storage;
  std::unique_ptr<Storage> storage;
};
// `hash`, when given, is the bytes' FNV-1a 64 hash, which the caller already computed.
Status parse_schema(const std::uint8_t* data, std::size_t size, ParsedSchema& out,
                    const std::uint64_t* hash = nullptr);

// Saves every root of `schema` as a payload (docs/format.md §3), replacing `out`'s contents.
// Reuses the capacity of `out` and of internal per-thread scratch: a steady state allocates
// nothing after the first call.
Status encode_payload(const Schema& schema, std::vector<std::uint8_t>& out);
// The payload's CRC-32C, when saving computed it while copying (large flat values).
struct PayloadCrc {
  bool known = false;
  std::uint32_t value = 0;
};
// Same, appending at out.size() (so a caller can reserve room for a header first); sets
// `payload_crc` if given.
Status append_payload(const Schema& schema, std::vector<std::uint8_t>& out,
                      PayloadCrc* payload_crc = nullptr);

// Restores a payload written with `writer` into the live roots of `reader`: resolves (plans are
// cached per writer-hash/reader pair), decodes and checks everything, and only then writes.
// On any failure the report is !ok() and no live object has been modified. `writer_owner`,
// if given, owns `writer` (a parsed schema): a plan built for it shares it instead of copying.
Report restore_payload(const Schema& writer, std::uint64_t writer_hash, const std::uint8_t* payload,
                       std::size_t size, const Schema& reader, const RestoreOptions& options,
                       std::shared_ptr<const ParsedSchema> writer_owner = nullptr);

// What restore_payload needs to know of the two schemas alone, resolved ahead of it (the plan,
// cached; for a schema restored into itself, that the same-build decoder holds it), so that a
// later restore only decodes and writes. Never fails: a refusing plan is cached and reported by
// the restore.
void prepare_restore(const Schema& writer, std::uint64_t writer_hash, const Schema& reader,
                     std::shared_ptr<const ParsedSchema> writer_owner);

// Pass 1 of restore_payload only: the full report (schema-level and value-level decisions)
// and status of restoring the payload into `reader`, without writing anything. The reader's
// roots need no addresses (e.g. a schema read from another build, for the CLI's `plan`).
// With payload == nullptr and size == 0, only the schema-level plan is reported.
Report plan_payload(const Schema& writer, std::uint64_t writer_hash, const std::uint8_t* payload,
                    std::size_t size, const Schema& reader, const RestoreOptions& options);

// Decodes a payload against its writer schema without any reader, calling the visitor for each
// scalar leaf with its symbolic path (for the CLI's inspect/diff). Returns the decode status.
struct PathFrame;
struct ValueVisitor {
  virtual ~ValueVisitor() = default;
  // Around every nested value, in the pass that reports leaves: the path as a stack of frames
  // (whose names are the schema's), for a visitor that keeps paths without copying them.
  virtual void enter(const PathFrame& /*frame*/) {}
  virtual void leave() {}
  // `path` like "copter.mission.items[3].lat"; `type` is the writer type of the leaf; `bytes`
  // the little-endian wire bytes (String: the characters; Pointer: textual target in `text`).
  virtual void leaf(const char* path, const TypeInfo& type, const std::uint8_t* bytes,
                    std::size_t size, const char* text) = 0;
};
Status visit_payload(const Schema& writer, const std::uint8_t* payload, std::size_t size,
                     ValueVisitor& visitor);

}  // namespace symcr::detail

#endif  // SYMCR_SRC_ENGINE_HPP
