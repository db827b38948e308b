// SPDX-License-Identifier: GPL-3.0-or-later
// The neighborhood of a vertex in a ball about it, grown with the radius, and
// the growth of the balls of the fits over a ball.
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_BALL_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_BALL_H

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// The ball of a vertex in its mesh, for the collectors below: the vertices inside
// the ball of a given radius about the center that are joined to it by edges
// inside the ball (the connected part of the mesh in the ball, so that the other
// side of a thin part is not taken), grown with the radius.
template <typename Vertex>
class Ball
{
public:
  void clear() { active_ = false; }
  // Whether grow has been called since clear.
  bool active() const { return active_; }

  // Grows the ball to `squared_radius` in `vertices`, the collector's gathered
  // vertices (the center, then the 1-ring up to `one_ring_end`, kept whole), to
  // which the vertices of the ball met beyond are appended: then the ball is the
  // vertices i with inside(i). neighbors(v, visit) visits v's neighbors, reach(w)
  // marks w as met (false where it was), squared_distance(w) to the center (NaN:
  // never inside). Returns whether vertices joined to the ball are left outside it.
  template <typename Neighbors, typename Reach, typename SquaredDistance>
  bool grow(std::vector<Vertex>& vertices, std::size_t one_ring_end, double squared_radius, const Neighbors& neighbors,
            const Reach& reach, const SquaredDistance& squared_distance)
  {
    to_expand_.clear();
    if (!active_) {
      active_ = true;
      outside_.clear();
      inside_.assign(vertices.size(), 0);
      joined_.clear();
      add(vertices, 0);
      for (std::size_t i = 1; i < one_ring_end; ++i) {
        const double d = squared_distance(vertices[i]);
        if (d <= squared_radius)
          add(vertices, i);
        else
          outside_.push_back({vertices[i], d, i});
      }
    } else {
      std::size_t kept = 0;
      for (const Outside& o : outside_)
        if (o.squared_distance <= squared_radius)
          add(vertices, o.index, o.vertex);
        else
          outside_[kept++] = o;
      outside_.resize(kept);
    }
    while (!to_expand_.empty()) {
      const Vertex v = to_expand_.back();
      to_expand_.pop_back();
      neighbors(v, [&](const Vertex& w) {
        if (!reach(w))
          return;
        const double d = squared_distance(w);
        if (d <= squared_radius)
          add(vertices, not_gathered, w);
        else
          outside_.push_back({w, d, not_gathered});
      });
    }
    return !outside_.empty();
  }

  bool inside(std::size_t i) const { return inside_[i] != 0; }
  std::size_t size() const { return joined_.size(); }
  // The place in the vertices of the k-th vertex to join the ball (k < size()):
  // those of a smaller ball join first.
  std::size_t joined(std::size_t k) const { return joined_[k]; }
  // Whether w was met next to the ball but outside it.
  bool met_outside(const Vertex& w) const
  {
    for (const Outside& o : outside_)
      if (o.vertex == w)
        return true;
    return false;
  }

private:
  static constexpr std::size_t not_gathered = std::size_t(-1);

  // Puts vertices[index] in the ball, or where not gathered, w appended to them.
  void add(std::vector<Vertex>& vertices, std::size_t index, const Vertex& w = Vertex())
  {
    if (index == not_gathered) {
      index = vertices.size();
      vertices.push_back(w);
      inside_.push_back(0);
    }
    inside_[index] = 1;
    to_expand_.push_back(vertices[index]);
    joined_.push_back(index);
  }

  // A vertex met next to the ball but outside it; index: where gathered (the
  // 1-ring), its place in the vertices.
  struct Outside
  {
    Vertex vertex;
    double squared_distance;
    std::size_t index;
  };
  bool active_ = false;
  std::vector<char> inside_;        // per gathered vertex
  std::vector<std::size_t> joined_; // the vertices in the ball, in the order they joined
  std::vector<Outside> outside_;
  std::vector<Vertex> to_expand_; // in the ball, their neighbors still to be met
};

// The growth of the balls of the fits over a ball: from `radius`, by the factor
// ball_growth until the ball holds twice the fit's `unknowns` vertices, then,
// while accepted() refuses its fit, up to ball_growth_for_conditioning times that
// radius. grow(radius) gathers the ball of that radius and returns whether
// vertices are left outside it; size() is its number of vertices. Returns 1 plus
// the number of growths, 0 where no ball was accepted.
constexpr double ball_growth = 1.25;
constexpr double ball_growth_for_conditioning = 2;

template <typename Grow, typename Size, typename Accepted>
int fit_in_growing_ball(double radius, int unknowns, const Grow& grow, const Size& size, const Accepted& accepted)
{
  int growths = 0;
  bool more = grow(radius);
  const auto grow_once = [&] {
    radius *= ball_growth;
    ++growths;
    more = grow(radius);
  };
  while (size() < std::size_t(2 * unknowns) && more)
    grow_once();
  const double widest = ball_growth_for_conditioning * radius * (1 + 1e-9);
  while (!(size() >= std::size_t(unknowns) && accepted())) {
    if (!more || radius * ball_growth > widest)
      return 0;
    grow_once();
  }
  return growths + 1;
}

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_BALL_H
