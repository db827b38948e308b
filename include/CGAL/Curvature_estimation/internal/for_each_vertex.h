// The vertex loop shared by the estimators: sequential, or TBB-parallel in blocks.
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_FOR_EACH_VERTEX_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_FOR_EACH_VERTEX_H

#include <CGAL/assertions.h>
#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#endif

#include <cstddef>
#include <iterator>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// A Worker is copyable (one copy per thread holds that thread's buffers) and has
//   Input  load(vertex) const           reads the user's input maps,
//   Result compute(vertex, const Input&) the estimate, touching no property map
//                                        but the vertex point map.
// store(vertex, result) writes the user's output maps.
// load and store always run on the calling thread: property maps such as the
// dynamic ones of Polyhedron_3 insert on `get` and are not thread-safe. In
// parallel, vertices go in blocks of fixed size, so the extra memory is
// O(block + threads x neighbourhood), not O(#vertices).
template <typename ConcurrencyTag, typename VertexRange, typename Worker, typename Store>
void for_each_vertex(const VertexRange& vertices, const Worker& worker, Store store)
{
#ifndef CGAL_LINKED_WITH_TBB
  static_assert(!std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value,
                "Parallel_tag is enabled but TBB is unavailable.");
#else
  if constexpr (std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value) {
    using Vertex = typename std::iterator_traits<decltype(std::begin(vertices))>::value_type;
    using Input = decltype(worker.load(std::declval<Vertex>()));
    using Result = decltype(std::declval<Worker&>().compute(std::declval<Vertex>(), std::declval<const Input&>()));
    constexpr std::size_t block_size = std::size_t(1) << 15;

    tbb::enumerable_thread_specific<Worker> workers(worker);
    std::vector<Vertex> block;
    std::vector<Input> inputs;
    std::vector<Result> results;
    block.reserve(block_size);
    inputs.reserve(block_size);

    auto it = std::begin(vertices);
    const auto end = std::end(vertices);
    while (it != end) {
      block.clear();
      inputs.clear();
      for (; it != end && block.size() < block_size; ++it) {
        block.push_back(*it);
        inputs.push_back(worker.load(*it));
      }
      results.resize(block.size());
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, block.size(), 512),
                        [&](const tbb::blocked_range<std::size_t>& range) {
                          Worker& local = workers.local();
                          for (std::size_t i = range.begin(); i != range.end(); ++i)
                            results[i] = local.compute(block[i], inputs[i]);
                        });
      for (std::size_t i = 0; i < block.size(); ++i)
        store(block[i], results[i]);
    }
    return;
  }
#endif
  Worker local = worker;
  for (const auto& v : vertices)
    store(v, local.compute(v, local.load(v)));
}

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_FOR_EACH_VERTEX_H
