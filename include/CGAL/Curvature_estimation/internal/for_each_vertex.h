// SPDX-License-Identifier: GPL-3.0-or-later
// The vertex loop shared by the estimators, and a plain index loop: sequential, or
// TBB-parallel in blocks.
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_FOR_EACH_VERTEX_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_FOR_EACH_VERTEX_H

#include <CGAL/Surface_mesh/Properties.h>
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

// Whether `get` and `put` on distinct keys of a property map may run on several
// threads at once. Known to be so only for the property maps of Surface_mesh and
// Point_set_3, which read and write a vector slot per index (except for bool,
// whose vector packs bits). Other maps, even lvalue ones, may insert on access
// (boost::associative_property_map, CGAL's dynamic maps of Polyhedron_3).
template <typename Map, typename = void>
struct Accessible_concurrently : std::false_type
{};

template <typename Map>
struct Accessible_concurrently<
  Map, std::enable_if_t<std::is_base_of<
         CGAL::Properties::Property_map_base<typename Map::key_type, typename Map::value_type, Map>, Map>::value>>
    : std::bool_constant<!std::is_same<typename Map::value_type, bool>::value>
{};

template <typename Map>
constexpr bool accessible_concurrently()
{
  return Accessible_concurrently<std::remove_cv_t<std::remove_reference_t<Map>>>::value;
}

// A Worker is copyable (one copy per thread) and has `Input load(vertex) const`
// (the user's input maps) and `Result compute(vertex, const Input&)` (touching no
// map but the vertex point map); store(vertex, result) writes the outputs. load
// and store run on the calling thread unless `concurrent_maps`. In parallel,
// vertices go in blocks of fixed size: extra memory O(block + threads x neighborhood).
template <typename ConcurrencyTag, bool concurrent_maps = false, typename VertexRange, typename Worker, typename Store>
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
    block.reserve(block_size);
    // body(worker, i) for every i of the block, on the worker threads.
    auto for_block = [&](auto body) {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, block.size(), 512),
                        [&](const tbb::blocked_range<std::size_t>& range) {
                          Worker& local = workers.local();
                          for (std::size_t i = range.begin(); i != range.end(); ++i)
                            body(local, i);
                        });
    };

    auto it = std::begin(vertices);
    const auto end = std::end(vertices);
    if constexpr (concurrent_maps) {
      // All on the worker threads: the calling thread only lists the block.
      while (it != end) {
        block.clear();
        for (; it != end && block.size() < block_size; ++it)
          block.push_back(*it);
        for_block(
          [&](Worker& local, std::size_t i) { store(block[i], local.compute(block[i], local.load(block[i]))); });
      }
    } else {
      std::vector<Input> inputs;
      std::vector<Result> results;
      inputs.reserve(block_size);
      while (it != end) {
        block.clear();
        inputs.clear();
        for (; it != end && block.size() < block_size; ++it) {
          block.push_back(*it);
          inputs.push_back(worker.load(*it));
        }
        results.resize(block.size());
        for_block([&](Worker& local, std::size_t i) { results[i] = local.compute(block[i], inputs[i]); });
        for (std::size_t i = 0; i < block.size(); ++i)
          store(block[i], results[i]);
      }
    }
    return;
  }
#endif
  Worker local = worker;
  for (const auto& v : vertices)
    store(v, local.compute(v, local.load(v)));
}

// body(i) for every i in [0, n): in order, or on TBB's threads in blocks (body
// touches no property map).
template <typename ConcurrencyTag, typename Body>
void for_each_index(std::size_t n, const Body& body)
{
#ifndef CGAL_LINKED_WITH_TBB
  static_assert(!std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value,
                "Parallel_tag is enabled but TBB is unavailable.");
#else
  if constexpr (std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n), [&](const tbb::blocked_range<std::size_t>& range) {
      for (std::size_t i = range.begin(); i != range.end(); ++i)
        body(i);
    });
    return;
  }
#endif
  for (std::size_t i = 0; i < n; ++i)
    body(i);
}

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_FOR_EACH_VERTEX_H
