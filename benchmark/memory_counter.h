// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Heap accounting for the benchmarks: replaces the global operator new/delete of the
// program that includes it (include it in exactly one translation unit) and keeps the
// current and peak number of bytes allocated.

#ifndef PSC_BENCHMARK_MEMORY_COUNTER_H
#define PSC_BENCHMARK_MEMORY_COUNTER_H

#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <new>

namespace psc_bench {

inline std::atomic<long long>& current_bytes()
{
  static std::atomic<long long> v{0};
  return v;
}
inline std::atomic<long long>& peak_bytes()
{
  static std::atomic<long long> v{0};
  return v;
}
inline std::atomic<long long>& allocation_count()
{
  static std::atomic<long long> v{0};
  return v;
}

// Starts a new measurement window: the peak restarts from the current level.
inline void reset_peak() { peak_bytes() = current_bytes().load(); }

inline void* counted_alloc(std::size_t n)
{
  // keep the size in a 16-byte header so delete knows how much to subtract
  void* p = std::malloc(n + 16);
  if(!p)
    throw std::bad_alloc();
  *static_cast<std::size_t*>(p) = n;
  const long long now = (current_bytes() += static_cast<long long>(n));
  ++allocation_count();
  long long peak = peak_bytes().load();
  while(now > peak && !peak_bytes().compare_exchange_weak(peak, now))
  {}
  return static_cast<char*>(p) + 16;
}

inline void counted_free(void* q)
{
  if(!q)
    return;
  void* p = static_cast<char*>(q) - 16;
  current_bytes() -= static_cast<long long>(*static_cast<std::size_t*>(p));
  std::free(p);
}

}  // namespace psc_bench

void* operator new(std::size_t n) { return psc_bench::counted_alloc(n); }
void* operator new[](std::size_t n) { return psc_bench::counted_alloc(n); }
void operator delete(void* p) noexcept { psc_bench::counted_free(p); }
void operator delete[](void* p) noexcept { psc_bench::counted_free(p); }
void operator delete(void* p, std::size_t) noexcept { psc_bench::counted_free(p); }
void operator delete[](void* p, std::size_t) noexcept { psc_bench::counted_free(p); }

#endif
