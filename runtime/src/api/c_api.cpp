// The C API (<symcr/symcr.h>): thin wrappers over the C++ API that turn statuses into codes
// and keep the last failure's message per thread.
#include "symcr/symcr.h"

#include <cstdio>
#include <cstring>
#include <new>
#include <string>
#include <vector>

#include "c_handles.hpp"
#include "symcr/symcr.hpp"
#include "report_access.hpp"

static_assert(SYMCR_ERROR_UNAUTHENTICATED == static_cast<int>(symcr::Error::Unauthenticated),
              "C error codes mirror symcr::Error");
static_assert(SYMCR_ERROR_STORE_FULL == static_cast<int>(symcr::Error::StoreFull),
              "C error codes mirror symcr::Error");
static_assert(SYMCR_ERROR_ROLLED_BACK == static_cast<int>(symcr::Error::RolledBack),
              "C error codes mirror symcr::Error");
static_assert(SYMCR_ERROR_TOO_LARGE == static_cast<int>(symcr::Error::TooLarge),
              "C error codes mirror symcr::Error");
static_assert(SYMCR_ERROR_NO_VALID_SLOT == static_cast<int>(symcr::Error::NoValidSlot),
              "C error codes mirror symcr::Error");
static_assert(SYMCR_ERROR_IO == static_cast<int>(symcr::Error::Io),
              "C error codes mirror symcr::Error");
static_assert(SYMCR_REJECTED == static_cast<int>(symcr::Decision::Rejected),
              "C decisions mirror symcr::Decision");
static_assert(SYMCR_REBASED == static_cast<int>(symcr::Decision::Rebased),
              "C decisions mirror symcr::Decision");

namespace {
thread_local char last_error[symcr::Status::kMessageCapacity];  // a Status message fits
}  // namespace

int symcr::detail::record_c_error(const symcr::Status& status) {
  if (!status.ok()) std::snprintf(last_error, sizeof last_error, "%s", status.message());
  return static_cast<int>(status.error());
}

using symcr::detail::record_c_error;

namespace {

int hand_over(symcr::Report&& report, symcr_report** out) {
  const int code = record_c_error(report.status());
  if (out != nullptr) *out = new (std::nothrow) symcr_report{std::move(report), {}, {}, {}};
  return code;
}

symcr::RestoreOptions restore_options(int flags) {
  symcr::RestoreOptions options;
  options.strict = (flags & SYMCR_RESTORE_STRICT) != 0;
  options.accept_other_program = (flags & SYMCR_RESTORE_ACCEPT_OTHER_PROGRAM) != 0;
  return options;
}

// A C counter's result as a Status: its error code, or Io for a value that is not one.
symcr::Status counter_status(int code, const char* operation) {
  if (code == SYMCR_OK) return symcr::Status();
  const bool known = std::strcmp(symcr_error_name(code), "Unknown") != 0;
  return symcr::Status(known ? static_cast<symcr::Error>(code) : symcr::Error::Io,
                       "the program's freshness counter: %s failed with %s", operation,
                       known ? symcr_error_name(code) : "an unknown code");
}
}  // namespace

symcr::Status symcr::detail::CFreshnessCounter::read(std::uint64_t& value) {
  std::uint64_t read_value = 0;
  const symcr::Status status = counter_status(counter_.read(counter_.context, &read_value), "read");
  if (status.ok()) value = read_value;
  return status;
}

symcr::Status symcr::detail::CFreshnessCounter::advance(std::uint64_t value) {
  return counter_status(counter_.advance(counter_.context, value), "advance");
}

