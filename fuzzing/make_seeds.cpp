// Writes the fuzzers' seed corpora from real checkpoints of the test program's worlds:
//   symcr_fuzz_seeds <dir>   ->  <dir>/record_restore/*, <dir>/schema_plan/*, <dir>/store/*,
//                                <dir>/record_header/*
// fuzzing/run calls it on every run (so seeds follow format changes); the committed copies in
// fuzzing/corpus/ are refreshed with `fuzzing/run --refresh-corpus`.
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "device_plan_encode.hpp"
#include "encode.hpp"
#include "freshness.hpp"
#include "fuzz_worlds.hpp"
#include "restore_journal.hpp"
#include "schema_blob.hpp"
#include "symcr/device.hpp"

namespace {

namespace le = symcr::format;
using namespace fuzz;

std::int32_t outside_static = 5;

// Heap objects of the pointer worlds, freed by reset_world.
template <typename T>
T* make(const T& value) {
  T* object = static_cast<T*>(Tracked<T>::create());
  *object = value;
  return object;
}

// Writer-side contents with something in every kind of value.
void fill_world(unsigned world) {
  reset_world(world);
  switch (world) {
    case kA0: {
      auto& b = w::a0::basic;
      b.heading = -123;
      b.narrow_fit = 1000;
      b.narrow_nofit = 70000;
      b.ratio = 0.5f;
      b.precise = 1.0 / 3;
      b.to_float_ok = 16;
      b.to_float_bad = 16777217;
      b.to_int_ok = 42.0;
      b.to_int_bad = 2.5;
      b.mode = w::a0::Mode::AUTO;
      b.mode_unknown = w::a0::Mode::GUIDED;
      b.removed = 9;
      b.same = 200;
      for (int i = 0; i < 3; ++i) b.grow[i] = i + 1;
      for (int i = 0; i < 4; ++i) b.shrink[i] = i + 1;
      b.inner = {1, 2, 3.5f};
      b.blob.word = 0x3f800000u;
      b.blob2.word = 7;
      b.kind_change = {4, 5, 6.5f};
      b.bits.a = 5;
      b.bits.b = 17;
      b.bits.c = -3;
      b.speed = 50;
      w::a0::old_counter = 12;
      w::a0::gone_root = 13;
      break;
    }
    case kA1: {
      auto& b = w::a1::basic;
      b.ratio = 2.25;
      b.yaw = 90;
      b.mode = w::a1::Mode::STABILIZE;
      b.speed = 30;
      b.inner.first = 1;
      b.bits.a = 3;
      w::a1::counter = 4;
      break;
    }
    case kB0: {
      auto& b = w::b0::bag;
      b.vec = {1, -2, 300};
      b.map = {{"a", 1}, {"b", 2}};
      b.set = {3, 5, 9};
      b.list = {w::b0::Item{1, 1.5}, w::b0::Item{2, 2.5}};
      b.deque = {7, 8};
      b.str = "writer";
      b.wide = u"hi";
      b.opt = w::b0::Item{3, 3.5};
      b.var_item = w::b0::Item{4, 4.5};
      b.var_gone = 5;
      b.up.reset(new w::b0::Item{6, 6.5});
      break;
    }
    case kB1: {
      auto& b = w::b1::bag;
      b.vec = {1, 2};
      b.map = {{"k", 1}};
      b.set = {4, 5};
      b.str = "reader";
      b.var_item = 2.5;
      b.up.reset(new w::b1::Item());
      break;
    }
    case kC0: {
      auto& s = w::c0::world;
      s.nav = w::c0::Nav{1.5, 2.5, {10, 11, 12, 13}};
      s.navs = {w::c0::Nav{3.5, 4.5, {20, 21, 22, 23}}, w::c0::Nav{5.5, 6.5, {30, 31, 32, 33}}};
      auto* n1 = make<w::c0::Node>(w::c0::Node{100, nullptr, nullptr});
      auto* n2 = make<w::c0::Node>(w::c0::Node{200, nullptr, nullptr});
      n1->next = n2;
      n2->next = n1;
      n1->other = n1;
      n2->other = n2;
      s.head = n1;
      s.target_ptr = &s.nav.target[2];
      s.lon_ptr = &s.nav.lon;
      s.pick = &s.navs[1];
      s.again = n2;
      s.outside = &outside_static;
      s.s1 = std::make_shared<w::c0::Leaf>(w::c0::Leaf{77});
      s.s2 = s.s1;
      s.into_node = &n1->value;
      break;
    }
    case kC1: {
      auto& s = w::c1::world;
      s.nav.lat = 1;
      s.navs.resize(3);
      auto* n = make<w::c1::Node>(w::c1::Node());
      n->next = n;
      s.head = n;
      s.pick = &s.navs[2];  // (into_node is saved before head: it may not point into a node)
      s.s1 = std::make_shared<w::c1::Leaf>();
      break;
    }
    case kD0: w::d0::derived.id = 1; w::d0::derived.g = 2; w::d0::derived.x = 3; break;
    case kD1: w::d1::derived.id = 4; w::d1::derived.e = 5; w::d1::derived.x = 6; break;
    case kE0: {
      auto& s = w::e0::small;
      s.a = -5;
      s.flag = 7;
      s.on = true;
      s.d = 3.25;
      s.v = {1, 2, 3};
      s.s = "writer";
      s.arr[0] = 4, s.arr[1] = 5, s.arr[2] = 6;
      s.p = &s.arr[1];
      w::e0::good = {1, 2};
      w::e0::bad = {5, 1};
      break;
    }
    case kE1: w::e1::small.a = 3; w::e1::small.p = &w::e1::small.arr[2]; w::e1::good = {1, 9}; break;
    case kT0:
      w::t0::tree = w::t0::Tree{1, {w::t0::Tree{2, {w::t0::Tree{3, {}}}}, w::t0::Tree{4, {}}}};
      w::t0::many = {1, 200, -3};
      break;
    case kT1:
      w::t1::tree.value = 5;
      w::t1::tree.children.resize(2);
      w::t1::many = {1, 2};
      break;
    case kP:
      for (int i = 0; i < 10; ++i) w::p::state.pids[i].limit = static_cast<std::int16_t>(i);
      w::p::state.lat = 42.1;
      w::p::state.mode = 3;
      break;
    default: {
      std::vector<w::g::Node*> nodes;
      nodes.reserve(6);
      for (int i = 0; i < 6; ++i) nodes.push_back(make<w::g::Node>(w::g::Node{i, nullptr, nullptr}));
      for (int i = 0; i < 6; ++i) {
        nodes[i]->next = i + 1 < 6 ? nodes[i + 1] : nullptr;
        nodes[i]->jump = nodes[(i * 5 + 1) % 6];
      }
      w::g::graph.first = nodes[0];
      w::g::graph.count = 6;
      break;
    }
  }
}

unsigned partner(unsigned world) {
  switch (world) {
    case kA0: return kA1; case kA1: return kA0;
    case kB0: return kB1; case kB1: return kB0;
    case kC0: return kC1; case kC1: return kC0;
    case kD0: return kD1; case kD1: return kD0;
    case kE0: return kE1; case kE1: return kE0;
    case kT0: return kT1; case kT1: return kT0;
    default: return world;
  }
}

std::string dir_of(const std::string& root, const char* target) {
  std::string dir = root + "/" + target;
  ::mkdir(root.c_str(), 0755);
  ::mkdir(dir.c_str(), 0755);
  return dir;
}

void write_seed(const std::string& dir, const std::string& name,
                const std::vector<std::uint8_t>& bytes) {
  const std::string path = dir + "/" + name;
  FILE* file = std::fopen(path.c_str(), "wb");
  if (!file || std::fwrite(bytes.data(), 1, bytes.size(), file) != bytes.size()) {
    std::perror(path.c_str());
    std::exit(1);
  }
  std::fclose(file);
}

void put32(std::vector<std::uint8_t>& out, std::uint32_t v) {
  const std::size_t at = out.size();
  out.resize(at + 4);
  le::store32(out.data() + at, v);
}

void put_section(std::vector<std::uint8_t>& out, const std::uint8_t* bytes, std::size_t size) {
  const std::size_t at = out.size();
  out.resize(at + 2);
  le::store16(out.data() + at, static_cast<std::uint16_t>(size));
  out.insert(out.end(), bytes, bytes + size);
}

std::vector<std::uint8_t> read_file(const std::string& path) {
  std::vector<std::uint8_t> bytes;
  FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) return bytes;
  std::uint8_t buffer[65536];
  std::size_t got = 0;
  while ((got = std::fread(buffer, 1, sizeof buffer, file)) > 0) bytes.insert(bytes.end(), buffer, buffer + got);
  std::fclose(file);
  return bytes;
}

