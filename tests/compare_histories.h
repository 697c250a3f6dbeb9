// Shared by the tests that solve a problem two ways (on two processes and
// on one, with a direct and with an iterative solver): the largest
// difference of two histories.
#ifndef ring_contact_compare_histories_h
#define ring_contact_compare_histories_h

#include <ring_contact/ring_contact_problem.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace RingContactTests
{
  using RingContact::HistoryRow;

  // The largest difference of two histories, relative to the scale of
  // each quantity; -1 if the steps or the Newton iterations differ.
  inline double
  difference(const std::vector<HistoryRow> &a, const std::vector<HistoryRow> &b)
  {
    if (a.size() != b.size())
      return -1;
    double              pressure_scale = 0;
    std::vector<double> quantity_scale(a.empty() ? 0 : a[0].quantities.size());
    for (const auto &row : a)
      {
        pressure_scale =
          std::max({pressure_scale,
                    std::isfinite(row.analytic) ? std::abs(row.analytic) : 0.,
                    std::abs(row.pressure_max)});
        for (unsigned int k = 0; k < quantity_scale.size(); ++k)
          quantity_scale[k] =
            std::max(quantity_scale[k], std::abs(row.quantities[k]));
      }
    double d = 0;
    for (unsigned int i = 0; i < a.size(); ++i)
      {
        if (a[i].step != b[i].step ||
            a[i].newton_iterations != b[i].newton_iterations ||
            a[i].active_nodes != b[i].active_nodes)
          return -1;
        for (const auto &[x, y] :
             {std::make_pair(a[i].pressure_A, b[i].pressure_A),
              std::make_pair(a[i].pressure_min, b[i].pressure_min),
              std::make_pair(a[i].pressure_max, b[i].pressure_max)})
          d = std::max(d, std::abs(x - y) / pressure_scale);
        if (std::isfinite(a[i].l2_relative_error))
          d =
            std::max(d,
                     std::abs(a[i].l2_relative_error - b[i].l2_relative_error));
        for (unsigned int k = 0; k < quantity_scale.size(); ++k)
          d = std::max(d,
                       std::abs(a[i].quantities[k] - b[i].quantities[k]) /
                         std::max(quantity_scale[k], 1e-300));
      }
    return d;
  }

} // namespace RingContactTests

#endif
