// The whole Hertz load in one step from bodies that touch, with Coulomb
// friction in small strain: steel on aluminium at mu = 0.2 and 0.5 with
// every scheme, and the first of four steps at h = 0.01, mu = 0.2. What
// each case shows and why: hertz_one_step.h.
#include "hertz_one_step.h"

int
main()
{
  for (const std::string mu : {"0.2", "0.5"})
    for (const std::string scheme : {"nodal", "Gauss 2", "segment-based 2"})
      one_step("steel on aluminium, d0 = 0, mu = " + mu + ", " + scheme,
               steel_on_aluminium() +
                 "subsection Contact\n set Integration schemes = " + scheme +
                 "\n set Friction coefficient = " + mu + "\nend\n",
               10,
               true);
  for (const std::string scheme : {"nodal", "Gauss 2", "segment-based 2"})
    first_of_four(scheme, "0.2");
}
