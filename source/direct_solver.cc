#include <ring_contact/direct_solver.h>
#include <ring_contact/utilities.h>

#include <suitesparse/umfpack.h>

#include <algorithm>
#include <iomanip>
#include <sstream>
#include <numeric>
#include <stdexcept>

namespace RingContact
{
  namespace
  {
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

  void
  DirectSolver::factorize(const SparseMatrix<double> &matrix,
                          const std::uint64_t         pattern_version)
  {
    const auto        &pattern = matrix.get_sparsity_pattern();
    const std::int64_t n       = matrix.m();
    const bool         new_pattern =
      !analysed || pattern_version != analysed_version ||
      static_cast<std::int64_t>(row_start.size()) != n + 1;
    if (new_pattern)
      {
        // Each row's entries sorted by column: the order of `source`.
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
    // The values in the order of `source`: the matrix's entries are
    // stored row by row, in the pattern's order.
    {
      std::size_t         at = 0;
      std::vector<double> stored(source.size());
      for (std::int64_t i = 0; i < n; ++i)
        for (auto entry = matrix.begin(i); entry != matrix.end(i); ++entry)
          stored[at++] = entry->value();
      if (at != source.size())
        throw std::runtime_error(
          "the direct solver's pattern differs from the matrix's");
      for (std::size_t k = 0; k < source.size(); ++k)
        values[k] = stored[source[k]];
    }
    if (new_pattern)
      {
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
        // instant, not after minutes of swapping (a fine master under a
        // coarse slave drove UMFPACK past 5.5 GB and 150 s without a word).
        const double bytes =
          info[UMFPACK_PEAK_MEMORY_ESTIMATE] * info[UMFPACK_SIZE_OF_UNIT];
        const double available = static_cast<double>(available_memory());
        if (estimate_observer)
          estimate_observer(bytes);
        if (available > 0 && bytes > 0.9 * available)
          {
            free_symbolic();
            analysed = false;
            std::ostringstream what;
            what << std::setprecision(3) << "the direct solver's factorization "
                 << "of the " << n << " unknowns would need about "
                 << bytes / 1e9 << " GB (UMFPACK's estimate), more than the "
                 << available / 1e9 << " GB this process can still have";
            throw FactorizationTooLarge(what.str(), bytes);
          }
      }
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
    ++counts.factorizations;
    counts.flops = info[UMFPACK_FLOPS];
  }

  void
  DirectSolver::solve(const Vector<double> &b, Vector<double> &x) const
  {
    if (numeric == nullptr)
      throw std::runtime_error("the direct solver has no factorization");
    x.reinit(b.size());
    // The stored rows are the columns of A^T: solve A^T' x = b, i.e. A x = b.
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
