#pragma once
/// @file
/// Counts heap allocations made by the calling thread, for the zero-allocation tests. Linking
/// rig_test_alloc_counter interposes malloc, calloc, realloc, posix_memalign and aligned_alloc
/// (forwarding to glibc's __libc_* entry points); operator new goes through malloc, so C++
/// allocations are counted too.

#include <cstdint>

namespace rig::test {

/// Allocations made so far by this thread (operator new, malloc, calloc, realloc).
std::uint64_t thread_allocation_count() noexcept;

/// Counts allocations of the current thread between construction and count().
class AllocationCounter {
 public:
  AllocationCounter() noexcept : start_(thread_allocation_count()) {}
  [[nodiscard]] std::uint64_t count() const noexcept { return thread_allocation_count() - start_; }

 private:
  std::uint64_t start_;
};

}  // namespace rig::test
