// v1: changes no mechanical rule can express, each with a symcr_migrate hook that reads v0's
// values by name (a global function, one in the type's namespace, a hidden friend): units
// (alt_m -> alt_cm, speed_kmh -> speed_ms, temp_f -> temp_c), a field split in two
// (packed_time -> hours, minutes), a nested struct flattened (pos.lat -> lat), an enum turned
// into a bool. Hooks run per element of a vector and an array and on a heap object, nested
// objects' hooks before their enclosing object's; a type whose schema did not change keeps its
// hook unused, and restoring v1's own checkpoint runs no hook at all.
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <symcr/generated.hpp>  // the test inspects the generated tables

#include "check.hpp"

namespace {
int flight_hooks = 0;
int sample_hooks = 0;
int log_hooks = 0;
int gains_hooks = 0;
int samples_done_before_log = -1;
}  // namespace

struct Flight {
  std::int32_t alt_cm;
  double speed_ms;
  std::int32_t hours;
  std::int32_t minutes;
  double lat;
  double lon;
  bool autopilot;
  int heading;
};

void symcr_migrate(Flight& flight, const symcr::OldValues& old);
void symcr_migrate(Flight& flight, const symcr::OldValues& old) {
  ++flight_hooks;
  double alt_m = 0, speed_kmh = 0;
  std::int64_t packed_time = 0;
  if (old.get("alt_m", alt_m)) flight.alt_cm = static_cast<std::int32_t>(std::lround(alt_m * 100));
  if (old.get("speed_kmh", speed_kmh)) flight.speed_ms = speed_kmh / 3.6;
  if (old.get("packed_time", packed_time)) {
    flight.hours = static_cast<std::int32_t>(packed_time / 100);
    flight.minutes = static_cast<std::int32_t>(packed_time % 100);
  }
  const symcr::OldValues pos = old.child("pos");
  XV_CHECK(pos.valid() && std::string(pos.type_name()) == "Position");
  pos.get("lat", flight.lat);
  pos.get("lon", flight.lon);
  const char* mode = nullptr;
  if (old.enumerator("mode", mode)) flight.autopilot = std::string(mode) == "Auto";
  // Mechanical rules already restored what they could express.
  XV_CHECK(flight.heading == 270);
  std::int64_t heading = 0;
  XV_CHECK(old.get("heading", heading) && heading == 270);
  XV_CHECK(!old.has("alt_cm"));
}

namespace logbook {
struct Sample {
  double temp_c;
  int id;
};
void symcr_migrate(Sample& sample, const symcr::OldValues& old);
void symcr_migrate(Sample& sample, const symcr::OldValues& old) {
  ++sample_hooks;
  double temp_f = 0;
  if (old.get("temp_f", temp_f)) sample.temp_c = (temp_f - 32.0) * 5.0 / 9.0;
}

struct Log {
  std::vector<Sample> samples;
  Sample fixed[2];
  Sample* last = nullptr;
  double warmest_c = -1000.0;  // new: computed from the migrated samples
  friend void symcr_migrate(Log& log, const symcr::OldValues& old) {
    ++log_hooks;
    samples_done_before_log = sample_hooks;
    XV_CHECK(old.count("samples") == 2 && old.count("fixed") == 2);
    for (const Sample& sample : log.samples) log.warmest_c = std::fmax(log.warmest_c, sample.temp_c);
    for (const Sample& sample : log.fixed) log.warmest_c = std::fmax(log.warmest_c, sample.temp_c);
  }
};
}  // namespace logbook

struct Gains {
  double p;
  double i;
};
void symcr_migrate(Gains& gains, const symcr::OldValues& old);
void symcr_migrate(Gains& gains, const symcr::OldValues&) {
  ++gains_hooks;  // the type did not change: never called
  gains.p *= 1000.0;
}

SYMCR_CHECKPOINT Flight flight;
SYMCR_CHECKPOINT logbook::Log book;
SYMCR_CHECKPOINT Gains gains;

