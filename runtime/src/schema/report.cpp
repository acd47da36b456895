// Report: the restore's account of every root and field, as a text table or JSON.
#include <algorithm>
#include <cinttypes>
#include <cstdio>
#include <string>
#include <utility>

#include "report_access.hpp"
#include "symcr/symcr.hpp"

namespace symcr {
namespace {

// Appends `text` as a JSON string. Names come from checkpoint files, which may hold any bytes:
// control characters are escaped and invalid UTF-8 becomes U+FFFD, so the output always parses.
__attribute__((cold)) void append_json_string(std::string& out, const std::string& text) {
  out += '"';
  const auto* bytes = reinterpret_cast<const unsigned char*>(text.data());
  const std::size_t size = text.size();
  std::size_t i = 0;
  while (i < size) {
    const unsigned char c = bytes[i];
    if (c < 0x80) {
      switch (c) {
        case '"':
          out += "\\\"";
          break;
        case '\\':
          out += "\\\\";
          break;
        case '\n':
          out += "\\n";
          break;
        case '\r':
          out += "\\r";
          break;
        case '\t':
          out += "\\t";
          break;
        case '\b':
          out += "\\b";
          break;
        case '\f':
          out += "\\f";
          break;
        default:
          if (c < 0x20 || c == 0x7f) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
            out += escaped;
          } else {
            out += static_cast<char>(c);
          }
      }
      ++i;
      continue;
    }
    // Multi-byte sequence: validate length, continuation bytes, overlongs and surrogates.
    std::size_t length = 0;
    std::uint32_t code = 0;
    if ((c & 0xE0) == 0xC0) {
      length = 2;
      code = c & 0x1F;
    } else if ((c & 0xF0) == 0xE0) {
      length = 3;
      code = c & 0x0F;
    } else if ((c & 0xF8) == 0xF0) {
      length = 4;
      code = c & 0x07;
    }
    bool valid = length != 0 && i + length <= size;
    for (std::size_t k = 1; valid && k < length; ++k) {
      if ((bytes[i + k] & 0xC0) != 0x80)
        valid = false;
      else
        code = (code << 6) | (bytes[i + k] & 0x3F);
    }
    if (valid) {
      static const std::uint32_t kMinimum[5] = {0, 0, 0x80, 0x800, 0x10000};
      valid = code >= kMinimum[length] && code <= 0x10FFFF && (code < 0xD800 || code > 0xDFFF);
    }
    if (valid) {
      out.append(text, i, length);
      i += length;
    } else {
      out += "\\ufffd";
      ++i;
    }
  }
  out += '"';
}

}  // namespace

const std::vector<ReportEntry>& Report::entries() const {
  return source_ ? source_->entries() : entries_;
}

namespace detail {

void ReportAccess::add(Report& report, std::string path, Decision decision, std::string detail,
                       bool lossy) {
  if (report.source_) {
    report.entries_ = report.source_->entries();
    report.source_.reset();
  }
  report.entries_.push_back(ReportEntry{std::move(path), decision, std::move(detail), lossy});
}

void ReportAccess::remove(Report& report, Decision decision) {
  if (report.source_) {
    report.entries_ = report.source_->entries();
    report.source_.reset();
  }
  std::vector<ReportEntry>& entries = report.entries_;
  entries.erase(std::remove_if(entries.begin(), entries.end(),
                               [decision](const ReportEntry& e) { return e.decision == decision; }),
                entries.end());
}

void ReportAccess::set_source(Report& report, std::shared_ptr<const ReportSource> source) {
  report.entries_.clear();
  report.source_ = std::move(source);
}

}  // namespace detail

Report::~Report() = default;
Report::Report(const Report& other) = default;
Report::Report(Report&& other) noexcept = default;
Report& Report::operator=(const Report& other) = default;
Report& Report::operator=(Report&& other) noexcept = default;

std::size_t Report::count(Decision decision) const {
  return static_cast<std::size_t>(
      std::count_if(entries().begin(), entries().end(),
                    [decision](const ReportEntry& entry) { return entry.decision == decision; }));
}

bool Report::lossless() const {
  return ok() && std::none_of(entries().begin(), entries().end(),
                              [](const ReportEntry& entry) { return entry.lossy; });
}

