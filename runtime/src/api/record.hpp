// Records (docs/format.md §1; the header's layout is the format core's, symcr/format/record.hpp):
// a 56-byte header (112 with a MAC), an optional inline schema and a payload, covered by one
// CRC-32C. Shared by single-file checkpoints, in-memory checkpoints and
// store slots. Parsing never trusts a length: every size is checked against the bytes available.
#ifndef SYMCR_SRC_RECORD_HPP
#define SYMCR_SRC_RECORD_HPP

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "crc32c.hpp"
#include "parsed_schema.hpp"
#include "schema_blob.hpp"
#include "symcr/format/record.hpp"
#include "symcr/generated.hpp"
#include "symcr/symcr.hpp"

namespace symcr::detail {

class ParsedSchema;

// The 56-byte header's fields (format::RecordHeader), and the authenticated header's after them.
struct RecordHeader : format::RecordHeader {
  std::uint32_t key_id = 0;             // kRecordAuthenticated: the key its MAC was made with
  std::uint32_t mac_version = 0;        // kRecordAuthenticated: kRecordMacVersion
  std::uint64_t journal_freshness = 0;  // kRecordAuthenticated, version 2
};

// A record validated in place: views into the caller's bytes, valid while they are.
struct RecordView {
  RecordHeader header;
  const std::uint8_t* schema = nullptr;  // inline schema (header.schema_size bytes) or null
  const std::uint8_t* payload = nullptr;
  std::size_t payload_size = 0;
  std::size_t record_size = 0;  // header_size + schema_size + payload_size
  // The inline schema is byte for byte the blob parse_record was told it might be (`known`).
  bool schema_is_known = false;
};

struct SchemaBlob;
struct KeyRing;
struct RecordBinding;
struct ClockReadings;

// How a record is authenticated: with `keys` (null: not at all), bound to `binding`, carrying
// `journal_freshness`. A store passes its own; without one, a record is signed with the keys in
// force as a standalone checkpoint. A null `binding` (with keys) lays the header out but leaves
// the MAC to reseal_record, once the record's place is known.
struct RecordSigning {
  const KeyRing* keys = nullptr;
  const RecordBinding* binding = nullptr;
  std::uint64_t journal_freshness = 0;
};

// The time a record's header carries: the wall clock, in nanoseconds since the Unix epoch.
std::uint64_t record_timestamp_ns();

// Replaces `out` with a complete record of every root of `schema`: header, the serialised
// schema when `inline_schema`, the payload, and the checksum. Reuses `out`'s capacity.
Status encode_record(const Schema& schema, bool inline_schema, std::uint64_t sequence,
                     std::vector<std::uint8_t>& out, const RecordSigning* signing = nullptr);
// The same record of `schema`'s roots under another schema's identity: the header's hash and
// program, and the inline bytes, are `identity`'s. For `symcr convert`, whose roots are another
// build's, laid out for this machine's memory (the payload never depends on the layout), and
// whose times of clocks hold the converted checkpoint's timebase: `clock_readings`, if given,
// end the payload (encode_payload_at).
Status encode_record_as(const Schema& schema, const SchemaBlob& identity, bool inline_schema,
                        std::uint64_t sequence, std::vector<std::uint8_t>& out,
                        const RecordSigning* signing = nullptr,
                        const ClockReadings* clock_readings = nullptr);

// Names `signing`'s key and journal freshness in an authenticated record's header, makes its
// MAC for `signing.binding` and rewrites its checksum: a record signed where its slot is known,
// or moved to another (a store rewritten for a new geometry; verified before it moves).
void reseal_record(std::uint8_t* record, std::size_t size, const RecordSigning& signing);

// Checks magic, version, header size, flags, sizes against `size` and the checksum, and for an
// inline schema that its bytes hash to `schema_hash`. Bytes after the record are not looked at
// (a store slot has room to spare). Does not parse the schema. When the inline schema is byte
// for byte `known` (a blob whose hash is already computed, e.g. the reader's own schema), its
// hash is taken from `known` instead of rehashing: the common case costs a memcmp. With
// `known_crc`, known's share of the CRC (crc32c_span), its bytes are not read for the CRC either.
Status parse_record(const std::uint8_t* data, std::size_t size, RecordView& out,
                    const SchemaBlob* known = nullptr, const Crc32cSpan* known_crc = nullptr);

// Incompatible when a checkpoint of program `writer_program_id` is not to be restored into
// program `reader_program_id` (named `reader_name`): both are named, they differ, and it is
// not accepted anyway.
Status check_program(std::uint32_t writer_program_id, std::uint32_t reader_program_id,
                     const char* reader_name, bool accept_other_program);

// Restores a record validated by parse_record whose writer schema is `writer`, unless it is
// another program's (check_program). The report carries the record's sequence. `writer_owner`:
// as for restore_payload.
Report restore_record(const RecordView& record, const Schema& writer, std::uint64_t writer_hash,
                      const Schema& reader, const RestoreOptions& options,
                      std::shared_ptr<const ParsedSchema> writer_owner = nullptr);

// Restores a complete, self-contained record (a single-file or in-memory checkpoint): it must
// carry its schema inline and have no bytes after it.
Report restore_standalone_record(const std::uint8_t* data, std::size_t size, const Schema& reader,
                                 const RestoreOptions& options);

}  // namespace symcr::detail

#endif  // SYMCR_SRC_RECORD_HPP
