// @sect3{Gmsh files: checked before gmsh reads them, and after}
//
// Every mesh the program does not generate itself comes from gmsh: the
// original meshes of the rings' case (format 1), files a user writes in any
// format gmsh saves, and .geo scripts that gmsh meshes when they are read. The
// reading itself is gmsh's own library, run in a child process
// (gmsh_process.cc); this file stands on both sides of it. Before: a light
// check of the text, because gmsh 4.8's readers trust the file (a low
// count silently drops the rest of a section, a file that is not a mesh is
// run as a script). After: what gmsh returns is held to what the program
// needs (gmsh_checks.cc: the cells and boundary elements of the dimension,
// finite nodes, one physical tag per entity, cells that are not folded).
// The result, a GmshMesh, is made into a triangulation by gmsh_mesh.cc. The
// hand-written reader this replaced lost 19 of 40 fixed segments of a format-1
// file with a low count, crashed on a triangle and read a short element past
// its end: each of those is now a one-line error that names the file.
#include <ring_contact/base/utilities.h>
#include <ring_contact/input/gmsh_checks.h>
#include <ring_contact/input/gmsh_file.h>
#include <ring_contact/input/gmsh_process.h>
#include <ring_contact/input/parameter_file.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <set>
#include <sstream>
#include <stdexcept>

namespace RingContact
{
  namespace Geometry
  {
    namespace
    {
      // A mesh of the rings at 1600 x 120 elements is a small fraction of this
      // in text (doc/validation.md, "Figures that were in the code's
      // comments"); a file much larger than that is not one of ours.
      constexpr std::size_t max_mesh_file_bytes = std::size_t(512) << 20;

      std::string
      in_quotes(const std::string &text)
      {
        return "'" + printable(text) + "'";
      }

      // Whether `filename` ends in `extension`, in any case. The extension
      // decides everything downstream: gmsh picks its reader by it, and a
      // .geo is meshed rather than read.
      bool
      has_extension(const std::string &filename, const std::string &extension)
      {
        if (filename.size() <= extension.size())
          return false;
        for (std::size_t i = 0; i < extension.size(); ++i)
          if (std::tolower(static_cast<unsigned char>(
                filename[filename.size() - extension.size() + i])) !=
              extension[i])
            return false;
        return true;
      }

      // @sect4{The light check of the file, before gmsh sees it}
      //
      // Only the structure that gmsh's readers take on trust is checked:
      // the header, the sections and, where the file is text, the count
      // of lines each section declares. Nodes and elements themselves are
      // parsed by gmsh alone, and their number is compared with the
      // declared counts once gmsh has read them.
      enum class Format
      {
        geo,
        msh1,
        msh2_ascii,
        msh2_binary,
        msh41_ascii,
        msh41_binary
      };

      // What the file says it holds: gmsh must read exactly that.
      struct Declared
      {
        Format      format   = Format::geo;
        std::size_t nodes    = 0;
        std::size_t elements = 0;
      };

      // A whole line that is one non-negative integer (or, with
      // `leading`, starts with `leading` of them). Digits only: no sign (a
      // node -1 in an ASCII 4.1 element crashed gmsh's reader), and at most
      // 19 of them, which std::stoull converts without overflow.
      bool
      read_integers(const std::string        &line,
                    std::vector<std::size_t> &values,
                    const unsigned int        leading,
                    const bool                exact)
      {
        std::istringstream in(line);
        values.clear();
        std::string word;
        while (in >> word)
          {
            if (word.empty() || word.size() > 19 ||
                word.find_first_not_of("0123456789") != std::string::npos)
              return false;
            values.push_back(std::stoull(word));
          }
        return exact ? values.size() == leading : values.size() >= leading;
      }

