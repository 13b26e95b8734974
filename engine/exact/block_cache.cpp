#include "exact/block_cache.h"

#include <gmp.h>
#include <sanitizer/asan_interface.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>

namespace gvm::exact {
namespace {

constexpr std::size_t kGranule = 8;    // nodes and GMP limbs come in multiples of 8 bytes
constexpr std::size_t kLargest = 512;  // larger blocks go to std::malloc directly
constexpr std::size_t kSizes = kLargest / kGranule;
// Bytes kept per size and thread: a burst of frees (one arrangement's nodes) is reused by
// the next burst. Only a few sizes are in use (the node, GMP numbers of a few limbs), so
// a thread keeps a few MB; 64 MB if every size filled up.
constexpr std::size_t kKeepBytes = std::size_t{1} << 20;

struct FreeBlock {
  FreeBlock* next;
};

struct Cache {
  FreeBlock* head[kSizes + 1] = {};
  std::uint32_t count[kSizes + 1] = {};
  ~Cache();
};

// Trivially destructible, so still readable while and after ~Cache runs at thread exit.
thread_local bool t_cache_gone = false;
thread_local Cache t_cache;

Cache::~Cache() {
  t_cache_gone = true;
  for (std::size_t k = 1; k <= kSizes; ++k) {
    while (FreeBlock* b = head[k]) {
      ASAN_UNPOISON_MEMORY_REGION(b, k * kGranule);
      head[k] = b->next;
      std::free(b);
    }
  }
}

// The list of an exact size, or 0 for sizes the cache does not take.
std::size_t size_index(std::size_t bytes) {
  return bytes >= kGranule && bytes <= kLargest && bytes % kGranule == 0 ? bytes / kGranule : 0;
}

[[noreturn]] void out_of_memory(std::size_t bytes) {
  std::fprintf(stderr, "gvm: out of memory (GMP asked for %zu bytes)\n", bytes);
  std::abort();  // GMP cannot unwind from its allocation functions
}

void* gmp_allocate(std::size_t bytes) {
  void* p = cached_allocate(bytes);
  if (!p) out_of_memory(bytes);
  return p;
}

void* gmp_reallocate(void* p, std::size_t old_bytes, std::size_t new_bytes) {
  if (size_index(old_bytes) == 0 && size_index(new_bytes) == 0) {
    void* q = std::realloc(p, new_bytes);
    if (!q) out_of_memory(new_bytes);
    return q;
  }
  void* q = gmp_allocate(new_bytes);
  std::memcpy(q, p, std::min(old_bytes, new_bytes));
  cached_free(p, old_bytes);
  return q;
}

void gmp_free(void* p, std::size_t bytes) { cached_free(p, bytes); }

}  // namespace

void* cached_allocate(std::size_t bytes) {
  const std::size_t k = size_index(bytes);
  if (k != 0 && !t_cache_gone) {
    Cache& c = t_cache;
    if (FreeBlock* b = c.head[k]) {
      ASAN_UNPOISON_MEMORY_REGION(b, bytes);
      c.head[k] = b->next;
      --c.count[k];
      return b;
    }
  }
  return std::malloc(bytes);
}

void cached_free(void* p, std::size_t bytes) {
  if (!p) return;
  const std::size_t k = size_index(bytes);
  if (k != 0 && !t_cache_gone) {
    Cache& c = t_cache;
    if (c.count[k] < kKeepBytes / bytes) {
      c.head[k] = new (p) FreeBlock{c.head[k]};
      ++c.count[k];
      // Under AddressSanitizer a cached block stays unusable, so that a use after free is
      // caught as if malloc had the block; all but the link, which LeakSanitizer must read
      // to see the rest of the list as held.
      ASAN_POISON_MEMORY_REGION(static_cast<char*>(p) + sizeof(FreeBlock), bytes - sizeof(FreeBlock));
      return;
    }
  }
  std::free(p);
}

void use_block_cache_for_gmp() {
  static std::once_flag once;
  std::call_once(once, [] { mp_set_memory_functions(gmp_allocate, gmp_reallocate, gmp_free); });
}

}  // namespace gvm::exact
