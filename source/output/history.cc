// @sect3{The history of a run}
//
// One row per converged step: what the problem class reports after each
// step, what the scenarios read to make their verdicts, and what
// history.csv holds for the report's scripts. The solver's columns are
// fixed; a scenario adds its own quantities by name (the rings' load
// factor and pressure at A, a general problem's checked quantities), so
// that each scenario's history has its own columns and nothing depends on
// a column's position. The file itself is an AppendOnlyFile
// (output_folder.cc): each row is on disk before the next step starts.
#include <ring_contact/output/history.h>

#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace RingContact
{
  // Only the scenario's quantities are searched (the callers ask about
  // those): a fixed column is always there, though has() says false for it.
  bool
  HistoryRow::has(const std::string &name) const
  {
    for (const auto *list : {&leading, &trailing})
      for (const auto &[column, value] : *list)
        if (column == name)
          return true;
    return false;
  }

  // The scenario's quantities first, then the solver's numeric columns.
  // An unknown name is a programming error (a check that names a column
  // the scenario does not report), hence std::logic_error rather than a
  // value that would silently fail or pass the check.
  double
  HistoryRow::value(const std::string &name) const
  {
    for (const auto *list : {&leading, &trailing})
      for (const auto &[column, value] : *list)
        if (column == name)
          return value;
    if (name == "time")
      return time;
    if (name == "newton_iterations")
      return newton_iterations;
    if (name == "step_cuts")
      return step_cuts;
    if (name == "active_nodes")
      return active_nodes;
    if (name == "cells")
      return cells;
    if (name == "unknowns")
      return static_cast<double>(unknowns);
    if (name == "equilibrium_error")
      return equilibrium_error;
    if (name == "action_reaction_error")
      return action_reaction_error;
    throw std::logic_error("the history has no column '" + name + "'");
  }

  // The header's order, which csv_row() below follows value by value: a
  // scenario must give each row its quantities in the order of the names
  // it gives here, since the file is read by column name.
  std::vector<std::string>
  history_columns(const std::vector<std::string> &leading,
                  const std::vector<std::string> &trailing)
  {
    std::vector<std::string> columns = {"scheme", "step", "time"};
    columns.insert(columns.end(), leading.begin(), leading.end());
    for (const char *fixed :
         {"newton_iterations",
          "step_cuts",
          "active_nodes",
          "wall_time",
          "cells",
          "unknowns"})
      columns.emplace_back(fixed);
    columns.insert(columns.end(), trailing.begin(), trailing.end());
    columns.emplace_back("equilibrium_error");
    columns.emplace_back("action_reaction_error");
    return columns;
  }

  namespace
  {
    // Unquoted: the columns are the program's own identifiers
    // (check_2_contact_pressure), and the values of the text column, the
    // scheme names ("Gauss 3"), hold no comma or quote either.
    std::string
    csv_header(const std::vector<std::string> &columns)
    {
      std::string header;
      for (const auto &column : columns)
        header += (header.empty() ? "" : ",") + column;
      return header + "\n";
    }

    // One row, ten significant digits (the invariants, round-off measures,
    // three). Ten digits are what the tests and the report compare
    // (MPI against one process to 1e-9); the invariants are relative
    // errors near round-off, whose three digits say all there is. The
    // default float format, not fixed: loads of 1e-200 and of 1e9 alike.
    std::string
    csv_row(const HistoryRow &r)
    {
      std::ostringstream out;
      out << std::setprecision(10);
      out << r.scheme << ',' << r.step << ',' << r.time;
      for (const auto &[name, value] : r.leading)
        out << ',' << value;
      out << ',' << r.newton_iterations << ',' << r.step_cuts << ','
          << r.active_nodes << ',' << r.wall_time << ',' << r.cells << ','
          << r.unknowns;
      for (const auto &[name, value] : r.trailing)
        out << ',' << value;
      out << std::setprecision(3) << ',' << r.equilibrium_error << ','
          << r.action_reaction_error << '\n';
      return out.str();
    }
  } // namespace

  // The header at once, so that a run stopped before its first converged
  // step still leaves a file a CSV reader opens.
  HistoryFile::HistoryFile(const std::string              &filename,
                           const std::vector<std::string> &columns)
      : file(filename, csv_header(columns))
  {}

  void
  HistoryFile::append(const HistoryRow &row)
  {
    file.append(csv_row(row));
  }
} // namespace RingContact
