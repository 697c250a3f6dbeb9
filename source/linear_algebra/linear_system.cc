// @sect3{The Newton system: one matrix, one or several processes}
//
// The problem class assembles the tangent K and the right-hand side -R of
// every Newton iteration through this class and asks it for the update;
// it does not know whether one process or several share the work. On one
// process the matrix is deal.II's SparseMatrix, factorized by UMFPACK
// (direct_solver.cc). Under MPI, as in step-17, every process holds the
// whole mesh and state but assembles only its own cells and slave points;
// the matrix is then Trilinos's, each process storing the rows of its own
// unknowns, and it is factorized by MUMPS (mumps_solver.cc) or solved by
// GMRES (block_solver.cc). The right-hand side is kept whole on every
// process, because the Newton loop's decisions (convergence, line search,
// step cuts) read it and must come out the same on all of them.
//
// The assembly's hot path is add_cell(): a cell that needs neither the
// constraints nor another process goes straight to the places of its
// entries in the matrix's storage, found once per sparsity pattern.
#include <ring_contact/base/utilities.h>
#include <ring_contact/linear_algebra/linear_system.h>
#include <ring_contact/linear_algebra/memory_estimate.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_Map.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace RingContact
{
  namespace
  {
    // Trilinos's matrix whenever the solver is MUMPS or GMRES (they read
    // it, even on one process), and for the automatic choice under MPI.
    bool
    needs_trilinos(const MPI_Comm communicator, const LinearSolverType solver)
    {
      return solver == LinearSolverType::mumps ||
             solver == LinearSolverType::iterative ||
             (solver == LinearSolverType::automatic &&
              n_processes(communicator) > 1);
    }
  } // namespace

  // A serial run does not start MPI (it costs about a second, more than
  // solving a modelisation), and deal.II's MPI queries need it started:
  // without it the run is one process, rank 0.
  unsigned int
  n_processes(const MPI_Comm communicator)
  {
    return dealii::Utilities::MPI::job_supports_mpi() ?
             dealii::Utilities::MPI::n_mpi_processes(communicator) :
             1;
  }

  unsigned int
  this_process(const MPI_Comm communicator)
  {
    return dealii::Utilities::MPI::job_supports_mpi() ?
             dealii::Utilities::MPI::this_mpi_process(communicator) :
             0;
  }

  // In place: the whole vector, each entry summed over the processes, on
  // every process (an all-reduce).
  void
  sum_over_processes(Vector<double> &v, const MPI_Comm communicator)
  {
    dealii::Utilities::MPI::sum(dealii::ArrayView<const double>(v.begin(),
                                                                v.size()),
                                communicator,
                                dealii::ArrayView<double>(v.begin(), v.size()));
  }

  LinearSystem::LinearSystem(const MPI_Comm         communicator,
                             const LinearSolverType solver,
                             const double           linear_tolerance)
      : communicator(communicator)
      , use_trilinos(needs_trilinos(communicator, solver))
  {
    // The two combinations that cannot work are refused here, with the
    // entry to change, before any matrix is built: UMFPACK sees one
    // process's matrix only, and Trilinos's objects need MPI started (main
    // starts it for a file that asks for MUMPS or the iterative solver).
    if (!use_trilinos && n_processes(communicator) > 1)
      throw std::runtime_error(
        "Newton/Linear solver = UMFPACK is serial: with several MPI "
        "processes use MUMPS (or auto)");
    if (use_trilinos && !dealii::Utilities::MPI::job_supports_mpi())
      throw std::runtime_error(
        "Newton/Linear solver = MUMPS or iterative needs MPI, which was not "
        "started");
    if (use_trilinos)
      {
        distributed_part = std::make_unique<Distributed>();
        // Trilinos and MUMPS communicate on a communicator of their own,
        // apart from the program's sums and gathers: on the program's own,
        // a message of MUMPS once met an MPI_Allgatherv of the program
        // (MPI_ERR_TRUNCATE, then a hang).
        MPI_Comm_dup(communicator, &distributed_part->communicator);
        if (solver == LinearSolverType::iterative)
          block_solver =
            std::make_unique<BlockSolver>(distributed_part->communicator,
                                          linear_tolerance);
      }
  }

  LinearSystem::~LinearSystem()
  {
    // The solver's Trilinos objects go before the communicator.
    block_solver.reset();
  }

  template <int dim>
  void
  LinearSystem::set_kinds(const std::vector<BlockSolver::Kind> &kinds,
                          const std::vector<Point<dim>>        &positions)
  {
    if (block_solver)
      block_solver->set_kinds(kinds, positions);
  }

  LinearSystem::Distributed::~Distributed()
  {
    // MUMPS ends its work before the communicator goes.
    mumps.reset();
    matrix.clear();
    if (communicator != MPI_COMM_NULL)
      MPI_Comm_free(&communicator);
  }

  // @sect4{The memory, judged before the pattern is built}
  //
  // A coarse slave on a fine master couples each slave segment's unknowns
  // with those of the thousands of master segments it faces: the pattern
  // then holds the square of that per segment, and UMFPACK's ordering
  // leaves those rows to the end, where they fill in as one dense block.
  // The analysis after the pattern, the matrix and UMFPACK's copy of them
  // were built (DirectSolver::analyse()) said so only after a minute and
  // gigabytes of them. Here the pattern's rows are counted from the
  // couplings (joined_row_lengths()), and what it, the matrix and the
  // factorization of its dense rows will hold is compared with the memory
  // this process can have, before any of it exists. It is an estimate from
  // below: the factorization of the sparse rows is not counted (UMFPACK's
  // analysis still judges the whole), so that a problem that fits is not
  // refused here.
  void
  LinearSystem::check_memory(
    const DynamicSparsityPattern                            &bulk,
    const std::vector<std::vector<types::global_dof_index>> &blocks)
  {
    const types::global_dof_index              n = bulk.n_rows();
    const std::vector<types::global_dof_index> row_lengths =
      joined_row_lengths(bulk, blocks);
    const double entries =
      std::accumulate(row_lengths.begin(), row_lengths.end(), 0.0);
    // On one process: deal.II's pattern, its matrix and UMFPACK's sorted
    // copy. Under Trilinos every process builds the whole contact pattern
    // in a DynamicSparsityPattern first (an index an entry), and its share
    // of the rows as Trilinos's matrix (a value, a 32-bit column and the
    // graph's own 32-bit column an entry).
    const double pattern_bytes =
      use_trilinos ? entries * (sizeof(types::global_dof_index) +
                                16.0 / n_processes(communicator)) :
                     entries * DirectSolver::bytes_per_entry;
    // The dense rows matter to UMFPACK's order only: MUMPS's (METIS's
    // nested dissection) and the iterative solver have no such rule.
    const DirectSolver::DenseRows dense =
      use_trilinos ? DirectSolver::DenseRows() :
                     DirectSolver::dense_rows(row_lengths);
    factorization_estimate = dense.bytes;
    double needed          = pattern_bytes + dense.bytes;
    double available       = static_cast<double>(available_memory());
    // Every process decides alike: the largest need against the smallest
    // memory (a process that cannot tell its memory, 0, does not count).
    if (n_processes(communicator) > 1)
      {
        needed = dealii::Utilities::MPI::max(needed, communicator);
        available =
          -dealii::Utilities::MPI::max(available > 0 ?
                                         -available :
                                         -std::numeric_limits<double>::max(),
                                       communicator);
        if (available == std::numeric_limits<double>::max())
          available = 0;
      }
    if (!(available > 0 && needed > 0.9 * available))
      return;
    std::ostringstream what;
    what << std::setprecision(3);
    if (dense.bytes > 0)
      what << "the direct solver's factorization of the " << n
           << " unknowns would need about " << needed / 1e9
           << " GB (UMFPACK's factors of the " << dense.rows
           << " unknowns whose rows are dense, " << dense.bytes / 1e9
           << " GB, and the matrix with its pattern, " << pattern_bytes / 1e9
           << " GB, estimated from the couplings before any is built)";
    else
      what << "the Newton system of the " << n << " unknowns would need about "
           << needed / 1e9 << " GB for its matrix and pattern (" << entries
           << " entries, estimated from the couplings before they are "
              "built)";
    what << ", more than the " << available / 1e9
         << " GB this process can still have";
    throw FactorizationTooLarge(what.str(), needed);
  }

  // The old pattern's matrix and factorization go before the new pattern
  // is made: without this a new pairing in the middle of a run counted
  // them against the memory left, and a problem that fits at the set-up
  // could be refused at its first new pattern (they are freed at the
  // reinit() that follows anyway).
  void
  LinearSystem::release()
  {
    if (!use_trilinos)
      {
        matrix.clear();
        sparsity_pattern.reinit(0, 0, 0);
        if (umfpack)
          umfpack->release();
      }
    else
      distributed_part->matrix.clear();
  }

  // @sect4{A new sparsity pattern}
  //
  // Called at the set-up, and when the pairing couples unknowns the
  // pattern has no room for (a slave point that slid past its old
  // partner's neighbours). The version number it increments is what the
  // solvers and add_cell() compare to decide whether their analysis and
  // places still hold.
  void
  LinearSystem::reinit(const DynamicSparsityPattern &dsp,
                       const IndexSet               &owned_rows,
                       const types::global_dof_index n)
  {
    owned = owned_rows;
    ++pattern_version;
    if (!use_trilinos)
      {
        sparsity_pattern.copy_from(dsp);
        matrix.reinit(sparsity_pattern);
      }
    else
      {
        auto &d = *distributed_part;
        // Each process's rows of other processes go to their owners (the
        // last argument, exchange_data): a contact point or a cell at the
        // partition's edge couples unknowns this process does not own, and
        // the owner's pattern must hold them before anything is added.
        d.matrix.reinit(owned, owned, dsp, d.communicator, true);
        // Epetra numbers a row's columns locally; the table of their global
        // indices is read here once, not through a GCID call per entry at every
        // solve, which cost every solve time (doc/validation.md, "Time and
        // memory behind the code's choices").
        const Epetra_Map &columns = d.matrix.trilinos_matrix().ColMap();
        global_column.resize(columns.NumMyElements());
        for (int k = 0; k < columns.NumMyElements(); ++k)
          global_column[k] = columns.GID64(k);
        // MUMPS is made once, with the first pattern, and keeps its own
        // record of the pattern it analysed.
        if (!d.mumps && !block_solver)
          d.mumps = std::make_unique<MumpsSolver>(d.communicator);
        // What this process adds to the right-hand side between two
        // compress() calls, whole-sized: contributions to any row.
        rhs_added.reinit(n);
      }
    rhs_vector.reinit(n);
  }

  void
  LinearSystem::set_zero()
  {
    rhs_vector = 0;
    if (!use_trilinos)
      matrix = 0;
    else
      {
        distributed_part->matrix = 0;
        rhs_added                = 0;
      }
  }

  // @sect4{Adding local contributions}
  //
  // The general path: deal.II condenses the constraints (imposed
  // displacements, the zero multipliers inside the slave layer, the
  // cyclic ties) into the local matrix and vector as it adds them. Under
  // MPI the right-hand side goes to rhs_added, summed at compress().
  void
  LinearSystem::add(const AffineConstraints<double>            &constraints,
                    const FullMatrix<double>                   &local_matrix,
                    const Vector<double>                       &local_rhs,
                    const std::vector<types::global_dof_index> &dofs)
  {
    if (!use_trilinos)
      constraints.distribute_local_to_global(
        local_matrix, local_rhs, dofs, matrix, rhs_vector);
    else
      constraints.distribute_local_to_global(
        local_matrix, local_rhs, dofs, distributed_part->matrix, rhs_added);
  }

  // The matrix's values as one array, so that an entry is found by its
  // place alone. deal.II's SparseMatrix is one array: the diagonal entry
  // (0, 0) sits at place sparsity_pattern(0, 0) of it, which gives its
  // start. Epetra's is one array once its storage is optimized, row 0
  // first. Otherwise (an empty matrix, or more entries than 32 bits can
  // number) nullptr, and add_cell() falls back to add().
  double *
  LinearSystem::value_array()
  {
    // The places are held in 32 bits.
    constexpr std::size_t most = std::numeric_limits<std::uint32_t>::max();
    if (!use_trilinos)
      return sparsity_pattern.n_nonzero_elements() == 0 ||
                 sparsity_pattern.n_nonzero_elements() > most ?
               nullptr :
               &matrix.diag_element(0) - sparsity_pattern(0, 0);
    const Epetra_CrsMatrix &m = distributed_part->matrix.trilinos_matrix();
    if (!m.StorageOptimized() || m.NumMyRows() == 0 ||
        static_cast<std::size_t>(m.NumMyNonzeros()) > most)
      return nullptr;
    int     n;
    double *values;
    int    *columns;
    m.ExtractMyRowView(0, n, values, columns);
    return values;
  }

  // The place of (i, j) in value_array(): deal.II's pattern answers it
  // directly; for Epetra, the entry's offset in its row's view plus the
  // row's offset from row 0. A linear search in the row, as this runs once
  // per entry per pattern only.
  std::size_t
  LinearSystem::place_of(const types::global_dof_index i,
                         const types::global_dof_index j) const
  {
    if (!use_trilinos)
      return sparsity_pattern(i, j);
    const Epetra_CrsMatrix &m = distributed_part->matrix.trilinos_matrix();
    int                     n;
    double                 *values, *first;
    int                    *columns;
    m.ExtractMyRowView(0, n, first, columns);
    m.ExtractMyRowView(m.LRID(static_cast<int>(i)), n, values, columns);
    const int column = m.LCID(static_cast<int>(j));
    const int k      = std::find(columns, columns + n, column) - columns;
    if (column < 0 || k == n)
      throw std::logic_error("LinearSystem: a cell's entry is not in the "
                             "sparsity pattern");
    return static_cast<std::size_t>(values + k - first);
  }

  // @sect4{The cells' fast path}
  //
  // Epetra's insertion by global index (binary searches, the maps from
  // global to local indices, deal.II's row buffers) was a large part of an
  // assembly on the Trilinos path. Most cells have no constrained unknown and
  // all their rows on this process; their entries are added here at places
  // computed once per pattern and kept by the cell's active index, which
  // shortened the assembly (doc/validation.md, "Time and memory behind the
  // code's choices"). The other cells, the boundary faces and the contact
  // points take add(); either way each entry receives the same sum.
  void
  LinearSystem::add_cell(const unsigned int               cell,
                         const AffineConstraints<double> &constraints,
                         const FullMatrix<double>        &local_matrix,
                         const Vector<double>            &local_rhs,
                         const std::vector<types::global_dof_index> &dofs)
  {
    // The storage, once per pattern.
    auto &places = cell_places;
    if (places.version != pattern_version)
      {
        places.version = pattern_version;
        places.values  = value_array();
        places.start.clear();
        places.place.clear();
      }
    // A constrained unknown needs the condensation, and a row of another
    // process would be written into storage this process does not have:
    // both take the general path.
    double *const values = places.values;
    bool          direct = values != nullptr;
    for (const auto dof : dofs)
      direct =
        direct && !constraints.is_constrained(dof) && owned.is_element(dof);
    if (!direct)
      {
        add(constraints, local_matrix, local_rhs, dofs);
        return;
      }
    // A cell's places are computed the first time it comes this way under
    // the current pattern; a cell that never does costs nothing.
    if (cell >= places.start.size())
      places.start.resize(cell + 1, CellPlaces::unknown);
    const unsigned int n = dofs.size();
    if (places.start[cell] == CellPlaces::unknown)
      {
        places.start[cell] = places.place.size();
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            places.place.push_back(
              static_cast<std::uint32_t>(place_of(dofs[i], dofs[j])));
      }
    Vector<double>      &rhs   = use_trilinos ? rhs_added : rhs_vector;
    const std::uint32_t *place = places.place.data() + places.start[cell];
    for (unsigned int i = 0; i < n; ++i)
      {
        rhs(dofs[i]) += local_rhs(i);
        for (unsigned int j = 0; j < n; ++j)
          values[*place++] += local_matrix(i, j);
      }
  }

  // The residual-only assembly (an iterate expected to converge) adds no
  // cell matrix, and deal.II condenses a vector alone as if its
  // constraints were homogeneous: it is used only when they are
  // (assemble_system() sees to it), which the assertion checks.
  void
  LinearSystem::add_rhs(const AffineConstraints<double>            &constraints,
                        const Vector<double>                       &local_rhs,
                        const std::vector<types::global_dof_index> &dofs)
  {
    Assert(!constraints.has_inhomogeneities(), ExcInternalError());
    constraints.distribute_local_to_global(
      local_rhs, dofs, use_trilinos ? rhs_added : rhs_vector);
  }

  // A diagonal term alone: the whole equation of an open contact node's
  // multiplier, w_k lambda_k = 0 (and of its tangential traction with
  // friction), or a term added to a row the points assemble (the small
  // regularisation of a sticking node's tangential row).
  void
  LinearSystem::add_diagonal(const types::global_dof_index i,
                             const double                  k,
                             const double                  r)
  {
    if (!use_trilinos)
      {
        matrix.add(i, i, k);
        rhs_vector(i) += r;
      }
    else
      {
        distributed_part->matrix.add(i, i, k);
        rhs_added(i) += r;
      }
  }

  // Nothing to exchange on one process. Under MPI, Trilinos sends the
  // rows added for other processes to their owners, and the right-hand
  // side contributions are summed into the whole vector on every process:
  // afterwards each process reads the same -R.
  void
  LinearSystem::compress()
  {
    if (!use_trilinos)
      return;
    distributed_part->matrix.compress(VectorOperation::add);
    sum_over_processes(rhs_added, communicator);
    rhs_vector += rhs_added;
    rhs_added = 0;
  }

  std::string
  LinearSystem::direct_solver_name() const
  {
    return block_solver ? "" : use_trilinos ? "MUMPS" : "UMFPACK";
  }

  FactorizationStatistics
  LinearSystem::direct_statistics() const
  {
    if (umfpack)
      return umfpack->statistics();
    if (distributed_part && distributed_part->mumps)
      return distributed_part->mumps->statistics();
    return {};
  }

  // @sect4{The solve}
  //
  // The update, whole on every process, and the relative residual of the
  // linear system, |K x - b| / |b|, by which the Newton loop tells a
  // singular tangent: a direct solve of a regular matrix, however
  // ill-conditioned, leaves a round-off of b; a singular one (a body free
  // to slide) leaves a residual of the order of b.
  double
  LinearSystem::solve(Vector<double> &x)
  {
    x.reinit(rhs_vector.size());
    if (!use_trilinos)
      {
        // Made with the first solve, and handed the memory observer then.
        if (!umfpack)
          {
            umfpack                    = std::make_unique<DirectSolver>();
            umfpack->estimate_observer = estimate_observer;
          }
        umfpack->factorize(matrix, pattern_version);
        umfpack->solve(rhs_vector, x);
        // UMFPACK refines its solution iteratively: on a regular matrix,
        // however ill-conditioned, K x - b is a round-off of b.
        Vector<double> residual(rhs_vector.size());
        matrix.vmult(residual, x);
        residual -= rhs_vector;
        // Norms that do not underflow (a load of 1e-200).
        EuclideanNorm r, b;
        for (types::global_dof_index i = 0; i < residual.size(); ++i)
          {
            r.add(residual(i));
            b.add(rhs_vector(i));
          }
        return r.value() / std::max(b.value(), 1e-300);
      }

    // Several processes (or MUMPS or GMRES asked for on one): the solvers
    // read the rows each process owns, and return x whole.
    auto &d = *distributed_part;
    if (block_solver)
      iterations =
        block_solver->solve(d.matrix, owned, pattern_version, rhs_vector, x);
    else
      {
        d.mumps->factorize(d.matrix.trilinos_matrix(), pattern_version);
        d.mumps->solve(rhs_vector, x);
      }
    // |K x - rhs| / |rhs|, each process its own rows, the squares scaled
    // by the largest |rhs| so that they do not underflow (a load of 1e-200).
    const Epetra_CrsMatrix &m     = d.matrix.trilinos_matrix();
    double                  scale = 0;
    for (int row = 0; row < m.NumMyRows(); ++row)
      scale = std::max(scale, std::abs(rhs_vector(m.GRID64(row))));
    scale = dealii::Utilities::MPI::max(scale, communicator);
    if (!(scale > 0))
      scale = 1;
    double squares[2] = {0, 0};
    for (int row = 0; row < m.NumMyRows(); ++row)
      {
        int     n;
        double *values;
        int    *columns;
        m.ExtractMyRowView(row, n, values, columns);
        const double b = rhs_vector(m.GRID64(row));
        double       r = -b;
        for (int k = 0; k < n; ++k)
          r += values[k] * x(global_column[columns[k]]);
        squares[0] += (r / scale) * (r / scale);
        squares[1] += (b / scale) * (b / scale);
      }
    dealii::Utilities::MPI::sum(dealii::ArrayView<const double>(squares, 2),
                                communicator,
                                dealii::ArrayView<double>(squares, 2));
    return std::sqrt(squares[0]) / std::max(std::sqrt(squares[1]), 1e-300);
  }
  // The two dimensions of the program (issue 48).
  template void
  LinearSystem::set_kinds<2>(const std::vector<BlockSolver::Kind> &,
                             const std::vector<Point<2>> &);
  template void
  LinearSystem::set_kinds<3>(const std::vector<BlockSolver::Kind> &,
                             const std::vector<Point<3>> &);
} // namespace RingContact
