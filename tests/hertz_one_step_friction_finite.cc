// The Hertz load from bodies that touch, with Coulomb friction in finite
// strain (Saint Venant-Kirchhoff, linearised first, mu = 0.2 and 0.5, every
// scheme): the first of four steps, and the whole load in one step at
// h = 0.005. What each case shows and why: hertz_one_step.h.
#include "hertz_one_step.h"

int
main()
{
  for (const std::string mu : {"0.2", "0.5"})
    for (const std::string scheme : {"nodal", "Gauss 2", "segment-based 2"})
      first_of_four(scheme, mu, "finite strain");
  for (const std::string mu : {"0.2", "0.5"})
    for (const std::string scheme : {"nodal", "Gauss 2", "segment-based 2"})
      frictional_step_in_finite_strain(scheme, mu);
}
