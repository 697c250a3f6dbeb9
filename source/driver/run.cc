// @sect3{The run: the schemes, the results folder, the verdicts}
//
// The run's driver (run.h): the scheme loop, the results folder, the
// verdicts and the exit code. main() reads the parameters and sets up MPI
// and the signals; what happens between the file read and the exit code
// is here. A run solves its problem once per contact integration scheme,
// each scheme in a ContactProblem of its own; the driver owns the files
// that outlive a scheme (the folder's lock, history.csv, verdicts.csv),
// so that the problem class only reports converged steps through an
// observer and never decides when the run stops. The exit code is 0 when
// every step converged and every check passed, 1 otherwise, and 128 + the
// signal after a stop by SIGINT or SIGTERM (130, 143), the shell's code
// for a process ended by a signal.
#include <ring_contact/base/utilities.h>
#include <ring_contact/config.h>
#include <ring_contact/driver/mpi_session.h>
#include <ring_contact/driver/run.h>
#include <ring_contact/driver/run_log.h>
#include <ring_contact/driver/signals.h>
#include <ring_contact/linear_algebra/linear_system.h>
#include <ring_contact/output/history.h>
#include <ring_contact/output/output_folder.h>
#include <ring_contact/output/progress.h>
#include <ring_contact/output/verdicts.h>
#include <ring_contact/problem/contact_problem.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <type_traits>

namespace RingContact
{
  namespace Driver
  {
    namespace
    {
      // "history.csv, verdicts.csv, 42 .vtu, 4 .pvd": the removed files in
      // one line, the two CSV files by name and the rest counted by kind
      // (a hidden name is a temporary left by a killed run).
      std::string
      describe_files(const std::vector<std::string> &names)
      {
        std::map<std::string, unsigned int> by_kind;
        std::string                         text;
        for (const auto &name : names)
          {
            const auto dot = name.rfind('.');
            const bool listed_by_name =
              name == "history.csv" || name == "verdicts.csv" ||
              name == "used_parameters.prm" || name == "run.log";
            if (listed_by_name)
              text += (text.empty() ? "" : ", ") + name;
            else
              ++by_kind[name.front() == '.' ? "temporary" : name.substr(dot)];
          }
        for (const auto &[kind, n] : by_kind)
          text += (text.empty() ? "" : ", ") + std::to_string(n) + " " + kind;
        return text;
      }

      // The output folder, held for the whole run (a run that writes no
      // file leaves the folder alone); process 0 holds it and writes the
      // history and the verdicts. An earlier run's files go, and the
      // history starts, once the first scheme is set up: a run whose input
      // or mesh fails leaves them.
      class ResultsFolder
      {
      public:
        ResultsFolder(const OutputParameters &output,
                      const MPI_Comm          world,
                      std::ostream           &out)
            : output(output)
            , world(world)
            , out(out)
            , writes_files(output.write_history || output.vtu_interval > 0)
        {
          // Taken at once, before any scheme is set up: a second run into
          // the folder is refused before it spends time on a mesh.
          if (writes_files)
            on_process_zero(world, [&]() {
              folder = std::make_unique<OutputFolder>(output.directory);
            });
        }

        // Before the first step of the first scheme (the problem's start
        // observer), once the input and the mesh have been found good.
        void
        prepare(const std::vector<std::string> &columns)
        {
          if (ready || !writes_files)
            return;
          ready = true;
          on_process_zero(world, [&]() {
            const auto removed = folder->remove_earlier_results();
            if (!removed.empty())
              out << wrap_text("Removed from " + output.directory + " the " +
                               std::to_string(removed.size()) +
                               " files of an earlier run (" +
                               describe_files(removed) + ")");
            if (output.write_history)
              history =
                std::make_unique<HistoryFile>(output.directory + "/history.csv",
                                              columns);
          });
          // Each process writes its piece of the VTU files into the folder,
          // the first (step 0) right after this: none may write before
          // process 0 has removed the earlier run's files, or a new piece
          // could be removed with them.
          if (n_processes(world) > 1)
            MPI_Barrier(world);
        }