// The store file at `path` in the fuzzer's compact form (fuzz_store.cpp).
// With `cut_in_slot`, the header section also asks the fuzzer to truncate the file 100 bytes
// into that slot; with a `fallback_depth`, it carries the restore journal and that depth; an
// `authenticated` one carries the journal's seals, the store's identity and its freshness
// counter file (<path>.fresh) too.
std::vector<std::uint8_t> compact_store(const std::string& path, std::uint8_t control,
                                        int cut_in_slot = -1, bool authenticated = false,
                                        std::uint8_t fallback_depth = 0) {
  const std::vector<std::uint8_t> file = read_file(path);
  std::vector<std::uint8_t> out{control};
  const std::uint32_t slot_count = le::load32(file.data() + 12);
  const std::uint32_t slot_size = le::load32(file.data() + 16);
  const std::uint32_t area_size = le::load32(file.data() + 20);
  const std::uint64_t slots_offset = le::load64(file.data() + 24);
  std::vector<std::uint8_t> header(file.begin(), file.begin() + 36);
  if (cut_in_slot >= 0 || authenticated) header.resize(authenticated ? 41 : 40);
  if (fallback_depth != 0 || authenticated) {
    header.resize(symcr::detail::kStoreHeaderPageRead);
    std::copy(file.begin() + 64, file.begin() + symcr::detail::kStoreHeaderPageRead,
              header.begin() + 64);
    header[41] = fallback_depth;
  }
  if (authenticated) {
    const std::vector<std::uint8_t> counter = read_file(path + ".fresh");
    header.resize(512, 0);
    header.insert(header.end(), counter.begin(), counter.end());
  }
  if (cut_in_slot >= 0) {
    le::store32(header.data() + 36, static_cast<std::uint32_t>(
                                        slots_offset + std::uint64_t(cut_in_slot) * slot_size + 100));
  }
  if (authenticated) header[40] = 1;
  put_section(out, header.data(), header.size());
  for (int a = 0; a < 2; ++a) {
    const std::uint8_t* area = file.data() + 4096 + std::uint64_t(a) * area_size;
    const std::uint32_t size = le::load32(area + 8);
    put_section(out, area, size ? 16 + size : 0);
  }
  for (std::uint32_t s = 0; s < slot_count; ++s) {
    const std::uint8_t* slot = file.data() + slots_offset + std::uint64_t(s) * slot_size;
    std::size_t used = 0;
    if (slot[0] == 'S') {
      used = le::load16(slot + 10) + std::size_t{le::load32(slot + 40)} + le::load32(slot + 44);
    }
    put_section(out, slot, used);
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s <corpus-root>\n", argv[0]);
    return 2;
  }
  const std::string root = argv[1];
  const std::string records = dir_of(root, "record_restore");
  const std::string plans = dir_of(root, "schema_plan");
  const std::string stores = dir_of(root, "store");
  const std::string headers = dir_of(root, "record_header");
  std::size_t written = 0;

  for (unsigned world = 0; world < kWorldCount; ++world) {
    fill_world(world);
    std::vector<std::uint8_t> record;
    const symcr::Status status = symcr::checkpoint_to_buffer(world_schema(world), record, 7);
    const symcr::detail::SchemaBlob& blob = symcr::detail::schema_blob(world_schema(world));
    std::vector<std::uint8_t> payload;
    (void)symcr::detail::encode_payload(world_schema(world), payload);
    reset_world(world);
    if (!status.ok()) {
      std::fprintf(stderr, "%s: %s\n", world_name(world), status.message());
      return 1;
    }
    write_seed(headers, std::string(world_name(world)) + "-record", record);  // no control byte
    ++written;
    for (unsigned reader : {world, partner(world)}) {
      // Unchanged and different reader; with integrity fixed up after mutation, and not.
      for (std::uint8_t extra : {std::uint8_t{0x10}, std::uint8_t{0x50}, std::uint8_t{0x00}}) {
        if (extra == 0x50 && reader != kC0 && reader != kC1 && reader != kG && reader != kB1) continue;
        std::vector<std::uint8_t> seed{static_cast<std::uint8_t>(reader | extra)};
        seed.insert(seed.end(), record.begin(), record.end());
        write_seed(records, std::string(world_name(world)) + "-into-" + world_name(reader) +
                                "-" + std::to_string(extra), seed);
        ++written;
      }
      // Schema pairs: into the world (bit 4 clear), and into a layout of the parsed reader.
      const symcr::detail::SchemaBlob& other = symcr::detail::schema_blob(world_schema(reader));
      for (std::uint8_t control : {static_cast<std::uint8_t>(reader), std::uint8_t{0x10},
                                   std::uint8_t{0x50}, std::uint8_t{0x90}}) {
        std::vector<std::uint8_t> seed{control};
        put32(seed, static_cast<std::uint32_t>(blob.size));
        seed.insert(seed.end(), blob.data, blob.data + blob.size);
        put32(seed, static_cast<std::uint32_t>(other.size));
        seed.insert(seed.end(), other.data, other.data + other.size);
        seed.insert(seed.end(), payload.begin(), payload.end());
        write_seed(plans, std::string(world_name(world)) + "-vs-" + world_name(reader) + "-" +
                              std::to_string(control), seed);
        ++written;
      }
    }
  }

  // Authenticated records (control bit 7: the reader holds the key), restored into the world
  // itself with integrity fixed up after mutation, and not.
  for (unsigned world = 0; world < kWorldCount; ++world) {
    fill_world(world);
    use_fuzz_key(true);
    std::vector<std::uint8_t> record;
    const symcr::Status status = symcr::checkpoint_to_buffer(world_schema(world), record, 7);
    use_fuzz_key(false);
    reset_world(world);
    if (!status.ok()) {
      std::fprintf(stderr, "%s: %s\n", world_name(world), status.message());
      return 1;
    }
    for (std::uint8_t extra : {std::uint8_t{0x90}, std::uint8_t{0x80}}) {
      std::vector<std::uint8_t> seed{static_cast<std::uint8_t>(world | extra)};
      seed.insert(seed.end(), record.begin(), record.end());
      write_seed(records, std::string(world_name(world)) + "-authenticated-" +
                              std::to_string(extra), seed);
      ++written;
    }
    write_seed(headers, std::string(world_name(world)) + "-authenticated", record);
    ++written;
  }

  // Stores: a few saves of a world, then (for pairs) a save by the patched build, so both
  // schema areas are in use; restored by the writer's world and by its partner.
  char tmpl[] = "/tmp/symcr-seeds-XXXXXX";
  if (!::mkdtemp(tmpl)) {
    std::perror("mkdtemp");
    return 1;
  }
  for (unsigned world : {kA0, kB0, kC0, kD0, kE0, kT0, kP, kG}) {
    const std::string path = std::string(tmpl) + "/store";
    ::unlink(path.c_str());
    symcr::StoreOptions options;
    options.slots = 3;
    options.slot_size = 1024;
    {
      symcr::Store store;
      symcr::Status status = symcr::Store::open(path.c_str(), world_schema(world), options, store);
      for (int i = 0; status.ok() && i < 4; ++i) {
        fill_world(world);
        status = store.save();
        reset_world(world);
      }
      if (!status.ok()) {
        std::fprintf(stderr, "store %s: %s\n", world_name(world), status.message());
        return 1;
      }
    }
    write_seed(stores, std::string(world_name(world)) + "-store",
               compact_store(path, static_cast<std::uint8_t>(world | 0x10)));
    write_seed(stores, std::string(world_name(world)) + "-store-raw",
               compact_store(path, static_cast<std::uint8_t>(partner(world) | 0x40)));
    written += 2;
    // The recovery paths: a zeroed header (found again by scanning the slots), another
    // geometry asked for, and a file cut inside its second slot.
    std::vector<std::uint8_t> zeroed = compact_store(path, static_cast<std::uint8_t>(world));
    std::fill(zeroed.begin() + 3, zeroed.begin() + 3 + 36, std::uint8_t{0});
    write_seed(stores, std::string(world_name(world)) + "-zeroed-header", zeroed);
    write_seed(stores, std::string(world_name(world)) + "-foreign-geometry",
               compact_store(path, static_cast<std::uint8_t>(world | 0x10 | 0x80)));
    write_seed(stores, std::string(world_name(world)) + "-truncated",
               compact_store(path, static_cast<std::uint8_t>(world | 0x10), /*cut_in_slot=*/1));
    written += 3;
    {
      // The crash-loop fallback: a restore recorded and never confirmed (the journal), which the
      // fuzzer's writable open then finds.
      symcr::StoreOptions with_fallback = options;
      with_fallback.fallback_depth = 2;
      symcr::Store store;
      symcr::Status status =
          symcr::Store::open(path.c_str(), world_schema(world), with_fallback, store);
      if (status.ok()) status = store.restore_latest().status();
      reset_world(world);
      if (!status.ok()) {
        std::fprintf(stderr, "store %s (fallback): %s\n", world_name(world), status.message());
        return 1;
      }
      store.close();
      write_seed(stores, std::string(world_name(world)) + "-unconfirmed-restore",
                 compact_store(path, static_cast<std::uint8_t>(world | 0x10), -1, false, 2));
      ++written;
    }
    if (partner(world) != world) {
      symcr::Store store;
      symcr::Status status = symcr::Store::open(path.c_str(), world_schema(partner(world)), options, store);
      if (status.ok()) {
        fill_world(partner(world));
        status = store.save();
        reset_world(partner(world));
      }
      if (!status.ok()) {
        std::fprintf(stderr, "store %s: %s\n", world_name(partner(world)), status.message());
        return 1;
      }
      store.close();
      write_seed(stores, std::string(world_name(world)) + "-then-" + world_name(partner(world)),
                 compact_store(path, static_cast<std::uint8_t>(partner(world) | 0x10)));
      ++written;
    }
    ::unlink(path.c_str());
  }
  // An authenticated store: every slot signed with the fuzzers' key, read with it.
  for (unsigned world : {kA0, kG}) {
    const std::string path = std::string(tmpl) + "/store";
    ::unlink(path.c_str());
    symcr::StoreOptions options;
    options.slots = 3;
    options.slot_size = 1024;
    use_fuzz_key(true);
    symcr::Status status;
    {
      symcr::Store store;
      status = symcr::Store::open(path.c_str(), world_schema(world), options, store);
      for (int i = 0; status.ok() && i < 4; ++i) {
        fill_world(world);
        status = store.save();
        reset_world(world);
      }
    }
    use_fuzz_key(false);
    if (!status.ok()) {
      std::fprintf(stderr, "authenticated store %s: %s\n", world_name(world), status.message());
      return 1;
    }
    write_seed(stores, std::string(world_name(world)) + "-authenticated-store",
               compact_store(path, static_cast<std::uint8_t>(world | 0x10), -1, true));
    ++written;
    // The same after a start that recorded its restore: a sealed journal.
    use_fuzz_key(true);
    {
      symcr::StoreOptions with_fallback = options;
      with_fallback.fallback_depth = 2;
      symcr::Store store;
      status = symcr::Store::open(path.c_str(), world_schema(world), with_fallback, store);
      if (status.ok()) status = store.restore_latest().status();
      reset_world(world);
    }
    use_fuzz_key(false);
    if (!status.ok()) {
      std::fprintf(stderr, "authenticated store %s (fallback): %s\n", world_name(world),
                   status.message());
      return 1;
    }
    write_seed(stores, std::string(world_name(world)) + "-authenticated-sealed-journal",
               compact_store(path, static_cast<std::uint8_t>(world | 0x10), -1, true, 2));
    ++written;
    ::unlink(path.c_str());
    ::unlink((path + ".fresh").c_str());
  }
  ::rmdir(tmpl);

  // The device profile's records (schema by hash) and the host's (schema inline) of each world
  // it holds; the control byte indexes the held worlds in order, as the harness does.
  const std::string devices = dir_of(root, "device_restore");
  std::uint8_t held = 0;
  for (unsigned world = 0; world < kWorldCount; ++world) {
    const symcr::Schema& schema = world_schema(world);
    if (symcr::device::check_schema(schema) != symcr::device::Result::Ok) continue;
    fill_world(world);
    std::vector<std::uint8_t> record(1 + symcr::device::record_size(schema));
    std::size_t size = 0;
    const symcr::device::Result result =
        symcr::device::save({&schema, symcr::detail::schema_blob(schema).hash}, 3,
                            record.data() + 1, record.size() - 1, &size);
    std::vector<std::uint8_t> host;
    const symcr::Status status = symcr::checkpoint_to_buffer(schema, host, 4);
    reset_world(world);
    if (result != symcr::device::Result::Ok || !status.ok()) {
      std::fprintf(stderr, "device %s: %s\n", world_name(world),
                   symcr::device::result_text(result));
      return 1;
    }
    record.resize(1 + size);
    for (std::uint8_t fix : {std::uint8_t{0x10}, std::uint8_t{0x00}}) {
      record[0] = static_cast<std::uint8_t>(held | fix);
      write_seed(devices, std::string(world_name(world)) + "-device-" + std::to_string(fix),
                 record);
      std::vector<std::uint8_t> inline_seed{static_cast<std::uint8_t>(held | fix)};
      inline_seed.insert(inline_seed.end(), host.begin(), host.end());
      write_seed(devices, std::string(world_name(world)) + "-host-" + std::to_string(fix),
                 inline_seed);
      written += 2;
    }
    ++held;
  }
  // Previous builds' records restored through device plan images: per pair the device holds
  // (the harness's order), the x0 world's device record, with the genuine image and with the
  // image in the input.
  const std::string device_plans = dir_of(root, "device_plan");
  std::uint8_t pair = 0;
  for (unsigned world = 0; world < kP; world += 2) {  // x0, x1 pairs
    const symcr::Schema& writer = world_schema(world);
    const symcr::Schema& reader = world_schema(world + 1);
    if (symcr::device::check_schema(writer) != symcr::device::Result::Ok ||
        symcr::device::check_schema(reader) != symcr::device::Result::Ok) {
      continue;
    }
    std::vector<std::uint8_t> image;
    std::string error;
    if (!symcr::detail::device_plan_image_for(writer, symcr::detail::schema_blob(writer).hash,
                                              reader, symcr::detail::schema_blob(reader).hash,
                                              image, error)) {
      std::printf("device plan %s: not the device's: %s\n", world_name(world), error.c_str());
      continue;
    }
    fill_world(world);
    std::vector<std::uint8_t> record(symcr::device::record_size(writer));
    std::size_t size = 0;
    const symcr::device::Result result = symcr::device::save(
        {&writer, symcr::detail::schema_blob(writer).hash}, 3, record.data(), record.size(),
        &size);
    reset_world(world);
    if (result != symcr::device::Result::Ok) {
      std::fprintf(stderr, "device plan %s: %s\n", world_name(world),
                   symcr::device::result_text(result));
      return 1;
    }
    record.resize(size);
    for (std::uint8_t mode : {std::uint8_t{0x30}, std::uint8_t{0x10}, std::uint8_t{0x50}}) {
      const bool genuine = (mode & 0x20) != 0;
      std::vector<std::uint8_t> seed{static_cast<std::uint8_t>(pair | mode)};
      const std::size_t length = genuine ? 0 : image.size();
      seed.push_back(static_cast<std::uint8_t>(length));
      seed.push_back(static_cast<std::uint8_t>(length >> 8));
      if (!genuine) seed.insert(seed.end(), image.begin(), image.end());
      seed.insert(seed.end(), record.begin(), record.end());
      write_seed(device_plans, std::string(world_name(world)) + "-plan-" + std::to_string(mode),
                 seed);
      ++written;
    }
    ++pair;
  }
  std::printf("wrote %zu seeds under %s\n", written, root.c_str());
  return 0;
}
