// @sect3{Diagnostics: stiffnesses too far apart for double precision}
//
// What is measured and why is in stiffness_spread.h. The bound comes from
// the two blocks of prm/two_blocks.prm made stiffer or thinner
// (doc/validation.md, "Stiffnesses too far apart for double precision"):
// there the direct solve's relative residual grows as eps S and exceeds its
// bound of 1e-6 where S is large enough, and the run stopped with "a body may
// be free to move rigidly", the advice for a singular tangent. The refusal at
// eps S = 1e-7 (S = 4.5e8) keeps a margin below that, for meshes whose
// round-off sums over more cells.
#include <ring_contact/base/dimension.h>
#include <ring_contact/diagnostics/stiffness_spread.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace RingContact
{
  namespace Diagnostics
  {
    namespace
    {
      constexpr double eps = std::numeric_limits<double>::epsilon();
    } // namespace

    bool
    StiffnessSpread::exceeds(const double fraction) const
    {
      return eps * factor > fraction;
    }

    std::string
    StiffnessSpread::describe() const
    {
      std::ostringstream text;
      text << std::setprecision(3) << "the cells' stiffnesses (Young's "
           << "modulus times a cell's length over its thickness) differ by "
           << "a factor " << factor << " (" << causes
           << "), and round-off leaves the forces about " << eps * factor
           << " of the load";
      return text.str();
    }

    // Round-off within a factor 100 of the solve's bound (eps S > 1e-8;
    // past 1e-7 the run was refused) may explain a residual the solve
    // cannot reduce: named first. The free body's words are those the
    // tests and doc/user-guide.md quote.
    std::string
    StiffnessSpread::singular_tangent_advice() const
    {
      const std::string free_body =
        "a body may be free to move rigidly (check that its supports, and "
        "the contact, hold it in every direction)";
      return exceeds(1e-8) ? describe() + "; or " + free_body : free_body;
    }

    // One pass over the cells: the stiffest (E a largest) and the softest
    // body (E smallest). A cell's thickness is its area over its longest
    // edge, so a square has a = 1 and a cell L long and h thick a = L / h.
    StiffnessSpread
    stiffness_spread(const Triangulation<dim>     &triangulation,
                     const std::vector<Body<dim>> &bodies)
    {
      const auto body_of = [&bodies](const types::material_id id) {
        return std::find_if(bodies.begin(),
                            bodies.end(),
                            [id](const Body<dim> &b) {
                              return b.material_id == id;
                            });
      };
      double stiffest = 0, softest = std::numeric_limits<double>::max();
      double aspect = 1, length = 0, thickness = 0;
      const Body<dim> *stiff_body = nullptr, *soft_body = nullptr;
      for (const auto &cell : triangulation.active_cell_iterators())
        {
          const auto body = body_of(cell->material_id());
          if (body == bodies.end())
            continue;
          double longest = 0;
          for (const unsigned int f : cell->face_indices())
            longest = std::max(longest, cell->face(f)->measure());
          const double area = cell->measure();
          const double a    = area > 0 ? longest * longest / area : 1.0;
          const double E    = body->material.youngs_modulus;
          if (E * a > stiffest)
            {
              stiffest   = E * a;
              aspect     = a;
              length     = longest;
              thickness  = area / longest;
              stiff_body = &*body;
            }
          if (E < softest)
            {
              softest   = E;
              soft_body = &*body;
            }
        }
      StiffnessSpread spread;
      if (stiff_body == nullptr)
        return spread;
      spread.factor = stiffest / softest;
      std::ostringstream causes;
      causes << std::setprecision(3) << stiff_body->name << " (material "
             << stiff_body->material_id
             << "), E = " << stiff_body->material.youngs_modulus;
      // A cell's shape is named only where it is a cause: a ratio of a few
      // is any mesh's.
      if (aspect > 10)
        causes << ", has cells " << aspect << " times longer than thick, "
               << length << " by " << thickness;
      causes << "; " << soft_body->name << " (material "
             << soft_body->material_id << "), E = " << softest;
      spread.causes = causes.str();
      // Refused where the solve cannot succeed (see the file's head): one
      // line, before anything is solved, with the two remedies.
      if (spread.exceeds(1e-7))
        {
          std::ostringstream message;
          message << std::setprecision(3)
                  << "the bodies' stiffnesses are too far apart for double "
                     "precision: "
                  << spread.describe()
                  << ", where the direct solve, whose residual is about six "
                     "times that, needs below 1e-6 (a factor below "
                  << 1e-7 / eps
                  << "): impose the displacement of a body much stiffer "
                     "than the others, and mesh a thin body with more cells "
                     "along it";
          throw std::runtime_error(message.str());
        }
      return spread;
    }
  } // namespace Diagnostics
} // namespace RingContact
