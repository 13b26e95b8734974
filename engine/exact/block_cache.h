// Per-thread caches of freed small blocks, by exact size, for the two allocations the
// exact layer makes millions of times per part: expression nodes (ExactVec) and GMP limbs
// of the exact stage. glibc's allocator spent a large share of an analysis in its slow
// paths (consolidating fast bins, unlinking chunks; docs/performance-history.md) because
// these come and go in bursts larger than its own per-thread cache; a list per size answers
// them in a few instructions.
//
// Blocks come from std::malloc and go back to std::free, so a block may be freed on any
// thread (into that thread's list) and a cache that is full, or already destroyed at
// thread exit, passes blocks straight to std::free. Sizes are exact, never rounded up: a
// block is only reused for a request of the size it was freed with, so blocks that GMP's
// default allocator made before ours was installed are safe to take in.
#pragma once

#include <cstddef>
#include <new>

namespace gvm::exact {

void* cached_allocate(std::size_t bytes);
void cached_free(void* p, std::size_t bytes);

// Makes GMP allocate through the caches (once per process; idempotent, thread-safe).
void use_block_cache_for_gmp();

// std::allocate_shared's allocator for the nodes.
template <class T>
struct CachedAllocator {
  using value_type = T;
  CachedAllocator() = default;
  template <class U>
  CachedAllocator(const CachedAllocator<U>&) {}  // NOLINT: rebinding
  T* allocate(std::size_t n) {
    void* p = cached_allocate(n * sizeof(T));
    if (!p) throw std::bad_alloc();
    return static_cast<T*>(p);
  }
  void deallocate(T* p, std::size_t n) { cached_free(p, n * sizeof(T)); }
  template <class U>
  bool operator==(const CachedAllocator<U>&) const { return true; }
};

}  // namespace gvm::exact
