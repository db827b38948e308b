// SPDX-License-Identifier: GPL-3.0-or-later
#include "heap_counter.h"

#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <new>

// Every heap allocation of the process through operator new, on any thread, is counted:
// the report checks that our estimators allocate nothing per vertex
// (`allocations_per_vertex`) and that their temporary memory stays small
// (`peak_heap_bytes_per_vertex`). A slot per thread, written only by its thread, so that
// counting does not slow down the estimators that do allocate (jet fitting) by contention
// on shared counters. Each block carries its size in a header, so that a delete knows
// what it frees.
namespace {
constexpr int allocation_slots = 64;
constexpr std::size_t size_header = alignof(std::max_align_t); // keeps the block aligned for any type

struct alignas(64) Allocation_slot // a cache line each: no false sharing between threads
{
  std::atomic<unsigned long long> allocations{0};
  std::atomic<long long> live_bytes{0}; // allocated minus freed by this thread since the last reset
  std::atomic<long long> peak_bytes{0}; // the largest live_bytes since the last reset
};
Allocation_slot slots[allocation_slots];
Allocation_slot beyond_slots; // threads without a slot of their own share this one
std::atomic<int> next_allocation_slot{0};

Allocation_slot& own_slot()
{
  thread_local const int slot = next_allocation_slot.fetch_add(1);
  return slot < allocation_slots ? slots[slot] : beyond_slots;
}

// An increment by the slot's own thread, the only one that writes it: no read-modify-write needed.
template <typename T>
void add(std::atomic<T>& a, T x)
{
  a.store(a.load(std::memory_order_relaxed) + x, std::memory_order_relaxed);
}

void count_allocation(std::size_t size)
{
  Allocation_slot& s = own_slot();
  if (&s == &beyond_slots) {
    beyond_slots.allocations.fetch_add(1, std::memory_order_relaxed);
    return; // shared: its live bytes would race; the report's runs use at most 2 threads
  }
  add(s.allocations, 1ULL);
  add(s.live_bytes, static_cast<long long>(size));
  const long long live = s.live_bytes.load(std::memory_order_relaxed);
  if (live > s.peak_bytes.load(std::memory_order_relaxed))
    s.peak_bytes.store(live, std::memory_order_relaxed);
}

void count_free(std::size_t size)
{
  Allocation_slot& s = own_slot();
  if (&s != &beyond_slots)
    add(s.live_bytes, -static_cast<long long>(size));
}

} // namespace

namespace ce_bench {

unsigned long long heap_allocations()
{
  unsigned long long sum = beyond_slots.allocations.load(std::memory_order_relaxed);
  for (const Allocation_slot& s : slots)
    sum += s.allocations.load(std::memory_order_relaxed);
  return sum;
}

void reset_peak_heap()
{
  for (Allocation_slot& s : slots) {
    s.live_bytes.store(0, std::memory_order_relaxed);
    s.peak_bytes.store(0, std::memory_order_relaxed);
  }
}

long long peak_heap_bytes()
{
  long long sum = 0;
  for (const Allocation_slot& s : slots)
    sum += s.peak_bytes.load(std::memory_order_relaxed);
  return sum;
}
} // namespace ce_bench

void* operator new(std::size_t size)
{
  count_allocation(size);
  if (void* p = std::malloc(size_header + size)) {
    *static_cast<std::size_t*>(p) = size;
    return static_cast<char*>(p) + size_header;
  }
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) { return operator new(size); }
void operator delete(void* p) noexcept
{
  if (!p)
    return;
  void* block = static_cast<char*>(p) - size_header;
  count_free(*static_cast<std::size_t*>(block));
  std::free(block);
}
void operator delete[](void* p) noexcept { operator delete(p); }
void operator delete(void* p, std::size_t) noexcept { operator delete(p); }
void operator delete[](void* p, std::size_t) noexcept { operator delete(p); }
