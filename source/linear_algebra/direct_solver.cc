// @sect3{The serial direct solver: UMFPACK with its analysis kept}
//
// On one process the Newton system K du = -R is solved by UMFPACK, the
// sparse LU of SuiteSparse that deal.II's SparseDirectUMFPACK wraps. It is
// called directly because deal.II's class redoes the symbolic analysis
// (fill-reducing ordering, elimination tree) at every factorization, while
// the pattern of the Newton matrix changes only when the contact couplings
// do: most iterations need the numerical factorization alone. LinearSystem
// owns one DirectSolver and tells it, by a version number, when the
// pattern is new; mumps_solver.cc is the same idea for several processes.
//
// The umfpack_dl_* functions are the double/64-bit-integer variants, so
// that the count of nonzeros of a large LU is not bounded by an int.
#include <ring_contact/base/utilities.h>
#include <ring_contact/linear_algebra/direct_solver.h>

#include <suitesparse/umfpack.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace RingContact
{
  namespace
  {
    // UMFPACK's status in words. A singular matrix is a warning for
    // UMFPACK (it completes the factorization with zero pivots), but the
    // callers treat every status other than UMFPACK_OK as a failure: a
    // singular Newton matrix is a motion that nothing holds, and its
    // solution would be arbitrary.
    std::string
    status_text(const long status)
    {
      switch (status)
        {
          case UMFPACK_WARNING_singular_matrix:
            return "the matrix is singular";
          case UMFPACK_ERROR_out_of_memory:
            return "out of memory";
          case UMFPACK_ERROR_invalid_matrix:
            return "invalid matrix";
          default:
            return "UMFPACK status " + std::to_string(status);
        }
    }
  } // namespace

  // UMFPACK's default controls, as deal.II uses them: its other strategies
  // and orderings were measured on the rings and were no faster (header).
  DirectSolver::DirectSolver()
      : control(UMFPACK_CONTROL)
  {
    umfpack_dl_defaults(control.data());
  }

  DirectSolver::~DirectSolver()
  {
    free_numeric();
    free_symbolic();
  }

  void
  DirectSolver::free_symbolic()
  {
    if (symbolic != nullptr)
      umfpack_dl_free_symbolic(&symbolic);
    symbolic = nullptr;
  }

  void
  DirectSolver::free_numeric()
  {
    if (numeric != nullptr)
      umfpack_dl_free_numeric(&numeric);
    numeric = nullptr;
  }

  // Before a new pattern is built (LinearSystem::release()): what the old
  // one held goes first, so that the memory check of the new one and its
  // peak do not count both.
  void
  DirectSolver::release()
  {
    free_numeric();
    free_symbolic();
    analysed = false;
    std::vector<std::int64_t>().swap(row_start);
    std::vector<std::int64_t>().swap(columns);
    std::vector<std::size_t>().swap(source);
    std::vector<double>().swap(values);
  }

  // @sect4{The factorization}
  //
  // Two parts: the arrays UMFPACK reads and its symbolic analysis, made
  // once per sparsity pattern; the values copied into those arrays and the
  // numerical LU, at every call.
  void
  DirectSolver::factorize(const SparseMatrix<double> &matrix,
                          const std::uint64_t         pattern_version)
  {
    const auto        &pattern = matrix.get_sparsity_pattern();
    const std::int64_t n       = matrix.m();
    // The size is compared as well as the version, so that a matrix of
    // another size under an old version number is analysed anew instead of
    // being read through arrays of the wrong length.
    const bool new_pattern =
      !analysed || pattern_version != analysed_version ||
      static_cast<std::int64_t>(row_start.size()) != n + 1;
    if (new_pattern)
      sort_pattern(pattern);
    // The values in the order of `source`: the matrix's entries are
    // stored row by row, in the pattern's order. The count is compared
    // with the analysed pattern's: a matrix whose pattern changed without a
    // new version would put its entries in the wrong places of the LU,
    // silently. (An entry beyond the analysed count is counted, not
    // stored: a matrix with more entries must not overrun `stored`.)
    {
      std::size_t         at = 0;
      std::vector<double> stored(source.size());
      for (std::int64_t i = 0; i < n; ++i)
        for (auto entry = matrix.begin(i); entry != matrix.end(i); ++entry)
          {
            if (at < stored.size())
              stored[at] = entry->value();
            ++at;
          }
      if (at != source.size())
        throw std::runtime_error(
          "the direct solver's pattern differs from the matrix's");
      for (std::size_t k = 0; k < source.size(); ++k)
        values[k] = stored[source[k]];
    }
    // The analysis is given the values too (UMFPACK looks at the diagonal's
    // values in choosing its strategy), but it is kept for later values of
    // the same pattern: its ordering is a property of the pattern, and the
    // numerical factorization still pivots for stability.
    if (new_pattern)
      analyse(pattern_version);
    // The previous LU is freed first: at the peak this process holds one
    // factorization, not two.
    free_numeric();
    std::vector<double> info(UMFPACK_INFO);
    const long          status = umfpack_dl_numeric(row_start.data(),
                                           columns.data(),
                                           values.data(),
                                           symbolic,
                                           &numeric,
                                           control.data(),
                                           info.data());
    if (status != UMFPACK_OK)
      {
        free_numeric();
        throw std::runtime_error("UMFPACK's factorization failed: " +
                                 status_text(status));
      }
    // The flops of this LU, printed with the timing (Print timing = true)
    // and read by the benchmarks: the arithmetic a factorization costs.
    ++counts.factorizations;
    counts.flops = info[UMFPACK_FLOPS];
  }


  // Each row's entries sorted by column: the order of `source`.
  // deal.II stores the diagonal entry of a square matrix first in its
  // row, and UMFPACK requires the indices of each of its columns in
  // increasing order. `at` counts the entries in the matrix's own
  // storage order, so that source[k] is where the k-th sorted entry
  // lives there.
  void
  DirectSolver::sort_pattern(const SparsityPattern &pattern)
  {
    const std::int64_t n = pattern.n_rows();
    free_numeric();
    free_symbolic();
    row_start.assign(n + 1, 0);
    columns.clear();
    source.clear();
    std::vector<std::pair<std::int64_t, std::size_t>> row;
    std::size_t                                       at = 0;
    for (std::int64_t i = 0; i < n; ++i)
      {
        row.clear();
        for (auto entry = pattern.begin(i); entry != pattern.end(i);
             ++entry, ++at)
          row.emplace_back(entry->column(), at);
        std::sort(row.begin(), row.end());
        for (const auto &[column, index] : row)
          {
            columns.push_back(column);
            source.push_back(index);
          }
        row_start[i + 1] = columns.size();
      }
    values.resize(columns.size());
  }


  // UMFPACK's symbolic analysis of the sorted pattern, and the memory its
  // factorization will take, estimated before it runs.
  void
  DirectSolver::analyse(const std::uint64_t pattern_version)
  {
    const std::int64_t  n = static_cast<std::int64_t>(row_start.size()) - 1;
    std::vector<double> info(UMFPACK_INFO);
    const long          status = umfpack_dl_symbolic(n,
                                            n,
                                            row_start.data(),
                                            columns.data(),
                                            values.data(),
                                            &symbolic,
                                            control.data(),
                                            info.data());
    if (status != UMFPACK_OK)
      {
        free_symbolic();
        throw std::runtime_error("UMFPACK's analysis failed: " +
                                 status_text(status));
      }
    analysed         = true;
    analysed_version = pattern_version;
    ++counts.analyses;
    // The analysis estimates the factorization's peak memory (an upper
    // bound): one that the machine cannot hold is said now, in an
    // instant, not after minutes of swapping (a fine master under a coarse
    // slave drove UMFPACK into gigabytes and minutes without a word:
    // doc/validation.md, "The memory guard").
    const double bytes =
      info[UMFPACK_PEAK_MEMORY_ESTIMATE] * info[UMFPACK_SIZE_OF_UNIT];
    const double available = static_cast<double>(available_memory());
    // The observer hears the estimate before the check and before the
    // factorization: a long one is announced (a note above 1 GB) before
    // it starts, not after.
    if (estimate_observer)
      estimate_observer(bytes);
    if (available > 0 && bytes > 0.9 * available)
      {
        free_symbolic();
        analysed = false;
        std::ostringstream what;
        what << std::setprecision(3) << "the direct solver's factorization "
             << "of the " << n << " unknowns would need about " << bytes / 1e9
             << " GB (UMFPACK's estimate), more than the " << available / 1e9
             << " GB this process can still have";
        throw FactorizationTooLarge(what.str(), bytes);
      }
  }

  // @sect4{The factorization's memory before the pattern is built}
  //
  // UMFPACK chooses its symmetric strategy for these matrices (their
  // pattern is symmetric, their diagonal nearly all nonzero). It first
  // takes out the singletons, here the constrained unknowns, whose rows
  // and columns hold the diagonal alone (the pattern leaves their
  // couplings out); the n rows left are ordered by AMD on A + A^T, which
  // leaves every row with more than max(16, a sqrt(n)) entries besides the
  // diagonal to the end of it, a being UMFPACK's control AMD_DENSE (10 by
  // default, read from UMFPACK's own defaults so that the rule is the
  // library's). Near that threshold a row's count decides between a
  // sparse order and a dense block: the counts are exact for that reason.
  //
  // The d rows left to the end are eliminated last, where the fill of all
  // that came before has coupled them with each other: a dense block. Its
  // factors hold d^2 values, the last frontal matrix, which is the block
  // itself, d^2 more while it is factorized, and UMFPACK's indices of the
  // factors and its copy of the matrix about d^2 again: 3.1 d^2 values in
  // all, the coefficient set a little below what UMFPACK's own estimates
  // of its peak give (doc/validation.md, "The memory guard"). Each of the
  // s sparse rows ordered before is coupled through the elimination with
  // about half of the dense ones, in L and in U alike: d s values more.
  // How much more fill a thick body under the surface brings (the sparse
  // rows' elimination reaching further into the dense ones) is not
  // counted: the estimate stays below UMFPACK's, so that a problem that
  // fits is not refused for it, and UMFPACK's analysis still judges the
  // whole before the factorization runs.
  DirectSolver::DenseRows
  DirectSolver::dense_rows(
    const std::vector<types::global_dof_index> &row_lengths)
  {
    const double ordered =
      std::count_if(row_lengths.begin(),
                    row_lengths.end(),
                    [](const types::global_dof_index l) { return l > 1; });
    std::vector<double> defaults(UMFPACK_CONTROL);
    umfpack_dl_defaults(defaults.data());
    const double threshold =
      std::min(ordered,
               std::max(16.0,
                        defaults[UMFPACK_AMD_DENSE] * std::sqrt(ordered)));
    DenseRows dense;
    dense.rows     = std::count_if(row_lengths.begin(),
                               row_lengths.end(),
                               [&](const types::global_dof_index l) {
                                 return l > 1 && l - 1 > threshold;
                               });
    const double d = dense.rows, s = ordered - d;
    dense.bytes = sizeof(double) * (3.1 * d * d + d * s);
    return dense;
  }

  void
  DirectSolver::solve(const Vector<double> &b, Vector<double> &x) const
  {
    if (numeric == nullptr)
      throw std::runtime_error("the direct solver has no factorization");
    x.reinit(b.size());
    // UMFPACK reads our compressed rows of A as the compressed columns of a
    // matrix, which is A^T: solving with that matrix transposed
    // (UMFPACK_At) is A x = b. UMFPACK refines the solution iteratively by
    // default, which the residual check in LinearSystem::solve() relies on.
    const long status = umfpack_dl_solve(UMFPACK_At,
                                         row_start.data(),
                                         columns.data(),
                                         values.data(),
                                         x.data(),
                                         b.data(),
                                         numeric,
                                         control.data(),
                                         nullptr);
    if (status != UMFPACK_OK)
      throw std::runtime_error("UMFPACK's solve failed: " +
                               status_text(status));
  }
} // namespace RingContact
