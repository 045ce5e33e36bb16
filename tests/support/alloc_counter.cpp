#include "tests/support/alloc_counter.h"

#include <cstddef>
#include <cstdlib>
#include <new>

// glibc's real allocator entry points, so that the interposed malloc family can forward.
extern "C" {
void* __libc_malloc(std::size_t size);  // NOLINT(bugprone-reserved-identifier)
void* __libc_calloc(std::size_t n, std::size_t size);  // NOLINT(bugprone-reserved-identifier)
void* __libc_realloc(void* p, std::size_t size);       // NOLINT(bugprone-reserved-identifier)
void* __libc_memalign(std::size_t align, std::size_t size);  // NOLINT
}

namespace {
thread_local std::uint64_t g_allocations = 0;
}  // namespace

namespace rig::test {
std::uint64_t thread_allocation_count() noexcept { return g_allocations; }
}  // namespace rig::test

extern "C" {
void* malloc(std::size_t size) {
  ++g_allocations;
  return __libc_malloc(size);
}
void* calloc(std::size_t n, std::size_t size) {
  ++g_allocations;
  return __libc_calloc(n, size);
}
void* realloc(void* p, std::size_t size) {
  ++g_allocations;
  return __libc_realloc(p, size);
}
int posix_memalign(void** out, std::size_t align, std::size_t size) {
  ++g_allocations;
  void* p = __libc_memalign(align, size);
  if (p == nullptr) return 12;  // ENOMEM
  *out = p;
  return 0;
}
void* aligned_alloc(std::size_t align, std::size_t size) {
  ++g_allocations;
  return __libc_memalign(align, size);
}
}
