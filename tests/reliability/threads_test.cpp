// The runtime has no thread of its own (no asynchronous writer), but it is thread-compatible:
// per-thread scratch (encode's buffers, the single-file record buffer, the C API's last error,
// the schema-cache memo) and mutex-guarded process-wide caches (serialised schemas, restore
// plans). Threads that each checkpoint and restore their *own* state concurrently must not
// race. scripts/test runs this test under ThreadSanitizer (build/tsan); the plain and ASan
// builds run it too.
#include <atomic>
#include <cstdint>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "file_test_util.hpp"
#include "reliability_schemas.hpp"
#include "symcr/symcr.hpp"

namespace reliability {
namespace {

constexpr int kRounds = 60;

// Opening a store of the build's own schema prepares the scratch of the process's first
// restore (written there, so that that restore meets no fresh page): the opens below prepare
// it, then one thread's first restore takes it while another thread opens stores again. It is
// taken once and freed once, and each restore is whole. First in this file: under
// ThreadSanitizer all Threads tests share one process, and only its first restore of the frame
// takes the prepared scratch.
TEST(Threads, OpeningStoresWhileAnotherThreadRestoresForTheFirstTimeDoesNotRace) {
  file_tests::TempDir dir;
  symcr::StoreOptions options;
  options.slots = 2;
  options.slot_size = 32 * 1024;
  std::vector<std::string> paths;
  for (int i = 0; i < 4; ++i) {
    paths.push_back(dir.file("opened" + std::to_string(i) + ".store"));
    fill_frame(static_cast<std::uint64_t>(100 + i));
    symcr::Store store;
    ASSERT_TRUE(symcr::Store::open(paths.back().c_str(), frame_schema(), options, store).ok());
    ASSERT_TRUE(store.save().ok());
  }
  fill_frame(7);
  std::vector<std::uint8_t> buffer;
  ASSERT_TRUE(symcr::checkpoint_to_buffer(frame_schema(), buffer).ok());
  frame = Frame{};

  std::atomic<int> go{0};
  std::atomic<int> failures{0};
  std::thread opener([&] {
    while (go.load() == 0) std::this_thread::yield();
    for (int round = 0; round < 20; ++round) {
      symcr::Store store;
      const std::string& path = paths[static_cast<std::size_t>(round) % paths.size()];
      if (!symcr::Store::open(path.c_str(), frame_schema(), options, store).ok()) ++failures;
    }
  });
  std::thread restorer([&] {
    while (go.load() == 0) std::this_thread::yield();
    for (int round = 0; round < 20; ++round) {
      frame.sequence = 0;
      const symcr::Report report =
          symcr::restore_from_buffer(frame_schema(), buffer.data(), buffer.size());
      if (!report.ok() || !frame_is(7)) ++failures;
    }
  });
  go.store(1);
  opener.join();
  restorer.join();
  EXPECT_EQ(failures.load(), 0);
}

TEST(Threads, ThreadsCheckpointingTheirOwnStateConcurrentlyDoNotRace) {
  file_tests::TempDir dir;
  const std::string store_path = dir.file("frames.store");
  const std::string file_path = dir.file("list.ckpt");
  std::atomic<int> go{0};
  std::atomic<int> failures{0};
  auto wait_for_go = [&] {
    while (go.load() == 0) std::this_thread::yield();
  };

  // Thread 1: a store of frames, save + restore_latest.
  std::thread frames([&] {
    wait_for_go();
    symcr::StoreOptions options;
    options.slots = 3;
    options.slot_size = 32 * 1024;
    symcr::Store store;
    if (!symcr::Store::open(store_path.c_str(), frame_schema(), options, store).ok()) {
      ++failures;
      return;
    }
    for (int round = 1; round <= kRounds; ++round) {
      fill_frame(static_cast<std::uint64_t>(round));
      if (!store.save().ok()) ++failures;
      frame.sequence = 0;
      const symcr::Report report = store.restore_latest();
      if (!report.ok() || !frame_is(static_cast<std::uint64_t>(round))) ++failures;
    }
  });

  // Thread 2: a container chain through in-memory checkpoints.
  std::thread chains([&] {
    wait_for_go();
    std::vector<std::uint8_t> buffer;
    for (int round = 1; round <= kRounds; ++round) {
      build_chain(chain, static_cast<std::size_t>(round % 20));
      if (!symcr::checkpoint_to_buffer(chain_schema(), buffer, round).ok()) ++failures;
      dismantle_chain(chain);
      const symcr::Report report =
          symcr::restore_from_buffer(chain_schema(), buffer.data(), buffer.size());
      std::size_t depth = 0;
      for (const Chain* at = &chain; !at->inner.empty(); at = &at->inner[0]) ++depth;
      if (!report.ok() || depth != static_cast<std::size_t>(round % 20)) ++failures;
      dismantle_chain(chain);
    }
  });

  // Thread 3: a small pointer list through single-file checkpoints.
  std::thread lists([&] {
    wait_for_go();
    for (int round = 1; round <= kRounds; ++round) {
      ListNode* head = nullptr;
      for (int i = 0; i < 16; ++i) head = new ListNode{round * 100 + i, head};
      list.head = head;
      list.length = 16;
      if (!symcr::checkpoint(list_schema(), file_path.c_str()).ok()) ++failures;
      list = List{};
      const symcr::Report report = symcr::restore(list_schema(), file_path.c_str());
      std::int64_t count = 0;
      for (ListNode* node = list.head; node;) {
        ListNode* next = node->next;
        delete node;
        node = next;
        ++count;
      }
      while (head) {
        ListNode* next = head->next;
        delete head;
        head = next;
      }
      if (!report.ok() || count != 16) ++failures;
      list = List{};
    }
  });

  go.store(1);
  frames.join();
  chains.join();
  lists.join();
  EXPECT_EQ(failures.load(), 0);
}

// Key rotation while other threads save: each save reads one consistent key set, so every
// record it returns is verifiable by the keys it was made with (here both rings hold both
// keys), and clearing the keys mid-save never crashes (the save is then signed or not, whole).
TEST(Threads, RotatingAndClearingKeysWhileOthersSaveNeverMixesKeySets) {
  static const std::uint8_t one[] = "key-one-0123456789abcdef";
  static const std::uint8_t two[] = "key-two-0123456789abcdef";
  const symcr::CheckpointKey ring_a[] = {{1, one, 24}, {2, two, 24}};
  const symcr::CheckpointKey ring_b[] = {{2, two, 24}, {1, one, 24}};
  ASSERT_TRUE(symcr::set_checkpoint_keys(ring_a, 2).ok());
  std::atomic<bool> stop{false};
  std::thread rotator([&] {
    for (int i = 0; !stop.load(); ++i) {
      if (i % 3 == 2) {
        (void)symcr::set_checkpoint_keys(nullptr, 0);
      } else {
        (void)symcr::set_checkpoint_keys(i % 2 ? ring_a : ring_b, 2);
      }
    }
  });
  constexpr int kSaves = 3000;
  std::vector<std::vector<std::uint8_t>> saved;
  saved.reserve(kSaves);
  std::atomic<int> failures{0};
  std::thread saver([&] {
    std::vector<std::uint8_t> buffer;
    for (int round = 1; round <= kSaves; ++round) {
      fill_frame(static_cast<std::uint64_t>(round));
      if (!symcr::checkpoint_to_buffer(frame_schema(), buffer, round).ok()) ++failures;
      saved.push_back(buffer);
    }
  });
  saver.join();
  stop.store(true);
  rotator.join();
  EXPECT_EQ(failures.load(), 0);
  ASSERT_TRUE(symcr::set_checkpoint_keys(ring_a, 2).ok());
  int signed_saves = 0, refused = 0;
  for (const std::vector<std::uint8_t>& bytes : saved) {
    if ((bytes[12] & 2u) == 0) continue;  // saved while the keys were cleared: no MAC
    ++signed_saves;
    const symcr::Report report =
        symcr::restore_from_buffer(frame_schema(), bytes.data(), bytes.size());
    if (!report.ok()) ++refused;
  }
  EXPECT_EQ(refused, 0) << "of " << signed_saves << " signed saves";
  ASSERT_TRUE(symcr::set_checkpoint_keys(nullptr, 0).ok());
}

}  // namespace
}  // namespace reliability
