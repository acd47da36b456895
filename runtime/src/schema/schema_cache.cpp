// The process-wide cache of serialised schemas and their facts, keyed by the Schema object.
// Programs have one schema (tests and tools a few), so a short list searched linearly, with a
// per-thread memo of the last hit, costs nothing on the checkpoint path after the first call.
#include <mutex>
#include <vector>

#include "device_format.hpp"
#include "schema_blob.hpp"
#include "schema_facts.hpp"
#include "symcr/format/hashes.hpp"

namespace symcr::detail {
namespace {

struct CacheKey {
  const Schema* schema;
  const TypeInfo* types;
  std::uint32_t type_count;
  const RootInfo* roots;
  std::uint32_t root_count;
  bool operator==(const CacheKey& other) const {
    return schema == other.schema && types == other.types && type_count == other.type_count &&
           roots == other.roots && root_count == other.root_count;
  }
};

struct CachedSchema {
  CacheKey key;
  const SchemaCacheEntry* entry;
};

CacheKey key_of(const Schema& schema) {
  // The tables are part of the key so a Schema object reused for other tables (e.g. a local in
  // a test) is not served a stale blob.
  return CacheKey{&schema, schema.types, schema.type_count, schema.roots, schema.root_count};
}

// symcr-gen's serialised form of `schema`, when it is the program's generated schema.
const SerialisedSchema* generated_form(const Schema& schema) {
  if (!symcr_program_schema || !symcr_program_serialised_schema) return nullptr;
  return symcr_program_schema() == &schema ? symcr_program_serialised_schema() : nullptr;
}

}  // namespace

const SchemaCacheEntry& schema_cache_entry(const Schema& schema) {
  const CacheKey key = key_of(schema);
  thread_local CachedSchema last{{nullptr, nullptr, 0, nullptr, 0}, nullptr};
  if (last.entry && last.key == key) return *last.entry;

  static std::mutex mutex;
  static std::vector<CachedSchema>* cache = new std::vector<CachedSchema>();  // never freed
  std::lock_guard<std::mutex> lock(mutex);
  for (const CachedSchema& cached : *cache) {
    if (cached.key == key) {
      last = cached;
      return *cached.entry;
    }
  }
  auto* entry = new SchemaCacheEntry();  // lives as long as the process, like the schema
  if (const SerialisedSchema* generated = generated_form(schema)) {
    entry->blob.data = generated->bytes;
    entry->blob.size = generated->size;
    entry->blob.hash = generated->hash;
  } else {
    serialise_blob(schema, entry->blob);
  }
  entry->blob.program_id = format::program_id(schema.program);
  entry->schema = &schema;
  cache->push_back(CachedSchema{key, entry});
  last = cache->back();
  return *entry;
}

const SchemaBlob& schema_blob(const Schema& schema) { return schema_cache_entry(schema).blob; }

}  // namespace symcr::detail
