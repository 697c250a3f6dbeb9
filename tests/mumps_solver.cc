// MumpsSolver, the parallel direct solver, on its own: the 5-point Laplacian
// of a k x k grid (Dirichlet rows at the border) plus a skew convection term
// (an unsymmetric matrix, as the contact tangents are), its rows split
// between the processes of mpirun -np 2. Asserted:
// - the solution of A x = A x_exact is x_exact to 1e-10, on two processes
//   and on each process alone (MPI_COMM_SELF);
// - the pivot order is METIS's nested dissection of the whole pattern: the
//   LU's flops are the same on two processes as on one (an order computed
//   from the gathered pattern, the same whatever the distribution; MUMPS's
//   own PORD order depends on the order in which the entries reach the
//   host), and below a fifth of those of the banded (natural) order,
//   2 n k^2, which a fill-reducing order must beat on a 2D grid (nested
//   dissection: O(n^1.5));
// - a second factorization with the same pattern keeps the analysis; a
//   new pattern version is analysed again;
// - a singular matrix is refused with MUMPS's reason;
// - a saddle-point matrix scaled as the contact problems are, [K B^T; B 0]
//   with K of the order of 1e9 (Young's modulus) and B of 1e-3 (int Phi N
//   ds), whose multipliers are of the order of 1e12: both its blocks are
//   solved to 1e-10 of their own size through MumpsSolver's equilibration
//   (row and column factors from 2^-30 to 2^12, applied to the entries,
//   the right-hand side and the solution). Measured while writing it: 2e-15
//   and 9e-15; MUMPS unscaled, or with its own scaling, does as well here.
#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <ring_contact/linear_algebra/mumps_solver.h>

#include "tests.h"

#include <array>
#include <cmath>
#include <stdexcept>

using namespace dealii;
using namespace RingContact;
using RingContactTests::check;
using RingContactTests::deallog_file;

namespace
{
  constexpr unsigned int k = 80; // grid points per side
  constexpr unsigned int n = k * k;

  // The matrix on `communicator`, each process owning a contiguous block of
  // rows; `singular`: the first row zero.
  TrilinosWrappers::SparseMatrix
  grid_matrix(const MPI_Comm communicator, const bool singular = false)
  {
    const unsigned int n_processes =
      Utilities::MPI::n_mpi_processes(communicator);
    const unsigned int rank = Utilities::MPI::this_mpi_process(communicator);
    IndexSet           owned(n);
    owned.add_range(n * rank / n_processes, n * (rank + 1) / n_processes);
    DynamicSparsityPattern pattern(n, n, owned);
    for (const auto row : owned)
      {
        const unsigned int i = row % k, j = row / k;
        pattern.add(row, row);
        if (i > 0 && i + 1 < k && j > 0 && j + 1 < k)
          for (const unsigned int neighbour :
               {row - 1, row + 1, row - k, row + k})
            pattern.add(row, neighbour);
      }
    TrilinosWrappers::SparseMatrix matrix;
    matrix.reinit(owned, owned, pattern, communicator);
    for (const auto row : owned)
      {
        const unsigned int i = row % k, j = row / k;
        if (i > 0 && i + 1 < k && j > 0 && j + 1 < k)
          {
            matrix.set(row, row, 4.0);
            matrix.set(row, row - 1, -1.3); // convection along i
            matrix.set(row, row + 1, -0.7);
            matrix.set(row, row - k, -1.0);
            matrix.set(row, row + k, -1.0);
          }
        else
          matrix.set(row, row, singular && row == 0 ? 0.0 : 1.0);
      }
    matrix.compress(VectorOperation::insert);
    return matrix;
  }

