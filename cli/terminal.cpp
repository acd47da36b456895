// Terminal and Table.
#include "terminal.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace symcr::cli {

Terminal Terminal::for_stdout() {
  const char* no_color = std::getenv("NO_COLOR");
  return Terminal(::isatty(STDOUT_FILENO) == 1 && (no_color == nullptr || *no_color == '\0'));
}

std::string Terminal::paint(Colour colour, const std::string& text) const {
  if (!colour_ || colour == Colour::None) return text;
  const char* code = "0";
  switch (colour) {
    case Colour::None:
      break;
    case Colour::Bold:
      code = "1";
      break;
    case Colour::Dim:
      code = "2";
      break;
    case Colour::Red:
      code = "31";
      break;
    case Colour::Green:
      code = "32";
      break;
    case Colour::Yellow:
      code = "33";
      break;
    case Colour::Cyan:
      code = "36";
      break;
  }
  return std::string("\x1b[") + code + "m" + text + "\x1b[0m";
}

std::string printable(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto byte = static_cast<unsigned char>(text[i]);
    const bool c1 = byte == 0xC2 && i + 1 < text.size() &&
                    static_cast<unsigned char>(text[i + 1]) >= 0x80 &&
                    static_cast<unsigned char>(text[i + 1]) <= 0x9F;
    if (byte < 0x20 || byte == 0x7F || c1) {
      const unsigned shown = c1 ? static_cast<unsigned char>(text[++i]) : byte;
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", shown);
      out += escaped;
    } else {
      out += text[i];
    }
  }
  return out;
}

std::size_t display_width(const std::string& text) {
  return static_cast<std::size_t>(std::count_if(text.begin(), text.end(), [](char c) {
    return (static_cast<unsigned char>(c) & 0xC0) != 0x80;
  }));
}

void Table::cap_column(std::size_t column, std::size_t cap) {
  if (caps_.size() <= column) caps_.resize(column + 1, 0);
  caps_[column] = cap;
}

void Table::pad_column(std::size_t column, std::size_t width) {
  if (pads_.size() <= column) pads_.resize(column + 1, 0);
  pads_[column] = width;
}

std::size_t Table::cell_width(const std::string& text, std::size_t cap) {
  const std::size_t width = display_width(printable(text));
  return cap != 0 ? std::min(width, cap) : width;
}

std::string Table::render(const Terminal& terminal, const char* separator) const {
  std::vector<std::vector<Cell>> rows = rows_;
  for (auto& row : rows) {
    for (Cell& cell : row) cell.text = printable(cell.text);
  }
  std::vector<std::size_t> widths = pads_;
  for (const auto& row : rows) {
    if (widths.size() < row.size()) widths.resize(row.size(), 0);
    for (std::size_t c = 0; c < row.size(); ++c) {
      std::size_t width = display_width(row[c].text);
      if (c < caps_.size() && caps_[c] != 0) width = std::min(width, caps_[c]);
      widths[c] = std::max(widths[c], width);
    }
  }
  std::string out;
  for (const auto& row : rows) {
    std::string line;
    for (std::size_t c = 0; c < row.size(); ++c) {
      line += terminal.paint(row[c].colour, row[c].text);
      if (c + 1 == row.size()) break;
      const std::size_t width = display_width(row[c].text);
      if (width < widths[c]) line.append(widths[c] - width, ' ');
      line += separator;
    }
    while (!line.empty() && line.back() == ' ') line.pop_back();
    out += line;
    out += '\n';
  }
  return out;
}

void print(const std::string& text) { std::fwrite(text.data(), 1, text.size(), stdout); }

void print_error(const std::string& text) {
  std::fprintf(stderr, "symcr: error: %s\n", printable(text).c_str());
}

}  // namespace symcr::cli
