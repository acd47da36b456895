// The criu method: the autopilot's whole process dumped and restored by CRIU, the baseline the
// paper compares with. The world runs the user's `criu` binary (given by the harness) as CRIU
// documents it for a process whose links lead outside the dump: the links are dumped as external
// (--external unix[...], file[...]) and the world's new ends are handed back at restore
// (--inherit-fd). CRIU's own checks run unmodified: it refuses an executable whose size or
// build-id changed, and the refusal is the outcome.
#ifndef WORLD_CRIU_CHECKPOINTER_HPP
#define WORLD_CRIU_CHECKPOINTER_HPP

#include <sys/types.h>

#include <cstdint>
#include <string>
#include <vector>

#include "autopilot_process.hpp"

namespace world {

struct CriuOutcome {
  bool ok = false;
  double seconds = 0;             // the criu command's wall time
  std::uint64_t image_bytes = 0;  // dump: all files of the images directory
  pid_t pid = -1;                 // restore: the restored autopilot
  std::string error;              // why not ok: criu's own first error line
};

class CriuCheckpointer {
 public:
  // `images_dir` receives the newest complete dump; `log_dir` criu's logs. `build_id`: CRIU's
  // default validation of files (size and ELF build-id); false: size only.
  CriuCheckpointer(std::string criu, std::string images_dir, std::string log_dir, bool build_id);

  // Dumps process `pid` (a child of this process, holding `links`). Without `leave_running`
  // CRIU kills it once dumped. A failed dump keeps the previous one.
  CriuOutcome dump(pid_t pid, const std::vector<ExternalLink>& links, bool leave_running);
  // Restores the newest dump as a child of this process, its dumped `links` replaced by `ends`.
  CriuOutcome restore(const std::vector<ExternalLink>& links, const ChildEnds& ends);
  bool has_dump() const { return dumps_ > 0; }

 private:
  CriuOutcome run(const std::vector<std::string>& args, const std::vector<int>& inherited,
                  const std::string& log);

  std::string criu_, images_dir_, log_dir_;
  bool build_id_;
  int dumps_ = 0;
};

}  // namespace world

#endif  // WORLD_CRIU_CHECKPOINTER_HPP
