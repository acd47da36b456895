// Terminal output: colour only when standard output is a terminal and NO_COLOR is unset or
// empty (https://no-color.org), and tables whose columns line up.
#ifndef SYMCR_CLI_TERMINAL_HPP
#define SYMCR_CLI_TERMINAL_HPP

#include <cstddef>
#include <string>
#include <vector>

namespace symcr::cli {

enum class Colour { None, Bold, Dim, Red, Green, Yellow, Cyan };

class Terminal {
 public:
  static Terminal for_stdout();
  explicit Terminal(bool colour) : colour_(colour) {}
  std::string paint(Colour colour, const std::string& text) const;

 private:
  bool colour_;
};

// Columns padded to their widest cell, the last one unpadded; cells are made printable(). A column
// listed in `capped` stops growing at `cap` characters (longer cells overflow their column), so one
// deep path does not push every line off the screen.
class Table {
 public:
  struct Cell {
    std::string text;
    Colour colour = Colour::None;
  };
  void add(std::vector<Cell> row) { rows_.push_back(std::move(row)); }
  void cap_column(std::size_t column, std::size_t cap);
  // Pads `column` to at least `width` (display width of the printable text, capped): for a
  // long table printed a row at a time, its widths measured beforehand.
  void pad_column(std::size_t column, std::size_t width);
  // The width `text` takes in a column capped at `cap` (0: uncapped).
  static std::size_t cell_width(const std::string& text, std::size_t cap);
  std::string render(const Terminal& terminal, const char* separator = "  ") const;
  bool empty() const { return rows_.empty(); }

 private:
  std::vector<std::vector<Cell>> rows_;
  std::vector<std::size_t> caps_;
  std::vector<std::size_t> pads_;
};

// `text` safe to print on a terminal: names and strings come from untrusted files, so control
// characters (C0, DEL, and C1 as UTF-8) are shown as \xNN instead of being sent to the
// terminal as escape sequences.
std::string printable(const std::string& text);

// Printed width of UTF-8 text (code points; the CLI prints no wide characters of its own).
std::size_t display_width(const std::string& text);

void print(const std::string& text);        // to stdout
void print_error(const std::string& text);  // "symcr: error: <text>" to stderr

}  // namespace symcr::cli

#endif  // SYMCR_CLI_TERMINAL_HPP
