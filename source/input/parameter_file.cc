// @sect3{Reading a parameter file}
//
// A `.prm` file in deal.II's syntax, read by our own reader rather than by
// ParameterHandler::parse_input(): deal.II 9.4's parser recursed without
// end on an include loop (a segmentation fault), ran every default when
// given a directory instead of a file, and printed its raw, many-line
// exception for a value such as 1e-320. Here the text is scanned line by
// line and each value handed to ParameterHandler::set(), whose action
// (parameter_checks.h, bound by parameters.cc to the member it sets)
// converts and checks it on the spot; every refusal becomes one line that
// names the file and the line. The reader also returns where each entry
// was set, so that the checks made once the whole file is read (between
// entries, or against the mesh) can name a line too (Parameters::located).
// read_text_file() is the guard shared with the mesh files (gmsh_file.cc)
// and .geo scripts: only regular files of a bounded size are read.
#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <ring_contact/input/parameter_file.h>
#include <ring_contact/base/utilities.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace RingContact
{
  namespace
  {
    namespace fs = std::filesystem;

    // Parameter files are a few kilobytes; a megabyte is certainly not one.
    constexpr std::size_t max_parameter_file_bytes = 1 << 20;
    // Deeper than this, an include chain is a mistake (or a loop through
    // different names of one file that canonical paths did not unmask).
    constexpr unsigned int max_include_depth = 16;

    // A value or a line quoted in a message, escaped: the bytes of a binary
    // file are never written raw to the terminal.
    std::string
    in_quotes(const std::string &text)
    {
      return "'" + printable(text) + "'";
    }

    // Reads one file (and those it includes) into the ParameterHandler.
    // Its state is the subsections entered (for the messages and the
    // origins' keys) and the files being read (for the loop check); an
    // error ends the whole read, so neither is unwound on the way out.
    class Reader
    {
    public:
      Reader(ParameterHandler                         &prm,
             const std::map<std::string, std::string> &moved)
          : prm(prm)
          , moved(moved)
      {}

      void
      read(const std::string &filename)
      {
        read_file(filename, 0);
      }

      // The command line's `--set "Subsection/Entry=value"`, in their order,
      // after the file: each is the line `set Entry = value` inside its
      // subsections, so that it meets the same checks as the file's lines;
      // its origin (and the place an error names) is "--set k", the k-th of
      // them.
      void
      apply_override(const std::string &assignment, const unsigned int k)
      {
        const std::string where = "--set " + std::to_string(k);
        const std::size_t equal = assignment.find('=');
        const std::size_t slash = assignment.rfind('/', equal);
        if (equal == std::string::npos || slash == std::string::npos ||
            slash == 0)
          fail(where,
               0,
               in_quotes(assignment) +
                 " is not 'Subsection/Entry=value' (for example --set "
                 "\"Newton/Tolerance=1e-9\")");
        const std::vector<std::string> subsections =
          Utilities::split_string_list(assignment.substr(0, slash), '/');
        for (const auto &name : subsections)
          scan_line("subsection " + name, where, 0, 0);
        scan_line("set " + assignment.substr(slash + 1, equal - slash - 1) +
                    " = " + assignment.substr(equal + 1),
                  where,
                  0,
                  0);
        for (std::size_t i = 0; i < subsections.size(); ++i)
          scan_line("end", where, 0, 0);
      }

      std::map<std::string, EntryOrigin> origins;

    private:
      ParameterHandler                         &prm;
      const std::map<std::string, std::string> &moved;
      std::vector<std::string>                  path; // subsections entered
      std::vector<std::string> include_stack;         // canonical file names

      // "A/B" for subsection B inside A: the form of the messages and of
      // entry_key(), which the rest of the program looks entries up by.
      std::string
      subsection_name() const
      {
        std::string name;
        for (const auto &s : path)
          name += (name.empty() ? "" : "/") + s;
        return name;
      }

      void
      read_file(const std::string &filename, const unsigned int depth)
      {
        const std::string text =
          read_text_file(filename, "parameter file", max_parameter_file_bytes);
        // The loop check compares canonical names: a.prm, ./a.prm and
        // ../here/a.prm are one file.
        const std::string canonical = fs::weakly_canonical(filename).string();
        include_stack.push_back(canonical);
        // A file must leave the subsections it enters: an included file
        // left inside one would put its includer's later entries there.
        const std::size_t depth_at_start = path.size();

        // A UTF-8 byte order mark (some editors write one) is not text: the
        // first line used to be refused as 'cannot read the line'.
        const bool         bom = text.compare(0, 3, "\xEF\xBB\xBF") == 0;
        std::istringstream in(bom ? text.substr(3) : text);
        std::string        raw;
        unsigned int       line_number = 0;
        while (std::getline(in, raw))
          {
            ++line_number;
            const unsigned int first_line = line_number;
            // A backslash at the end continues the line (deal.II's syntax;
            // spaces after it are forgiven). The pieces are joined by a
            // space, and an error in the joined line names its first line,
            // where the entry starts.
            std::string line = raw;
            while (!line.empty() && Utilities::trim(line).size() > 0 &&
                   Utilities::trim(line).back() == '\\' &&
                   std::getline(in, raw))
              {
                ++line_number;
                line = Utilities::trim(line);
                line.pop_back();
                line += " " + raw;
              }
            scan_line(line, filename, first_line, depth);
          }
        if (path.size() != depth_at_start)
          throw std::runtime_error(
            filename + ": the file ends inside subsection " +
            in_quotes(path.back()) + " (an 'end' is missing)");
        include_stack.pop_back();
      }

      // Every error is "file:line: what", the form compilers use: one line
      // that an editor or a script can take the place from.
      [[noreturn]] void
      fail(const std::string &file,
           const unsigned int line,
           const std::string &what) const
      {
        // Line 0: a command-line override, named by itself.
        throw std::runtime_error(
          (line == 0 ? file : file + ":" + std::to_string(line)) + ": " +
          what);
      }

      void
      scan_line(std::string        line,
                const std::string &file,
                const unsigned int line_number,
                const unsigned int depth)
      {
        const std::string original = line;
        // A control character means a binary file (a mesh given as the
        // parameter file, a corrupted one): refused at its first line rather
        // than read as entries of garbage. Tabs and the carriage returns of
        // files written on Windows are text.
        for (const char c : line)
          if ((static_cast<unsigned char>(c) < 0x20 && c != '\t' &&
               c != '\r') ||
              c == 0x7F)
            fail(file,
                 line_number,
                 "the line " + in_quotes(original) +
                   " holds a control character: not a text parameter "
                   "file?");
        // '#' starts a comment anywhere on the line, a value included.
        if (line.find('#') != std::string::npos)
          line.erase(line.find('#'));
        for (char &c : line)
          if (c == '\t' || c == '\r')
            c = ' ';
        line = Utilities::trim(line);
        if (line.empty())
          return;

        // The keywords in lower or upper case, as deal.II accepts them.
        const auto starts_with = [&](const std::string &keyword) {
          return line.compare(0, keyword.size(), keyword) == 0;
        };
        if (starts_with("subsection ") || starts_with("SUBSECTION "))
          {
            // A misspelt subsection is named as such, at its own line,
            // rather than as an unknown first entry inside it.
            const std::string name = Utilities::trim(line.substr(11));
            if (!prm.subsection_path_exists({name}))
              fail(file,
                   line_number,
                   "no subsection " + in_quotes(name) +
                     (path.empty() ?
                        std::string() :
                        " in subsection " + in_quotes(subsection_name())) +
                     " (ring_contact --print-parameters lists them)");
            prm.enter_subsection(name);
            path.push_back(name);
          }
        else if (line == "end" || line == "END")
          {
            if (path.empty())
              fail(file, line_number, "'end' without a subsection to leave");
            prm.leave_subsection();
            path.pop_back();
          }
        else if (starts_with("set ") || starts_with("SET "))
          set_entry(line, original, file, line_number);
        else if (starts_with("include ") || starts_with("INCLUDE "))
          include_file(line, file, line_number, depth);
        else
          fail(file,
               line_number,
               "cannot read the line " + in_quotes(original) +
                 " (expected 'set', 'subsection', 'end' or 'include')");
      }

      // "set <entry> = <value>": the value handed to the entry (whose action
      // checks it), every refusal turned into one line that names the file,
      // the line, the entry and its subsection, and where it was set
      // recorded for the messages of later checks.
      void
      set_entry(const std::string &line,
                const std::string &original,
                const std::string &file,
                const unsigned int line_number)
      {
        // The name ends at the first '=': the value may hold more of them
        // (Problem/Constants and Geo parameters are lists of
        // 'name = value').
        const std::size_t equal = line.find('=');
        if (equal == std::string::npos)
          fail(file,
               line_number,
               "the line " + in_quotes(original) +
                 " has no '=' (set <entry> = <value>)");
        const std::string entry = Utilities::trim(line.substr(4, equal - 4));
        const std::string value = Utilities::trim(line.substr(equal + 1));
        const std::string where =
          in_quotes(entry) +
          (path.empty() ? std::string(" (top level)") :
                          " in subsection " + in_quotes(subsection_name()));
        // set() runs the entry's action, which converts and checks the
        // value (a number finite and in range, a choice among its names...)
        // and stores it in its member: a refusal is thrown here, at the
        // line that set it, an included file's line too.
        try
          {
            prm.set(entry, value);
          }
        catch (const ParameterError &e)
          {
            // The entry's own check (its action) refused the value.
            fail(file, line_number, e.what());
          }
        // An entry that no longer exists where the file sets it (the patch
        // test's, once in subsection Mesh) is told where it went: an old
        // file gets a fix, not a bare "no entry".
        catch (const ParameterHandler::ExcEntryUndeclared &)
          {
            const auto now = moved.find(entry_key(subsection_name(), entry));
            if (now != moved.end())
              fail(file,
                   line_number,
                   "the entry " + where + " has moved: " + now->second);
            fail(file,
                 line_number,
                 "no entry " + where +
                   " (ring_contact --print-parameters lists them)");
          }
        catch (const dealii::ExceptionBase &e)
          {
            // "The string <value> does not match the given pattern
            // <description>.": keep the description, quote the value
            // ourselves (escaped). deal.II's message spans several lines
            // with the source location of the check, which says nothing to
            // the user; a long pattern (a selection of many names) is cut.
            std::ostringstream info;
            e.print_info(info);
            const std::string message = info.str();
            const std::string marker  = "the given pattern <";
            const std::size_t at      = message.rfind(marker);
            std::string       allowed;
            if (at != std::string::npos)
              allowed = message.substr(at + marker.size());
            while (!allowed.empty() &&
                   (allowed.back() == '\n' || allowed.back() == '.' ||
                    allowed.back() == '>' || allowed.back() == ' '))
              allowed.pop_back();
            fail(file,
                 line_number,
                 "the value " + in_quotes(value) + " of " + where +
                   " is not allowed" +
                   (allowed.empty() ?
                      std::string() :
                      " (allowed: " + printable(allowed, 200) + ")"));
          }
        // Set twice, the last value counts (deal.II's rule), and so does
        // its line.
        origins[entry_key(subsection_name(), entry)] = {file, line_number};
      }

      // "include <file>": read where the including file lies first, then
      // (deal.II's rule) in the current folder; a loop or a nesting deeper
      // than max_include_depth refused, an error inside named by both files.
      void
      include_file(const std::string &line,
                   const std::string &file,
                   const unsigned int line_number,
                   const unsigned int depth)
      {
        const std::string name = Utilities::trim(line.substr(8));
        if (depth + 1 >= max_include_depth)
          fail(file,
               line_number,
               "includes are nested deeper than " +
                 std::to_string(max_include_depth) + " files");
        // The including file's folder first, then (deal.II's rule)
        // the current folder.
        // Beside the includer first: a file that includes a shared one then
        // works from any current folder. Beside the includer, too, when the
        // file exists in neither place: the error then names the path the
        // author most likely meant.
        fs::path included(name);
        if (included.is_relative())
          {
            const fs::path beside = fs::path(file).parent_path() / name;
            if (fs::exists(beside) || !fs::exists(included))
              included = beside;
          }
        const std::string canonical = fs::weakly_canonical(included).string();
        // A loop is a file included while it is still being read; the same
        // file included twice one after the other is allowed.
        for (const auto &open : include_stack)
          if (open == canonical)
            fail(file,
                 line_number,
                 "'include " + printable(name) +
                   "' is an include loop: that file is already being "
                   "read");
        // An error inside the included file gets this include's place in
        // front of its own: "top.prm:3: in 'include x.prm': x.prm:5: ...".
        try
          {
            read_file(included.lexically_normal().string(), depth + 1);
          }
        catch (const std::exception &e)
          {
            fail(file,
                 line_number,
                 "in 'include " + printable(name) + "': " + e.what());
          }
      }
    };
  } // namespace

  // One key for an entry wherever it is looked up: the origins, the moved
  // entries, and the checks that locate their errors by it.
  std::string
  entry_key(const std::string &subsection, const std::string &entry)
  {
    return subsection + "/" + entry;
  }

  // @sect3{Reading a whole text file, safely}
  //
  // Everything is asked of the file system before a byte is read, each
  // refusal with its own message: the name escaped and cut (a name can be
  // any bytes), a missing file told apart from one that cannot be examined,
  // a directory or a special file (a FIFO, /dev/zero, which would block or
  // never end) refused, and the size bounded before the file is loaded
  // into memory.
  std::string
  read_text_file(const std::string &filename,
                 const std::string &role,
                 const std::size_t  max_bytes)
  {
    const std::string name = "'" + printable(filename, 200) + "'";
    std::error_code   error;
    const auto        status = fs::status(filename, error);
    if (filename.empty())
      throw std::runtime_error(role + ": no file name given");
    // Before `error`: status() reports a missing file as an error too, and
    // "does not exist" says more than the system's message.
    if (status.type() == fs::file_type::not_found)
      throw std::runtime_error(role + " " + name + " does not exist");
    if (error)
      throw std::runtime_error(role + " " + name +
                               " cannot be examined: " + error.message());
    if (status.type() == fs::file_type::directory)
      throw std::runtime_error(role + " " + name +
                               " is a directory, not a file");
    if (status.type() != fs::file_type::regular)
      throw std::runtime_error(role + " " + name + " is not a regular file");
    const auto size = fs::file_size(filename, error);
    if (error)
      throw std::runtime_error(role + " " + name +
                               " cannot be examined: " + error.message());
    if (size > max_bytes)
      throw std::runtime_error(role + " " + name + " has " +
                               std::to_string(size) + " bytes, more than the " +
                               std::to_string(max_bytes) + " accepted");
    // In binary, the bytes as they are: the callers judge them (the
    // parameter reader refuses control characters, gmsh reads binary
    // meshes).
    std::ifstream in(filename, std::ios::binary);
    if (!in)
      throw std::runtime_error(role + " " + name +
                               " cannot be opened: " + std::strerror(errno));
    std::string text(size, '\0');
    in.read(text.data(), static_cast<std::streamsize>(size));
    // A file that shrank between the size and the read would leave zeros
    // at the end of the text: an error, not a shorter file.
    if (in.bad() || static_cast<std::size_t>(in.gcount()) != size)
      throw std::runtime_error("cannot read " + role + " " + name +
                               " (I/O error)");
    return text;
  }

  std::map<std::string, EntryOrigin>
  read_parameter_file(ParameterHandler                         &prm,
                      const std::string                        &filename,
                      const std::map<std::string, std::string> &moved,
                      const std::vector<std::string>           &overrides)
  {
    Reader reader(prm, moved);
    reader.read(filename);
    for (unsigned int k = 0; k < overrides.size(); ++k)
      reader.apply_override(overrides[k], k + 1);
    return reader.origins;
  }
} // namespace RingContact
