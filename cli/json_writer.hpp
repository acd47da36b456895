// Streaming JSON output (LLVM's json::OStream behind a small interface, so only one TU of the
// CLI pays for LLVM's JSON header). Output is indented by 2 and always valid: strings that are
// not UTF-8 (names and text come from untrusted files) are repaired, not passed through.
#ifndef SYMCR_CLI_JSON_WRITER_HPP
#define SYMCR_CLI_JSON_WRITER_HPP

#include <cstdint>
#include <memory>
#include <string>

namespace symcr::cli {

// One JSON scalar: what a decoded value or a header field turns into.
struct JsonScalar {
  enum class Kind : std::uint8_t { Null, Bool, Int, UInt, Double, String } kind = Kind::Null;
  bool boolean = false;
  std::int64_t integer = 0;
  std::uint64_t unsigned_integer = 0;
  double real = 0;
  std::string string;

  static JsonScalar null() { return {}; }
  static JsonScalar of(bool b) {
    JsonScalar s;
    s.kind = Kind::Bool;
    s.boolean = b;
    return s;
  }
  static JsonScalar of_int(std::int64_t i) {
    JsonScalar s;
    s.kind = Kind::Int;
    s.integer = i;
    return s;
  }
  static JsonScalar of_uint(std::uint64_t u) {
    JsonScalar s;
    s.kind = Kind::UInt;
    s.unsigned_integer = u;
    return s;
  }
  static JsonScalar of_double(double d) {
    JsonScalar s;
    s.kind = Kind::Double;
    s.real = d;
    return s;
  }
  static JsonScalar of(const char* text) { return of(std::string(text)); }
  static JsonScalar of(std::string text) {
    JsonScalar s;
    s.kind = Kind::String;
    s.string = std::move(text);
    return s;
  }
};

// Writes one JSON document to standard output, followed by a newline when destroyed.
class JsonWriter {
 public:
  JsonWriter();
  ~JsonWriter();
  JsonWriter(const JsonWriter&) = delete;
  JsonWriter& operator=(const JsonWriter&) = delete;

  void object_begin();
  void object_end();
  void array_begin();
  void array_end();
  // Inside an object: `"key": ` followed by exactly one value, object or array, then key_end.
  void key_begin(const std::string& key);
  void key_end();
  void value(const JsonScalar& scalar);

  // Shorthands for `key: scalar`.
  void field(const std::string& key, const JsonScalar& scalar);
  void field(const std::string& key, const std::string& text) { field(key, JsonScalar::of(text)); }
  void field(const std::string& key, const char* text) {
    field(key, JsonScalar::of(std::string(text)));
  }
  void field(const std::string& key, bool b) { field(key, JsonScalar::of(b)); }
  void field(const std::string& key, std::uint64_t u) { field(key, JsonScalar::of_uint(u)); }
  void field(const std::string& key, std::uint32_t u) { field(key, JsonScalar::of_uint(u)); }
  void field(const std::string& key, int i) { field(key, JsonScalar::of_int(i)); }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace symcr::cli

#endif  // SYMCR_CLI_JSON_WRITER_HPP
