// v1 of interior_pointers: the fields reordered, one added, the label re-typed.
#include <string>
#include <vector>

#include "check.hpp"

struct Parser {
  int version;  // new
  std::vector<int> samples;
  std::string word;
  std::string buffer;
  const char* end;
  int* newest;
  const char* cursor;
  const char* word_cursor;
  std::u16string label;
  const char* label_cursor;
};

SYMCR_CHECKPOINT Parser parser;

int main(int argc, char** argv) {
  static const char kept[] = "kept";
  parser.version = 1;
  parser.label_cursor = kept;
  symcr::Report report = xv::restore(argc, argv);
  XV_CHECK(report.ok());
  XV_CHECK(parser.buffer == "GOTO 12.5 7.25 ALT 100 -- a command longer than the SSO buffer");
  XV_CHECK(parser.cursor == parser.buffer.data() + 5);
  XV_CHECK(std::string(parser.cursor, 4) == "12.5");
  XV_CHECK(parser.end == parser.buffer.data() + parser.buffer.size());
  XV_CHECK(parser.word == "hi" && parser.word_cursor == parser.word.data() + 1);
  XV_CHECK(parser.samples.size() == 4 && parser.newest == &parser.samples[2]);
  XV_CHECK(parser.newest != nullptr && *parser.newest == 30);
  // A character index means nothing in a re-encoded string: the pointer keeps v1's value and
  // the report says why.
  XV_CHECK(parser.label == u"altitude hold, a label longer than the inline buffer");
  XV_CHECK(parser.label_cursor == kept);
  bool reported = false;
  for (const symcr::ReportEntry& e : report.entries()) {
    reported = reported || (e.path == "parser.label_cursor" &&
                            e.decision == symcr::Decision::Rejected &&
                            e.detail.find("re-encoded") != std::string::npos);
  }
  XV_CHECK(reported);
  return xv::verdict();
}
