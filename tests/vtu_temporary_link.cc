// A symbolic link planted under the name of a VTU file's temporary
// (.<name>.tmp, in the results folder) is not written through. The VTU
// files were written by an std::ofstream opened on the temporary's name,
// which follows a link: a link planted there had its target overwritten
// with the run's VTU data, or created where it pointed nowhere yet. The
// history and the lock file already refused links (O_NOFOLLOW); every
// temporary is now made new (O_CREAT | O_EXCL | O_NOFOLLOW).
// - A link that points nowhere yet (a file the run would create, outside
//   the folder) under the name of step 0's bodies' temporary, planted
//   before the run (the run's removal of an earlier run's files keeps to
//   regular files): the run ends at once with a message that names the
//   temporary and says it is a symbolic link, and nothing is created.
// - A link to an existing file under the name of the last step's slave
//   surface temporary, planted while the run is at its first step of eight
//   (Hertz, prm/hertz.prm): the run ends at that step with the same
//   message, the file keeps its contents, and the files of the steps
//   before are whole.
// - A hard link to an existing file, planted the same way (an opening with
//   O_TRUNC emptied what the two names share): the name is removed and the
//   temporary made anew; the file keeps its contents, and the run passes.
#include "run_program.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>

using RingContactTests::check;

namespace
{
  const std::string tag = "nodal";

  // `problem` (a general problem of prm/) with the nodal scheme, Hertz in
  // eight steps.
  std::string
  write_prm(const std::string &name, const std::string &problem)
  {
    std::ofstream prm(name + ".prm");
    prm << "include " SOURCE_DIR "/../prm/" << problem << ".prm\n"
        << "subsection Mesh\n set Mesh file = " SOURCE_DIR "/../meshes/"
        << problem << ".geo\nend\n"
        << "subsection Contact\n set Integration schemes = nodal\nend\n"
        << (problem == "hertz" ?
              "subsection Load program\n set Number of steps = 8\nend\n" :
              "")
        << "subsection Output\n set Directory = " << name
        << "\n set Print timing = false\nend\n"
        << "subsection Newton\n set Verbose = false\nend\n";
    return name + ".prm";
  }

  std::string
  error_line(const RingContactTests::RunResult &result)
  {
    for (const auto &line : result.lines)
      if (line.find("error:") != std::string::npos)
        return line.substr(line.find("error:"));
    return "";
  }

  void
  write_text(const std::string &file, const std::string &text)
  {
    std::ofstream out(file);
    out << text;
  }

  // A link of kind `kind` ("symbolic" or "hard") to `target` under the
  // name of the temporary of `file` in the folder `name`.
  void
  plant(const std::string &name,
        const std::string &file,
        const std::string &target,
        const std::string &kind)
  {
    const std::string temporary = name + "/." + file + ".tmp";
    if (kind == "symbolic")
      std::filesystem::create_symlink(std::filesystem::absolute(target),
                                      temporary);
    else
      std::filesystem::create_hard_link(target, temporary);
  }

  // Hertz, the link planted under the name of step 8's slave temporary
  // while the run prints its first step.
  RingContactTests::RunResult
  plant_during_run(const std::string &name,
                   const std::string &target,
                   const std::string &kind)
  {
    std::filesystem::remove_all(name);
    write_text(target, "the user's own file\n");
    bool planted = false;
    auto result  = RingContactTests::run_program(
      write_prm(name, "hertz"), [&](const std::string &line, const pid_t) {
        if (!planted && line.rfind(" 1/8 ", 0) == 0)
          {
            plant(name, "slave-" + tag + "-0008.vtu", target, kind);
            planted = true;
          }
      });
    check(planted, name + ": planted at step 1");
    check(RingContactTests::file_contents(target) == "the user's own file\n",
          name + ": the link's target is untouched");
    return result;
  }
} // namespace

int
main()
{
  auto &out = RingContactTests::deallog_file;
  {
    const std::string victim = "victim_not_yet_there";
    std::filesystem::remove(victim);
    std::filesystem::remove_all("dangling");
    std::filesystem::create_directory("dangling");
    plant("dangling", "solution-" + tag + "-0000.vtu", victim, "symbolic");
    const auto result =
      RingContactTests::run_program(write_prm("dangling", "two_blocks"));
    const std::string message = error_line(result);
    check(result.exit_code > 1,
          "the run ends with an error: exit code " +
            std::to_string(result.exit_code));
    check(message.find("its temporary file "
                       "'dangling/.solution-" +
                       tag +
                       "-0000.vtu.tmp' "
                       "is a symbolic link, which this program does not "
                       "follow") != std::string::npos,
          "the message names the link: " + message);
    check(!std::filesystem::exists(victim),
          "the file the link points to is not created");
    out << "a symbolic link to nothing at the bodies' temporary of step 0: "
           "exit code "
        << result.exit_code << ", nothing created: " << message << std::endl;
  }
  {
    const auto result =
      plant_during_run("symbolic", "symbolic_target.txt", "symbolic");
    const std::string message = error_line(result);
    check(result.exit_code > 1,
          "the run ends with an error: exit code " +
            std::to_string(result.exit_code));
    check(message.find(".slave-" + tag + "-0008.vtu.tmp' is a symbolic link") !=
            std::string::npos,
          "the message names the link: " + message);
    check(RingContactTests::check_results("symbolic",
                                          "--quiet --allow-temporaries"),
          "the files of the steps before read back whole");
    out << "a symbolic link to a file at step 8's slave temporary: exit code "
        << result.exit_code << ", the file untouched, steps 0 to 7 whole"
        << std::endl;
  }
  {
    const auto result = plant_during_run("hard", "hard_target.txt", "hard");
    check(result.exit_code == 0, "the run passes");
    check(RingContactTests::check_results("hard", "--quiet --rows 8"),
          "the results read back whole");
    out << "a hard link to a file at step 8's slave temporary: the run "
           "passes, the file untouched"
        << std::endl;
  }
}
