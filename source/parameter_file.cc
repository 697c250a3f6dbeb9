#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <ring_contact/parameter_file.h>
#include <ring_contact/utilities.h>

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

    std::string
    in_quotes(const std::string &text)
    {
      return "'" + printable(text) + "'";
    }

    // Reads one file (and those it includes) into the ParameterHandler.
    class Reader
    {
    public:
      Reader(ParameterHandler &prm)
          : prm(prm)
      {}

      void
      read(const std::string &filename)
      {
        read_file(filename, 0);
      }

      std::map<std::string, EntryOrigin> origins;

    private:
      ParameterHandler        &prm;
      std::vector<std::string> path;          // subsections entered
      std::vector<std::string> include_stack; // canonical file names

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
        const std::string canonical = fs::weakly_canonical(filename).string();
        include_stack.push_back(canonical);
        const std::size_t depth_at_start = path.size();

        // A UTF-8 byte order mark (some editors write one) is not text.
        const bool         bom = text.compare(0, 3, "\xEF\xBB\xBF") == 0;
        std::istringstream in(bom ? text.substr(3) : text);
        std::string        raw;
        unsigned int       line_number = 0;
        while (std::getline(in, raw))
          {
            ++line_number;
            const unsigned int first_line = line_number;
            // A backslash at the end continues the line.
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

      [[noreturn]] void
      fail(const std::string &file,
           const unsigned int line,
           const std::string &what) const
      {
        throw std::runtime_error(file + ":" + std::to_string(line) + ": " +
                                 what);
      }

      void
      scan_line(std::string        line,
                const std::string &file,
                const unsigned int line_number,
                const unsigned int depth)
      {
        const std::string original = line;
        for (const char c : line)
          if ((static_cast<unsigned char>(c) < 0x20 && c != '\t' &&
               c != '\r') ||
              c == 0x7F)
            fail(file,
                 line_number,
                 "the line " + in_quotes(original) +
                   " holds a control character: not a text parameter "
                   "file?");
        if (line.find('#') != std::string::npos)
          line.erase(line.find('#'));
        for (char &c : line)
          if (c == '\t' || c == '\r')
            c = ' ';
        line = Utilities::trim(line);
        if (line.empty())
          return;

        const auto starts_with = [&](const std::string &keyword) {
          return line.compare(0, keyword.size(), keyword) == 0;
        };
        if (starts_with("subsection ") || starts_with("SUBSECTION "))
          {
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
          {
            const std::size_t equal = line.find('=');
            if (equal == std::string::npos)
              fail(file,
                   line_number,
                   "the line " + in_quotes(original) +
                     " has no '=' (set <entry> = <value>)");
            const std::string entry =
              Utilities::trim(line.substr(4, equal - 4));
            const std::string value = Utilities::trim(line.substr(equal + 1));
            const std::string where =
              in_quotes(entry) +
              (path.empty() ? std::string(" (top level)") :
                              " in subsection " + in_quotes(subsection_name()));
            try
              {
                prm.set(entry, value);
              }
            catch (const ParameterError &e)
              {
                // The entry's own check (its action) refused the value.
                fail(file, line_number, e.what());
              }
            catch (const ParameterHandler::ExcEntryUndeclared &)
              {
                fail(file,
                     line_number,
                     "no entry " + where +
                       " (ring_contact --print-parameters lists them)");
              }
            catch (const dealii::ExceptionBase &e)
              {
                // "The string <value> does not match the given pattern
                // <description>.": keep the description, quote the value
                // ourselves (escaped).
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
            origins[entry_key(subsection_name(), entry)] = {file, line_number};
          }
        else if (starts_with("include ") || starts_with("INCLUDE "))
          {
            const std::string name = Utilities::trim(line.substr(8));
            if (depth + 1 >= max_include_depth)
              fail(file,
                   line_number,
                   "includes are nested deeper than " +
                     std::to_string(max_include_depth) + " files");
            // The including file's folder first, then (deal.II's rule)
            // the current folder.
            fs::path included(name);
            if (included.is_relative())
              {
                const fs::path beside = fs::path(file).parent_path() / name;
                if (fs::exists(beside) || !fs::exists(included))
                  included = beside;
              }
            const std::string canonical =
              fs::weakly_canonical(included).string();
            for (const auto &open : include_stack)
              if (open == canonical)
                fail(file,
                     line_number,
                     "'include " + printable(name) +
                       "' is an include loop: that file is already being "
                       "read");
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
        else
          fail(file,
               line_number,
               "cannot read the line " + in_quotes(original) +
                 " (expected 'set', 'subsection', 'end' or 'include')");
      }
    };
  } // namespace

  std::string
  entry_key(const std::string &subsection, const std::string &entry)
  {
    return subsection + "/" + entry;
  }

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
    std::ifstream in(filename, std::ios::binary);
    if (!in)
      throw std::runtime_error(role + " " + name +
                               " cannot be opened: " + std::strerror(errno));
    std::string text(size, '\0');
    in.read(text.data(), static_cast<std::streamsize>(size));
    if (in.bad() || static_cast<std::size_t>(in.gcount()) != size)
      throw std::runtime_error("cannot read " + role + " " + name +
                               " (I/O error)");
    return text;
  }

  std::map<std::string, EntryOrigin>
  read_parameter_file(ParameterHandler &prm, const std::string &filename)
  {
    Reader reader(prm);
    reader.read(filename);
    return reader.origins;
  }
} // namespace RingContact
