// SPDX-License-Identifier: GPL-3.0-or-later
// Point_set_search (internal/point_set_search.h), the neighbors of the point-set estimator: against brute force,
// on random points and on a grid, where most distances tie; and the points that are not finite, never neighbors.
#include <CGAL/Curvature_estimation/internal/point_set_search.h>

#include <gtest/gtest.h>

#include "random_numbers.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <tuple>
#include <vector>

namespace CE = CGAL::Curvature_estimation;
using Search = CE::internal::Point_set_search;

// The k nearest of the search are the k nearest by brute force, ties by position, then index (CGAL's radius query
// with a cap would not give them), and the points within a radius all of them, in the same order: on random points,
// on a grid, where most distances tie, with copies of points, which tie at 0, and with distances that overflow.
TEST(PointSetSearch, NearestNeighborsAreTheTrueNearest)
{
  std::mt19937 gen(17);
  std::vector<Eigen::Vector3d> random, grid;
  for (int i = 0; i < 3000; ++i)
    random.emplace_back(ce_test::uniform_symmetric(gen), ce_test::uniform_symmetric(gen),
                        0.3 * ce_test::uniform_symmetric(gen));
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 40; ++j)
      grid.emplace_back(0.1 * i, 0.1 * j, 0.);
  // Copies: 600 of the origin and 100 of another point among random ones, whose queries tie at 0.
  std::vector<Eigen::Vector3d> copies(random.begin(), random.begin() + 500);
  copies.insert(copies.begin() + 100, 600, Eigen::Vector3d::Zero());
  copies.insert(copies.end(), 100, random[7]);
  // Coordinates near 1e200, whose squared distances overflow to infinity: every distance ties.
  std::vector<Eigen::Vector3d> huge;
  for (std::size_t i = 0; i < 300; ++i)
    huge.push_back(1e200 * random[i]);
  for (const auto* points : {&random, &grid, &copies, &huge}) {
    const Search search(*points, CGAL::Sequential_tag());
    Search::Found found;
    for (std::size_t j = 0; j < points->size(); j += 7)
      for (std::size_t k : {16u, 64u}) {
        search.nearest(Search::Index(j), k, found);
        Search::Found brute;
        for (std::size_t m = 0; m < points->size(); ++m)
          if (m != j)
            brute.emplace_back((search.point(m) - search.point(j)).squaredNorm(), Search::Index(m));
        std::sort(brute.begin(), brute.end(), [&](const auto& a, const auto& b) {
          const Eigen::Vector3d &p = search.point(a.second), &q = search.point(b.second);
          return std::make_tuple(a.first, p.x(), p.y(), p.z(), a.second) <
                 std::make_tuple(b.first, q.x(), q.y(), q.z(), b.second);
        });
        ASSERT_EQ(found.size(), k);
        for (std::size_t m = 0; m < k; ++m)
          ASSERT_EQ(found[m].second, brute[m].second) << "point " << j << ", neighbor " << m;
        const double radius = std::sqrt(brute[k - 1].first);
        const std::size_t inside = std::size_t(
          std::count_if(brute.begin(), brute.end(), [&](const auto& b) { return b.first <= radius * radius; }));
        search.within(Search::Index(j), radius, found);
        ASSERT_EQ(found.size(), inside) << j;
        for (std::size_t m = 0; m < inside; ++m)
          ASSERT_EQ(found[m].second, brute[m].second) << "point " << j << ", neighbor " << m;
      }
  }
}

// A part of the set (a tile) finds the neighbors that the whole set finds, in the same order, where they are all
// in the part: on a grid, where most distances tie, and whose Morton order differs between the part and the whole.
TEST(PointSetSearch, APartFindsTheNeighborsOfTheWhole)
{
  std::vector<Eigen::Vector3d> whole, part;
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 40; ++j) {
      whole.emplace_back(0.1 * i, 0.1 * j, 0.);
      if (i >= 5 && j < 23)
        part.push_back(whole.back());
    }
  const Search all(whole, CGAL::Sequential_tag()), tile(part, CGAL::Sequential_tag());
  const auto positions = [](const Search& search, const Search::Found& found) {
    std::vector<Eigen::Vector3d> p;
    for (const auto& f : found)
      p.push_back(search.point(f.second));
    return p;
  };
  std::size_t compared = 0;
  for (Search::Index t = 0; t < tile.size(); ++t) {
    const Eigen::Vector3d& q = tile.point(t);
    Search::Index w = 0;
    while (all.point(w) != q)
      ++w;
    Search::Found in_whole, in_tile;
    for (std::size_t k : {12u, 30u}) {
      all.nearest(w, k, in_whole);
      // Complete in the tile: nearer to every point of the tile than to its cut (x = 0.45, y = 2.25).
      if (std::sqrt(in_whole.back().first) >= (std::min)(q.x() - 0.45, 2.25 - q.y()))
        continue;
      tile.nearest(t, k, in_tile);
      ASSERT_EQ(positions(all, in_whole), positions(tile, in_tile)) << t;
      const double radius = std::sqrt(in_whole.back().first);
      all.within(w, radius, in_whole);
      tile.within(t, radius, in_tile);
      ASSERT_EQ(positions(all, in_whole), positions(tile, in_tile)) << t;
      ++compared;
    }
  }
  EXPECT_GT(compared, tile.size());
}

// A non-finite point is no one's neighbor and has none; the others are found as without it.
TEST(PointSetSearch, NonFinitePointsAreNoNeighbors)
{
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j)
      points.emplace_back(i, j, 0.5 * ((i * j) % 3));
  std::vector<Eigen::Vector3d> with = points;
  with.emplace_back(std::numeric_limits<double>::quiet_NaN(), 0., 0.);
  with.emplace_back(4.5, std::numeric_limits<double>::infinity(), 0.);
  const Search search(points, CGAL::Sequential_tag()), searched(with, CGAL::Sequential_tag());
  ASSERT_EQ(searched.size(), with.size());
  ASSERT_EQ(searched.finite_size(), points.size());
  Search::Found found, expected;
  for (Search::Index i = 0; i < searched.size(); ++i) {
    searched.nearest(i, 8, found);
    if (i >= searched.finite_size()) {
      EXPECT_TRUE(found.empty()) << i;
      searched.within(i, 1e300, found);
      EXPECT_TRUE(found.empty()) << i;
      continue;
    }
    // The same point in `search`: the finite points are in the same order in both.
    ASSERT_EQ(searched.original(i), search.original(i));
    search.nearest(i, 8, expected);
    EXPECT_EQ(found, expected) << i;
    searched.within(i, 1e300, found);
    EXPECT_EQ(found.size(), points.size() - 1) << i;
  }
}