        // Both called by every process: on_process_zero() is collective
        // (it broadcasts process 0's failure), so its condition must not
        // depend on which process holds the file.
        void
        append(const HistoryRow &row)
        {
          if (output.write_history)
            on_process_zero(world, [&]() { history->append(row); });
        }

        /// The parameters as they ran, beside the results.
        void
        record_parameters(const std::string &text)
        {
          if (writes_files && !text.empty())
            on_process_zero(world, [&]() {
              write_file_atomically(output.directory + "/used_parameters.prm",
                                    text);
              RunLog::attach(output.directory + "/run.log");
            });
        }

        void
        write_verdicts(const std::vector<Verdict> &verdicts)
        {
          if (output.write_history)
            on_process_zero(world, [&]() {
              RingContact::write_verdicts(output.directory + "/verdicts.csv",
                                          verdicts);
            });
        }

        /// This run's files in the folder, in one line (describe_files());
        /// empty where the run writes none.
        std::string
        contents() const
        {
          if (!writes_files)
            return "";
          std::vector<std::string> names;
          std::error_code          error;
          for (const auto &entry :
               std::filesystem::directory_iterator(output.directory, error))
            {
              const std::string name = entry.path().filename().string();
              if (OutputFolder::is_result_file(name) && name.front() != '.')
                names.push_back(name);
            }
          std::sort(names.begin(), names.end());
          return describe_files(names);
        }

      private:
        const OutputParameters       &output;
        const MPI_Comm                world;
        std::ostream                 &out;
        const bool                    writes_files;
        bool                          ready = false;
        std::unique_ptr<OutputFolder> folder;
        std::unique_ptr<HistoryFile>  history;
      };

      // A stop asked of any process is a stop of all, after the same step.
      // mpirun sends SIGTERM to every process, but a signal sent to one
      // (kill) must not leave the others to solve the next step alone.
      bool
      stop_asked(const MPI_Comm world)
      {
        const bool here = stop_signal != 0;
        return n_processes(world) > 1 ?
                 dealii::Utilities::MPI::logical_or(here, world) :
                 here;
      }

      // The largest process's peak memory (what each machine needs),
      // rounded to the nearest MB.
      void
      print_peak_memory(std::ostream &out, const MPI_Comm world)
      {
        const unsigned int n = n_processes(world);
        const std::size_t  peak =
          n > 1 ? dealii::Utilities::MPI::max(peak_memory(), world) :
                   peak_memory();
        out << "Peak memory: " << (peak + (1 << 19)) / (1 << 20) << " MB"
            << (n > 1 ?
                  " (the largest of " + std::to_string(n) + " processes)" :
                  std::string())
            << "\n";
      }

      std::string
      absolute_path(const std::string &directory)
      {
        std::error_code error;
        const auto      path = std::filesystem::absolute(directory, error);
        return error ? directory : path.lexically_normal().string();
      }

      // The first line of a run: the program, the file, the schemes and
      // where the results go, so that a log read later says what it is.
      std::string
      start_line(const Parameters &parameters)
      {
        const OutputParameters &output = parameters.output;
        std::string             schemes;
        for (const auto &scheme : parameters.contact.schemes)
          schemes += (schemes.empty() ? "" : ", ") + scheme.name();
        const unsigned int n = parameters.contact.schemes.size();
        return wrap_text(
          "ring_contact " RING_CONTACT_VERSION ": " + parameters.prm_file +
          ", " + std::to_string(n) + (n == 1 ? " scheme (" : " schemes (") +
          schemes + "); results in " +
          (output.write_history || output.vtu_interval > 0 ?
             absolute_path(output.directory) :
             std::string("no folder (no history, no VTU output)")));
      }

      // The run's totals, for the line that ends it.
      struct RunSummary
      {
        unsigned int steps = 0, iterations = 0, cuts = 0, schemes = 0;