      // The file's lines, without trailing blanks and carriage returns; a
      // control character refused (a binary file read as ASCII). Carriage
      // returns are stripped so that a file written on Windows compares
      // its end markers like any other.
      std::vector<std::string>
      split_lines(const std::string &filename, const std::string &text)
      {
        std::vector<std::string> lines;
        std::size_t              start = 0;
        while (start < text.size())
          {
            std::size_t end = text.find('\n', start);
            if (end == std::string::npos)
              end = text.size();
            std::string line = text.substr(start, end - start);
            while (!line.empty() && (line.back() == '\r' ||
                                     line.back() == ' ' || line.back() == '\t'))
              line.pop_back();
            for (const char c : line)
              if ((static_cast<unsigned char>(c) < 0x20 && c != '\t') ||
                  c == 0x7F)
                refuse_mesh_file(
                  filename,
                  "line " + std::to_string(lines.size() + 1) +
                    ": a control character (not an ASCII gmsh file?)");
            lines.push_back(line);
            start = end + 1;
          }
        return lines;
      }

      // The count line of a node or element section (one number in formats
      // 1 and 2.2; in 4.1 "numEntityBlocks numItems minTag maxTag") against
      // the lines the section lists (`body`, the count line first); `i` is
      // the section's line. Returns the count.
      std::size_t
      checked_count(const std::string              &filename,
                    const std::vector<std::string> &body,
                    const std::string              &line,
                    const std::size_t               i,
                    const bool                      nodes,
                    const bool                      format_4,
                    const std::size_t               text_size)
      {
        const auto at_line = [&](const std::size_t k, const std::string &what) {
          refuse_mesh_file(filename,
                           "line " + std::to_string(k + 1) + ": " + what);
        };
        const std::string what = nodes ? "node" : "element";
        // The count line: one number in formats 1 and 2.2; in 4.1
        // "numEntityBlocks numItems minTag maxTag".
        std::vector<std::size_t> numbers;
        if (body.empty() ||
            !read_integers(body[0], numbers, format_4 ? 2 : 1, !format_4))
          at_line(i + 1,
                  "the count of section " + in_quotes(line) + " is " +
                    in_quotes(body.empty() ? "" : body[0]) + ", not " +
                    (format_4 ? "'blocks " + what + "s ...'" : "a number"));
        const std::size_t count  = format_4 ? numbers[1] : numbers[0];
        const std::size_t blocks = format_4 ? numbers[0] : 0;
        // Format 4.1: a line per block, then per node a tag line and
        // a coordinate line, per element one line.
        const std::size_t listed = body.size() - 1;
        // Every item takes at least a byte: a count beyond the
        // file's size is a damaged number, and refusing it keeps
        // the line arithmetic below from overflowing.
        if (count > text_size || blocks > text_size)
          at_line(i + 1,
                  "the " + what + " section declares " + std::to_string(count) +
                    " " + what + "s: more than the file can hold");
        // Either way the file is damaged; gmsh would silently drop
        // what a low count leaves out.
        const std::size_t expected =
          blocks + (format_4 && nodes ? 2 * count : count);
        if (listed != expected)
          at_line(i,
                  format_4 ? "the " + what + " section declares " +
                               std::to_string(count) + " " + what + "s in " +
                               std::to_string(blocks) + " blocks (" +
                               std::to_string(expected) + " lines) but has " +
                               std::to_string(listed) + " lines" :
                             "the " + what + " section declares " +
                               std::to_string(count) + " " + what +
                               "s but lists " + std::to_string(listed));
        return count;
      }

