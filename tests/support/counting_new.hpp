// Replaces the global operator new with one that counts its calls, for the
// allocation tests and benchmarks. Include it in exactly ONE source file of an
// executable (it defines the replacement functions); read rtamp_allocations().
#pragma once

#include <atomic>
#include <cstdlib>
#include <new>

inline std::atomic<long> rtamp_allocation_count{0};

// Calls of global operator new so far.
inline long rtamp_allocations() { return rtamp_allocation_count.load(std::memory_order_relaxed); }

// GCC flags free() on memory from (our own, malloc-based) operator new once inlined.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif
void* operator new(std::size_t n) {
  rtamp_allocation_count.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
