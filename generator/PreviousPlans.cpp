//===- PreviousPlans.cpp - Plans previous builds' schemas at build time ---===//
//
// See PreviousPlans.h. The plan is the runtime's (plan_image_for), made
// against the same tables the schema source prints (SchemaTables): the
// planner decides from what the tables record, not from code pointers, which
// are null here, so the image is the plan the built program would make.
//
//===----------------------------------------------------------------------===//
#include "PreviousPlans.h"
#include "SchemaTables.h"

#include "device_plan_encode.hpp"
#include "parsed_schema.hpp"
#include "plan.hpp"
#include "schema_blob.hpp"
#include "symcr/format/hashes.hpp"
#include "schema_file.hpp"

namespace symcr_gen {

bool planPreviousSchemas(ProgramModel &Program,
                         const std::vector<std::string> &SchemaFiles,
                         Diagnostics &Diags) {
  Program.PreviousPlans.clear();
  if (SchemaFiles.empty())
    return true;
  SchemaTables Tables(Program);
  const std::uint64_t OwnHash = Tables.serialised().hash;
  const std::uint32_t OwnProgram =
      symcr::format::program_id(Tables.schema().program);
  for (const std::string &File : SchemaFiles) {
    symcr::detail::ParsedSchema Previous;
    std::uint32_t PreviousProgram = 0;
    symcr::Status Status = symcr::detail::read_schema_file(
        File.c_str(), Previous, &PreviousProgram);
    if (!Status.ok()) {
      Diags.error(Location(),
                  "--previous-schema '" + File + "': " + Status.message());
      return false;
    }
    // An anonymous program (id 0) accepts, and is accepted by, any other.
    if (PreviousProgram != 0 && OwnProgram != 0 &&
        PreviousProgram != OwnProgram) {
      Diags.error(Location(),
                  "--previous-schema '" + File +
                      "' is another program's schema (its checkpoints are "
                      "refused by this build): give a schema file of an "
                      "earlier build of '" +
                      (Program.Name.empty() ? std::string("this program")
                                            : Program.Name) +
                      "'");
      return false;
    }
    if (Previous.hash() == OwnHash)
      continue; // this build's own schema: restored without a plan
    PreviousPlanModel Plan;
    Plan.SchemaFile = File;
    Plan.WriterHash = Previous.hash();
    if (Program.Profile != RuntimeProfile::Device) {
      symcr::detail::plan_image_for(Previous.schema(), Previous.hash(),
                                    Tables.schema(), OwnHash, Plan.Image);
    } else {
      // The device executes a compiled form of the same plan: what it cannot
      // carry out is refused here, by member path, rather than on the device.
      std::string Error;
      if (!symcr::detail::device_plan_image_for(
              Previous.schema(), Previous.hash(), Tables.schema(), OwnHash,
              Plan.Image, Error)) {
        Diags.error(Location(), "--previous-schema '" + File +
                                    "': the device profile cannot restore "
                                    "its checkpoints: " +
                                    Error);
        return false;
      }
    }
    Program.PreviousPlans.push_back(std::move(Plan));
  }
  return true;
}

} // namespace symcr_gen
