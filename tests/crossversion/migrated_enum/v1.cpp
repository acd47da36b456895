// v1: Mode::Return became Mode::Rtl. Navigator's symcr_migrate reads the removed enumerator by
// its old name and maps it: the values the rules reject inside a migrated object (at any depth:
// a field, a nested struct's field, a vector's elements, a field whose kind changed) go to the
// hook instead of being lost, so the restore (strict too), `symcr plan` and the STRICT gate
// agree that nothing is lost.
#include <cstring>
#include <string>
#include <vector>

#include "check.hpp"

enum class Mode { Manual, Auto, Rtl };

struct Leg {
  Mode mode = Mode::Manual;
  int seconds = 0;
};

struct Navigator {
  Mode mode = Mode::Manual;
  int waypoint = 0;
  Leg last;
  std::vector<Mode> history;
  int spare = -1;  // was a Leg: its seconds
};

namespace {
int hooks = 0;
Mode mapped(const char* old_name, Mode otherwise) {
  return old_name && std::strcmp(old_name, "Return") == 0 ? Mode::Rtl : otherwise;
}
}  // namespace

void symcr_migrate(Navigator& nav, const symcr::OldValues& old);
void symcr_migrate(Navigator& nav, const symcr::OldValues& old) {
  ++hooks;
  const char* name = nullptr;
  std::int64_t value = -1;
  // The hook is handed the removed enumerator's name and value.
  XV_CHECK(old.enumerator("mode", name) && std::string(name) == "Return");
  XV_CHECK(old.get("mode", value) && value == 2);
  nav.mode = mapped(name, nav.mode);
  const symcr::OldValues last = old.child("last");
  if (last.enumerator("mode", name)) nav.last.mode = mapped(name, nav.last.mode);
  // The element v1 could not restore kept the new build's initial value; the hook sets it.
  std::int64_t spare_seconds = 0;
  if (old.child("spare").get("seconds", spare_seconds)) nav.spare = static_cast<int>(spare_seconds);
  for (std::size_t i = 0; i < nav.history.size() && i < old.count("history"); ++i) {
    if (old.element("history", i).enumerator(nullptr, name)) {
      nav.history[i] = mapped(name, nav.history[i]);
    }
  }
}

SYMCR_CHECKPOINT Navigator nav;

namespace {

bool handed(const symcr::Report& report, const char* path, const char* why) {
  for (const symcr::ReportEntry& e : report.entries()) {
    if (e.path == path && e.decision == symcr::Decision::Converted && !e.lossy &&
        e.detail == std::string(why) + "; the old value goes to symcr_migrate(Navigator)") {
      return true;
    }
  }
  std::fprintf(stderr, "'%s': no converted entry handing '%s' to the hook\n", path, why);
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  // Strict: nothing handed to the hook is a loss.
  symcr::Report report = xv::restore(argc, argv, /*strict=*/true);
  XV_CHECK(report.ok());
  XV_CHECK(hooks == 1);
  XV_CHECK(nav.mode == Mode::Rtl);
  XV_CHECK(nav.waypoint == 4);
  XV_CHECK(nav.last.mode == Mode::Rtl && nav.last.seconds == 30);
  XV_CHECK(nav.history.size() == 2);
  if (nav.history.size() == 2) {
    XV_CHECK(nav.history[0] == Mode::Auto && nav.history[1] == Mode::Rtl);
  }
  XV_CHECK(handed(report, "nav.mode", "enum Return not in this build"));
  XV_CHECK(handed(report, "nav.last.mode", "enum Return not in this build"));
  XV_CHECK(handed(report, "nav.history[1]", "enum Return not in this build"));
  XV_CHECK(xv::decided(report, "nav", symcr::Decision::Converted));
  // A kind change inside the migrated object goes to the hook too.
  XV_CHECK(nav.spare == 12);
  const symcr::ReportEntry* spare = xv::entry(report, "nav.spare");
  XV_CHECK(spare && spare->decision == symcr::Decision::Converted && !spare->lossy &&
           spare->detail.find("; the old value goes to symcr_migrate(Navigator)") !=
               std::string::npos);
  XV_CHECK(report.count(symcr::Decision::Rejected) == 0);
  XV_CHECK(report.lossless());
  return xv::verdict();
}
