// The direct solver of the Newton systems: UMFPACK (SuiteSparse) with its
// default controls, as in deal.II's SparseDirectUMFPACK, but the symbolic
// analysis (the fill-reducing ordering and the elimination tree) is kept
// while the sparsity pattern does not change, so that a Newton iteration
// with the same contact couplings only factorizes numerically (deal.II's
// class analyses at every call). UMFPACK's other choices (its symmetric and
// unsymmetric strategies, the METIS ordering) were measured on the rings at
// 640 x 48 and are no faster there; their figures, with the time of the
// analysis and of the factorization, are in doc/validation.md, "Time and memory
// behind the code's choices".
// The matrix is handed over as it is stored (deal.II's compressed rows,
// which are the compressed columns of A^T, solved with UMFPACK_At), each
// row's columns sorted, as UMFPACK requires, once per pattern.
#ifndef ring_contact_linear_algebra_direct_solver_h
#define ring_contact_linear_algebra_direct_solver_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <cstdint>
#include <functional>
#include <vector>

namespace RingContact
{
  using namespace dealii;

  /// What a direct solver did in a run: its analyses (one per sparsity
  /// pattern), its numerical factorizations, and the floating-point
  /// operations of the last factorization (the solver's own count).
  struct FactorizationStatistics
  {
    unsigned int analyses       = 0;
    unsigned int factorizations = 0;
    double       flops          = 0;
  };

  class DirectSolver
  {
  public:
    DirectSolver();
    ~DirectSolver();
    DirectSolver(const DirectSolver &) = delete;
    DirectSolver &
    operator=(const DirectSolver &) = delete;

    /// LU of `matrix`. The analysis is redone when `pattern_version`
    /// differs from that of the last call (the caller counts its sparsity
    /// patterns) or the size changed. Throws std::runtime_error when
    /// UMFPACK fails, and when the matrix is singular.
    void
    factorize(const SparseMatrix<double> &matrix,
              const std::uint64_t         pattern_version);

    /// x = A^-1 b with the last factorization (UMFPACK's iterative
    /// refinement included).
    void
    solve(const Vector<double> &b, Vector<double> &x) const;

    const FactorizationStatistics &
    statistics() const
    {
      return counts;
    }

    /// The memory of a factorization judged before the pattern is built
    /// (LinearSystem::check_memory()), from the lengths of the pattern's
    /// rows (the diagonal included): the rows that UMFPACK's fill-reducing
    /// ordering leaves to the end as dense, and an estimate from below of
    /// UMFPACK's peak memory [bytes] for the block they make there. Both
    /// zero where no row is dense; the factorization of the other rows is
    /// not estimated.
    struct DenseRows
    {
      types::global_dof_index rows  = 0;
      double                  bytes = 0;
    };
    static DenseRows
    dense_rows(const std::vector<types::global_dof_index> &row_lengths);

    /// The bytes this class and the matrix hold per entry of the pattern
    /// while UMFPACK factorizes: deal.II's pattern (4) and matrix (8), and
    /// the sorted copy UMFPACK reads (64-bit columns and values, the place
    /// of each value in the matrix: 24).
    static constexpr double bytes_per_entry = 36;

    /// Free the factorization, the analysis and the sorted copy of the
    /// pattern (a new pattern is coming); the statistics stay.
    void
    release();

    /// Called after each analysis with UMFPACK's estimate of the
    /// factorization's peak memory [bytes], before it runs (a note in the
    /// log when it is large: a long factorization is then said before).
    std::function<void(double)> estimate_observer;

  private:
    /// The pattern's rows sorted by column (row_start, columns, source).
    void
    sort_pattern(const SparsityPattern &pattern);
    /// The symbolic analysis; the factorization's memory estimated.
    void
    analyse(const std::uint64_t pattern_version);

    void
    free_symbolic();
    void
    free_numeric();

    /// The pattern of the last analysis (its version and size).
    std::uint64_t analysed_version = 0;
    bool          analysed         = false;
    /// Compressed rows with sorted columns, and where each value comes
    /// from in the matrix's own storage.
    std::vector<std::int64_t> row_start, columns;
    std::vector<std::size_t>  source;
    std::vector<double>       values;
    void                     *symbolic = nullptr;
    void                     *numeric  = nullptr;
    std::vector<double>       control;
    FactorizationStatistics   counts;
  };
} // namespace RingContact

#endif
