// The iterative solver (Newton/Linear solver = iterative: GMRES with the
// block preconditioner of BlockSolver) against the direct one (UMFPACK),
// on one process: for every case and scheme, the same steps and Newton
// iterations, and every history quantity within 1e-9 of the case's scale,
// at a linear tolerance of 1e-12. The cases: A (both schemes), C (nodal,
// segment-based), G (Q2 curved, the rotation in 20 steps), a
// cyclic-symmetry sector of C, C with Coulomb friction, and two general
// problems whose bodies the contact alone holds in some direction (which
// makes the displacement block singular, see BlockSolver): three blocks
// with two contact pairs, and Hertz. GMRES's iterations per
// solve are asserted to stay below 100 on these meshes (without the
// preconditioner GMRES(100) does not converge) (they are printed in the log of
// every run).
#include <deal.II/base/mpi.h>

#include <ring_contact/config.h>
#include <ring_contact/problem/contact_problem.h>

#include "compare_histories.h"
#include "run_problem.h"

#include <regex>

using namespace RingContact;
using RingContactTests::check;
using RingContactTests::difference;
using RingContactTests::modelisation;

namespace
{
  struct Run
  {
    std::vector<std::vector<HistoryRow>> histories;
    /// GMRES's iterations and solves, summed over the schemes.
    unsigned int iterations = 0, solves = 0;
  };

  Run
  solve(const std::string &name, const std::string &prm_text)
  {
    std::ofstream(name + ".prm")
      << prm_text
      << "\nsubsection Output\n set VTU interval = 0\n set Print timing = "
         "false\n set Write history = false\nend\n"
         "subsection Newton\n set Verbose = false\nend\n";
    Parameters parameters;
    parameters.read(name + ".prm");
    Run run;
    for (const auto &scheme : parameters.contact.schemes)
      {
        std::ostringstream  log;
        ContactProblem<dim> problem(parameters, scheme, log, MPI_COMM_WORLD);
        check(problem.run(), name + ", " + scheme.name() + ": solved");
        run.histories.push_back(problem.history());
        std::smatch       match;
        const std::string text = log.str();
        if (std::regex_search(
              text,
              match,
              std::regex("GMRES: ([0-9]+) iterations in ([0-9]+) solves")))
          {
            run.iterations += std::stoi(match[1]);
            run.solves += std::stoi(match[2]);
          }
      }
    return run;
  }

  void
  compare(const std::string &name, const std::string &prm_text)
  {
    static unsigned int n      = 0;
    const std::string   file   = "case-" + std::to_string(++n);
    const Run           direct = solve(file + "-direct", prm_text);
    const Run           iterative =
      solve(file + "-iterative",
            prm_text + "\nsubsection Newton\n set Linear solver = iterative\n"
                       " set Linear tolerance = 1e-12\nend\n");
    check(iterative.solves > 0, name + ": GMRES was used");
    const double per_solve = double(iterative.iterations) / iterative.solves;
    bool         same = direct.histories.size() == iterative.histories.size();
    for (unsigned int s = 0; same && s < direct.histories.size(); ++s)
      {
        const double d =
          difference(direct.histories[s], iterative.histories[s]);
        same = d >= 0 && d < 1e-9;
        if (!same)
          std::cerr << name << ", scheme " << s << ": difference " << d
                    << std::endl;
      }
    RingContactTests::deallog_file
      << name << ": " << direct.histories.front().size() << " steps, "
      << (same ? "the same as" : "DIFFERENT from") << " UMFPACK; GMRES "
      << (per_solve < 100 ? "below" : "NOT below")
      << " 100 iterations per solve" << std::endl;
    check(same, name + ": the iterative solver gives the direct one's results");
    check(per_solve < 100, name + ": GMRES below 100 iterations per solve");
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  compare("A", modelisation('a', ""));
  compare("C",
          modelisation('c',
                       "subsection Contact\n set Integration schemes = nodal, "
                       "segment-based 2\nend"));
  compare("G, the whole rotation in 20 steps",
          modelisation('g',
                       "subsection Load program\n set Rotation steps = 20\n"
                       "end"));
  compare("C, a sector of 3 elements",
          modelisation('c',
                       "subsection Mesh\n set Sector elements = 3\nend\n"
                       "subsection Contact\n set Integration schemes = "
                       "segment-based 2\nend"));
  compare("C with friction (mu = 0.2)",
          modelisation('c',
                       "subsection Contact\n set Integration schemes = "
                       "segment-based 2\n set Friction coefficient = 0.2\n"
                       "end"));
  compare("three blocks",
          std::string("include ") + RING_CONTACT_SOURCE_DIR +
            "/prm/three_blocks.prm\nsubsection Mesh\n set Mesh file = " +
            RING_CONTACT_SOURCE_DIR + "/meshes/three_blocks.geo\nend\n");
  compare("Hertz (a general problem, plane strain, two pressed bodies)",
          std::string("include ") + RING_CONTACT_SOURCE_DIR +
            "/prm/hertz.prm\nsubsection Mesh\n set Mesh file = " +
            RING_CONTACT_SOURCE_DIR + "/meshes/hertz.geo\nend\n");
}
