// The per-thread block caches behind ExactVec nodes and GMP numbers: blocks are reused
// only for their exact size, survive being freed on another thread, and GMP really
// allocates through them.
#include <gmp.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <thread>
#include <vector>

#include "exact/block_cache.h"

namespace gvm::exact {
namespace {

TEST(BlockCache, ReusesAFreedBlockForTheSameSizeOnly) {
  void* a = cached_allocate(48);
  cached_free(a, 48);
  // Kept by the cache, not handed back to malloc (which would give it out again).
  void* from_malloc = std::malloc(48);
  EXPECT_NE(from_malloc, a);
  std::free(from_malloc);
  void* other_size = cached_allocate(56);
  EXPECT_NE(other_size, a);
  void* same_size = cached_allocate(48);
  EXPECT_EQ(same_size, a);
  cached_free(other_size, 56);
  cached_free(same_size, 48);
  // Sizes the cache does not take come from, and go back to, malloc.
  void* big = cached_allocate(4096);
  ASSERT_NE(big, nullptr);
  cached_free(big, 4096);
}

TEST(BlockCache, GmpAllocatesThroughTheCache) {
  void* (*allocate)(size_t) = nullptr;
  void* (*reallocate)(void*, size_t, size_t) = nullptr;
  void (*release)(void*, size_t) = nullptr;
  mp_get_memory_functions(&allocate, &reallocate, &release);
  // A block the cache holds (not malloc) is what GMP gets next.
  void* p = allocate(64);
  cached_free(p, 64);
  void* q = allocate(64);
  EXPECT_EQ(q, p);
  release(q, 64);
  // A number that grows through several sizes keeps its value.
  mpz_t x;
  mpz_init_set_ui(x, 1);
  for (int i = 0; i < 40; ++i) mpz_mul_ui(x, x, 1000003);
  mpz_t y;
  mpz_init(y);
  mpz_ui_pow_ui(y, 1000003, 40);
  EXPECT_EQ(mpz_cmp(x, y), 0);
  mpz_clears(x, y, nullptr);
}

// Blocks made on one thread and freed on another, written and checked all along: a block
// handed out twice, or too small, shows up as a broken pattern.
TEST(BlockCache, BlocksMoveBetweenThreadsIntact) {
  constexpr int kBlocks = 20000;
  const size_t sizes[] = {8, 24, 136, 512};
  std::vector<std::pair<unsigned char*, size_t>> made(kBlocks);
  auto fill = [](unsigned char* p, size_t n, unsigned char tag) { std::memset(p, tag, n); };
  auto intact = [](const unsigned char* p, size_t n, unsigned char tag) {
    for (size_t i = 0; i < n; ++i) {
      if (p[i] != tag) return false;
    }
    return true;
  };
  for (int round = 0; round < 3; ++round) {
    std::thread maker([&] {
      for (int i = 0; i < kBlocks; ++i) {
        const size_t n = sizes[i % 4];
        auto* p = static_cast<unsigned char*>(cached_allocate(n));
        fill(p, n, static_cast<unsigned char>(i));
        made[i] = {p, n};
      }
    });
    maker.join();
    int broken = 0;
    std::thread freer([&] {
      // Half freed and taken again on this thread, so its cache hands out the maker's blocks.
      struct Taken {
        unsigned char* p;
        size_t n;
        unsigned char tag;
      };
      std::vector<Taken> again;
      for (int i = 0; i < kBlocks; ++i) {
        auto [p, n] = made[i];
        broken += !intact(p, n, static_cast<unsigned char>(i));
        cached_free(p, n);
        if (i % 2 == 0) {
          auto* q = static_cast<unsigned char*>(cached_allocate(n));
          const auto tag = static_cast<unsigned char>(i / 2 + 1);
          fill(q, n, tag);
          again.push_back({q, n, tag});
        }
      }
      for (const Taken& t : again) {
        broken += !intact(t.p, t.n, t.tag);
        cached_free(t.p, t.n);
      }
    });
    freer.join();
    EXPECT_EQ(broken, 0) << "round " << round;
  }
}

}  // namespace
}  // namespace gvm::exact
