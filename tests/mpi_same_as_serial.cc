// MPI: the same results on two processes as on one. Under mpirun -np 2
// every case is solved twice: by both processes together (the cells
// partitioned, MUMPS), and by each process alone (MPI_COMM_SELF: the serial
// program, UMFPACK). Asserted for every step of every scheme: the same
// Newton iterations, and the pressure at the probe, the extreme pressures,
// the L2 error and every checked quantity within 1e-9 (relative to the
// case's scale). The cases: A (its two schemes), C with every contact
// integration scheme, G (Q2, curved; its three schemes, the whole rotation
// in 20 steps), a cyclic-symmetry sector of C, and three blocks with two
// contact pairs (a general problem: tractions, resultant forces), and
// Coulomb friction: C with mu = 0.2 (nodal and segment-based) and the
// frictional patch test.
// Also MUMPS on one process against UMFPACK, for A; and the iterative
// solver (GMRES, block preconditioner) on two processes against UMFPACK on
// one, for A and C (nodal, segment-based), at a linear tolerance of 1e-12.
#include <deal.II/base/mpi.h>

#include <ring_contact/config.h>
#include <ring_contact/problem/contact_problem.h>

#include "compare_histories.h"
#include "run_problem.h"

#include <algorithm>
#include <cmath>

using namespace RingContact;
using RingContactTests::check;
using RingContactTests::difference;
using RingContactTests::modelisation;

namespace
{
  // Quiet runs without files.
  const std::string quiet =
    "\nsubsection Output\n set VTU interval = 0\n set Print timing = false\n"
    " set Write history = false\nend\n"
    "subsection Newton\n set Verbose = false\nend\n";

  // Every scheme of the file, on `communicator`.
  std::vector<std::vector<HistoryRow>>
  solve(const Parameters &parameters, const MPI_Comm communicator)
  {
    std::vector<std::vector<HistoryRow>> histories;
    for (const auto &scheme : parameters.contact.schemes)
      {
        std::ostringstream  log;
        ContactProblem<dim> problem(parameters, scheme, log, communicator);
        check(problem.run(), scheme.name() + ": every step is solved");
        histories.push_back(problem.history());
      }
    return histories;
  }

  void
  compare(const std::string &name,
          const std::string &prm_text,
          const std::string &serial_solver = "auto")
  {
    const MPI_Comm     world = MPI_COMM_WORLD;
    const unsigned int me    = Utilities::MPI::this_mpi_process(world);
    // One file, written by process 0, read by all.
    static unsigned int case_number = 0;
    const std::string   file = "case-" + std::to_string(++case_number) + ".prm";
    if (me == 0)
      std::ofstream(file) << prm_text << quiet;
    MPI_Barrier(world);
    Parameters parameters;
    parameters.read(file);
    const auto together = solve(parameters, world);

    std::ofstream(file + "." + std::to_string(me))
      << "include " << file
      << "\nsubsection Newton\n set Linear solver = " << serial_solver
      << "\nend\n";
    Parameters serial_parameters;
    serial_parameters.read(file + "." + std::to_string(me));
    const auto alone = solve(serial_parameters, MPI_COMM_SELF);

    for (unsigned int s = 0; s < together.size(); ++s)
      {
        const double       d      = difference(alone[s], together[s]);
        const std::string  scheme = parameters.contact.schemes[s].name();
        std::ostringstream difference_text;
        difference_text << std::scientific << std::setprecision(0) << d;
        if (me == 0)
          RingContactTests::deallog_file
            << name << ", " << scheme << ": " << together[s].size()
            << " steps, "
            << (d < 0    ? "other steps or Newton iterations than" :
                d < 1e-9 ? "the same as" :
                           "DIFFERENT (" + difference_text.str() + ") from")
            << " one process (" << serial_solver << ")" << std::endl;
        check(d >= 0 && d < 1e-9,
              name + ", " + scheme + ": two processes give the serial results");
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check(Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) == 2,
        "run with mpirun -np 2");

  compare("A", modelisation('a', ""));
  compare("A", modelisation('a', ""), "MUMPS");
  compare("C",
          modelisation('c',
                       "subsection Contact\n set Integration schemes = nodal, "
                       "Gauss 2, Simpson 3, Newton-Cotes 4, segment-based "
                       "2\nend"));
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
                       "subsection Contact\n set Integration schemes = nodal, "
                       "segment-based 2\n set Friction coefficient = 0.2\n"
                       "end"));
  const std::string iterative =
    "subsection Newton\n set Linear solver = iterative\n"
    " set Linear tolerance = 1e-12\nend\n";
  compare("A, iterative", modelisation('a', iterative));
  compare("C, iterative",
          modelisation('c',
                       iterative + "subsection Contact\n set Integration "
                                   "schemes = nodal, segment-based 2\nend"));
  compare("the frictional patch test",
          std::string("include ") + RING_CONTACT_SOURCE_DIR +
            "/prm/two_blocks_friction.prm\nsubsection Mesh\n set Mesh file = " +
            RING_CONTACT_SOURCE_DIR + "/meshes/two_blocks.geo\nend\n");
  compare("three blocks",
          std::string("include ") + RING_CONTACT_SOURCE_DIR +
            "/prm/three_blocks.prm\nsubsection Mesh\n set Mesh file = " +
            RING_CONTACT_SOURCE_DIR + "/meshes/three_blocks.geo\nend\n");
}
