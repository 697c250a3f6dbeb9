// An independent computation: the values the original Code_Aster test
// reports (VALE_CALC of TEST_RESU in the public ssnp152a.comm and
// ssnp152c.comm: LAGS_C at node N10, i.e. node A). With the same choices as
// those inputs (smoothed master normals, LISSAGE = OUI; nodal and Gauss
// integration; finite strain, GROT_GDEP), and reporting the pressure per
// reference length (the original's multiplier is a nominal pressure), the
// program reproduces them to the 9 digits they are printed with: A and B
// (plane stress and plane strain, ssnp152b.comm of the same version) within
// 1e-8, C at s = 1 within 1e-7. D, E-H print no value in that version (E-H
// would differ anyway: 8-node elements and straight interior edges there).
#include "code_aster.h"

namespace
{
  std::vector<double>
  pressures(const std::string &modelisation, const std::string &scheme)
  {
    return RingContactTests::pressures_at_A(modelisation.back(), scheme);
  }

  void
  compare(const std::string                                  &what,
          const std::vector<double>                          &ours,
          const std::vector<std::pair<unsigned int, double>> &aster,
          const double                                        tolerance)
  {
    RingContactTests::compare_with_code_aster(
      "Code_Aster", what, ours, aster, tolerance);
  }
} // namespace

int
main()
{
  // ssnp152a.comm, RESU1 (nodal) and RESU2 (Gauss), steps 1 to 21.
  const std::vector<double> a_nodal = {
    9.19489592E+04, 1.15753309E+05, 1.45719119E+05, 1.83440528E+05,
    2.30923720E+05, 2.90693200E+05, 3.65925335E+05, 4.60616091E+05,
    5.79791587E+05, 7.29772188E+05, 9.18503450E+05, 1.15597031E+06,
    1.45471468E+06, 1.83048090E+06, 2.30301873E+06, 2.89707887E+06,
    3.64364217E+06, 4.58142879E+06, 5.75873791E+06, 7.23566853E+06,
    9.08676545E+06};
  const std::vector<double> a_gauss = {
    9.21382551E+04, 1.15991611E+05, 1.46019112E+05, 1.83818178E+05,
    2.31399124E+05, 2.91291652E+05, 3.66678667E+05, 4.61564364E+05,
    5.80985208E+05, 7.31274574E+05, 9.20394379E+05, 1.15835012E+06,
    1.45770951E+06, 1.83424932E+06, 2.30775996E+06, 2.90304310E+06,
    3.65114335E+06, 4.59086061E+06, 5.77059346E+06, 7.25056464E+06,
    9.10547242E+06};
  const auto steps = [](const std::vector<double> &values) {
    std::vector<std::pair<unsigned int, double>> s;
    for (unsigned int k = 0; k < values.size(); ++k)
      s.emplace_back(k + 1, values[k]);
    return s;
  };
  compare("A, nodal", pressures("ssnp152a", "nodal"), steps(a_nodal), 1e-8);
  compare("A, Gauss 3", pressures("ssnp152a", "Gauss 3"), steps(a_gauss), 1e-8);

  // ssnp152b.comm (plane strain), RESU1 (nodal) and RESU2 (Gauss).
  const std::vector<double> b_nodal = {
    9.19352266E+04, 1.15736368E+05, 1.45698344E+05, 1.83415248E+05,
    2.30893280E+05, 2.90657072E+05, 3.65883332E+05, 4.60568727E+05,
    5.79740695E+05, 7.29721964E+05, 9.18462162E+05, 1.15595310E+06,
    1.45474808E+06, 1.83061021E+06, 2.30331975E+06, 2.89767678E+06,
    3.64474164E+06, 4.58336196E+06, 5.76204070E+06, 7.24120178E+06,
    9.09590686E+06};
  const std::vector<double> b_gauss = {
    9.21244943E+04, 1.15974635E+05, 1.45998294E+05, 1.83792846E+05,
    2.31368621E+05, 2.91255450E+05, 3.66636578E+05, 4.61516902E+05,
    5.80934211E+05, 7.31224248E+05, 9.20353005E+05, 1.15833286E+06,
    1.45774298E+06, 1.83437890E+06, 2.30806161E+06, 2.90364224E+06,
    3.65224508E+06, 4.59279775E+06, 5.77390304E+06, 7.25610928E+06,
    9.11463266E+06};
  compare("B, nodal", pressures("ssnp152b", "nodal"), steps(b_nodal), 1e-8);
  compare("B, Gauss 3", pressures("ssnp152b", "Gauss 3"), steps(b_gauss), 1e-8);

  // ssnp152c.comm: step 100 (s = 1), nodal and 2 Gauss points.
  compare("C, nodal",
          pressures("ssnp152c", "nodal"),
          {{100, 9.08676484E+06}},
          1e-7);
  compare("C, Gauss 2",
          pressures("ssnp152c", "Gauss 2"),
          {{100, 9.10546887E+06}},
          1e-7);
}
