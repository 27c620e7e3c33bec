// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The tool's large allocations backed by transparent huge pages (Linux).
//
// A run on a large cloud allocates a few large arrays (the points, the sorted cloud, the
// results, the output rows) and touches every page of them once. On a machine whose kernel
// gives huge pages only where a program asks for them (/sys/kernel/mm/transparent_hugepage/
// enabled = madvise, the default of many distributions), each 4 KB page is a page fault on
// first touch, and under virtualization a fault is expensive: on this project's 2-core VM, a
// run of the tool on 1M points of .xyz with normals spent a quarter of its time in them
// (--neighbors 40: 4.43 s against 3.33 s with huge pages; the default 7.56 s against 5.66 s;
// the same peak memory). So the tool's global operator new asks for huge pages (madvise
// MADV_HUGEPAGE on a 2 MB-aligned block) for blocks of at least least_huge_block bytes; smaller
// ones are plain malloc. Every block is freed by free(). Nothing changes in the results.
//
// Not in builds with AddressSanitizer, which replaces operator new itself to check its use.

#include <cstddef>
#include <cstdlib>
#include <new>

#if defined(__linux__)
#include <malloc.h>
#include <sys/mman.h>
#endif

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define PSC_TOOL_NO_HUGE_PAGES
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define PSC_TOOL_NO_HUGE_PAGES
#endif

#if defined(__linux__) && defined(MADV_HUGEPAGE) && !defined(PSC_TOOL_NO_HUGE_PAGES)

namespace {

constexpr std::size_t huge_page = std::size_t(2) << 20;
// At least four huge pages: rounding a block up to whole huge pages then costs at most a fifth
// of it.
constexpr std::size_t least_huge_block = 4 * huge_page;

// Blocks of that size mapped and unmapped on their own (a fixed threshold: glibc's own rises
// as blocks are freed, after which large blocks come from the heap and stay resident once freed;
// with the huge pages, the peak memory of a run on 1M points grew by 40% that way).
[[maybe_unused]] const bool mapped_alone = ::mallopt(M_MMAP_THRESHOLD, int(least_huge_block)) == 1;

void* allocate(std::size_t n)
{
  for(;;)
  {
    void* p = nullptr;
    if(n >= least_huge_block)
    {
      const std::size_t size = (n + huge_page - 1) / huge_page * huge_page;
      p = std::aligned_alloc(huge_page, size);
      if(p)
        ::madvise(p, size, MADV_HUGEPAGE);  // (advice only: a refusal leaves 4 KB pages)
    }
    else
      p = std::malloc(n == 0 ? 1 : n);
    if(p)
      return p;
    std::new_handler handler = std::get_new_handler();
    if(!handler)
      throw std::bad_alloc();
    handler();
  }
}

}  // namespace

void* operator new(std::size_t n) { return allocate(n); }
void* operator new[](std::size_t n) { return allocate(n); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept
{
  try
  {
    return allocate(n);
  }
  catch(...)
  {
    return nullptr;
  }
}
void* operator new[](std::size_t n, const std::nothrow_t& t) noexcept { return operator new(n, t); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }

#endif