        void
        add(const std::vector<HistoryRow> &history)
        {
          ++schemes;
          steps += history.size();
          for (const auto &row : history)
            {
              iterations += row.newton_iterations;
              cuts += row.step_cuts;
            }
        }

        std::string
        text(const double                seconds,
             const bool                  solved,
             const std::vector<Verdict> &verdicts) const
        {
          unsigned int passed = 0;
          for (const auto &verdict : verdicts)
            passed += verdict.pass;
          return wrap_text(
            std::string(solved ? "Done: " : "Stopped: ") +
            std::to_string(steps) + (steps == 1 ? " step" : " steps") +
            (schemes > 1 ? " of " + std::to_string(schemes) + " schemes" :
                           std::string()) +
            " in " + format_duration(seconds) + ", " +
            std::to_string(iterations) +
            (iterations == 1 ? " Newton iteration, " : " Newton iterations, ") +
            std::to_string(cuts) +
            (cuts == 1 ? " step cut; " : " step cuts; ") +
            (verdicts.empty() ?
               std::string("no checks") :
               std::to_string(passed) + " of " +
                 std::to_string(verdicts.size()) + " checks pass"));
        }
      };

      // Every scheme, one after the other; the exit code.
      int
      run_schemes(const Parameters &parameters,
                  const MPI_Comm    world,
                  std::ostream     &out,
                  bool             &started)
      {
        const OutputParameters &output = parameters.output;
        ResultsFolder           folder(output, world, out);
        std::vector<Verdict>    verdicts;
        bool                    solved = true, stop = false;
        RunProgress             progress(parameters.contact.schemes.size());
        RunSummary              summary;
        if (output.print_steps)
          out << start_line(parameters);
        // How the file was read, where it needs saying (an entry under its
        // old name): said whether or not the steps are.
        for (const std::string &note : parameters.notes)
          out << wrap_text(note);
        // Each scheme is a problem of its own (its mesh, unknowns and
        // history): the schemes share nothing but the results folder and
        // the verdicts, which accumulate over them.
        // One scheme's problem in the problem's dimension (the scenario's:
        // Parameters::dimension); false if the run is to stop after it.
        const auto run_scheme = [&](const unsigned int s, auto dimension) {
          constexpr int            spacedim = decltype(dimension)::value;
          const auto              &scheme   = parameters.contact.schemes[s];
          ContactProblem<spacedim> problem(parameters, scheme, out, world);
          const auto               columns = problem.history_columns();
          problem.set_progress(progress);
          progress.start_scheme(s);
          // Until the problem starts, an error is a refusal of its input
          // (exit code 2); after, a failure of the run (3).
          started = false;
          problem.set_start_observer([&]() {
            started = true;
            folder.prepare(columns);
            folder.record_parameters(parameters.used_parameters);
          });
          problem.set_step_observer([&](const HistoryRow &row) {
            // Every process takes part (process 0's failure is all of
            // theirs): the condition is the same on all of them.
            folder.append(row);
            stop = stop_asked(world);
            return !stop;
          });
          // run() first: `solved && problem.run()` would skip the later
          // schemes once one failed.
          solved = problem.run() && solved;
          summary.add(problem.history());
          // Asked again: the observer does not run after a failed step,
          // and a signal may come after its last call.
          stop = stop_asked(world);
          // A scheme stopped by a signal before its last step has no
          // verdicts: its checks are not known.
          const auto &history = problem.history();
          if (stop &&
              (history.empty() || history.back().step < problem.n_steps()))
            {
              out << "Stopped after "
                  << (history.empty() ?
                        std::string("no converged step") :
                        "step " + std::to_string(history.back().step))
                  << " of scheme " << scheme.name() << '\n';
              return false;
            }
          // verdicts.csv holds all the schemes done so far, rewritten
          // whole after each: a run stopped later keeps them.
          const auto these = problem.verdicts();
          verdicts.insert(verdicts.end(), these.begin(), these.end());
          folder.write_verdicts(verdicts);
          return true;
        };
        for (unsigned int s = 0; s < parameters.contact.schemes.size(); ++s)
          {
            if (stop)
              break;
            const bool go_on =
              parameters.dimension == 3 ?
                run_scheme(s, std::integral_constant<int, 3>()) :
                run_scheme(s, std::integral_constant<int, 2>());
            if (!go_on)
              break;
          }
        // A stopped run shows the verdicts of its finished schemes, and
        // says on stderr where its complete results are: the converged
        // steps' files, whole.
        if (stop)
          {
            if (!verdicts.empty())
              print_verdicts(out, verdicts);
            out << std::flush;
            const int signal = stopping_signal();
            if (this_process(world) == 0)
              std::cerr << "ring_contact: interrupted by "
                        << signal_name(signal)
                        << ": the converged steps' results are complete"
                        << (output.write_history || output.vtu_interval > 0 ?
                              " in " + output.directory :
                              std::string())
                        << std::endl;
            return 128 + signal;
          }
        if (output.print_timing)
          print_peak_memory(out, world);
        const bool pass = print_verdicts(out, verdicts);
        if (!solved)
          out << "A load step could not be solved (see above).\n";
        if (output.print_steps)
          {
            out << summary.text(progress.elapsed(), solved, verdicts);
            if (const auto files = folder.contents(); !files.empty())
              out << wrap_text("Results in " + absolute_path(output.directory) +
                               ": " + files);
          }
        return !solved ? ExitCode::step_failed :
               pass    ? ExitCode::success :
                         ExitCode::check_failed;
      }
    } // namespace

