// What a run reports: one history row per step, the checks of the `.prm`
// (the original's TEST_RESU) turned into verdicts, the CSV file, and the
// VTU/PVD output for ParaView.
#ifndef ring_contact_postprocessing_h
#define ring_contact_postprocessing_h

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/hp/mapping_collection.h>
#include <deal.II/lac/vector.h>

#include <ring_contact/material.h>
#include <ring_contact/output_folder.h>
#include <ring_contact/parameters.h>

#include <map>
#include <ostream>
#include <set>
#include <string>
#include <vector>

namespace RingContact
{
  /// The state after one converged step.
  struct HistoryRow
  {
    std::string  scheme;
    unsigned int step;
    double       time;
    double       load_factor; ///< p / p_check: the pressure p [Pa]
    double       rotation;    ///< rotation parameter s (elements)
    double       pressure_A;
    double       analytic;
    double       relative_error; ///< (pressure_A - analytic) / analytic
    double       l2_relative_error;
    double       pressure_min;
    double       pressure_max;
    unsigned int newton_iterations;
    unsigned int step_cuts;
    unsigned int active_nodes;
    double       wall_time; ///< seconds spent on the step
    /// The invariants (equilibrium.h): the worst body's equilibrium and
    /// the worst pair's action and reaction, relative to their forces.
    double equilibrium_error     = 0;
    double action_reaction_error = 0;
    /// A general problem: the value of each of its checks' quantities.
    std::vector<double> quantities;
  };

  /// One checked value and its outcome.
  struct Verdict
  {
    std::string  scheme;
    std::string  quantity;
    unsigned int step;
    double       value;
    double       reference;
    double       error; ///< relative or absolute, as `relative` says
    double       tolerance;
    bool         pass;
    /// (value - reference) / |reference|, or value - reference.
    bool relative = true;
    /// Where the reference comes from: "closed form", "Code_Aster", "publication", "other code", or "" (not said).
    std::string source;
  };

  /// Turn the history of scheme `scheme` into the verdicts asked for. The
  /// last step is the load program's `n_steps`: a run that stopped before
  /// it fails its checks of the last step ("step not reached"), it does not
  /// check the last step it converged instead.
  std::vector<Verdict>
  evaluate_checks(const CheckParameters         &checks,
                  const std::string             &scheme,
                  const std::vector<HistoryRow> &history,
                  const unsigned int             n_steps);

  /// The verdicts of a general problem's checks (Check 1, 2, ...) from the
  /// quantities of its history rows, the references evaluated at each
  /// row's pseudo-time; a checked step not reached fails, as above.
  std::vector<Verdict>
  evaluate_checks(const ProblemParameters       &problem,
                  const std::string             &scheme,
                  const std::vector<HistoryRow> &history,
                  const unsigned int             n_steps);

  /// The verdict table; returns true if every check passes.
  bool
  print_verdicts(std::ostream &out, const std::vector<Verdict> &verdicts);

  /// verdicts.csv: one row per check (scheme, quantity, step, value,
  /// reference, error, tolerance, PASS/FAIL), for reports; replaced
  /// atomically (the old or the new file, whole).
  void
  write_verdicts(const std::string          &filename,
                 const std::vector<Verdict> &verdicts);

  /// history.csv with a header row, replaced atomically.
  void
  write_history(const std::string              &filename,
                const std::vector<HistoryRow>  &history,
                const std::vector<std::string> &extra_columns = {});

  /// history.csv as a run writes it: the header, then one row per converged
  /// step, each on disk (fsync'ed) before append() returns; a failed write
  /// throws naming the file and leaves the rows before it whole.
  class HistoryFile
  {
  public:
    /// `extra_columns`: the names of the rows' quantities.
    explicit HistoryFile(const std::string              &filename,
                         const std::vector<std::string> &extra_columns = {});

    void
    append(const HistoryRow &row);

  private:
    AppendOnlyFile file;
  };

  /// VTU of the rings (displacement, Cauchy stress, ring id, contact
  /// pressure) and of the slave surface (contact pressure and gap), and the
  /// PVD records that list them. Every file is written under a temporary
  /// name and renamed, the VTU files first, then the PVD file that lists
  /// them: a PVD on disk lists only whole VTU files.
  class VtuWriter
  {
  public:
    /// With several processes in `communicator`, write() is collective:
    /// each process writes the cells of its subdomain as a piece
    /// (solution-<tag>-<step>.<process>.vtu), process 0 the .pvtu that
    /// lists them, the slave surface and the .pvd files; a file that one
    /// process cannot write is an error of all.
    VtuWriter(const std::string &directory,
              const std::string &tag,
              const unsigned int subdivisions,
              const MPI_Comm     communicator = MPI_COMM_SELF);

    void
    write(const DoFHandler<2>                    &dof_handler,
          const hp::MappingCollection<2>         &mapping,
          const Vector<double>                   &solution,
          const Vector<double>                   &nodal_gap,
          const std::map<unsigned int, Material> &materials,
          const std::set<types::boundary_id>     &slave_boundary_ids,
          const unsigned int                      step,
          const double                            time);

  private:
    void
    write_slave_surface(const DoFHandler<2>                &dof_handler,
                        const hp::MappingCollection<2>     &mapping,
                        const Vector<double>               &solution,
                        const Vector<double>               &nodal_gap,
                        const std::set<types::boundary_id> &slave_boundary_ids,
                        const unsigned int                  step,
                        const DataOutBase::VtkFlags        &flags);
    template <int patch_dim>
    void
    write_vtu_file(const DataOutInterface<patch_dim, 2> &data,
                   const std::string                    &filename) const;
    static void
    record(std::vector<std::pair<double, std::string>> &records,
           const double                                 time,
           const std::string                           &name);
    static std::string
    pvd_contents(const std::vector<std::pair<double, std::string>> &records);

    const std::string                           directory;
    const std::string                           tag;
    const unsigned int                          subdivisions;
    const MPI_Comm                              communicator;
    std::vector<std::pair<double, std::string>> bulk_records;
    std::vector<std::pair<double, std::string>> surface_records;
  };
} // namespace RingContact

#endif
