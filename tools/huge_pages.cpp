// SPDX-License-Identifier: GPL-3.0-or-later
// The tool's operator new: on Linux, blocks of 8 MB or more on transparent huge
// pages (2 MB).
//
// Why: a 1M-vertex mesh makes the tool touch about 320 MB of fresh memory (the
// file's text, the soup, the mesh, the outputs), one page fault per 4 KB page
// on first touch. On the virtual machines we measure on, these faults were a
// quarter of the tool's wall time end to end (perf: 26% in exc_page_fault, on
// the 82 MB OFF of benchmark/tool_end_to_end.sh). A huge page takes one fault
// for 512 small ones. Where the kernel allows huge pages only on request
// (/sys/kernel/mm/transparent_hugepage/enabled = madvise, Debian's default),
// madvise(MADV_HUGEPAGE) is that request; where it refuses, the block simply
// stays on small pages. Small blocks go to malloc as usual: rounding them up
// to 2 MB would waste memory.
//
// Not under AddressSanitizer, whose own operator new checks what this would hide.
#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define CE_TOOL_ADDRESS_SANITIZER
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define CE_TOOL_ADDRESS_SANITIZER
#endif

#if defined(__linux__) && !defined(CE_TOOL_ADDRESS_SANITIZER)

#include <sys/mman.h>

#include <cstddef>
#include <cstdlib>
#include <new>

namespace {

constexpr std::size_t huge_page = std::size_t(1) << 21;
constexpr std::size_t huge_block = 4 * huge_page;

// A block of `size` bytes, or null.
void* allocate(std::size_t size)
{
  if (size < huge_block)
    return std::malloc(size != 0 ? size : 1);
  if (size > static_cast<std::size_t>(-1) - huge_page)
    return nullptr;
  const std::size_t rounded = (size + huge_page - 1) & ~(huge_page - 1);
  void* block = std::aligned_alloc(huge_page, rounded);
  if (block != nullptr)
    madvise(block, rounded, MADV_HUGEPAGE); // advice: where refused, small pages
  return block;
}

// As the standard operator new: the new-handler until it gives up, then bad_alloc.
void* allocate_or_throw(std::size_t size)
{
  while (true) {
    if (void* block = allocate(size))
      return block;
    const std::new_handler handler = std::get_new_handler();
    if (handler == nullptr)
      throw std::bad_alloc();
    handler();
  }
}

} // namespace

void* operator new(std::size_t size) { return allocate_or_throw(size); }
void* operator new[](std::size_t size) { return allocate_or_throw(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept
{
  try {
    return allocate_or_throw(size);
  } catch (...) {
    return nullptr;
  }
}
void* operator new[](std::size_t size, const std::nothrow_t& tag) noexcept { return operator new(size, tag); }
// malloc and aligned_alloc blocks alike go back with free.
void operator delete(void* block) noexcept { std::free(block); }
void operator delete[](void* block) noexcept { std::free(block); }
void operator delete(void* block, std::size_t) noexcept { std::free(block); }
void operator delete[](void* block, std::size_t) noexcept { std::free(block); }
void operator delete(void* block, const std::nothrow_t&) noexcept { std::free(block); }
void operator delete[](void* block, const std::nothrow_t&) noexcept { std::free(block); }

#endif
