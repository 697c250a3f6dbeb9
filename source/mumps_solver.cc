#include <ring_contact/mumps_solver.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_Map.h>
#include <dmumps_c.h>

#include <stdexcept>
#include <string>

namespace RingContact
{
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
  } // namespace

  MumpsSolver::MumpsSolver(const MPI_Comm communicator)
      : communicator(communicator)
      , data(std::make_unique<Data>())
  {
    DMUMPS_STRUC_C &id = data->id;
    id.comm_fortran    = static_cast<MUMPS_INT>(MPI_Comm_c2f(communicator));
    id.par             = 1; // process 0 works too
    id.sym             = 0; // unsymmetric: contact and follower loads
    run(-1);
    // Silent; the matrix distributed as each process's rows; the
    // right-hand side and the solution centralized on process 0.
    for (const int stream : {1, 2, 3})
      id.icntl[at(stream)] = -1;
    id.icntl[at(4)]  = 0;
    id.icntl[at(18)] = 3;
    id.icntl[at(20)] = 0;
    id.icntl[at(21)] = 0;
    // Room for the pivoting of the contact rows, whose diagonal is zero
    // (MUMPS's default is 20 %).
    id.icntl[at(14)] = 50;
  }

  MumpsSolver::~MumpsSolver()
  {
    data->id.job = -2;
    dmumps_c(&data->id);
  }

  int
  MumpsSolver::run(const int job)
  {
    data->id.job = job;
    dmumps_c(&data->id);
    return data->id.infog[at(1)];
  }

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
    id.n       = matrix.NumGlobalRows();
    id.nnz_loc = static_cast<MUMPS_INT8>(rows.size());
    id.irn_loc = rows.data();
    id.jcn_loc = columns.data();
    id.a_loc   = values.data();
    if (!analysed || pattern_version != analysed_version)
      {
        analysed      = false;
        const int err = run(1);
        if (err < 0)
          throw std::runtime_error("MUMPS's analysis failed: " +
                                   error_text(err, id.infog[at(2)]));
        analysed         = true;
        analysed_version = pattern_version;
      }
    // Short of workspace (the pivoting delayed more than estimated): more,
    // and again.
    for (int attempt = 0;; ++attempt)
      {
        const int err = run(2);
        if (err >= 0)
          return;
        const bool workspace =
          error_text(err, 0) == "its workspace is too small";
        if (!workspace || attempt == 3)
          throw std::runtime_error("MUMPS's factorization failed: " +
                                   error_text(err, id.infog[at(2)]));
        id.icntl[at(14)] *= 2;
      }
  }

  void
  MumpsSolver::solve(const Vector<double> &b, Vector<double> &x)
  {
    DMUMPS_STRUC_C &id   = data->id;
    const bool      host = Utilities::MPI::this_mpi_process(communicator) == 0;
    rhs.assign(b.begin(), b.end());
    id.rhs        = host ? rhs.data() : nullptr;
    id.nrhs       = 1;
    id.lrhs       = static_cast<MUMPS_INT>(rhs.size());
    const int err = run(3);
    if (err < 0)
      throw std::runtime_error("MUMPS's solve failed: " +
                               error_text(err, id.infog[at(2)]));
    // The solution, on process 0, to every process.
    x.reinit(b.size());
    if (host)
      std::copy(rhs.begin(), rhs.end(), x.begin());
    const int ierr = MPI_Bcast(
      x.begin(), static_cast<int>(x.size()), MPI_DOUBLE, 0, communicator);
    AssertThrowMPI(ierr);
  }

  double
  MumpsSolver::factorization_flops() const
  {
    return data->id.rinfog[at(3)];
  }
} // namespace RingContact