      // ASCII: every section closed, one node and one element section, and
      // their lines as many as their counts say (gmsh reads the count and
      // skips what follows: a count lower than the lines would silently
      // drop elements). Control characters are refused: not a text file.
      Declared
      check_ascii(const std::string &filename,
                  const std::string &text,
                  const Format       format)
      {
        const std::vector<std::string> lines    = split_lines(filename, text);
        const bool                     format_1 = format == Format::msh1;
        const bool                     format_4 = format == Format::msh41_ascii;
        const std::string nodes_name            = format_1 ? "$NOD" : "$Nodes";
        const std::string elements_name = format_1 ? "$ELM" : "$Elements";
        // A line number in a message is the file's own (1-based), so that
        // the user can open the file at it.
        Declared declared;
        declared.format          = format;
        bool       have_nodes    = false;
        bool       have_elements = false;
        const auto at_line = [&](const std::size_t i, const std::string &what) {
          refuse_mesh_file(filename,
                           "line " + std::to_string(i + 1) + ": " + what);
        };
        // Section by section: each line at this level must open one, and
        // the whole section (up to its end marker) is skipped at once.
        // Sections this program does not read ($PhysicalNames, $Comments,
        // $Entities...) are only required to be closed.
        for (std::size_t i = 0; i < lines.size(); ++i)
          {
            const std::string &line = lines[i];
            if (line.empty())
              continue;
            if (line[0] != '$')
              at_line(i,
                      "unexpected text " + in_quotes(line) +
                        " outside of a section");
            if (line.compare(0, 4, "$End") == 0 ||
                line.compare(0, 4, "$END") == 0)
              at_line(i, in_quotes(line) + " closes no section");
            // Format 1 closes its two sections in capitals ($ENDNOD,
            // $ENDELM); everything else is $EndName.
            const std::string end_marker =
              format_1 && (line == "$NOD" || line == "$ELM") ?
                "$END" + line.substr(1) :
                "$End" + line.substr(1);
            std::size_t end = i + 1;
            while (end < lines.size() && lines[end] != end_marker)
              ++end;
            if (end == lines.size())
              at_line(i,
                      "section " + in_quotes(line) + " is not closed by " +
                        in_quotes(end_marker));
            if (line == "$NOD" || line == "$Nodes" || line == "$ELM" ||
                line == "$Elements")
              {
                // One node and one element section, of this format's
                // names, the nodes first, as every format has them.
                const bool nodes = line == "$NOD" || line == "$Nodes";
                if (line != (nodes ? nodes_name : elements_name))
                  at_line(i,
                          "section " + in_quotes(line) + " in a file of " +
                            (format_1 ? "format 1" : "format 2 or 4"));
                if (nodes ? have_nodes : have_elements)
                  at_line(i, "a second " + in_quotes(line) + " section");
                if (!nodes && !have_nodes)
                  at_line(i, "the element section comes before the nodes");
                // The section's non-empty lines: a '$' among them is an
                // end marker mistyped or a section cut short.
                std::vector<std::string> body;
                for (std::size_t j = i + 1; j < end; ++j)
                  if (!lines[j].empty())
                    {
                      if (lines[j][0] == '$')
                        at_line(j,
                                in_quotes(lines[j]) + " inside section " +
                                  in_quotes(line));
                      body.push_back(lines[j]);
                    }
                const std::size_t count = checked_count(
                  filename, body, line, i, nodes, format_4, text.size());
                (nodes ? declared.nodes : declared.elements) = count;
                (nodes ? have_nodes : have_elements)         = true;
              }
            // A second header: two files run together, or a damaged one.
            else if (line == "$MeshFormat" && i != 0)
              at_line(i, "a second '$MeshFormat' section");
            i = end;
          }
        // Without either section there is no mesh to give gmsh, whatever
        // else the file holds.
        if (!have_nodes)
          refuse_mesh_file(filename, "no node section (" + nodes_name + ")");
        if (!have_elements)
          refuse_mesh_file(filename,
                           "no element section (" + elements_name + ")");
        return declared;
      }

