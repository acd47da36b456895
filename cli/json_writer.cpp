// JsonWriter over llvm::json::OStream.
#include "json_writer.hpp"

#include <llvm/Support/JSON.h>
#include <llvm/Support/raw_ostream.h>

namespace symcr::cli {

struct JsonWriter::Impl {
  llvm::json::OStream out{llvm::outs(), /*IndentSize=*/2};
};

namespace {

std::string valid_utf8(const std::string& text) {
  return llvm::json::isUTF8(text) ? text : llvm::json::fixUTF8(text);
}

}  // namespace

JsonWriter::JsonWriter() : impl_(new Impl()) {}

JsonWriter::~JsonWriter() {
  llvm::outs() << '\n';
  llvm::outs().flush();
}

void JsonWriter::object_begin() { impl_->out.objectBegin(); }
void JsonWriter::object_end() { impl_->out.objectEnd(); }
void JsonWriter::array_begin() { impl_->out.arrayBegin(); }
void JsonWriter::array_end() { impl_->out.arrayEnd(); }
void JsonWriter::key_begin(const std::string& key) { impl_->out.attributeBegin(valid_utf8(key)); }
void JsonWriter::key_end() { impl_->out.attributeEnd(); }

void JsonWriter::value(const JsonScalar& s) {
  switch (s.kind) {
    case JsonScalar::Kind::Null:
      impl_->out.value(nullptr);
      return;
    case JsonScalar::Kind::Bool:
      impl_->out.value(s.boolean);
      return;
    case JsonScalar::Kind::Int:
      impl_->out.value(s.integer);
      return;
    case JsonScalar::Kind::UInt:
      impl_->out.value(s.unsigned_integer);
      return;
    case JsonScalar::Kind::Double:
      impl_->out.value(s.real);
      return;
    case JsonScalar::Kind::String:
      impl_->out.value(valid_utf8(s.string));
      return;
  }
}

void JsonWriter::field(const std::string& key, const JsonScalar& scalar) {
  key_begin(key);
  value(scalar);
  key_end();
}

}  // namespace symcr::cli