__attribute__((cold)) std::string Report::losses_to_text() const {
  std::string out;
  if (!ok()) {
    out += "restore failed: ";
    out += error_name(status_.error());
    out += ": ";
    out += status_.message();
    out += '\n';
  }
  std::size_t lossy = 0;
  for (const ReportEntry& entry : entries()) {
    if (!entry.lossy) continue;
    ++lossy;
    out += entry.path;
    out += "  ";
    out += decision_name(entry.decision);
    out += ": ";
    out += entry.detail;
    out += '\n';
  }
  if (lossy != 0) {
    out += std::to_string(lossy);
    out += lossy == 1 ? " lossy decision" : " lossy decisions";
    out += ": checkpointed data this build does not hold (rejected values keep this build's)\n";
  }
  return out;
}

__attribute__((cold)) std::string Report::to_text() const {
  // Column widths from the content, with the path column capped so one deep path does not
  // push every line off the screen (longer paths simply overflow their column).
  constexpr std::size_t kMaxPathWidth = 60;
  std::size_t path_width = 4;
  for (const ReportEntry& entry : entries()) {
    path_width = std::max(path_width, std::min(entry.path.size(), kMaxPathWidth));
  }
  constexpr std::size_t kDecisionWidth = 9;  // "converted"
  std::string out;
  auto pad = [&out](std::size_t used, std::size_t width) {
    if (used < width) out.append(width - used, ' ');
  };
  out += "path";
  pad(4, path_width);
  out += "  decision ";
  out += " detail\n";
  for (const ReportEntry& entry : entries()) {
    out += entry.path;
    pad(entry.path.size(), path_width);
    out += "  ";
    const char* name = decision_name(entry.decision);
    out += name;
    pad(std::string(name).size(), kDecisionWidth);
    out += entry.lossy ? " * " : "   ";
    out += entry.detail;
    out += '\n';
  }
  for (const SkippedCheckpoint& skipped : skipped_) {
    char slot[64];
    std::snprintf(slot, sizeof slot,
                  "skipped slot %" PRIu32 " (sequence %" PRIu64 "): ", skipped.slot,
                  skipped.sequence);
    out += slot;
    out += skipped.reason;
    out += '\n';
  }
  for (const std::string& warning : warnings_) {
    out += "warning: ";
    out += warning;
    out += '\n';
  }
  char summary[64];
  std::snprintf(summary, sizeof summary, "sequence %" PRIu64 ", ", sequence_);
  out += summary;
  if (ok()) {
    out += "status: ok\n";
  } else {
    out += "status: ";
    out += error_name(status_.error());
    out += ": ";
    out += status_.message();
    out += '\n';
  }
  return out;
}

__attribute__((cold)) std::string Report::to_json() const {
  std::string out = "{\"ok\":";
  out += ok() ? "true" : "false";
  out += ",\"error\":";
  append_json_string(out, error_name(status_.error()));
  out += ",\"message\":";
  append_json_string(out, status_.message());
  char number[32];
  std::snprintf(number, sizeof number, "%" PRIu64, sequence_);
  out += ",\"sequence\":";
  out += number;
  out += ",\"entries\":[";
  bool first = true;
  for (const ReportEntry& entry : entries()) {
    if (!first) out += ',';
    first = false;
    out += "{\"path\":";
    append_json_string(out, entry.path);
    out += ",\"decision\":";
    append_json_string(out, decision_name(entry.decision));
    out += ",\"detail\":";
    append_json_string(out, entry.detail);
    out += ",\"lossy\":";
    out += entry.lossy ? "true" : "false";
    out += '}';
  }
  out += "],\"skipped\":[";
  first = true;
  for (const SkippedCheckpoint& skipped : skipped_) {
    if (!first) out += ',';
    first = false;
    std::snprintf(number, sizeof number, "%" PRIu32, skipped.slot);
    out += "{\"slot\":";
    out += number;
    std::snprintf(number, sizeof number, "%" PRIu64, skipped.sequence);
    out += ",\"sequence\":";
    out += number;
    out += ",\"reason\":";
    append_json_string(out, skipped.reason);
    out += '}';
  }
  out += "],\"warnings\":[";
  first = true;
  for (const std::string& warning : warnings_) {
    if (!first) out += ',';
    first = false;
    append_json_string(out, warning);
  }
  out += "]}";
  return out;
}

}  // namespace symcr