      // Binary (formats 2.2 and 4.1): the counts at the head of the node
      // and element sections, for the comparison with what gmsh reads.
      Declared
      check_binary(const std::string &filename,
                   const std::string &text,
                   const Format       format,
                   const std::size_t  header_end)
      {
        // The lines of a binary section cannot be counted: only the counts
        // are read here, and gmsh's result is held to them.
        Declared declared;
        declared.format = format;
        // gmsh writes the integer 1 after the format line, to tell the
        // byte order.
        int one = 0;
        if (header_end + sizeof(int) > text.size())
          refuse_mesh_file(filename, "the binary file ends in its header");
        // Copied, not cast: the text's bytes have no alignment.
        std::memcpy(&one, text.data() + header_end, sizeof(int));
        if (one != 1)
          refuse_mesh_file(
            filename,
            "a binary file of another byte order, or damaged (convert it "
            "to ASCII with gmsh)");
        // A section's name is a text line of its own even in a binary
        // file: searched with its line ends, from after the header.
        const auto count_of = [&](const std::string &name) -> std::size_t {
          const std::size_t at = text.find("\n" + name + "\n", header_end);
          if (at == std::string::npos)
            refuse_mesh_file(filename, "no " + name + " section");
          // The data start after the name and its two line ends; the end
          // marker must follow somewhere, or the file was cut short.
          const std::size_t data = at + name.size() + 2;
          if (text.find("\n$End" + name.substr(1), data) == std::string::npos)
            refuse_mesh_file(filename, "section '" + name + "' is not closed");
          std::size_t count = 0;
          if (format == Format::msh2_binary)
            {
              // The count is a text line.
              const std::size_t        eol = text.find('\n', data);
              std::vector<std::size_t> values;
              if (eol == std::string::npos ||
                  !read_integers(
                    text.substr(data, eol - data), values, 1, true))
                refuse_mesh_file(filename,
                                 "the count of section '" + name +
                                   "' is not a number");
              count = values[0];
            }
          else
            {
              // numEntityBlocks, count, minTag, maxTag as size_t, whose
              // size the format line declared as 8 (check_file()).
              if (data + 4 * sizeof(std::size_t) > text.size())
                refuse_mesh_file(filename,
                                 "section '" + name + "' ends in its header");
              std::memcpy(&count,
                          text.data() + data + sizeof(std::size_t),
                          sizeof(std::size_t));
            }
          // Damaged bytes read as a count give a number beyond the file's
          // size: said here, before gmsh tries to allocate for it.
          if (count > text.size())
            refuse_mesh_file(filename,
                             "section '" + name + "' declares " +
                               std::to_string(count) +
                               " items: more than the file can hold");
          return count;
        };
        declared.nodes    = count_of("$Nodes");
        declared.elements = count_of("$Elements");
        return declared;
      }

      // Which reader gmsh will use, and whether the file fits it. A script
      // is a program, not data: it is only required not to be empty (gmsh
      // reports its own errors), and should come from a trusted source.
      Declared
      check_file(const std::string &filename, const std::string &text)
      {
        if (is_geo_file(filename))
          {
            if (text.find_first_not_of(" \t\r\n") == std::string::npos)
              refuse_mesh_file(filename, "the gmsh script is empty");
            return Declared();
          }
        // gmsh chooses its reader by the name first: a mesh must be named
        // so that gmsh reads it as one.
        if (!has_extension(filename, ".msh"))
          refuse_mesh_file(
            filename,
            "its name must end in .msh (a gmsh mesh) or .geo (a gmsh "
            "script)");
        if (text.empty())
          refuse_mesh_file(filename, "the file is empty");
        // The first line, cut at 80 characters: it is quoted in the
        // message when it is not a gmsh header (a binary file has no line
        // end where a text file would).
        std::size_t       eol   = text.find('\n');
        const std::string first = [&]() {
          std::string line = text.substr(0, std::min(eol, std::size_t(80)));
          while (!line.empty() && (line.back() == '\r' || line.back() == ' '))
            line.pop_back();
          return line;
        }();
        // Format 1 has no header; anything else that is not $MeshFormat
        // would be run by gmsh as a script.
        if (first == "$NOD")
          return check_ascii(filename, text, Format::msh1);
        if (first != "$MeshFormat")
          refuse_mesh_file(
            filename,
            "not a gmsh mesh: it starts with " + in_quotes(first) +
              " (a mesh file starts with '$MeshFormat', or '$NOD' for "
              "format 1; a gmsh script must be named *.geo)");
        const std::size_t start = eol + 1;
        eol                     = text.find('\n', start);
        if (eol == std::string::npos)
          refuse_mesh_file(filename, "the file ends in '$MeshFormat'");
        // "version file-type data-size": 2.0 to 2.2 share gmsh's 2.2
        // reader; of format 4, only 4.1, whose layout of lines the checks
        // above count (4.0 lists its nodes otherwise). File-type 0 is
        // ASCII, 1 binary; the data size is 8 (doubles in 2.2, size_t in
        // 4.1), which check_binary() relies on.
        std::istringstream fields(text.substr(start, eol - start));
        std::string        version, file_type, data_size;
        fields >> version >> file_type >> data_size;
        const bool v2 = version == "2" || version == "2.0" ||
                        version == "2.1" || version == "2.2";
        if (!v2 && version != "4.1")
          refuse_mesh_file(
            filename,
            "gmsh format " + in_quotes(version) +
              " (this program reads formats 1, 2.2 and 4.1; gmsh writes "
              "them with Mesh.MshFileVersion or '-format msh22' / "
              "'msh41')");
        if ((file_type != "0" && file_type != "1") || data_size != "8")
          refuse_mesh_file(filename,
                           "the format line " +
                             in_quotes(text.substr(start, eol - start)) +
                             " is not 'version 0|1 8'");
        if (file_type == "0")
          return check_ascii(filename,
                             text,
                             v2 ? Format::msh2_ascii : Format::msh41_ascii);
        return check_binary(filename,
                            text,
                            v2 ? Format::msh2_binary : Format::msh41_binary,
                            eol + 1);
      }

    } // namespace

