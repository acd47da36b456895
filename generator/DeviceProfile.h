//===- DeviceProfile.h - What the device profile's runtime can hold
//--------===//
//
// The device profile (runtime/device, symcr_add_checkpointing(... PROFILE
// device)) runs without a heap or standard containers. It holds bool, integers
// and enums of up to 8 bytes, 4- and 8-byte floating point, structs, unions,
// fixed arrays and raw pointers (saved as references by path; it never saves
// a pointee through the pointer). This check names every member of the roots
// whose type it cannot hold, with its path and the change that fixes it, so a
// build never produces code the device would refuse at run time.
//
//===----------------------------------------------------------------------===//

#ifndef SYMCR_GENERATOR_DEVICEPROFILE_H
#define SYMCR_GENERATOR_DEVICEPROFILE_H

#include "Model.h"

namespace symcr_gen {

/// Reports an error per member (and per program point) the device profile
/// cannot serve; true when there was none.
bool checkDeviceProfile(const ProgramModel &Program, Diagnostics &Diags);

} // namespace symcr_gen

#endif // SYMCR_GENERATOR_DEVICEPROFILE_H
