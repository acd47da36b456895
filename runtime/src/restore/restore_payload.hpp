// Restoring a payload into a reader schema's roots, and planning it (docs/resolution.md): the
// restore engine's entry points. Internal to the runtime; tools and tests may include it too.
#ifndef SYMCR_SRC_RESTORE_PAYLOAD_HPP
#define SYMCR_SRC_RESTORE_PAYLOAD_HPP

#include <cstddef>
#include <cstdint>
#include <memory>

#include "symcr/generated.hpp"
#include "symcr/symcr.hpp"

namespace symcr::detail {

class ParsedSchema;  // parsed_schema.hpp

// Restores a payload written with `writer` into the live roots of `reader`: resolves (plans are
// cached per writer-hash/reader pair), decodes and checks everything, and only then writes.
// On any failure the report is !ok() and no live object has been modified. `writer_owner`,
// if given, owns `writer` (a parsed schema): a plan built for it shares it instead of copying.
Report restore_payload(const Schema& writer, std::uint64_t writer_hash, const std::uint8_t* payload,
                       std::size_t size, const Schema& reader, const RestoreOptions& options,
                       std::shared_ptr<const ParsedSchema> writer_owner = nullptr);

// What restore_payload needs to know of the two schemas alone, resolved ahead of it (the plan,
// cached; for a schema restored into itself, that the same-build decoder holds it; the first
// restore's scratch, touched), so that a later restore only decodes and writes. Never fails: a
// refusing plan is cached and reported by the restore.
void prepare_restore(const Schema& writer, std::uint64_t writer_hash, const Schema& reader,
                     std::shared_ptr<const ParsedSchema> writer_owner);

// Pass 1 of restore_payload only: the full report (schema-level and value-level decisions)
// and status of restoring the payload into `reader`, without writing anything. The reader's
// roots need no addresses (e.g. a schema read from another build, for the CLI's `plan`).
// With payload == nullptr and size == 0, only the schema-level plan is reported.
Report plan_payload(const Schema& writer, std::uint64_t writer_hash, const std::uint8_t* payload,
                    std::size_t size, const Schema& reader, const RestoreOptions& options);

}  // namespace symcr::detail

#endif  // SYMCR_SRC_RESTORE_PAYLOAD_HPP
