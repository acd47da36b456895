// Record encoding and validation (docs/format.md §1).
#include "record.hpp"

#include <time.h>

#include <cstring>

#include "authentication.hpp"
#include "crc32c.hpp"
#include "encode.hpp"
#include "parsed_schema.hpp"
#include "plan.hpp"
#include "report_access.hpp"
#include "restore_payload.hpp"
#include "schema_blob.hpp"
#include "schema_facts.hpp"
#include "symcr/format/bytes.hpp"

namespace symcr::detail {

std::uint64_t record_timestamp_ns() {
  timespec now{};
  clock_gettime(CLOCK_REALTIME, &now);
  return static_cast<std::uint64_t>(now.tv_sec) * 1000000000u +
         static_cast<std::uint64_t>(now.tv_nsec);
}

namespace {

void store_header(const RecordHeader& h, std::uint8_t* p) {
  format::encode_record_header(h, p);
  if ((h.flags & format::kRecordAuthenticated) != 0) {
    format::RecordAuthentication authentication;
    authentication.key_id = h.key_id;
    authentication.mac_version = h.mac_version;
    authentication.journal_freshness = h.journal_freshness;
    format::encode_record_authentication(authentication, p);
  }
}

// CRC of the record with the checksum field read as zero, without modifying the bytes.
std::uint32_t record_checksum(const std::uint8_t* record, std::size_t size) {
  return format::record_checksum(record, size, crc32c_extend);
}

// True when `bytes` are exactly `blob`'s and `hash` is its hash: then the hash need not be
// recomputed to trust it.
bool is_blob(const SchemaBlob* blob, const std::uint8_t* bytes, std::size_t size,
             std::uint64_t hash) {
  return blob != nullptr && hash == blob->hash && size == blob->size &&
         std::memcmp(bytes, blob->data, size) == 0;
}

}  // namespace

Status encode_record(const Schema& schema, bool inline_schema, std::uint64_t sequence,
                     std::vector<std::uint8_t>& out, const RecordSigning* signing) {
  return encode_record_as(schema, schema_blob(schema), inline_schema, sequence, out, signing);
}

Status encode_record_as(const Schema& schema, const SchemaBlob& identity, bool inline_schema,
                        std::uint64_t sequence, std::vector<std::uint8_t>& out,
                        const RecordSigning* signing, const ClockReadings* clock_readings) {
  // Without a store's signing, a standalone checkpoint signed with the keys in force: one
  // snapshot names the key and makes the MAC.
  KeySnapshot snapshot;
  RecordBinding standalone;
  RecordSigning own;
  if (signing == nullptr) {
    snapshot = current_keys();
    own.keys = snapshot.get();
    if (own.keys != nullptr) schema_digest(identity.data, identity.size, standalone.schema_digest);
    own.binding = &standalone;
    signing = &own;
  }
  // With keys set, the record is authenticated: a longer header, with the key id and the MAC.
  const bool authenticated = signing->keys != nullptr;
  const std::uint16_t header_size =
      authenticated ? format::kRecordAuthenticatedHeaderSize : format::kRecordHeaderSize;
  std::size_t schema_size = 0;
  if (inline_schema) {
    schema_size = identity.size;
    if (schema_size > UINT32_MAX) {
      return Status(Error::TooLarge, "schema of %zu bytes exceeds the format's 4 GiB limit",
                    schema_size);
    }
  }
  // Written over what `out` holds (the previous record, when checkpoints reuse a buffer),
  // never cleared first: the payload's large values are then copied straight over it.
  if (out.size() < header_size + schema_size) out.resize(header_size + schema_size);
  std::memset(out.data(), 0, header_size);
  if (schema_size != 0) std::memcpy(out.data() + header_size, identity.data, schema_size);
  PayloadCrc payload_crc;
  Status status =
      encode_payload_at(schema, out, header_size + schema_size, &payload_crc, clock_readings);
  if (!status.ok()) return status;
  const std::size_t payload_size = out.size() - header_size - schema_size;
  if (payload_size > UINT32_MAX) {
    return Status(Error::TooLarge, "payload of %zu bytes exceeds the format's 4 GiB limit",
                  payload_size);
  }
  RecordHeader header;
  header.format_version = format::kRecordFormatVersion;
  header.header_size = header_size;
  header.flags = (inline_schema ? format::kRecordSchemaInline : 0) |
                 (authenticated ? format::kRecordAuthenticated : 0);
  if (authenticated) {
    header.key_id = signing->keys->signing().id;
    header.mac_version = format::kRecordMacVersion;
    header.journal_freshness = signing->journal_freshness;
  }
  header.sequence = sequence;
  header.timestamp_ns = record_timestamp_ns();
  header.schema_hash = identity.hash;
  header.schema_size = static_cast<std::uint32_t>(schema_size);
  header.payload_size = static_cast<std::uint32_t>(payload_size);
  header.program_id = identity.program_id;
  store_header(header, out.data());
  if (authenticated && signing->binding != nullptr) {  // the CRC then covers the MAC too
    sign_record(*signing->keys, out.data(), out.size(), *signing->binding);
  }
  // A large payload's CRC was computed as it was copied: only the header and schema are read.
  const std::uint32_t checksum =
      payload_crc.known ? crc32c_combine(record_checksum(out.data(), header_size + schema_size),
                                         payload_crc.value, payload_size)
                        : record_checksum(out.data(), out.size());
  format::store32(out.data() + format::kRecordChecksumOffset, checksum);
  return Status();
}

void reseal_record(std::uint8_t* record, std::size_t size, const RecordSigning& signing) {
  format::RecordAuthentication authentication;
  authentication.key_id = signing.keys->signing().id;
  authentication.mac_version = format::kRecordMacVersion;
  authentication.journal_freshness = signing.journal_freshness;
  format::encode_record_authentication(authentication, record);
  sign_record(*signing.keys, record, size, *signing.binding);
  format::store32(record + format::kRecordChecksumOffset, record_checksum(record, size));
}

Status parse_record(const std::uint8_t* data, std::size_t size, RecordView& out,
                    const SchemaBlob* known, const Crc32cSpan* known_crc) {
  out = RecordView();
  RecordHeader& h = out.header;
  switch (format::decode_record_header(data, size, &h)) {
    case format::HeaderFault::None:
      break;
    case format::HeaderFault::Empty:
      return Status(Error::Truncated, "truncated: empty");
    case format::HeaderFault::BadMagic:
      return Status(Error::NotACheckpoint, "not a symcr checkpoint (bad magic)");
    case format::HeaderFault::Truncated:
      return Status(Error::Truncated, "truncated: %zu bytes, shorter than the %u-byte header", size,
                    unsigned{format::kRecordHeaderSize});
    case format::HeaderFault::FutureVersion:
      return Status(Error::FutureVersion,
                    "written by checkpoint format version %u; this build reads up to version %u",
                    unsigned{h.format_version}, unsigned{format::kRecordFormatVersion});
    case format::HeaderFault::ZeroVersion:
      return Status(Error::Corrupt, "format version 0 is invalid");
    case format::HeaderFault::ShortHeader:
      return Status(Error::Corrupt, "header size %u is below the minimum %u",
                    unsigned{h.header_size}, unsigned{format::kRecordHeaderSize});
  }
  const std::uint64_t record_size = format::claimed_record_size(h);
  if (record_size > size) {
    return Status(Error::Truncated, "truncated: header says %llu bytes, %zu available",
                  static_cast<unsigned long long>(record_size), size);
  }
  // The inline schema's bytes, if they are `known`'s, are compared once; their share of the
  // CRC is then known, and only the header and payload are read for it. The CRC is the same.
  const std::uint64_t schema_end = std::uint64_t{h.header_size} + h.schema_size;
  const bool known_inline = known_crc != nullptr && (h.flags & format::kRecordSchemaInline) != 0 &&
                            schema_end <= record_size &&
                            is_blob(known, data + h.header_size, h.schema_size, h.schema_hash);
  const std::uint32_t actual =
      known_inline
          ? crc32c_extend(crc32c_extend_span(record_checksum(data, h.header_size), *known_crc),
                          data + schema_end, static_cast<std::size_t>(record_size - schema_end))
          : record_checksum(data, static_cast<std::size_t>(record_size));
  if (actual != h.checksum) {
    return Status(Error::Checksum, "checksum mismatch: stored %08x, computed %08x", h.checksum,
                  actual);
  }
  if ((h.flags & ~format::kRecordKnownFlags) != 0) {
    return Status(Error::Corrupt, "unknown header flags %08x", h.flags);
  }
  if ((h.flags & format::kRecordAuthenticated) != 0) {
    if (h.header_size < format::kRecordLegacyAuthenticatedHeaderSize) {
      return Status(Error::Corrupt, "authenticated, but a %u-byte header has no room for a MAC",
                    unsigned{h.header_size});
    }
    h.key_id = format::load32(data + format::kRecordKeyIdOffset);
    h.mac_version = format::load32(data + format::kRecordMacVersionOffset);
    if (h.mac_version != 0 && h.header_size < format::kRecordAuthenticatedHeaderSize) {
      return Status(Error::Corrupt, "MAC version %u, but a %u-byte header has no room for it",
                    h.mac_version, unsigned{h.header_size});
    }
    if (h.mac_version != 0) {
      h.journal_freshness = format::load64(data + format::kRecordJournalFreshnessOffset);
    }
  }
  const bool inline_schema = (h.flags & format::kRecordSchemaInline) != 0;
  if (inline_schema != (h.schema_size != 0)) {
    return Status(Error::Corrupt, "schema flag %s but %u bytes of inline schema",
                  inline_schema ? "set" : "clear", h.schema_size);
  }
  out.schema = inline_schema ? data + h.header_size : nullptr;
  out.payload = data + h.header_size + h.schema_size;
  out.payload_size = h.payload_size;
  out.record_size = static_cast<std::size_t>(record_size);
  out.schema_is_known =
      known_inline || (inline_schema && is_blob(known, out.schema, h.schema_size, h.schema_hash));
  if (inline_schema && !out.schema_is_known &&
      format::fnv1a64(out.schema, h.schema_size) != h.schema_hash) {
    return Status(Error::Corrupt, "inline schema does not match its hash %016llx",
                  static_cast<unsigned long long>(h.schema_hash));
  }
  return Status();
}

Status check_program(std::uint32_t writer_program_id, std::uint32_t reader_program_id,
                     const char* reader_name, bool accept_other_program) {
  if (writer_program_id == 0 || reader_program_id == 0 || writer_program_id == reader_program_id ||
      accept_other_program) {
    return Status();
  }
  return Status(Error::Incompatible,
                "written by another program (program id %08x; this is '%s', id %08x): nothing "
                "restored (RestoreOptions::accept_other_program restores it anyway)",
                writer_program_id, reader_name ? reader_name : "?", reader_program_id);
}

Report restore_record(const RecordView& record, const Schema& writer, std::uint64_t writer_hash,
                      const Schema& reader, const RestoreOptions& options,
                      std::shared_ptr<const ParsedSchema> writer_owner) {
  const Status program = check_program(record.header.program_id, schema_blob(reader).program_id,
                                       reader.program, options.accept_other_program);
  if (!program.ok()) {
    Report report;
    ReportAccess::set_status(report, program);
    ReportAccess::set_sequence(report, record.header.sequence);
    return report;
  }
  Report report = restore_payload(writer, writer_hash, record.payload, record.payload_size, reader,
                                  options, std::move(writer_owner));
  ReportAccess::set_sequence(report, record.header.sequence);
  return report;
}

Report restore_standalone_record(const std::uint8_t* data, std::size_t size, const Schema& reader,
                                 const RestoreOptions& options) {
  Report report;
  RecordView record;
  // A known inline schema needs neither hashing nor parsing: the reader's own (written by this
  // very build, the usual case), or one a cached plan was built from (restoring the checkpoint
  // of an earlier build again). The header's hash only picks the candidate; the bytes decide.
  const SchemaBlob& own = schema_blob(reader);
  std::shared_ptr<const Plan> plan;
  const std::uint64_t schema_hash = size >= format::kRecordHeaderSize
                                        ? format::load64(data + format::kRecordSchemaHashOffset)
                                        : 0;
  if (size >= format::kRecordHeaderSize && schema_hash != own.hash) {
    plan = cached_plan(schema_hash, reader);
  }
  SchemaBlob plan_blob;  // the cached plan's writer schema, to recognise it by its bytes
  if (plan && plan->writer_owner) {
    plan_blob.data = plan->writer_owner->bytes().data();
    plan_blob.size = plan->writer_owner->bytes().size();
    plan_blob.hash = plan->writer_owner->hash();
  }
  Status status = plan_blob.data ? parse_record(data, size, record, &plan_blob, &plan->writer_crc)
                                 : parse_record(data, size, record, &own,
                                                &schema_cache_entry(reader).blob_crc());
  if (status.ok() && record.record_size != size) {
    status = Status(Error::Corrupt, "%zu unexpected bytes after the %zu-byte record",
                    size - record.record_size, record.record_size);
  }
  if (status.ok() && record.schema == nullptr) {
    status = Status(Error::SchemaUnknown,
                    "the record references schema %016llx by hash (a store slot) and carries "
                    "no schema of its own",
                    static_cast<unsigned long long>(record.header.schema_hash));
  }
  if (status.ok()) status = check_standalone_authentication(current_keys().get(), data, record);
  if (!status.ok()) {
    ReportAccess::set_status(report, status);
    return report;
  }
  // Written by this very build (the usual case): the inline schema is byte for byte the
  // reader's own, so the reader serves as the writer schema and nothing needs parsing.
  // parse_record compared the bytes with the one candidate it was given.
  if (!plan_blob.data && record.schema_is_known) {
    return restore_record(record, reader, own.hash, reader, options);
  }
  if (plan_blob.data && record.schema_is_known) {
    return restore_record(record, *plan->writer, record.header.schema_hash, reader, options,
                          plan->writer_owner);
  }
  auto writer = std::make_shared<ParsedSchema>();
  // parse_record checked that the inline bytes hash to the header's hash.
  status =
      parse_schema(record.schema, record.header.schema_size, *writer, &record.header.schema_hash);
  if (!status.ok()) {
    ReportAccess::set_status(report, status);
    return report;
  }
  const Schema& writer_schema = writer->schema();
  return restore_record(record, writer_schema, record.header.schema_hash, reader, options,
                        std::move(writer));
}

}  // namespace symcr::detail
