// The history of a run: one row per converged step, written to
// history.csv as it comes. A row holds the solver's fixed columns (the
// scheme, the step, its pseudo-time, the Newton iterations, the step cuts,
// the active contact nodes, the wall time, and the invariants of
// equilibrium.h) and the quantities the scenario reports, by name: those it
// shows before the solver's columns and those after them. Nothing passes by
// position: a column is found by its name.
#ifndef ring_contact_output_history_h
#define ring_contact_output_history_h

#include <ring_contact/output/output_folder.h>

#include <string>
#include <utility>
#include <vector>

namespace RingContact
{
  /// A quantity of a row: its column name and its value.
  using NamedValue = std::pair<std::string, double>;

  /// The state after one converged step.
  struct HistoryRow
  {
    std::string  scheme;
    unsigned int step              = 0;
    double       time              = 0;
    unsigned int newton_iterations = 0;
    unsigned int step_cuts         = 0;
    unsigned int active_nodes      = 0;
    double       wall_time         = 0; ///< seconds spent on the step
    /// The mesh the step was solved on (adaptive refinement changes it):
    /// active cells and unknowns.
    unsigned int       cells    = 0;
    unsigned long long unknowns = 0;
    /// The invariants (equilibrium.h): the worst body's equilibrium and
    /// the worst pair's action and reaction, relative to their forces.
    double equilibrium_error     = 0;
    double action_reaction_error = 0;
    /// The scenario's quantities before the solver's columns, and after.
    std::vector<NamedValue> leading, trailing;

    /// The value of the column `name` (a quantity of the scenario or a
    /// fixed column); throws if the row has none of that name.
    double
    value(const std::string &name) const;

    /// Whether the row has a column of that name.
    bool
    has(const std::string &name) const;
  };

  /// The columns of history.csv for rows with these leading and trailing
  /// quantities: scheme, step, time, the leading ones, newton_iterations,
  /// step_cuts, active_nodes, wall_time, cells, unknowns, the trailing ones, then
  /// equilibrium_error and action_reaction_error.
  std::vector<std::string>
  history_columns(const std::vector<std::string> &leading,
                  const std::vector<std::string> &trailing);

  /// history.csv as a run writes it: the header, then one row per converged
  /// step, each on disk (fsync'ed) before append() returns; a failed write
  /// throws naming the file and leaves the rows before it whole.
  class HistoryFile
  {
  public:
    HistoryFile(const std::string              &filename,
                const std::vector<std::string> &columns);

    void
    append(const HistoryRow &row);

  private:
    AppendOnlyFile file;
  };
} // namespace RingContact

#endif
