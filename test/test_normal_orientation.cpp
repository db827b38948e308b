// SPDX-License-Identifier: GPL-3.0-or-later
// The orientation of a point set's normals (internal/normal_orientation.h): Prim_front, the front of its Prim, pops the
// edges that a queue of every edge offered pops, in the same order (ties included), skipping the points reached; the
// trees grown in blocks are joined into one part, the same on any number of threads.
#include <CGAL/Curvature_estimation/internal/normal_orientation.h>

#include <CGAL/tags.h>

#include <gtest/gtest.h>

#include <queue>
#include <random>
#include <tuple>
#include <vector>

namespace CE = CGAL::Curvature_estimation;
using Front = CE::internal::Prim_front;

TEST(NormalOrientation, FrontPopsAsAQueueOfEveryEdge)
{
  std::mt19937 gen(3);
  const std::uint32_t n = 500;
  for (int run = 0; run < 20; ++run) {
    Front front(0, n);
    std::priority_queue<std::tuple<float, std::uint32_t, std::uint32_t>> queue;
    std::vector<char> reached(n, 0);
    const auto offer = [&](float agreement, std::uint32_t point, std::uint32_t from) {
      front.offer({agreement, point, from});
      queue.emplace(agreement, point, from);
    };
    offer(1.f, 0, 0);
    std::size_t pops = 0;
    while (!front.empty()) {
      const Front::Edge edge = front.pop();
      while (reached[std::get<1>(queue.top())])
        queue.pop();
      const auto [agreement, point, from] = queue.top();
      queue.pop();
      ASSERT_EQ(edge.agreement, agreement);
      ASSERT_EQ(edge.point, point);
      ASSERT_EQ(edge.from, from);
      reached[point] = 1;
      ++pops;
      // Eight edges to random points not reached; agreements on 4 levels, so that most tie.
      for (int e = 0; e < 8; ++e) {
        const std::uint32_t j = gen() % n;
        if (!reached[j])
          offer(float(gen() % 4) / 4.f, j, point);
      }
    }
    while (!queue.empty() && reached[std::get<1>(queue.top())])
      queue.pop();
    EXPECT_TRUE(queue.empty());
    EXPECT_GT(pops, n / 2);
  }
}

namespace {

// A side x side grid of the plane, rows of its 4 neighbors, normals +z or -z at random: every agreement is 1.
struct Grid
{
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector3f> normals;
  std::vector<std::uint32_t> rows;
};

Grid plane_grid(std::size_t side)
{
  constexpr std::uint32_t none = CE::internal::Normal_orientation::no_part;
  Grid g{{}, {}, std::vector<std::uint32_t>(side * side * 4, none)};
  std::mt19937 gen(9);
  for (std::size_t i = 0; i < side * side; ++i) {
    const std::size_t x = i % side, y = i / side;
    g.points.emplace_back(double(x), double(y), 0);
    g.normals.emplace_back(0.f, 0.f, gen() % 2 ? 1.f : -1.f);
    std::size_t k = 0;
    if (x + 1 < side)
      g.rows[i * 4 + k++] = std::uint32_t(i + 1);
    if (x > 0)
      g.rows[i * 4 + k++] = std::uint32_t(i - 1);
    if (y + 1 < side)
      g.rows[i * 4 + k++] = std::uint32_t(i + side);
    if (y > 0)
      g.rows[i * 4 + k++] = std::uint32_t(i - side);
  }
  return g;
}

template <typename ConcurrencyTag>
CE::internal::Normal_orientation orient(const Grid& g, std::vector<Eigen::Vector3f>& normals)
{
  normals = g.normals;
  return CE::internal::orient_normals<ConcurrencyTag>(g.points, normals, [&](std::size_t i, const auto& visit) {
    for (std::size_t k = 0; k < 4 && g.rows[i * 4 + k] != CE::internal::Normal_orientation::no_part; ++k)
      visit(g.rows[i * 4 + k]);
  });
}

} // namespace

// 360,000 points: the trees grow in several blocks, joined into one part with every normal on one side, the same bits
// on one thread and on several (every agreement ties).
TEST(NormalOrientation, BlocksJoinTheSameOnAnyNumberOfThreads)
{
  const Grid g = plane_grid(600);
  std::vector<Eigen::Vector3f> sequential, parallel;
  const auto a = orient<CGAL::Sequential_tag>(g, sequential);
  const auto b = orient<CGAL::Parallel_if_available_tag>(g, parallel);
  EXPECT_EQ(sequential, parallel);
  EXPECT_EQ(a.part, b.part);
  EXPECT_EQ(a.confidence, b.confidence);
  for (std::size_t i = 0; i < g.points.size(); ++i) {
    ASSERT_EQ(a.part[i], 0u) << i;
    ASSERT_EQ(sequential[i], sequential[0]) << i;
  }
}
