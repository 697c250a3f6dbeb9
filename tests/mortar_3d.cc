// The weighted gaps of a pair of bilinear faces in 3D
// (contact/mortar_3d.h), g_i = int N_i (x_m - x_s) . n dA on the clip
// triangles:
// - a master face parallel to the slave face at a distance delta, over
//   all of it or shifted by (0.3, 0.2): g_i = delta int N_i over the
//   overlap, in closed form, to 1e-15;
// - the linearisation: on a generic pair (tilted, warped, turned, partly
//   overlapping) the derivatives of the four gaps with respect to the 24
//   coordinates of the two faces, in AD numbers through the clip, the
//   points and their preimages, equal central differences (the exact
//   tangent the 3D Newton iteration will take).
#include <ring_contact/contact/mortar_3d.h>

#include "tests.h"

#include <cmath>
#include <iomanip>
#include <vector>

using namespace RingContact;
using namespace RingContact::Mortar3D;
using RingContactTests::check;

namespace
{
  using AD   = Sacado::Fad::DFad<double>;
  using Face = std::vector<Vector3<double>>;

  // The square [x0, x0 + 1] x [y0, y0 + 1] at height z, its nodes in the
  // basis' order; mirrored in xi_1 for a master face (normal down).
  Face
  square(const double x0, const double y0, const double z, const bool master)
  {
    if (master)
      return {{{x0 + 1, y0, z}},
              {{x0, y0, z}},
              {{x0 + 1, y0 + 1, z}},
              {{x0, y0 + 1, z}}};
    return {{{x0, y0, z}},
            {{x0 + 1, y0, z}},
            {{x0, y0 + 1, z}},
            {{x0 + 1, y0 + 1, z}}};
  }
} // namespace

int
main()
{
  auto &out = RingContactTests::deallog_file;
  out << std::setprecision(10) << std::fixed;

  // Parallel faces at a distance delta.
  const double delta = 0.01;
  {
    const auto g =
      weighted_gaps(square(0, 0, 0, false), square(0, 0, delta, true));
    double worst = 0;
    for (const double gi : g)
      worst = std::max(worst, std::abs(gi - delta / 4));
    check(worst < 1e-15, "facing squares: g_i = delta / 4");
    out << "facing squares at 0.01: g = " << g[0] << ", " << g[1] << ", "
        << g[2] << ", " << g[3] << std::endl;
  }
  {
    // Over [a, 1] x [b, 1]: int (1 - x) = (1 - a)^2 / 2, int x =
    // (1 - a^2) / 2, and the same in y.
    const double a = 0.3, b = 0.2;
    const double X[2] = {(1 - a) * (1 - a) / 2, (1 - a * a) / 2};
    const double Y[2] = {(1 - b) * (1 - b) / 2, (1 - b * b) / 2};
    const auto   g =
      weighted_gaps(square(0, 0, 0, false), square(a, b, delta, true));
    double worst = 0;
    for (unsigned int i = 0; i < 4; ++i)
      worst = std::max(worst, std::abs(g[i] - delta * X[i % 2] * Y[i / 2]));
    check(worst < 1e-15, "shifted squares: g_i = delta int N_i");
    out << "squares shifted by (0.3, 0.2): g = " << g[0] << ", " << g[1] << ", "
        << g[2] << ", " << g[3] << ", as delta int N_i over the overlap"
        << std::endl;
  }

  // The linearisation on a generic pair.
  {
    const Face               slave  = {{{0, 0, 0}},
                                       {{1.05, 0.02, 0.03}},
                                       {{-0.03, 0.98, -0.02}},
                                       {{1.0, 1.03, 0.04}}};
    Face                     master = {{{1.2, 0.1, 0.05}},
                                       {{0.25, 0.3, 0.02}},
                                       {{1.05, 1.1, 0.08}},
                                       {{0.1, 1.2, 0.01}}};
    std::vector<Vector3<AD>> s(4), m(4);
    for (unsigned int k = 0; k < 4; ++k)
      for (unsigned int d = 0; d < 3; ++d)
        {
          s[k][d] = AD(24, 3 * k + d, slave[k][d]);
          m[k][d] = AD(24, 12 + 3 * k + d, master[k][d]);
        }
    const auto   g     = weighted_gaps(s, m);
    const double h     = 1e-6;
    double       worst = 0, largest = 0;
    for (unsigned int k = 0; k < 24; ++k)
      {
        Face sp = slave, sm = slave, mp = master, mm = master;
        if (k < 12)
          {
            sp[k / 3][k % 3] += h;
            sm[k / 3][k % 3] -= h;
          }
        else
          {
            mp[(k - 12) / 3][k % 3] += h;
            mm[(k - 12) / 3][k % 3] -= h;
          }
        const auto up = weighted_gaps(sp, mp), down = weighted_gaps(sm, mm);
        for (unsigned int i = 0; i < 4; ++i)
          {
            const double fd = (up[i] - down[i]) / (2 * h);
            worst           = std::max(worst, std::abs(g[i].dx(k) - fd));
            largest         = std::max(largest, std::abs(fd));
          }
      }
    check(largest > 0.01 && worst < 1e-7 * largest,
          "the gaps' AD derivatives equal central differences");
    out << "a tilted, warped, turned pair: the AD derivatives of the four "
           "weighted gaps (24 variables) equal central differences to 1e-7"
        << std::endl;
  }
  return 0;
}