    // @sect4{Reading a gmsh file}
    //
    // The stages in order: the text (a regular file of bounded size), the
    // light check, gmsh in its child process, and the check of its answer.
    // Each stage ends the read with one line when it refuses; nothing of a
    // refused file reaches deal.II.
    bool
    is_geo_file(const std::string &filename)
    {
      return has_extension(filename, ".geo");
    }

    template <int dim>
    GmshMesh<dim>
    read_gmsh_file(const std::string &filename,
                   const GeoNumbers  &geo_numbers,
                   const unsigned int element_order)
    {
      const std::string text =
        read_text_file(filename, "mesh file", max_mesh_file_bytes);
      // The file is read here once for the light check; gmsh reads it again
      // in its own process (a mesh file is small beside the problem it
      // describes).
      const Declared declared = check_file(filename, text);
      const bool     geo      = declared.format == Format::geo;
      // The limit applies to mesh files only. A legal mesh takes gmsh well
      // under a second per megabyte; a script may mesh for as long as it
      // asks (it is the user's program). A hang on a damaged file thus ends
      // within a minute and some, and Ctrl-C stops a script at once
      // (gmsh_process.cc).
      const double time_limit =
        geo ? 0 : 60 + static_cast<double>(text.size()) / (1 << 20);
      return checked_mesh<dim>(
        run_gmsh(filename, geo, geo_numbers, element_order, time_limit),
        filename,
        DeclaredCounts{geo, declared.nodes, declared.elements});
    }

    // The model opened (a script not meshed): its highest entity dimension,
    // with the same light check of a mesh file first.
    unsigned int
    model_dimension(const std::string &filename, const GeoNumbers &geo_numbers)
    {
      const std::string text =
        read_text_file(filename, "mesh file", max_mesh_file_bytes);
      const Declared  declared = check_file(filename, text);
      const bool      geo      = declared.format == Format::geo;
      const GmshModel model =
        run_gmsh(filename,
                 false,
                 geo_numbers,
                 1,
                 geo ? 0 : 60 + static_cast<double>(text.size()) / (1 << 20));
      int highest = 2;
      for (const auto &entity : model.entities)
        highest = std::max(highest, entity.dim);
      return static_cast<unsigned int>(highest);
    }

    // The two dimensions of the program (issue 48).
    template GmshMesh<2>
    read_gmsh_file<2>(const std::string &, const GeoNumbers &, unsigned int);
    template GmshMesh<3>
    read_gmsh_file<3>(const std::string &, const GeoNumbers &, unsigned int);
  } // namespace Geometry
} // namespace RingContact
