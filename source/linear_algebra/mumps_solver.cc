// @sect3{The parallel direct solver: MUMPS through its C interface}
//
// Under MPI the Newton matrix is Trilinos's, each process holding the rows
// of its own unknowns, and MUMPS factorizes it on all processes together.
// Four choices shape this file (their measures are in the comments below
// and in the header): MUMPS is called directly rather than through
// Amesos_Mumps, which rebuilt its triplets and redistributed the matrix at
// every factorization; the analysis is kept while the sparsity pattern
// does not change, as for UMFPACK (direct_solver.cc); the pivot order is
// METIS's, computed by us, because Debian's MUMPS has neither METIS nor
// Scotch built in; and the matrix is equilibrated by us, because MUMPS
// redid its own scaling at every factorization of a distributed matrix.
#include <ring_contact/linear_algebra/mumps_solver.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_Map.h>
#include <dmumps_c.h>
#include <metis.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace RingContact
{
  // MUMPS's structure behind a pointer, so that the header, and every file
  // that includes it, needs no MUMPS header.
  struct MumpsSolver::Data
  {
    DMUMPS_STRUC_C id;
  };

  namespace
  {
    // MUMPS's control and information arrays are numbered from 1.
    constexpr int
    at(const int fortran_index)
    {
      return fortran_index - 1;
    }

    // INFOG(1) in words. The workspace codes are grouped: MUMPS estimates
    // its workspace in the analysis, and the delayed pivots of the
    // contact rows can exceed it; factorize() retries on these with more.
    std::string
    error_text(const int infog1, const int infog2)
    {
      switch (infog1)
        {
          case -10:
            return "the matrix is numerically singular";
          case -13:
            return "out of memory";
          case -8:
          case -9:
          case -14:
          case -15:
          case -17:
          case -20:
            return "its workspace is too small";
          default:
            return "MUMPS error INFOG(1) = " + std::to_string(infog1) +
                   ", INFOG(2) = " + std::to_string(infog2);
        }
    }

    // A nested-dissection order of the matrix's unknowns by METIS, from the
    // entries (row, column), numbered from 1, of the whole matrix: the
    // position of each unknown in the pivot order, from 1 (MUMPS's PERM_IN).
    // Empty if METIS fails. On the rings its LU takes fewer flops than with the
    // PORD order MUMPS chooses itself (doc/validation.md, "Time and memory
    // behind the code's choices"), which also varies from run to run with the
    // order in which the processes' entries reach it; METIS's, from the sorted
    // graph, does not.
    std::vector<int>
    nested_dissection_order(const int               n,
                            const std::vector<int> &rows,
                            const std::vector<int> &columns)
    {
      // The graph of the symmetrised pattern without its diagonal, in
      // compressed rows: count, fill, then sort and merge each row.
      std::vector<idx_t> start(n + 1, 0);
      for (std::size_t k = 0; k < rows.size(); ++k)
        if (rows[k] != columns[k])
          {
            ++start[rows[k]];
            ++start[columns[k]];
          }
      for (int i = 0; i < n; ++i)
        start[i + 1] += start[i];
      std::vector<idx_t> neighbours(start[n]);
      {
        std::vector<idx_t> next(start.begin(), start.end() - 1);
        for (std::size_t k = 0; k < rows.size(); ++k)
          if (rows[k] != columns[k])
            {
              const int i = rows[k] - 1, j = columns[k] - 1;
              neighbours[next[i]++] = j;
              neighbours[next[j]++] = i;
            }
      }
      idx_t kept = 0;
      for (int i = 0; i < n; ++i)
        {
          const auto first = neighbours.begin() + start[i];
          const auto last  = neighbours.begin() + start[i + 1];
          std::sort(first, last);
          const idx_t row_begin = kept;
          for (auto j = first; j != last; ++j)
            if (j == first || *j != *(j - 1))
              neighbours[kept++] = *j;
          start[i] = row_begin;
        }
      start[n] = kept;

      idx_t              n_vertices = n;
      std::vector<idx_t> permutation(n), position(n);
      idx_t              options[METIS_NOPTIONS];
      METIS_SetDefaultOptions(options);
      if (METIS_NodeND(&n_vertices,
                       start.data(),
                       neighbours.data(),
                       nullptr,
                       options,
                       permutation.data(),
                       position.data()) != METIS_OK)
        return {};
      // METIS's iperm: unknown i is the position[i]-th pivot.
      std::vector<int> order(n);
      for (int i = 0; i < n; ++i)
        order[i] = static_cast<int>(position[i]) + 1;
      return order;
    }
  } // namespace

  MumpsSolver::MumpsSolver(const MPI_Comm communicator)
      : communicator(communicator)
      , data(std::make_unique<Data>())
  {
    // JOB = -1 initializes the instance on every process of the
    // communicator and sets the default controls: the controls are
    // changed after it, or it would overwrite them.
    DMUMPS_STRUC_C &id = data->id;
    id.comm_fortran    = static_cast<MUMPS_INT>(MPI_Comm_c2f(communicator));
    id.par             = 1; // process 0 works too
    id.sym             = 0; // unsymmetric: contact and follower loads
    run(-1);
    // Silent (ICNTL(1)-(4): no output streams, no messages); the matrix
    // distributed as each process's rows (ICNTL(18) = 3); the right-hand
    // side dense and centralized on process 0 (ICNTL(20) = 0), the solution
    // distributed (ICNTL(21) = 1, see solve()).
    for (const int stream : {1, 2, 3})
      id.icntl[at(stream)] = -1;
    id.icntl[at(4)]  = 0;
    id.icntl[at(18)] = 3;
    id.icntl[at(20)] = 0;
    id.icntl[at(21)] = 1;
    // Room for the pivoting of the contact rows, whose diagonal is zero
    // (MUMPS's default is 20 %).
    id.icntl[at(14)] = 50;
    // The matrix comes scaled (equilibrate()).
    id.icntl[at(8)] = 0;
  }

  // JOB = -2 frees MUMPS's memory on every process; collective, so the
  // owner destroys the solver on all processes at once (LinearSystem does,
  // and frees the communicator only after it).
  MumpsSolver::~MumpsSolver()
  {
    data->id.job = -2;
    dmumps_c(&data->id);
  }

  // INFOG(1) is the same on every process, so that every process takes
  // the same branch after a phase (retry, throw or go on).
  int
  MumpsSolver::run(const int job)
  {
    data->id.job = job;
    dmumps_c(&data->id);
    return data->id.infog[at(1)];
  }

  // @sect4{The factorization}
  //
  // Once per pattern: the entries' global row and column indices (from 1,
  // as MUMPS numbers them), the pivot order and MUMPS's analysis. At every
  // call: the values in the same order, equilibrated, and the numerical
  // factorization.
  void
  MumpsSolver::factorize(const Epetra_CrsMatrix &matrix,
                         const std::uint64_t     pattern_version)
  {
    DMUMPS_STRUC_C &id = data->id;
    // The entries of this process's rows, in the matrix's storage order.
    const int n_local_rows = matrix.NumMyRows();
    if (!analysed || pattern_version != analysed_version)
      {
        rows.clear();
        columns.clear();
        for (int r = 0; r < n_local_rows; ++r)
          {
            int     n;
            double *v;
            int    *c;
            matrix.ExtractMyRowView(r, n, v, c);
            for (int k = 0; k < n; ++k)
              {
                rows.push_back(matrix.GRID(r) + 1);
                columns.push_back(matrix.GCID(c[k]) + 1);
              }
          }
        values.resize(rows.size());
      }
    // The values in the order of the indices above: Epetra's row views
    // walk each row in the same storage order while the pattern is the
    // same.
    {
      std::size_t at_entry = 0;
      for (int r = 0; r < n_local_rows; ++r)
        {
          int     n;
          double *v;
          int    *c;
          matrix.ExtractMyRowView(r, n, v, c);
          if (at_entry + n > values.size())
            throw std::runtime_error(
              "MUMPS: the matrix's pattern differs from the analysed one");
          for (int k = 0; k < n; ++k)
            values[at_entry++] = v[k];
        }
    }
    // MUMPS keeps pointers to these arrays, not copies: they must live, and
    // keep their order, until the next factorization.
    id.n = matrix.NumGlobalRows();
    equilibrate(id.n);
    id.nnz_loc = static_cast<MUMPS_INT8>(rows.size());
    id.irn_loc = rows.data();
    id.jcn_loc = columns.data();
    id.a_loc   = values.data();
    // `analysed` is cleared first: an analysis that throws leaves the next
    // call to analyse again instead of factorizing with a stale one.
    if (!analysed || pattern_version != analysed_version)
      {
        analysed = false;
        order_unknowns(id.n);
        const int err = run(1);
        if (err < 0)
          throw std::runtime_error("MUMPS's analysis failed: " +
                                   error_text(err, id.infog[at(2)]));
        analysed         = true;
        analysed_version = pattern_version;
        ++counts.analyses;
      }
    // Short of workspace (the pivoting delayed more than estimated): more,
    // and again. ICNTL(14) is the extra workspace in per cent of the
    // estimate: 50, then 100, 200 and 400, after which the error is given.
    // The increase stays for the later factorizations of the run.
    for (int attempt = 0;; ++attempt)
      {
        const int err = run(2);
        if (err >= 0)
          {
            ++counts.factorizations;
            counts.flops = id.rinfog[at(3)];
            return;
          }
        const bool workspace =
          error_text(err, 0) == "its workspace is too small";
        if (!workspace || attempt == 3)
          throw std::runtime_error("MUMPS's factorization failed: " +
                                   error_text(err, id.infog[at(2)]));
        id.icntl[at(14)] *= 2;
      }
  }

  // The matrix scaled, D_r A D_c, as LAPACK's equilibration does
  // (dgeequb): each row divided by its largest entry, then each column by
  // its largest; the factors are powers of 2, so that the scaling is
  // exact. The multiplier rows and columns (entries int Phi N ds, of the
  // order of a segment's length) and the stiffness rows (of the order of
  // Young's modulus) are twelve orders of magnitude apart on the rings,
  // and threshold pivoting compares the entries of a column across rows:
  // a scaling is its usual safeguard, and MUMPS's default. (The rings and
  // the saddle point of the test mumps_solver solve as accurately without
  // one; a badly scaled pivot needs less regular matrices.) MUMPS's own
  // iterative scaling, redone at every factorization of a distributed matrix,
  // cost a noticeable part of each factorization (doc/validation.md, "Time and
  // memory behind the code's choices"); this one is two passes over the entries
  // and two sums. It is applied here, to the entries MUMPS receives, to the
  // right-hand side and to the solution, and MUMPS is told not to scale
  // (ICNTL(8) = 0):
  // scaling arrays handed to MUMPS instead (ICNTL(8) = -1) are freed by
  // MUMPS when it ends (valgrind: free() of the caller's arrays in
  // dmumps_end_driver).
  void
  MumpsSolver::equilibrate(const int n)
  {
    // 2^-e with 2^(e-1) <= largest < 2^e: the scaled largest entry lies in
    // [1/2, 1). A row or column with no nonzero entry keeps the factor 1.
    const auto power_of_two_inverse = [](const double largest) {
      if (!(largest > 0) || !std::isfinite(largest))
        return 1.;
      int exponent;
      std::frexp(largest, &exponent);
      // Below the normal numbers (largest < 2^-1022) 2^-exponent would
      // overflow: the factor stops at 2^1000.
      return std::ldexp(1., std::min(-exponent, 1000));
    };
    // Each process's rows are its own: the others' factors stay 0, below
    // any factor, in the maximum over the processes.
    std::vector<double> largest(n, -1.);
    for (std::size_t k = 0; k < values.size(); ++k)
      largest[rows[k] - 1] =
        std::max(largest[rows[k] - 1], std::abs(values[k]));
    row_scaling.assign(n, 0.);
    for (int i = 0; i < n; ++i)
      if (largest[i] >= 0)
        row_scaling[i] = power_of_two_inverse(largest[i]);
    // The columns' largest entries once the rows are scaled, over all the
    // processes' rows.
    std::fill(largest.begin(), largest.end(), 0.);
    for (std::size_t k = 0; k < values.size(); ++k)
      largest[columns[k] - 1] =
        std::max(largest[columns[k] - 1],
                 row_scaling[rows[k] - 1] * std::abs(values[k]));
    // The row factors of every process are needed whole on each too:
    // solve() scales the whole right-hand side, hence the second
    // all-reduce.
    column_scaling.resize(n);
    for (auto [mine, all] : {std::make_pair(&largest, &column_scaling),
                             std::make_pair(&row_scaling, &row_scaling)})
      {
        const int ierr =
          MPI_Allreduce(mine == all ? MPI_IN_PLACE : mine->data(),
                        all->data(),
                        n,
                        MPI_DOUBLE,
                        MPI_MAX,
                        communicator);
        AssertThrowMPI(ierr);
      }
    for (int i = 0; i < n; ++i)
      {
        column_scaling[i] = power_of_two_inverse(column_scaling[i]);
        if (row_scaling[i] == 0)
          row_scaling[i] = 1; // a row without entries: singular anyway
      }
    for (std::size_t k = 0; k < values.size(); ++k)
      // One factor at a time: for subnormal entries their product
      // overflows.
      values[k] =
        values[k] * row_scaling[rows[k] - 1] * column_scaling[columns[k] - 1];
  }

  // The pivot order for the analysis: the whole pattern gathered on process
  // 0 (where MUMPS's analysis gathers it too) and ordered there by METIS;
  // MUMPS's own choice if METIS fails.
  void
  MumpsSolver::order_unknowns(const int n)
  {
    DMUMPS_STRUC_C &id        = data->id;
    const unsigned  n_process = Utilities::MPI::n_mpi_processes(communicator);
    const bool      host = Utilities::MPI::this_mpi_process(communicator) == 0;
    // Each process's entries, in the order of the processes, on process 0
    // (one process: a copy of its own; MPI_Gatherv copies the root's part
    // too, so that one process and several take the same path).
    const int        mine = static_cast<int>(rows.size());
    std::vector<int> counts(n_process), offsets(n_process + 1, 0);
    int              ierr =
      MPI_Gather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, communicator);
    AssertThrowMPI(ierr);
    for (unsigned p = 0; p < n_process; ++p)
      offsets[p + 1] = offsets[p] + counts[p];
    std::vector<int> all_rows(host ? offsets[n_process] : 0),
      all_columns(host ? offsets[n_process] : 0);
    for (auto [mine_part, all_part] : {std::make_pair(&rows, &all_rows),
                                       std::make_pair(&columns, &all_columns)})
      {
        ierr = MPI_Gatherv(mine_part->data(),
                           mine,
                           MPI_INT,
                           all_part->data(),
                           counts.data(),
                           offsets.data(),
                           MPI_INT,
                           0,
                           communicator);
        AssertThrowMPI(ierr);
      }
    // Only process 0 knows whether METIS succeeded; every process sets
    // the same ICNTL(7) from it (1: PERM_IN given, 7: MUMPS's own choice).
    int ordered = 0;
    if (host)
      {
        pivot_order = nested_dissection_order(n, all_rows, all_columns);
        ordered     = pivot_order.empty() ? 0 : 1;
      }
    ierr = MPI_Bcast(&ordered, 1, MPI_INT, 0, communicator);
    AssertThrowMPI(ierr);
    id.perm_in      = host && ordered ? pivot_order.data() : nullptr;
    id.icntl[at(7)] = ordered ? 1 : 7;
  }

  // The right-hand side centralized on process 0, the solution left
  // distributed as MUMPS's processes hold it (ICNTL(21) = 1) and gathered on
  // every process from there: a centralized solution is first gathered on
  // process 0 by MUMPS, then sent to the others.
  void
  MumpsSolver::solve(const Vector<double> &b, Vector<double> &x)
  {
    // The system solved is (D_r A D_c) y = D_r b, and x = D_c y: the row
    // factors scale b here, the column factors the solution below.
    DMUMPS_STRUC_C &id   = data->id;
    const bool      host = Utilities::MPI::this_mpi_process(communicator) == 0;
    rhs.resize(b.size());
    for (std::size_t i = 0; i < rhs.size(); ++i)
      rhs[i] = row_scaling[i] * b[i];
    id.rhs  = host ? rhs.data() : nullptr;
    id.nrhs = 1;
    id.lrhs = static_cast<MUMPS_INT>(rhs.size());
    // INFO(23): how many solution entries this process holds.
    const int mine = id.info[at(23)];
    // At least one entry: MUMPS is handed a valid pointer even by a
    // process that holds no pivot.
    solution_part.resize(std::max(mine, 1));
    solution_indices.resize(std::max(mine, 1));
    id.sol_loc    = solution_part.data();
    id.isol_loc   = solution_indices.data();
    id.lsol_loc   = mine;
    const int err = run(3);
    if (err < 0)
      throw std::runtime_error("MUMPS's solve failed: " +
                               error_text(err, id.infog[at(2)]));
    const unsigned int n_process =
      Utilities::MPI::n_mpi_processes(communicator);
    std::vector<int> counts(n_process), offsets(n_process + 1, 0);
    int              ierr =
      MPI_Allgather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, communicator);
    AssertThrowMPI(ierr);
    for (unsigned int p = 0; p < n_process; ++p)
      offsets[p + 1] = offsets[p] + counts[p];
    // Each unknown is a pivot of exactly one process: the parts together
    // are the whole solution, once.
    AssertThrow(offsets[n_process] == static_cast<int>(b.size()),
                ExcMessage("MUMPS's distributed solution is not whole"));
    all_solution_parts.resize(b.size());
    all_solution_indices.resize(b.size());
    ierr = MPI_Allgatherv(solution_part.data(),
                          mine,
                          MPI_DOUBLE,
                          all_solution_parts.data(),
                          counts.data(),
                          offsets.data(),
                          MPI_DOUBLE,
                          communicator);
    AssertThrowMPI(ierr);
    ierr = MPI_Allgatherv(solution_indices.data(),
                          mine,
                          MPI_INT,
                          all_solution_indices.data(),
                          counts.data(),
                          offsets.data(),
                          MPI_INT,
                          communicator);
    AssertThrowMPI(ierr);
    // The parts come in the processes' order, each in MUMPS's order of
    // its pivots: x is put together by the gathered indices, not by
    // position.
    x.reinit(b.size());
    for (std::size_t k = 0; k < b.size(); ++k)
      {
        const int i = all_solution_indices[k] - 1;
        x[i]        = column_scaling[i] * all_solution_parts[k];
      }
  }

} // namespace RingContact
