// The Newton system K du = -R, on one process or on several (MPI).
//
// On one process it is what the program always had: deal.II's SparseMatrix
// and UMFPACK (`DirectSolver`, its symbolic analysis kept while the sparsity
// pattern does not change). Under MPI the work is shared as in deal.II's
// step-17 and step-18: every process holds the whole mesh and the whole
// state (the contact search needs both surfaces whole at every iteration,
// and in two dimensions they are small), the cells are partitioned by METIS
// and each process assembles its own cells and contact points; the matrix
// is Trilinos's, each process storing the rows of its own unknowns, and it
// is factorized by MUMPS on all processes together (MumpsSolver), the
// analysis kept while the pattern does not change.
//
// Every process adds its contributions to any row (a contact point couples
// unknowns of other processes); compress() sums them: the matrix rows on
// their owners, the right-hand side whole on every process. So the callers
// read the right-hand side as one vector everywhere, and the rows of the
// matrix on the process that owns them.
#ifndef ring_contact_linear_algebra_linear_system_h
#define ring_contact_linear_algebra_linear_system_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <ring_contact/input/parameters.h>
#include <ring_contact/linear_algebra/block_solver.h>
#include <ring_contact/linear_algebra/direct_solver.h>
#include <ring_contact/linear_algebra/mumps_solver.h>

#include <cstdint>
#include <memory>
#include <vector>

namespace RingContact
{
  using namespace dealii;

  /// The number of processes of `communicator`, and this one's rank: 1 and
  /// 0 when MPI was not started (a serial run does not start it).
  unsigned int
  n_processes(const MPI_Comm communicator);
  unsigned int
  this_process(const MPI_Comm communicator);

  /// Each entry of `v` replaced by its sum over the processes.
  void
  sum_over_processes(Vector<double> &v, const MPI_Comm communicator);

  class LinearSystem
  {
  public:
    /// `solver`: Newton/Linear solver (auto is UMFPACK on one process and
    /// MUMPS on several). MUMPS and the iterative solver need MPI started
    /// (main() does it when the file asks for them). `linear_tolerance`:
    /// the iterative solver's relative residual.
    LinearSystem(const MPI_Comm         communicator,
                 const LinearSolverType solver,
                 const double           linear_tolerance = 1e-8);
    ~LinearSystem();
    LinearSystem(const LinearSystem &) = delete;
    LinearSystem &
    operator=(const LinearSystem &) = delete;

    /// Free the matrix, its pattern and the direct solver's factorization
    /// before a new pattern is built: they are replaced by it, and the
    /// memory check of the new one must not count them. The matrix is
    /// unusable until reinit().
    void
    release();

    /// Before a new sparsity pattern is built: `bulk` holds the couplings
    /// of this process's cells, `blocks` the contact's (each a sorted set of
    /// unknowns coupled all with all: ContactInterface::coupling_blocks()).
    /// Throws FactorizationTooLarge, saying the estimate and the memory
    /// this process can have, when the pattern, the matrix and (on one
    /// process) UMFPACK's factorization of its dense rows would need more
    /// than 90 % of that memory. Collective under MPI.
    void
    check_memory(
      const DynamicSparsityPattern                            &bulk,
      const std::vector<std::vector<types::global_dof_index>> &blocks);

    /// The factorization's memory [bytes] that the last check_memory()
    /// estimated from the couplings (0 where it estimated none): said
    /// beside UMFPACK's own estimate once its analysis has run.
    double
    estimated_factorization_memory() const
    {
      return factorization_estimate;
    }

    /// A new sparsity pattern: `dsp` holds the couplings of this process's
    /// cells and contact points (rows of any process); `owned` the rows this
    /// process stores (all of them on one process). The matrix is zero.
    void
    reinit(const DynamicSparsityPattern &dsp,
           const IndexSet               &owned,
           const types::global_dof_index n);

    /// Matrix and right-hand side to zero.
    void
    set_zero();

    /// Add a cell's (or contact point's) matrix and right-hand side,
    /// condensed with `constraints`.
    void
    add(const AffineConstraints<double>            &constraints,
        const FullMatrix<double>                   &local_matrix,
        const Vector<double>                       &local_rhs,
        const std::vector<types::global_dof_index> &dofs);

    /// The same for a cell's matrix, `cell` being its active index. When
    /// none of the cell's unknowns is constrained and all its rows are this
    /// process's, the entries go straight to their places in the matrix's
    /// storage, found once per sparsity pattern and kept by the cell:
    /// neither the search of each entry in its row nor the constraints'
    /// bookkeeping is repeated at every assembly.
    void
    add_cell(const unsigned int                          cell,
             const AffineConstraints<double>            &constraints,
             const FullMatrix<double>                   &local_matrix,
             const Vector<double>                       &local_rhs,
             const std::vector<types::global_dof_index> &dofs);

    /// A cell's right-hand side alone (an assembly without the tangent);
    /// the constraints must be homogeneous.
    void
    add_rhs(const AffineConstraints<double>            &constraints,
            const Vector<double>                       &local_rhs,
            const std::vector<types::global_dof_index> &dofs);

    /// K_ii += k, rhs_i += r (a row that is its own equation).
    void
    add_diagonal(const types::global_dof_index i,
                 const double                  k,
                 const double                  r);

