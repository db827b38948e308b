// SPDX-License-Identifier: GPL-3.0-or-later
// Prim_front (internal/normal_orientation.h), the front of the orientation's Prim: it pops the edges that a
// queue of every edge offered pops, in the same order (ties included), skipping the points reached.
#include <CGAL/Curvature_estimation/internal/normal_orientation.h>

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
    Front front(n);
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
