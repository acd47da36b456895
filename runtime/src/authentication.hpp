// Internal: authenticated checkpoints (docs/format.md §1, "Authentication"). With keys set
// (symcr::set_checkpoint_keys), every record this process writes carries an HMAC-SHA-256 of the
// whole record, made with the first key and naming it by id, and every checkpoint it restores
// must carry one that verifies with the key of that id.
#ifndef SYMCR_SRC_AUTHENTICATION_HPP
#define SYMCR_SRC_AUTHENTICATION_HPP

#include <cstddef>
#include <cstdint>

#include "record.hpp"
#include "symcr/symcr.hpp"

namespace symcr::detail {

// True when the program has set keys: records are signed and must verify.
bool keys_set();
// The id of the key records are signed with (keys_set() only).
std::uint32_t signing_key_id();

// Writes the MAC of the complete record at `record` (its header laid out for authentication,
// the checksum not yet written) into the header.
void sign_record(std::uint8_t* record, std::size_t size);

// Whether a record parse_record accepted may be restored by this program: without keys, any;
// with keys, only an authenticated one whose MAC verifies with the key its header names
// (Error::Unauthenticated otherwise, saying which of the three it is).
Status check_authentication(const std::uint8_t* record, const RecordView& view);

}  // namespace symcr::detail

#endif  // SYMCR_SRC_AUTHENTICATION_HPP
