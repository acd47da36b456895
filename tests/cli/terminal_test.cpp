// The CLI's terminal output (cli/terminal.hpp): untrusted text cannot reach the terminal as
// control sequences, and columns line up.
#include "terminal.hpp"

#include <gtest/gtest.h>

namespace {

using symcr::cli::printable;
using symcr::cli::Table;
using symcr::cli::Terminal;

TEST(Printable, EscapesControlCharacters) {
  EXPECT_EQ(printable("copter.mode"), "copter.mode");
  EXPECT_EQ(printable("a\x1b]0;pwned\x07z"), "a\\x1b]0;pwned\\x07z");
  EXPECT_EQ(printable("tab\there\x7f"), "tab\\x09here\\x7f");
  EXPECT_EQ(printable("csi\xc2\x9b" "31m"), "csi\\x9b31m");          // C1 CSI as UTF-8
  EXPECT_EQ(printable("caf\xc3\xa9 \xc2\xb0"), "caf\xc3\xa9 \xc2\xb0");  // ordinary UTF-8
}

TEST(Table, AlignsColumnsAndEscapesCells) {
  Table table;
  table.add({{"copter.ticks"}, {"="}, {"1001"}});
  table.add({{"x\x1b"}, {"="}, {"caf\xc3\xa9"}});
  EXPECT_EQ(table.render(Terminal(false), " "),
            "copter.ticks = 1001\n"
            "x\\x1b        = caf\xc3\xa9\n");
}

TEST(Table, PaintsOnlyWithColour) {
  Table table;
  table.add({{"valid", symcr::cli::Colour::Green}});
  EXPECT_EQ(table.render(Terminal(false)), "valid\n");
  EXPECT_EQ(table.render(Terminal(true)), "\x1b[32mvalid\x1b[0m\n");
}

}  // namespace
