// SPDX-License-Identifier: GPL-3.0-or-later
// The heap a benchmark's calls allocate (heap_counter.cpp, linked into every speed
// benchmark, replaces operator new and delete of the process).
#ifndef CE_BENCHMARK_HEAP_COUNTER_H
#define CE_BENCHMARK_HEAP_COUNTER_H

namespace ce_bench {

// The heap allocations through operator new of every thread since the process started.
unsigned long long heap_allocations();

// Starts the count of peak_heap_bytes(); called between calls, when no other thread allocates.
void reset_peak_heap();

// The most heap that the calls since reset_peak_heap() held at once: exact for one thread;
// with several, the sum of each thread's peak, an upper bound (a block freed by another
// thread than its allocator's lowers only the freeing thread's count).
long long peak_heap_bytes();

} // namespace ce_bench

#endif // CE_BENCHMARK_HEAP_COUNTER_H
