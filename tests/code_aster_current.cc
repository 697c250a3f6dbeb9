// An independent computation, the current one: since 2021 Code_Aster runs
// SSNP152 A, C and D with logarithmic strains (DEFORMATION = 'GDEF_LOG',
// an elastic VMIS_ISOT_LINE: Hencky) and prints other values than the
// GROT_GDEP ones of code_aster_comparison (up to 2.5 % apart). With
// Materials/Kinematics = logarithmic strain and the original's contact
// choices (smoothed master normals, LISSAGE = OUI; nodal and Gauss
// integration; the nominal pressure, its LAGS_C), the program reproduces
// the VALE_CALC of TEST_RESU in the public ssnp152a.comm, ssnp152c.comm and
// ssnp152d.comm of the current version (LAGS_C at node N10, i.e. node A):
// A at steps 1, 5, 10, 15 and 21 with nodal and 3-point Gauss integration;
// C and D at s = 1, where the current files turn the inner ring through one
// element in 10 steps (p = 1e7 from the first), with nodal and 2-point
// Gauss integration. Asserted to 1e-7 (the issue asks 1e-5).
#include "code_aster.h"

namespace
{
  std::vector<double>
  pressures(const char         letter,
            const std::string &scheme,
            const std::string &extra)
  {
    return RingContactTests::pressures_at_A(
      letter,
      scheme,
      "subsection Materials\n set Material law = Hencky\nend\n" +
        extra);
  }

  void
  compare(const std::string                                  &what,
          const std::vector<double>                          &ours,
          const std::vector<std::pair<unsigned int, double>> &aster)
  {
    RingContactTests::compare_with_code_aster(
      "the current Code_Aster", what, ours, aster, 1e-7);
  }
} // namespace

int
main()
{
  // ssnp152a.comm: RESU1 (INTEGRATION = AUTO: nodal) and RESU2 (GAUSS).
  compare("A, nodal",
          pressures('a', "nodal", ""),
          {{1, 91970.88643542175},
           {5, 231062.07978232342},
           {10, 731156.0766568179},
           {15, 2316866.9425789905},
           {21, 9306899.915319547}});
  compare("A, Gauss 3",
          pressures('a', "Gauss 3", ""),
          {{1, 92160.22745993559},
           {5, 231537.76869670523},
           {10, 732661.312134766},
           {15, 2321636.6906968807},
           {21, 9326060.086987112}});

  // ssnp152c.comm and ssnp152d.comm: one element of rotation in 10 steps,
  // step 10 (GAUSS with ORDRE_INT = 2).
  const std::string ten_steps =
    "subsection Load program\n set Rotation steps = 10\nend\n";
  compare("C, nodal",
          pressures('c', "nodal", ten_steps),
          {{10, 9306900.061031366}});
  compare("C, Gauss 2",
          pressures('c', "Gauss 2", ten_steps),
          {{10, 9326056.127025047}});
  compare("D, nodal",
          pressures('d', "nodal", ten_steps),
          {{10, 2457910.1009857887}});
  compare("D, Gauss 2",
          pressures('d', "Gauss 2", ten_steps),
          {{10, 2462969.0126585956}});
}
