// v0: pointers into the storage of strings and vectors, the way parsers and ring buffers keep
// cursors. Each must come back pointing into the restored object's own storage, or be
// reported: never re-pointed at a copy.
#include <string>
#include <vector>

#include "check.hpp"

struct Parser {
  std::string buffer;        // longer than the inline (SSO) buffer: heap characters
  const char* cursor;        // buffer[5]
  const char* end;           // buffer's terminator
  std::string word;          // short: characters inside the string object
  const char* word_cursor;   // word[1]
  std::vector<int> samples;
  int* newest;               // samples[2]
  std::string label;         // v1: std::u16string, so no index maps
  const char* label_cursor;  // label[3]
};

SYMCR_CHECKPOINT Parser parser;

int main(int argc, char** argv) {
  parser.buffer = "GOTO 12.5 7.25 ALT 100 -- a command longer than the SSO buffer";
  parser.cursor = parser.buffer.data() + 5;
  parser.end = parser.buffer.data() + parser.buffer.size();
  parser.word = "hi";
  parser.word_cursor = parser.word.data() + 1;
  parser.samples = {10, 20, 30, 40};
  parser.newest = &parser.samples[2];
  parser.label = "altitude hold, a label longer than the inline buffer";
  parser.label_cursor = parser.label.data() + 3;
  return xv::save(argc, argv);
}
