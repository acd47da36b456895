// The firmware's checkpoints: a ring of slots in backup RAM (RAM a reset leaves alone), written
// and read by symcr's device profile. AP_Checkpoint (AP_Checkpoint.cpp here) saves into it from
// the scheduler and restores from it at start-up; the firmware's test reaches in to damage it.
#ifndef SPECIMEN_FIRMWARE_BACKUP_RING_HPP
#define SPECIMEN_FIRMWARE_BACKUP_RING_HPP

#include <cstddef>
#include <cstdint>
#include <symcr/device.hpp>

namespace firmware {

constexpr std::size_t kSlots = 4;
// A record of `copter` on this target (2068 B), and room to grow.
constexpr std::size_t kSlotSize = 2304;

// Opens the ring (once per boot) and counts the boot. A record or staged copy that does not fit
// its buffer is the save's or the restore's NoSpace, which AP_Checkpoint prints.
bool open_backup_ring();
symcr::device::Ring& backup_ring();
// The ring's bytes: kSlots slots of kSlotSize.
std::uint8_t* backup_slots();
// Boots since the backup RAM lost power (1 on the first).
std::uint32_t boot_count();

// A record's buffer and the staged copy restore writes into.
std::uint8_t* record_buffer();
std::size_t record_capacity();
std::uint8_t* scratch_buffer();
std::size_t scratch_capacity();

}  // namespace firmware

#endif  // SPECIMEN_FIRMWARE_BACKUP_RING_HPP
