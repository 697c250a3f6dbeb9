#include <ring_contact/linear_system.h>
#include <ring_contact/utilities.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_Map.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace RingContact
{
  namespace
  {
    bool
    needs_trilinos(const MPI_Comm communicator, const LinearSolverType solver)
    {
      return solver == LinearSolverType::mumps ||
             solver == LinearSolverType::iterative ||
             (solver == LinearSolverType::automatic &&
              n_processes(communicator) > 1);
    }
  } // namespace

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
        // apart from the program's sums and gathers.
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

  void
  LinearSystem::set_kinds(const std::vector<BlockSolver::Kind> &kinds,
                          const std::vector<Point<2>>          &positions)
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
        // Each process's rows of other processes go to their owners.
        d.matrix.reinit(owned, owned, dsp, d.communicator, true);
        const Epetra_Map &columns = d.matrix.trilinos_matrix().ColMap();
        global_column.resize(columns.NumMyElements());
        for (int k = 0; k < columns.NumMyElements(); ++k)
          global_column[k] = columns.GID64(k);
        if (!d.mumps && !block_solver)
          d.mumps = std::make_unique<MumpsSolver>(d.communicator);
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

  void
  LinearSystem::add_rhs(const AffineConstraints<double>            &constraints,
                        const Vector<double>                       &local_rhs,
                        const std::vector<types::global_dof_index> &dofs)
  {
    Assert(!constraints.has_inhomogeneities(), ExcInternalError());
    constraints.distribute_local_to_global(
      local_rhs, dofs, use_trilinos ? rhs_added : rhs_vector);
  }

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

  double
  LinearSystem::solve(Vector<double> &x)
  {
    x.reinit(rhs_vector.size());
    if (!use_trilinos)
      {
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
} // namespace RingContact
