// Newton/Extrapolate in a general problem: each step starts from the linear
// extrapolation of the last two converged states in the pseudo-time, in
// which the problem's boundary data are written. The predictor keyed on the
// rings' pressure and rotation only, and a general problem's load states
// carry neither: it never extrapolated (the same Newton iterations with
// Extrapolate = true and false).
// - The patch test of two blocks (prm/two_blocks.prm, small strain, four
//   steps): the solution is linear in t, so the extrapolation is exact and
//   steps 2 to 4 take no Newton iteration (one each without it).
// - Hertz (prm/hertz.prm, h = 0.02, eight steps, Gauss 2): fewer
//   iterations in all, 15 against 21 (the second step, after one from
//   rest, scaled as the square root of the load: 1 iteration, 3 linearly
//   extrapolated).
#include "run_problem.h"

using RingContactTests::check;
using RingContactTests::run_problem;

namespace
{
  std::vector<unsigned int>
  iterations(const std::string &name,
             const std::string &base,
             const std::string &extra,
             const bool         extrapolate)
  {
    const auto history =
      run_problem(name,
                  "include " RING_CONTACT_SOURCE_DIR "/prm/" + base + ".prm\n" +
                    "subsection Mesh\n set Mesh file = " RING_CONTACT_SOURCE_DIR
                    "/meshes/" +
                    base + ".geo\nend\n" + extra +
                    "subsection Newton\n set Extrapolate = " +
                    (extrapolate ? "true" : "false") + "\nend\n");
    std::vector<unsigned int> n;
    for (const auto &row : history)
      n.push_back(row.newton_iterations);
    return n;
  }

  std::string
  text(const std::vector<unsigned int> &n)
  {
    std::string t;
    for (const unsigned int k : n)
      t += (t.empty() ? "" : " ") + std::to_string(k);
    return t;
  }
} // namespace

int
main()
{
  auto &out = RingContactTests::deallog_file;

  const std::string four_steps =
    "subsection Load program\n set Time points = 0.25, 0.5, 0.75, 1\nend\n";
  const auto blocks_on  = iterations("blocks", "two_blocks", four_steps, true);
  const auto blocks_off = iterations("blocks", "two_blocks", four_steps, false);
  out << "two blocks, Newton iterations per step: " << text(blocks_on)
      << " extrapolated, " << text(blocks_off) << " not" << std::endl;
  check(blocks_on == std::vector<unsigned int>({1, 0, 0, 0}),
        "the extrapolation of a linear problem is exact");
  check(blocks_off == std::vector<unsigned int>({1, 1, 1, 1}),
        "without it, one iteration per step");

  const std::string hertz =
    "subsection Mesh\n set Geo parameters = h = 0.02\nend\n"
    "subsection Contact\n set Integration schemes = Gauss 2\nend\n"
    "subsection Load program\n set Number of steps = 8\nend\n";
  const auto   hertz_on  = iterations("hertz", "hertz", hertz, true);
  const auto   hertz_off = iterations("hertz", "hertz", hertz, false);
  unsigned int sum_on = 0, sum_off = 0;
  for (const unsigned int k : hertz_on)
    sum_on += k;
  for (const unsigned int k : hertz_off)
    sum_off += k;
  out << "Hertz, Newton iterations per step: " << text(hertz_on)
      << " extrapolated (" << sum_on << "), " << text(hertz_off) << " not ("
      << sum_off << ")" << std::endl;
  check(sum_on < sum_off, "fewer iterations with the extrapolation");
}