    /// Sum what the processes added since the last call: the matrix rows on
    /// their owners, the right-hand side on every process.
    void
    compress();

    /// The whole right-hand side -R, on every process (after compress()).
    const Vector<double> &
    rhs() const
    {
      return rhs_vector;
    }

    /// The rows this process stores.
    const IndexSet &
    owned_rows() const
    {
      return owned;
    }

    /// f(column, value) for every nonzero stored entry of an owned row i
    /// (the pattern's zeros skipped: the callers sum products and absolute
    /// values, and right after the contact terms, whose magnitudes are
    /// measured on their own, nearly all the matrix is still zero).
    template <typename Function>
    void
    for_each_entry(const types::global_dof_index i, const Function &f) const;

    /// The iterative solver's blocks: the kind of every unknown (whole).
    /// Ignored by the direct solvers.
    template <int dim>
    void
    set_kinds(const std::vector<BlockSolver::Kind> &kinds,
              const std::vector<Point<dim>>        &positions);

    /// x = K^-1 rhs, whole on every process. Throws std::runtime_error when
    /// the solver fails or the matrix is singular (IterativeSolverFailure
    /// when GMRES does not converge). Returns |K x - rhs| / |rhs|.
    double
    solve(Vector<double> &x);

    /// Whether the solver is iterative, and its iterations in the last
    /// solve.
    bool
    iterative() const
    {
      return block_solver != nullptr;
    }
    unsigned int
    last_iterations() const
    {
      return iterations;
    }

    /// The direct solver's name ("UMFPACK" or "MUMPS") and what it did;
    /// an empty name for the iterative solver.
    std::string
    direct_solver_name() const;
    FactorizationStatistics
    direct_statistics() const;

    /// See DirectSolver::estimate_observer (UMFPACK only).
    std::function<void(double)> estimate_observer;

    /// The matrix on one process (deal.II's): for tests.
    const SparseMatrix<double> &
    serial_matrix() const
    {
      return matrix;
    }

    MPI_Comm
    get_communicator() const
    {
      return communicator;
    }

  private:
    const MPI_Comm communicator;
    const bool     use_trilinos;
    IndexSet       owned;
    /// One process: deal.II's matrix and UMFPACK.
    SparsityPattern               sparsity_pattern;
    SparseMatrix<double>          matrix;
    std::unique_ptr<DirectSolver> umfpack;
    /// check_memory()'s estimate of the factorization [bytes].
    double factorization_estimate = 0;
    /// Counts the sparsity patterns: the solvers keep their analysis while
    /// it does not change.
    std::uint64_t pattern_version = 0;
    /// Several processes: Trilinos's matrix, MUMPS. Made only then (even
    /// an empty Trilinos object needs MPI started).
    struct Distributed
    {
      /// A communicator of their own for Trilinos and MUMPS, apart from
      /// the program's sums and gathers.
      MPI_Comm                       communicator = MPI_COMM_NULL;
      TrilinosWrappers::SparseMatrix matrix;
      std::unique_ptr<MumpsSolver>   mumps;
      ~Distributed();
    };
    std::unique_ptr<Distributed> distributed_part;
    /// The global index of each local column of the distributed matrix
    /// (Epetra's column map, read once per pattern).
    std::vector<types::global_dof_index> global_column;
    /// Linear solver = iterative (on Trilinos's matrix).
    std::unique_ptr<BlockSolver> block_solver;
    unsigned int                 iterations = 0;
    /// The matrix's values, one array (nullptr when the storage is not
    /// one array: then add_cell() is add()).
    double *
    value_array();
    /// The place in value_array() of entry (i, j) of the pattern, i a row
    /// this process stores.
    std::size_t
    place_of(const types::global_dof_index i,
             const types::global_dof_index j) const;
    /// The cells' places (add_cell()), for the pattern `version`: its
    /// value_array(), and the places of cell c's entries, row by row, from
    /// place[start[c]].
    struct CellPlaces
    {
      static constexpr std::uint64_t unknown = ~std::uint64_t(0);
      std::uint64_t                  version = 0;
      double                        *values  = nullptr;
      std::vector<std::uint64_t>     start;
      std::vector<std::uint32_t>     place;
    } cell_places;

    /// The right-hand side, whole; and (several processes) what this
    /// process added since the last compress().
    Vector<double> rhs_vector;
    Vector<double> rhs_added;
  };


  template <typename Function>
  void
  LinearSystem::for_each_entry(const types::global_dof_index i,
                               const Function               &f) const
  {
    if (!use_trilinos)
      {
        for (auto e = matrix.begin(i); e != matrix.end(i); ++e)
          if (e->value() != 0)
            f(e->column(), e->value());
        return;
      }
    // Epetra's own view of the row (deal.II's row iterators over a Trilinos
    // matrix clear a buffer of the matrix's width at every row).
    const Epetra_CrsMatrix &m = distributed_part->matrix.trilinos_matrix();
    int                     n = 0;
    double                 *values;
    int                    *columns;
    m.ExtractMyRowView(m.LRID(static_cast<int>(i)), n, values, columns);
    for (int k = 0; k < n; ++k)
      if (values[k] != 0)
        f(global_column[columns[k]], values[k]);
  }
} // namespace RingContact

#endif