    int
    run(const Parameters &parameters, const MPI_Comm world)
    {
      // The other processes' log goes nowhere: a stream without a buffer
      // discards what it is given. Every process still runs the same code,
      // so that the collective calls in it match.
      std::ostream  null_stream(nullptr);
      std::ostream &out = this_process(world) == 0 ? std::cout : null_stream;
      // Made before the run, with its own communicator: an error must be
      // reported whatever state the run's communication was left in.
      const ErrorBarrier errors(world);
      bool               started = false;
      // An error before the problem starts refuses the input; one after
      // ends a run that could not be completed.
      const auto code = [&started]() {
        return started ? ExitCode::step_failed : ExitCode::input_refused;
      };
      try
        {
          return run_schemes(parameters, world, out, started);
        }
      catch (const Interrupted &e)
        {
          // Thrown while gmsh meshes a script, in a scheme's set-up. In the
          // first scheme nothing of this run is written yet, and an earlier
          // run's results are as they were; in a later scheme the earlier
          // schemes' files are complete, though the message below says
          // that nothing was written. Every process meshes: one that was
          // not interrupted would not come, hence the barrier with a
          // timeout and the abort.
          const int signal = stopping_signal();
          if (n_processes(world) > 1 && !errors.all_processes_arrive(10))
            MPI_Abort(world, 128 + signal);
          if (this_process(world) == 0)
            std::cerr << "ring_contact: interrupted by " << signal_name(signal)
                      << " " << e.what()
                      << ", before the first step: nothing written"
                      << std::endl;
          return 128 + signal;
        }
      catch (const FactorizationTooLarge &e)
        {
          // The mesh is too large for this machine: the input's fault.
          return errors.fail(one_line_message(e), ExitCode::input_refused);
        }
      catch (const ParameterError &e)
        {
          // A value found wrong once the mesh is known: its file and line.
          return errors.fail(parameters.located(e), ExitCode::input_refused);
        }
      // Before std::exception, which would give the bare "std::bad_alloc":
      // the message names the two ways to a smaller problem.
      catch (const std::bad_alloc &)
        {
          return errors.fail(
            "out of memory (a smaller mesh, or 'Mesh/Sector elements' for "
            "cyclic symmetry)",
            code());
        }
      catch (const std::exception &e)
        {
          return errors.fail(one_line_message(e), code());
        }
      // Anything else, not even a std::exception: still one line and
      // exit code 1 rather than std::terminate.
      catch (...)
        {
          return errors.fail("an unknown exception", code());
        }
    }
  } // namespace Driver
} // namespace RingContact