namespace {

bool near(double a, double b) { return std::fabs(a - b) < 1e-4; }

void check_values() {
  XV_CHECK(flight.alt_cm == 12345);
  XV_CHECK(near(flight.speed_ms, 25.0));
  XV_CHECK(flight.hours == 17 && flight.minutes == 42);
  XV_CHECK(flight.lat == 48.125 && flight.lon == 11.5);
  XV_CHECK(flight.autopilot);
  XV_CHECK(flight.heading == 270);
  XV_CHECK(book.samples.size() == 2);
  if (book.samples.size() == 2) {
    XV_CHECK(near(book.samples[0].temp_c, 100.0) && book.samples[0].id == 1);
    XV_CHECK(near(book.samples[1].temp_c, 0.0) && book.samples[1].id == 2);
  }
  XV_CHECK(near(book.fixed[0].temp_c, 10.0) && book.fixed[0].id == 3);
  XV_CHECK(near(book.fixed[1].temp_c, -40.0) && book.fixed[1].id == 4);
  XV_CHECK(book.last != nullptr);
  if (book.last) XV_CHECK(near(book.last->temp_c, 37.0) && book.last->id == 5);
  XV_CHECK(near(book.warmest_c, 100.0));
  XV_CHECK(gains.p == 0.25 && gains.i == 0.125);
}

bool migrated(const symcr::Report& report, const char* path, const char* type) {
  const symcr::ReportEntry* e = xv::entry(report, path);
  const std::string detail = std::string("migrated by symcr_migrate(") + type + ")";
  if (e && e->decision == symcr::Decision::Converted && !e->lossy &&
      e->detail.find(detail) != std::string::npos) {
    return true;
  }
  std::fprintf(stderr, "'%s': expected converted, %s\n", path, detail.c_str());
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  const symcr::Schema* schema = symcr_program_schema();
  XV_CHECK(schema != nullptr);
  for (std::uint32_t t = 0; schema && t < schema->type_count; ++t) {
    const symcr::TypeInfo& type = schema->types[t];
    const std::string name = type.name;
    const bool hooked = name == "Flight" || name == "logbook::Sample" || name == "logbook::Log" ||
                        name == "Gains";
    XV_CHECK(hooked == (type.migrate != nullptr));
    XV_CHECK(hooked == ((type.flags & symcr::kTypeMigrated) != 0));
  }

  // Strict mode: the removed fields go to the hooks, so nothing is lossy.
  symcr::Report report = xv::restore(argc, argv, /*strict=*/true);
  XV_CHECK(report.ok());
  check_values();
  XV_CHECK(flight_hooks == 1);
  XV_CHECK(sample_hooks == 5);  // two vector elements, two array elements, one heap object
  XV_CHECK(log_hooks == 1);
  XV_CHECK(samples_done_before_log == 4);  // the heap object comes after all roots
  XV_CHECK(gains_hooks == 0);

  XV_CHECK(migrated(report, "flight", "Flight"));
  XV_CHECK(migrated(report, "book", "logbook::Log"));
  XV_CHECK(migrated(report, "book.samples[]", "logbook::Sample"));
  XV_CHECK(migrated(report, "book.fixed[]", "logbook::Sample"));
  XV_CHECK(migrated(report, "(logbook::Sample)", "logbook::Sample"));
  XV_CHECK(xv::decided(report, "flight.alt_m", symcr::Decision::Dropped));
  XV_CHECK(xv::decided(report, "flight.alt_cm", symcr::Decision::Kept));
  const symcr::ReportEntry* dropped = xv::entry(report, "flight.packed_time");
  XV_CHECK(dropped && !dropped->lossy &&
           dropped->detail.find("symcr_migrate(Flight)") != std::string::npos);
  XV_CHECK(xv::restored(report, "gains"));
  XV_CHECK(xv::restored(report, "flight.heading"));

  // v1's own checkpoint restored into v1: nothing changed, so no hook runs.
  if (argc >= 2) {
    const std::string own = std::string(argv[1]) + ".v1";
    XV_CHECK(symcr::checkpoint(own.c_str()).ok());
    flight = Flight{};
    book.samples.clear();
    book.fixed[0] = logbook::Sample{};
    book.warmest_c = 0;
    gains = Gains{};
    symcr::Report again = symcr::restore(own.c_str());
    XV_CHECK(again.ok());
    XV_CHECK(again.count(symcr::Decision::Converted) == 0);
    check_values();
    XV_CHECK(flight_hooks == 1 && sample_hooks == 5 && log_hooks == 1 && gains_hooks == 0);
    std::remove(own.c_str());
  }
  delete book.last;
  return xv::verdict();
}
