// MUMPS, the parallel direct solver, called through its C interface: the
// distributed matrix as each process's own rows (MUMPS's distributed
// assembled input), the analysis (ordering, elimination tree, mapping onto
// the processes) kept while the sparsity pattern does not change, and the
// right-hand side and solution whole on every process (they are, in this
// program: see LinearSystem). The pivot order is METIS's nested dissection
// of the whole pattern, computed on process 0 (MUMPS's own choice, PORD in
// Debian's build, which has neither METIS nor Scotch, makes more flops on the
// rings: doc/validation.md, "Time and memory behind the code's choices").
//
// Trilinos's Amesos_Mumps does the same through Epetra, but rebuilds its
// triplets and redistributes the matrix at every factorization, which took a
// large part of each factorization's time beside MUMPS's own work (measured at
// 640 x 48 on two processes: the same section). The same reason the serial path
// calls UMFPACK itself (DirectSolver).
#ifndef ring_contact_linear_algebra_mumps_solver_h
#define ring_contact_linear_algebra_mumps_solver_h

#include <deal.II/base/mpi.h>
#include <deal.II/lac/vector.h>

#include <ring_contact/linear_algebra/direct_solver.h>

#include <cstdint>
#include <memory>
#include <vector>

class Epetra_CrsMatrix;

namespace RingContact
{
  using namespace dealii;

  class MumpsSolver
  {
  public:
    /// Every process of `communicator` takes part (the constructor, like
    /// every member function, is collective).
    explicit MumpsSolver(const MPI_Comm communicator);
    ~MumpsSolver();
    MumpsSolver(const MumpsSolver &) = delete;
    MumpsSolver &
    operator=(const MumpsSolver &) = delete;

    /// LU of `matrix` (each process gives its own rows). The analysis is
    /// redone when `pattern_version` differs from that of the last call.
    /// Throws std::runtime_error, on every process, when MUMPS fails (a
    /// singular matrix among others), after retrying with more workspace
    /// when it ran short of it.
    void
    factorize(const Epetra_CrsMatrix &matrix,
              const std::uint64_t     pattern_version);

    /// x = A^-1 b with the last factorization; b whole on every process
    /// (process 0's is used), x whole on every process.
    void
    solve(const Vector<double> &b, Vector<double> &x);

    /// Analyses, factorizations, and the floating-point operations of the
    /// last factorization (MUMPS's RINFOG(3), all processes).
    const FactorizationStatistics &
    statistics() const
    {
      return counts;
    }

  private:
    struct Data;
    /// Run MUMPS's phase `job`; its error code INFOG(1) (the same on every
    /// process).
    int
    run(const int job);

    /// Choose the pivot order of the next analysis (collective).
    void
    order_unknowns(const int n);

    void
    equilibrate(const int n);

    const MPI_Comm        communicator;
    std::unique_ptr<Data> data;
    bool                  analysed         = false;
    std::uint64_t         analysed_version = 0;
    /// Each process's entries: global row and column (from 1), and where
    /// each value comes from in the matrix's storage of its rows.
    std::vector<int>    rows, columns;
    std::vector<double> values;
    std::vector<double> rhs;
    /// This process's part of the solution (MUMPS's distributed solution)
    /// and its unknowns (from 1); then all processes' parts.
    std::vector<double> solution_part, all_solution_parts;
    std::vector<int>    solution_indices, all_solution_indices;
    /// The scaling of the last matrix factorized (equilibrate()), whole.
    std::vector<double> row_scaling, column_scaling;
    /// Process 0's pivot order (MUMPS's PERM_IN), kept through the analysis.
    std::vector<int>        pivot_order;
    FactorizationStatistics counts;
  };
} // namespace RingContact

#endif