  // [K B^T; B 0] on `communicator`: K the grid matrix times 1e9, and a
  // multiplier for each grid column j, tying the points (j, 1) and (j, 2)
  // of the grid's second and third rows with weights of 1e-3, contiguous
  // blocks of rows on each process.
  constexpr unsigned int n_multipliers = k - 2;
  TrilinosWrappers::SparseMatrix
  saddle_point_matrix(const MPI_Comm communicator)
  {
    const unsigned int size = n + n_multipliers;
    const unsigned int n_processes =
      Utilities::MPI::n_mpi_processes(communicator);
    const unsigned int rank = Utilities::MPI::this_mpi_process(communicator);
    IndexSet           owned(size);
    owned.add_range(size * rank / n_processes, size * (rank + 1) / n_processes);
    // The multiplier of column j and its two points, with their weights.
    const auto tied = [](const unsigned int m) {
      const unsigned int j = m + 1;
      return std::array<std::pair<unsigned int, double>, 2>{
        {{k + j, 0.7e-3}, {2 * k + j, 0.3e-3}}};
    };
    DynamicSparsityPattern pattern(size, size, owned);
    const auto             grid = grid_matrix(MPI_COMM_SELF);
    for (const auto row : owned)
      if (row < n)
        for (auto e = grid.begin(row); e != grid.end(row); ++e)
          pattern.add(row, e->column());
      else
        pattern.add(row, row);
    for (unsigned int m = 0; m < n_multipliers; ++m)
      for (const auto &[point, weight] : tied(m))
        {
          (void)weight;
          if (owned.is_element(point))
            pattern.add(point, n + m);
          if (owned.is_element(n + m))
            pattern.add(n + m, point);
        }
    TrilinosWrappers::SparseMatrix matrix;
    matrix.reinit(owned, owned, pattern, communicator);
    for (const auto row : owned)
      if (row < n)
        for (auto e = grid.begin(row); e != grid.end(row); ++e)
          matrix.set(row, e->column(), 1e9 * e->value());
    for (unsigned int m = 0; m < n_multipliers; ++m)
      for (const auto &[point, weight] : tied(m))
        {
          if (owned.is_element(point))
            matrix.set(point, n + m, weight);
          if (owned.is_element(n + m))
            matrix.set(n + m, point, weight);
        }
    matrix.compress(VectorOperation::insert);
    return matrix;
  }

  // x from A x = A x_exact by `mumps` (b = A x_exact whole on every
  // process; the pattern's version 1).
  Vector<double>
  solve_exact(const TrilinosWrappers::SparseMatrix &matrix,
              const Vector<double>                 &exact,
              const MPI_Comm                        communicator,
              MumpsSolver                          &mumps)
  {
    Vector<double> owned_part(exact.size()), b(exact.size()), x;
    for (const auto row : matrix.locally_owned_range_indices())
      for (auto e = matrix.begin(row); e != matrix.end(row); ++e)
        owned_part(row) += e->value() * exact(e->column());
    Utilities::MPI::sum(owned_part, communicator, b);
    mumps.factorize(matrix.trilinos_matrix(), 1);
    mumps.solve(b, x);
    return x;
  }

  // The largest error of the grid's solution for x_exact(i) = sin(i).
  double
  grid_error(const TrilinosWrappers::SparseMatrix &matrix,
             const MPI_Comm                        communicator,
             MumpsSolver                          &mumps)
  {
    Vector<double> exact(n);
    for (unsigned int i = 0; i < n; ++i)
      exact(i) = std::sin(1.0 + i);
    const Vector<double> x = solve_exact(matrix, exact, communicator, mumps);
    double               error = 0;
    for (unsigned int i = 0; i < n; ++i)
      error = std::max(error, std::abs(x(i) - exact(i)));
    return error;
  }

  // Solve with x_exact(i) = sin(i): the largest error, and the LU's flops.
  std::pair<double, double>
  solve(const MPI_Comm communicator)
  {
    const auto   matrix = grid_matrix(communicator);
    MumpsSolver  mumps(communicator);
    const double error = grid_error(matrix, communicator, mumps);

    // The same pattern: no new analysis; a new version: a new one.
    mumps.factorize(matrix.trilinos_matrix(), 1);
    check(mumps.statistics().analyses == 1 &&
            mumps.statistics().factorizations == 2,
          "the analysis is kept while the pattern version does not change");
    mumps.factorize(matrix.trilinos_matrix(), 2);
    check(mumps.statistics().analyses == 2,
          "a new pattern version is analysed again");
    return {error, mumps.statistics().flops};
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check(Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) == 2,
        "run with mpirun -np 2");

