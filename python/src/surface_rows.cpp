// SPDX-License-Identifier: GPL-3.0-or-later
#include "surface_rows.h"

namespace ce_python {

ce_tool::Soup soup_of(const double* xyz, std::size_t n, const std::size_t* indices, std::size_t m, std::size_t k)
{
  ce_tool::Soup soup;
  soup.points.reserve(n);
  for (std::size_t i = 0; i < n; ++i)
    soup.points.emplace_back(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
  soup.faces.reserve(m, m * k);
  for (std::size_t f = 0; f < m; ++f) {
    for (std::size_t c = 0; c < k; ++c)
      soup.faces.add_index(indices[f * k + c]);
    soup.faces.end_polygon();
  }
  return soup;
}

void write_rows(const ce_tool::Surface_estimates& rows, const Surface_outputs& out)
{
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const ce_tool::Row r = rows[i];
    out.k_max[i] = r.k_max;
    out.k_min[i] = r.k_min;
    out.mean[i] = r.mean;
    out.gaussian[i] = r.gaussian;
    for (std::size_t c = 0; c < 3; ++c) {
      out.d_max[3 * i + c] = r.d_max[c];
      out.d_min[3 * i + c] = r.d_min[c];
    }
    out.status[i] = static_cast<std::uint8_t>(r.status);
    if (out.radius != nullptr) {
      const auto [radius, noise] = rows.radius_and_noise(i);
      out.radius[i] = radius;
      out.noise[i] = noise;
    }
    if (out.reach != nullptr)
      out.reach[i] = rows.reach(i);
  }
}

} // namespace ce_python
