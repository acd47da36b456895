// The host of a live pair (crossversion.<name>.live): v0 and v1 of a pair, each built as a
// loadable module, in one process. v0's main fills its state and reaches its save point
// (xv::save), its quiescent point: there, with v0's state live, the host loads v1 and runs v1's
// main, which takes the state by symcr::transfer from v0's roots instead of restoring a file
// (check.hpp, XV_LIVE_FROM) and runs its usual checks on every value and decision: the transfer
// must give what the file restore gives. v0 then finishes (and frees what it allocated).
//
//   xv_live_host <v0 module> <v1 module> <checkpoint path>
#include <dlfcn.h>

#include <cinttypes>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

namespace {

using Main = int (*)(int, char**);

const char* g_v1_path = nullptr;
const char* g_checkpoint = nullptr;
int g_v1_result = -1;  // -1: v0 never reached its save point

void* load(const char* path) {
  // RTLD_LOCAL: each module's references resolve within it (its roots, its runtime, its
  // generated schema), as two builds of one program must not share any of them.
  void* module = ::dlopen(path, RTLD_NOW | RTLD_LOCAL);
  if (module == nullptr) std::fprintf(stderr, "cannot load %s: %s\n", path, ::dlerror());
  return module;
}

Main find_main(void* module) {
  void* symbol = ::dlsym(module, "main");
  if (symbol == nullptr) std::fprintf(stderr, "no main in the module: %s\n", ::dlerror());
  return reinterpret_cast<Main>(symbol);
}

// Called by v0 at its save point with its schema; runs v1 on v0's live state. v1 stays loaded:
// its state may point at objects v0's teardown must not free twice, and the process ends soon.
extern "C" int run_v1_at_save_point(const void* v0_schema) {
  char from[32];
  std::snprintf(from, sizeof from, "%" PRIxPTR, reinterpret_cast<std::uintptr_t>(v0_schema));
  ::setenv("XV_LIVE_FROM", from, 1);
  void* v1 = load(g_v1_path);
  Main v1_main = v1 != nullptr ? find_main(v1) : nullptr;
  if (v1_main == nullptr) return g_v1_result = 2;
  char name[] = "v1";
  char* argv[] = {name, const_cast<char*>(g_checkpoint), nullptr};
  g_v1_result = v1_main(2, argv);
  ::unsetenv("XV_LIVE_FROM");
  return g_v1_result;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: %s <v0 module> <v1 module> <checkpoint>\n", argv[0]);
    return 2;
  }
  g_v1_path = argv[2];
  g_checkpoint = argv[3];
  char hook[32];
  std::snprintf(hook, sizeof hook, "%" PRIxPTR,
                reinterpret_cast<std::uintptr_t>(&run_v1_at_save_point));
  ::setenv("XV_LIVE_AT_SAVE", hook, 1);
  void* v0 = load(argv[1]);
  Main v0_main = v0 != nullptr ? find_main(v0) : nullptr;
  if (v0_main == nullptr) return 2;
  char name[] = "v0";
  char* v0_argv[] = {name, argv[3], nullptr};
  const int v0_result = v0_main(2, v0_argv);
  if (g_v1_result == -1) {
    std::fprintf(stderr, "v0 never reached its save point\n");
    return 1;
  }
  return v0_result != 0 ? v0_result : g_v1_result;
}
