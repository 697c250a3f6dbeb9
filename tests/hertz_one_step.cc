// The whole Hertz load in one step from bodies that touch, without
// friction: every scheme from an exact touch and from the shipped overlap,
// and steel on aluminium in finite strain (Saint Venant-Kirchhoff and
// neo-Hookean), linearised first. What each case shows and why:
// hertz_one_step.h.
#include "hertz_one_step.h"

int
main()
{
  for (const std::string touch : {"d0 = 0", "d0 = 2e-4"})
    for (const std::string scheme : {"nodal", "Gauss 2", "segment-based 2"})
      one_step(touch + ", " + scheme,
               "subsection Mesh\n set Geo parameters = h = 0.005, " + touch +
                 "\nend\nsubsection Contact\n set Integration schemes = " +
                 scheme + "\nend\n",
               6,
               false);
  for (const std::string kinematics : {"finite strain", "neo-Hookean"})
    for (const std::string scheme : {"nodal", "Gauss 2", "segment-based 2"})
      finite_strain_step(kinematics, scheme);
}