  const auto [error_two, flops_two]   = solve(MPI_COMM_WORLD);
  const auto [error_alone, flops_one] = solve(MPI_COMM_SELF);
  check(error_two < 1e-10, "two processes: x = x_exact to 1e-10");
  check(error_alone < 1e-10, "one process: x = x_exact to 1e-10");
  check(flops_two == flops_one,
        "the same pivot order on two processes as on one (LU flops " +
          std::to_string(flops_two) + " and " + std::to_string(flops_one) +
          ")");
  const double banded = 2.0 * n * k * k;
  check(flops_two < 0.2 * banded,
        "a fill-reducing order: LU flops " + std::to_string(flops_two) +
          " against " + std::to_string(banded) + " in the banded order");
  deallog_file << "grid " << k << " x " << k
               << ": x = x_exact to 1e-10 on two processes and on one, the "
                  "same LU flops on both, below a fifth of the banded order's"
               << std::endl;

  // The saddle point: u_i = sin(i), lambda_m = 1e12 cos(m), b = A x.
  {
    const auto     matrix = saddle_point_matrix(MPI_COMM_WORLD);
    const auto     size   = n + n_multipliers;
    Vector<double> exact(size);
    for (unsigned int i = 0; i < size; ++i)
      exact(i) = i < n ? std::sin(1.0 + i) : 1e12 * std::cos(1.0 + i);
    MumpsSolver          mumps(MPI_COMM_WORLD);
    const Vector<double> x = solve_exact(matrix, exact, MPI_COMM_WORLD, mumps);
    double               error[2] = {0, 0}, largest[2] = {0, 0};
    for (unsigned int i = 0; i < size; ++i)
      {
        const unsigned int block = i < n ? 0 : 1;
        error[block]   = std::max(error[block], std::abs(x(i) - exact(i)));
        largest[block] = std::max(largest[block], std::abs(exact(i)));
      }
    check(error[0] < 1e-10 * largest[0],
          "saddle point: the displacements to 1e-10 of their size (" +
            std::to_string(error[0] / largest[0]) + ")");
    check(error[1] < 1e-10 * largest[1],
          "saddle point: the multipliers to 1e-10 of their size (" +
            std::to_string(error[1] / largest[1]) + ")");
    deallog_file << "saddle point [K B^T; B 0], K ~ 1e9, B ~ 1e-3: both "
                    "blocks to 1e-10 of their size"
                 << std::endl;
  }

  // The grid times 1e-310: entries below the normal numbers, whose
  // equilibration factor 2^1030 would overflow. Subnormal data carry about
  // 8 bits fewer: the solution to 1e-8.
  {
    auto matrix = grid_matrix(MPI_COMM_WORLD);
    matrix *= 1e-310;
    MumpsSolver  mumps(MPI_COMM_WORLD);
    const double error = grid_error(matrix, MPI_COMM_WORLD, mumps);
    check(error < 1e-8,
          "subnormal entries: x = x_exact to 1e-8 (" + std::to_string(error) +
            ")");
    deallog_file << "grid times 1e-310 (subnormal entries): x = x_exact to "
                    "1e-8"
                 << std::endl;
  }

  // A singular matrix: refused, on every process, with MUMPS's reason.
  {
    const auto  matrix = grid_matrix(MPI_COMM_WORLD, true);
    MumpsSolver mumps(MPI_COMM_WORLD);
    std::string message;
    try
      {
        mumps.factorize(matrix.trilinos_matrix(), 1);
      }
    catch (const std::runtime_error &e)
      {
        message = e.what();
      }
    check(message.find("singular") != std::string::npos,
          "a singular matrix is refused as singular (got '" + message + "')");
    deallog_file << "singular matrix: " << message << std::endl;
  }
}