extern "C" {

const char* symcr_error_name(int error) {
  if (error < 0 || error > static_cast<int>(symcr::Error::RolledBack)) return "Unknown";
  return symcr::error_name(static_cast<symcr::Error>(error));
}

const char* symcr_last_error(void) { return last_error; }

int symcr_set_checkpoint_keys(const symcr_checkpoint_key* keys, size_t count) {
  if (count != 0 && keys == nullptr) {
    return record_c_error(symcr::Status(symcr::Error::Unsupported, "no keys given"));
  }
  std::vector<symcr::CheckpointKey> copied;
  for (size_t i = 0; i < count; ++i) copied.push_back({keys[i].id, keys[i].bytes, keys[i].size});
  return record_c_error(symcr::set_checkpoint_keys(copied.data(), count));
}

int symcr_checkpoint(const char* path) { return symcr_checkpoint_with(nullptr, path, 0); }

int symcr_checkpoint_with(const symcr_schema* schema, const char* path, int fdatasync) {
  if (path == nullptr) return record_c_error(symcr::Status(symcr::Error::Io, "no path given"));
  symcr::CheckpointOptions options;
  options.durability = fdatasync != 0 ? symcr::Durability::Fdatasync : symcr::Durability::PageCache;
  return record_c_error(schema != nullptr ? symcr::checkpoint(*schema, path, options)
                                          : symcr::checkpoint(path, options));
}

int symcr_restore(const char* path, int flags, symcr_report** report) {
  return symcr_restore_with(nullptr, path, flags, report);
}

int symcr_restore_with(const symcr_schema* schema, const char* path, int flags,
                       symcr_report** report) {
  symcr::Report result;
  if (path == nullptr) {
    symcr::detail::ReportAccess::set_status(result,
                                            symcr::Status(symcr::Error::Io, "no path given"));
  } else {
    result = schema != nullptr ? symcr::restore(*schema, path, restore_options(flags))
                               : symcr::restore(path, restore_options(flags));
  }
  return hand_over(std::move(result), report);
}

int symcr_report_ok(const symcr_report* report) { return report != nullptr && report->report.ok(); }

int symcr_report_lossless(const symcr_report* report) {
  return report != nullptr && report->report.lossless();
}

int symcr_report_error(const symcr_report* report) {
  return report != nullptr ? static_cast<int>(report->report.status().error()) : SYMCR_ERROR_IO;
}

uint64_t symcr_report_sequence(const symcr_report* report) {
  return report != nullptr ? report->report.sequence() : 0;
}

size_t symcr_report_count(const symcr_report* report, int decision) {
  if (report == nullptr || decision < 0 || decision > static_cast<int>(symcr::Decision::Rebased)) {
    return 0;
  }
  return report->report.count(static_cast<symcr::Decision>(decision));
}

size_t symcr_report_skipped(const symcr_report* report) {
  return report != nullptr ? report->report.skipped().size() : 0;
}

const char* symcr_report_text(symcr_report* report) {
  if (report == nullptr) return "";
  report->text = report->report.to_text();
  return report->text.c_str();
}

const char* symcr_report_json(symcr_report* report) {
  if (report == nullptr) return "";
  report->json = report->report.to_json();
  return report->json.c_str();
}

const char* symcr_report_losses_text(symcr_report* report) {
  if (report == nullptr) return "";
  report->losses = report->report.losses_to_text();
  return report->losses.c_str();
}

void symcr_report_free(symcr_report* report) { delete report; }

void symcr_store_options_init(symcr_store_options* options) {
  if (options == nullptr) return;
  const symcr::StoreOptions defaults;
  options->slots = defaults.slots;
  options->slot_size = defaults.slot_size;
  options->fdatasync = defaults.durability == symcr::Durability::Fdatasync;
  options->fallback_depth = defaults.fallback_depth;
  options->allow_unrecorded_restore = defaults.allow_unrecorded_restore;
  options->freshness_counter = nullptr;
  options->counter_path = defaults.counter_path;
}

int symcr_store_open(const char* path, const symcr_schema* schema,
                     const symcr_store_options* options, symcr_store** store) {
  if (store == nullptr || path == nullptr) {
    return record_c_error(symcr::Status(symcr::Error::Io, "symcr_store_open: no path or handle"));
  }
  *store = nullptr;
  symcr::StoreOptions store_options;
  if (options != nullptr) {
    store_options.slots = options->slots;
    store_options.slot_size = options->slot_size;
    store_options.durability =
        options->fdatasync != 0 ? symcr::Durability::Fdatasync : symcr::Durability::PageCache;
    store_options.fallback_depth = options->fallback_depth;
    store_options.allow_unrecorded_restore = options->allow_unrecorded_restore != 0;
    store_options.counter_path = options->counter_path;
  }
  const symcr_freshness_counter* counter =
      options != nullptr ? options->freshness_counter : nullptr;
  if (counter != nullptr && (counter->read == nullptr || counter->advance == nullptr)) {
    return record_c_error(symcr::Status(
        symcr::Error::Unsupported, "symcr_store_open: a freshness counter needs read and advance"));
  }
  auto* handle = new (std::nothrow) symcr_store;
  if (handle == nullptr) return record_c_error(symcr::Status(symcr::Error::Io, "out of memory"));
  if (counter != nullptr) {
    handle->counter.reset(new (std::nothrow) symcr::detail::CFreshnessCounter(*counter));
    if (handle->counter == nullptr) {
      delete handle;
      return record_c_error(symcr::Status(symcr::Error::Io, "out of memory"));
    }
    store_options.freshness_counter = handle->counter.get();
  }
  const symcr::Status status = schema != nullptr
                                   ? symcr::Store::open(path, *schema, store_options, handle->store)
                                   : symcr::Store::open(path, store_options, handle->store);
  if (!status.ok()) {
    delete handle;
    return record_c_error(status);
  }
  *store = handle;
  return SYMCR_OK;
}

int symcr_store_save(symcr_store* store) {
  if (store == nullptr) return record_c_error(symcr::Status(symcr::Error::Io, "no store"));
  return record_c_error(store->store.save());
}

int symcr_store_restore_latest(symcr_store* store, int flags, symcr_report** report) {
  symcr::Report result;
  if (store == nullptr) {
    symcr::detail::ReportAccess::set_status(result, symcr::Status(symcr::Error::Io, "no store"));
  } else {
    result = store->store.restore_latest(restore_options(flags));
  }
  return hand_over(std::move(result), report);
}

int symcr_store_confirm(symcr_store* store) {
  if (store == nullptr) return record_c_error(symcr::Status(symcr::Error::Io, "no store"));
  return record_c_error(store->store.confirm());
}

uint64_t symcr_store_last_sequence(const symcr_store* store) {
  return store != nullptr ? store->store.last_sequence() : 0;
}

void symcr_store_close(symcr_store* store) { delete store; }

}  // extern "C"
