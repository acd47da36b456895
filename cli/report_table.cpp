#include "report_table.hpp"

#include <string>

#include "terminal.hpp"
#include "values.hpp"

namespace symcr::cli {
namespace {

Colour decision_colour(Decision decision) {
  switch (decision) {
    case Decision::Restored:
      return Colour::None;
    case Decision::Kept:
    case Decision::Rebased:
      return Colour::Cyan;
    case Decision::Dropped:
    case Decision::Converted:
      return Colour::Yellow;
    case Decision::Rejected:
      return Colour::Red;
  }
  return Colour::None;
}

}  // namespace

std::size_t lossy_count(const Report& report) {
  std::size_t lossy = 0;
  for (const ReportEntry& entry : report.entries()) lossy += entry.lossy;
  return lossy;
}

void print_report_table(const Report& report) {
  const Terminal terminal = Terminal::for_stdout();
  Table table;
  table.cap_column(0, 60);
  table.add({{"path", Colour::Bold},
             {"decision", Colour::Bold},
             {"", Colour::None},
             {"detail", Colour::Bold}});
  for (const ReportEntry& entry : report.entries()) {
    table.add({{entry.path},
               {decision_name(entry.decision), decision_colour(entry.decision)},
               {entry.lossy ? "*" : ""},
               {entry.detail}});
  }
  print(table.render(terminal));
  std::string summary;
  for (const Decision decision : {Decision::Restored, Decision::Converted, Decision::Kept,
                                  Decision::Dropped, Decision::Rejected, Decision::Rebased}) {
    if (!summary.empty()) summary += ", ";
    summary += std::to_string(report.count(decision)) + " " + decision_name(decision);
  }
  print("\n" + summary + "; " + std::to_string(lossy_count(report)) + " lossy (*)\n");
}

}  // namespace symcr::cli
