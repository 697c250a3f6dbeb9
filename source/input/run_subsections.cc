// @sect3{Run-time parameters: the subsections of the run}
//
// The common subsections that say how a problem is solved and what a run
// writes: the load program, the Newton solver and the output (those of the
// model, Mesh to Contact, are in subsections.cc; the checks against a
// reference pressure are those scenarios' own,
// scenarios/reference_pressure_entries.cc). How an
// entry is declared, checked and documented is told at the top of
// parameters.cc.

#include <ring_contact/base/utilities.h>
#include <ring_contact/input/parameter_checks.h>
#include <ring_contact/input/parameters.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace RingContact
{
  using namespace ParameterChecks;

  // @sect4{Subsection Load program}
  //
  // Which program loads the problem, one of the scenarios' (the rings' ramp and
  // rotation, which the scenarios declare with their entries), and the steps
  // program's entries: the given pseudo-times of a general problem, whose
  // boundary data are expressions of t. Each program's entries are read only by
  // the scenarios that run it (restricted_entries()): a general problem's file
  // that sets the ramp's steps is refused, not run with its own steps as if the
  // line were not there.

  namespace
  {
    // The entry Time points: numbers and ranges from:step:to. Each point lies
    // above the one before, the first above 0: t = 0 is the unloaded state,
    // step 0 of every program.
    std::vector<double>
    parse_time_points(const std::string &text)
    {
      std::vector<double> time_points;
      const std::string   points_text = Utilities::trim(text);
      // A number, or NaN for anything else.
      const auto number = [](const std::string &word) {
        double t = std::nan("");
        try
          {
            t = Utilities::string_to_double(Utilities::trim(word));
          }
        catch (...)
          {}
        return t;
      };
      for (const auto &item : Utilities::split_string_list(points_text))
        {
          const double previous =
            time_points.empty() ? 0.0 : time_points.back();
          const auto parts = Utilities::split_string_list(item, ':');
          if (parts.size() == 3)
            {
              // from:step:to, the points after `from` up to `to`.
              const double from = number(parts[0]), step = number(parts[1]),
                           to = number(parts[2]);
              // The number of steps of the range, kept finite for a zero or
              // negative step, which the check below then refuses by name.
              const double n = std::round((to - from) / std::max(step, 1e-300));
              // `step` must divide to - from to round-off: 0:0.3:1 would
              // otherwise be run with steps of 1/3, which the file did not say.
              require(std::isfinite(from) && std::isfinite(step) &&
                        std::isfinite(to) && from >= previous && step > 0 &&
                        to > from &&
                        std::abs(n * step - (to - from)) <= 1e-9 * (to - from),
                      "Load program",
                      "Time points",
                      "has the range '" + printable(item) +
                        "': a range is from:step:to with from at or after "
                        "the previous point, step > 0 dividing to - from "
                        "(e.g. 0:0.02:1, 1:0.005:2)");
              // Counted before any point is stored: 0:1e-9:1 would otherwise
              // fill the memory before the total was checked.
              require(time_points.size() + n <= LoadParameters::max_steps,
                      "Load program",
                      "Time points",
                      "gives more than " +
                        std::to_string(LoadParameters::max_steps) +
                        " steps (the range '" + printable(item) + "' has " +
                        to_text(n) + ")");
              // Each point from the range's ends, not by adding `step` n times:
              // no round-off accumulates along a long range, and the last point
              // is `to` exactly, where the next range may start.
              for (unsigned int k = 1; k <= n; ++k)
                time_points.push_back(k == n ? to : from + (to - from) * k / n);
              continue;
            }
          // A single number; an item with one colon or more than two is neither
          // a number nor a range, and is refused as not a number.
          const double t = parts.size() == 1 ? number(item) : std::nan("");
          require(std::isfinite(t) && std::abs(t) < 1e300 && t > previous,
                  "Load program",
                  "Time points",
                  "must be increasing finite numbers above 0, got '" +
                    printable(item) + "' in '" + printable(points_text) + "'");
          time_points.push_back(t);
        }
      require(time_points.size() <= LoadParameters::max_steps,
              "Load program",
              "Time points",
              "gives more than " + std::to_string(LoadParameters::max_steps) +
                " steps");
      return time_points;
    }
  } // namespace

  void
  LoadParameters::add_parameters(
    ParameterHandler                                       &prm,
    const std::vector<std::pair<std::string, std::string>> &programs)
  {
    Subsection  s(prm, "Load program");
    std::string names, documentation;
    for (const auto &[name, sentence] : programs)
      {
        names += (names.empty() ? "" : "|") + name;
        documentation +=
          (documentation.empty() ? "" : "; ") + name + ": " + sentence;
      }
    s.add("Program",
          program,
          programs.front().first,
          documentation + ".",
          Patterns::Selection(names));
    s.add("Number of steps",
          number_of_steps,
          "1",
          1,
          max_steps,
          "Program = steps: n equal steps from t = 0 to 1.");
    s.add("Time points",
          "",
          Patterns::Anything(),
          "Program = steps: the pseudo-times at the ends of "
          "the steps, increasing from above 0, e.g. '0.1, "
          "0.5, 1', and ranges from:step:to of equal steps "
          "after 'from' up to 'to', e.g. '0:0.02:1, "
          "1:0.005:2' (empty: 'Number of steps' equal "
          "steps).",
          [this](const std::string &text) {
            time_points = parse_time_points(text);
          });
  }

  // No Time points: 'Number of steps' equal steps from 0 to 1. Done here, not
  // in an action, because the two entries may come in either order.
  void
  LoadParameters::finish()
  {
    if (time_points.empty())
      for (unsigned int k = 1; k <= number_of_steps; ++k)
        time_points.push_back(static_cast<double>(k) / number_of_steps);
  }

  // @sect4{Subsection Newton}
  //
  // The semi-smooth Newton iteration of problem/newton_solver.cc and its linear
  // solver. The defaults are those doc/intro.md states: 12 iterations, after
  // which the step is halved and retried, up to 5 times, and convergence at
  // 1e-10 in scale-free measures.

  void
  NewtonParameters::add_parameters(ParameterHandler &prm)
  {
    Subsection s(prm, "Newton");
    s.add("Maximum iterations",
          max_iterations,
          "12",
          1,
          1000,
          "Newton iterations before the step is cut.");
    // Relative measures with estimated round-off floors, so that one value fits
    // any units and loads: modelisation A at p0 = 1e-200 Pa converges to the
    // same p_A / analytic as at 1e6 Pa (test tiny_scales).
    s.add("Tolerance",
          tolerance,
          "1e-10",
          "Converged when the active set no longer changes and "
          "(a) the residual of the free displacement rows "
          "relative to the reaction forces and (b) the largest "
          "gap of an active contact row relative to the largest "
          "displacement are each below this or at their "
          "round-off floor (10 eps times the magnitude of the "
          "terms of the rows, estimated at every iteration): "
          "scale-free, the same value fits any E, p and radii.",
          {[](const double x) { return x > 0; }, "must be positive", 0});
    s.add("Maximum step cuts",
          max_step_cuts,
          "5",
          0,
          30,
          "How many times a step that fails is halved and "
          "retried before the run stops.");
    // The predictor. For the rings it extrapolates in the pressure and the
    // rotation, for a general problem in the pseudo-time in which its boundary
    // data are written; a step that fails from the extrapolated state is tried
    // again from the last converged one before it is cut.
    s.add("Extrapolate",
          extrapolate,
          "true",
          "Start each step from the linear extrapolation of the "
          "last two converged states.");
    // Off by default: the step's line says how many iterations a step took;
    // the residuals are for whoever studies the convergence.
    s.add("Verbose",
          verbose,
          "false",
          "Print the residual of every Newton iteration (besides the "
          "step's line).");
    // 'auto' keeps a serial run free of MPI (starting it costs about a second):
    // UMFPACK on one process, MUMPS under mpirun. MUMPS asked for on one
    // process starts MPI for itself. The iterative solver is for meshes whose
    // factors do not fit in memory; where both run it was slower than the
    // direct ones at every size measured (doc/validation.md).
    s.add("Linear solver",
          linear_solver,
          "auto",
          {{"auto", LinearSolverType::automatic},
           {"UMFPACK", LinearSolverType::umfpack},
           {"MUMPS", LinearSolverType::mumps},
           {"iterative", LinearSolverType::iterative}},
          "The solver of the Newton systems. auto: UMFPACK on one process, "
          "MUMPS on several (mpirun -np N ring_contact file.prm). UMFPACK is "
          "serial; MUMPS factorizes on every process together, and also runs "
          "on one (MPI is then started for it). Both keep their analysis of "
          "the matrix while the sparsity pattern does not change. iterative: "
          "GMRES with a block preconditioner (algebraic multigrid on the "
          "displacements, an approximate Schur complement for the "
          "multipliers), for meshes too large to factorize; one or several "
          "processes; its iterations are printed with the Newton iterations.");
    s.add("Linear tolerance",
          linear_tolerance,
          "1e-8",
          "Linear solver = iterative: GMRES stops when the "
          "relative residual |K x - b| / |b| is below this "
          "(1e-14 to 1e-7; the Newton iteration converges as "
          "with a direct solver when it is well below the "
          "Newton tolerance).",
          {[](const double x) { return x >= 1e-14 && x <= 1e-7; },
           "must be between 1e-14 and 1e-7"});
  }

  // @sect4{Subsection Output}
  //
  // Results go to results/<name of the .prm> in the folder the program runs in,
  // unlike 'Mesh file', which is relative to the .prm. The folder is held by
  // one run at a time and cleared of an earlier run's files only once the new
  // run's input and mesh are found good (output/output_folder.cc).

  void
  OutputParameters::add_parameters(ParameterHandler &prm)
  {
    Subsection s(prm, "Output");
    s.add("Directory",
          directory,
          "",
          "Where results go; empty: results/<prm file name> in "
          "the current folder.");
    s.add("VTU interval",
          vtu_interval,
          "1",
          0,
          1000000000,
          "Write VTU files every this many steps (0: never; the "
          "last step is always written when > 0).");
    // 0: the highest of the mapping and displacement degrees
    // (problem/postprocessing.cc), the cells written as VTK Lagrange cells of
    // that degree, so that curved edges are shown curved and a Q2 field is not
    // drawn bilinear.
    s.add("VTU subdivisions",
          vtu_subdivisions,
          "0",
          0,
          8,
          "Subdivisions of each cell in the VTU files; 0: the "
          "mapping degree (curved cells are shown curved).");
    s.add("Write history",
          write_history,
          "true",
          "Write history.csv (one row per step and scheme) and "
          "verdicts.csv (one row per check).");
    s.add("Print steps",
          print_steps,
          "true",
          "Print the run's progress: its first line (file, schemes, "
          "results folder), one line per step (step k/N, pseudo-time, "
          "Newton iterations, the checked quantities, elapsed and "
          "remaining time) and a summary at the end.");
    // Switched off in the tests: the times change from run to run, and a test's
    // output is compared line by line with the expected one.
    s.add("Print timing",
          print_timing,
          "true",
          "Print the timing summary at the end, and the direct "
          "solver's factorizations and their flops (switch off in "
          "tests).");
  }

  void
  OutputParameters::finish(const std::string &prm_name)
  {
    if (directory.empty())
      directory = "results/" + prm_name;
  }
} // namespace RingContact
