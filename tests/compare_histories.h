// Shared by the tests that solve a problem two ways (on two processes and
// on one, with a direct and with an iterative solver): the largest
// difference of two histories.
#ifndef ring_contact_compare_histories_h
#define ring_contact_compare_histories_h

#include <ring_contact/problem/contact_problem.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace RingContactTests
{
  using RingContact::HistoryRow;

  // The largest difference of two histories, relative to the scale of
  // each column (the pressures share theirs, the relative errors are
  // compared as they are); -1 if the steps, the Newton iterations, the
  // active nodes or the columns differ.
  inline double
  difference(const std::vector<HistoryRow> &a, const std::vector<HistoryRow> &b)
  {
    if (a.size() != b.size())
      return -1;
    if (a.empty())
      return 0;
    const auto is_pressure = [](const std::string &column) {
      return column == "pressure_A" || column == "pressure_min" ||
             column == "pressure_max" || column == "analytic";
    };
    const auto is_relative = [](const std::string &column) {
      return column == "relative_error" || column == "l2_relative_error";
    };
    std::vector<std::string> columns;
    for (const auto *list : {&a[0].leading, &a[0].trailing})
      for (const auto &[column, value] : *list)
        columns.push_back(column);

    // The scale of each column over the first history.
    std::map<std::string, double> scale;
    double                        pressure_scale = 0;
    for (const auto &row : a)
      for (const auto &column : columns)
        {
          const double v = std::abs(row.value(column));
          if (!std::isfinite(v))
            continue;
          if (is_pressure(column))
            pressure_scale = std::max(pressure_scale, v);
          else
            scale[column] = std::max(scale[column], v);
        }

    double d = 0;
    for (unsigned int i = 0; i < a.size(); ++i)
      {
        if (a[i].step != b[i].step ||
            a[i].newton_iterations != b[i].newton_iterations ||
            a[i].active_nodes != b[i].active_nodes)
          return -1;
        for (const auto &column : columns)
          {
            if (!b[i].has(column))
              return -1;
            const double x = a[i].value(column), y = b[i].value(column);
            if (!std::isfinite(x) && !std::isfinite(y))
              continue;
            const double s = is_relative(column) ? 1.0 :
                             is_pressure(column) ? pressure_scale :
                                                   scale[column];
            d = std::max(d, std::abs(x - y) / std::max(s, 1e-300));
          }
      }
    return d;
  }

} // namespace RingContactTests

#endif
