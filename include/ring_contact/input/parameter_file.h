// Reading a `.prm` file into a deal.II ParameterHandler so that no input
// crashes, hangs or is misread: the file must be a regular, readable text
// file of sane size; `include` statements are followed with a loop check
// and a depth cap (deal.II's own parser recurses without either); every
// error is one line that names the file, the line, the entry and the value
// (escaped: a binary file is never echoed raw to the terminal). The syntax
// is deal.II's: `subsection`, `end`, `set name = value`, `include file`,
// `#` comments, `\` at the end of a line to continue it.
#ifndef ring_contact_input_parameter_file_h
#define ring_contact_input_parameter_file_h

#include <deal.II/base/parameter_handler.h>

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace RingContact
{
  using namespace dealii;

  /// Where the value of an entry was last set.
  struct EntryOrigin
  {
    std::string  file;
    unsigned int line;
  };

  /// A value that is wrong for its entry: what the check says, and which
  /// entry, so that the caller can name the file and line that set it.
  class ParameterError : public std::runtime_error
  {
  public:
    ParameterError(const std::string &subsection,
                   const std::string &entry,
                   const std::string &message)
        : std::runtime_error(message)
        , subsection(subsection)
        , entry(entry)
    {}
    const std::string subsection;
    const std::string entry;
  };

  /// Read `filename` into `prm` (whose entries are declared). Relative
  /// include paths are taken from the folder of the including file, or, as
  /// deal.II does, from the current folder. Returns, for every entry that a
  /// file sets, "Subsection/Entry" -> where. Throws std::runtime_error with a
  /// one-line message on any error.
  /// `moved` ("Subsection/Entry" -> where it is now) turns an entry that no
  /// longer exists into a message that names its new place.
  std::map<std::string, EntryOrigin>
  read_parameter_file(ParameterHandler                         &prm,
                      const std::string                        &filename,
                      const std::map<std::string, std::string> &moved = {},
                      const std::vector<std::string>           &overrides = {});

  /// The key of read_parameter_file()'s map.
  std::string
  entry_key(const std::string &subsection, const std::string &entry);

  /// The content of a file that must be a regular, readable file of at most
  /// `max_bytes` bytes; `role` ("parameter file", "mesh file") starts the
  /// message of the error, which names the file.
  std::string
  read_text_file(const std::string &filename,
                 const std::string &role,
                 std::size_t        max_bytes);
} // namespace RingContact

#endif
