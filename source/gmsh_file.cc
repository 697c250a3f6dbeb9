#include <ring_contact/gmsh_file.h>
#include <ring_contact/parameter_file.h>
#include <ring_contact/utilities.h>

#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>

namespace RingContact
{
  namespace Geometry
  {
    namespace
    {
      // A mesh of the rings at 1600 x 120 elements is ~40 MB of text; a
      // file much larger than that is not one of ours.
      constexpr std::size_t max_mesh_file_bytes = std::size_t(512) << 20;

      // The nodes of each accepted element type, and its name for messages.
      unsigned int
      nodes_of_type(const int type)
      {
        switch (type)
          {
            case 1:
              return 2; // 2-node line
            case 3:
              return 4; // 4-node quadrilateral
            case 8:
              return 3; // 3-node line
            case 10:
              return 9; // 9-node quadrilateral
            case 15:
              return 1; // point
            default:
              return 0;
          }
      }

      std::string
      name_of_type(const int type)
      {
        switch (type)
          {
            case 2:
              return "3-node triangle";
            case 4:
              return "tetrahedron";
            case 5:
              return "hexahedron";
            case 6:
              return "prism";
            case 7:
              return "pyramid";
            case 9:
              return "6-node triangle";
            case 16:
              return "8-node quadrilateral";
            default:
              return "type " + std::to_string(type);
          }
      }

      class Parser
      {
      public:
        Parser(GmshMesh &mesh)
            : mesh(mesh)
            , in(mesh.text)
        {}

        void
        parse()
        {
          bool        have_nodes = false, have_elements = false;
          std::string line;
          while (next_line(line))
            {
              if (line.empty())
                continue;
              if (line == "$NOD" || line == "$Nodes")
                {
                  if (have_nodes)
                    fail("a second node section");
                  const bool format_1 = line == "$NOD";
                  if (!format_1 && !have_format)
                    fail("'$Nodes' without a '$MeshFormat' section");
                  read_nodes(format_1 ? "$ENDNOD" : "$EndNodes");
                  have_nodes    = true;
                  format_1_file = format_1;
                }
              else if (line == "$ELM" || line == "$Elements")
                {
                  if (!have_nodes)
                    fail("the element section comes before the nodes");
                  if (have_elements)
                    fail("a second element section");
                  if ((line == "$ELM") != format_1_file)
                    fail("format 1 and format 2 sections mixed");
                  read_elements(line == "$ELM" ? "$ENDELM" : "$EndElements",
                                line == "$ELM");
                  have_elements = true;
                }
              else if (line == "$MeshFormat")
                read_format();
              else if (line[0] == '$' && line.compare(0, 4, "$End") != 0 &&
                       line.compare(0, 4, "$END") != 0)
                skip_section(line);
              else
                fail("unexpected text " + in_quotes(line) +
                     " outside of a section (not a gmsh file?)");
            }
          if (!have_nodes)
            fail("no node section ($NOD or $Nodes)");
          if (!have_elements)
            fail("no element section ($ELM or $Elements)");
          check_cells();
        }

      private:
        GmshMesh          &mesh;
        std::istringstream in;
        unsigned int       line_number   = 0;
        bool               have_format   = false;
        bool               format_1_file = false;

        static std::string
        in_quotes(const std::string &text)
        {
          return "'" + printable(text) + "'";
        }

        [[noreturn]] void
        fail(const std::string &what, unsigned int at = 0) const
        {
          throw std::runtime_error("cannot read mesh file '" +
                                   printable(mesh.filename, 200) + "', line " +
                                   std::to_string(at == 0 ? line_number : at) +
                                   ": " + what);
        }

        bool
        next_line(std::string &line)
        {
          if (!std::getline(in, line))
            return false;
          ++line_number;
          while (!line.empty() && (line.back() == '\r' || line.back() == ' ' ||
                                   line.back() == '\t'))
            line.pop_back();
          for (const char c : line)
            if (static_cast<unsigned char>(c) < 0x20 && c != '\t')
              fail("a control character: not an ASCII gmsh file?");
          return true;
        }

        void
        read_format()
        {
          std::string line;
          if (!next_line(line))
            fail("the file ends in '$MeshFormat'");
          std::istringstream fields(line);
          std::string        version;
          int                file_type = -1, data_size = -1;
          fields >> version >> file_type >> data_size;
          if (version != "2.2" && version != "2.1" && version != "2")
            fail("gmsh format " + in_quotes(version) +
                 " (this program reads formats 1 and 2.2; gmsh writes 2.2 "
                 "with '-format msh22')");
          if (file_type != 0)
            fail("a binary gmsh file (this program reads ASCII files)");
          if (!next_line(line) || line != "$EndMeshFormat")
            fail("'$MeshFormat' is not closed by '$EndMeshFormat'");
          have_format = true;
        }

        void
        skip_section(const std::string &name)
        {
          const std::string  end   = "$End" + name.substr(1);
          const std::string  END   = "$END" + name.substr(1);
          const unsigned int start = line_number;
          std::string        line;
          while (next_line(line))
            if (line == end || line == END)
              return;
          fail("section " + in_quotes(name) + " is not closed", start);
        }

        // The count line of a section.
        std::size_t
        read_count(const std::string &section)
        {
          std::string line;
          if (!next_line(line))
            fail("the file ends after " + in_quotes(section));
          std::istringstream fields(line);
          long               n = -1;
          std::string        rest;
          if (!(fields >> n) || n < 0 || (fields >> rest))
            fail("the count of section " + in_quotes(section) + " is " +
                 in_quotes(line) + ", not a number");
          return static_cast<std::size_t>(n);
        }

        void
        read_nodes(const std::string &end_marker)
        {
          const std::size_t declared = read_count(end_marker);
          std::string       line;
          std::size_t       n       = 0;
          double            largest = 0;
          std::vector<std::pair<double, unsigned int>> z_values;
          while (true)
            {
              if (!next_line(line))
                fail("the node section is not closed by " +
                     in_quotes(end_marker));
              if (line == end_marker)
                break;
              std::istringstream fields(line);
              long               id = 0;
              double             x, y, z;
              std::string        rest;
              if (!(fields >> id >> x >> y >> z) || (fields >> rest))
                fail("the node line " + in_quotes(line) + " is not 'id x y z'");
              if (id <= 0)
                fail("node id " + std::to_string(id) + " (must be positive)");
              if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z) ||
                  std::abs(x) > 1e100 || std::abs(y) > 1e100 ||
                  std::abs(z) > 1e100)
                fail("node " + std::to_string(id) +
                     " has a coordinate that is not a finite number");
              if (!mesh.nodes.emplace(id, Point<2>(x, y)).second)
                fail("node " + std::to_string(id) + " is defined twice");
              largest = std::max({largest, std::abs(x), std::abs(y)});
              z_values.emplace_back(z, line_number);
              ++n;
            }
          if (n != declared)
            fail("the node section declares " + std::to_string(declared) +
                 " nodes but lists " + std::to_string(n));
          for (const auto &[z, at] : z_values)
            if (std::abs(z) > 1e-10 * largest)
              fail("a node with z = " + std::to_string(z) +
                     ": the rings are a plane mesh",
                   at);
        }

        void
        read_elements(const std::string &end_marker, const bool format_1)
        {
          const std::size_t declared = read_count(end_marker);
          std::string       line;
          std::set<long>    ids;
          while (true)
            {
              if (!next_line(line))
                fail("the element section is not closed by " +
                     in_quotes(end_marker));
              if (line == end_marker)
                break;
              std::istringstream fields(line);
              std::vector<long>  numbers;
              std::string        word;
              while (fields >> word)
                {
                  std::size_t used  = 0;
                  long        value = 0;
                  try
                    {
                      value = std::stol(word, &used);
                    }
                  catch (...)
                    {
                      used = 0;
                    }
                  if (used != word.size())
                    fail("the element line " + in_quotes(line) +
                         " holds something that is not an integer: " +
                         in_quotes(word));
                  numbers.push_back(value);
                }
              // format 1: id type physical elementary n-nodes nodes...
              // format 2: id type n-tags tags... nodes...
              if (numbers.size() < 3)
                fail("the element line " + in_quotes(line) + " is too short");
              GmshElement element;
              const long  id              = numbers[0];
              element.type                = static_cast<int>(numbers[1]);
              element.line                = line_number;
              const unsigned int expected = nodes_of_type(element.type);
              if (expected == 0)
                fail("element " + std::to_string(id) + " is a " +
                     name_of_type(element.type) +
                     ": the rings must be meshed with quadrilaterals (gmsh "
                     "types 3 and 10) and lines (1 and 8)");
              std::size_t first_node = 0;
              if (format_1)
                {
                  if (numbers.size() < 5)
                    fail("the element line " + in_quotes(line) +
                         " is too short");
                  element.physical = numbers[2];
                  if (numbers[4] != static_cast<long>(expected))
                    fail("element " + std::to_string(id) + " (" +
                         (expected == 4 ? "4-node quadrilateral" :
                          expected == 9 ? "9-node quadrilateral" :
                          expected == 1 ? "point" :
                                          std::to_string(expected) +
                                            "-node line") +
                         ") declares " + std::to_string(numbers[4]) + " nodes");
                  first_node = 5;
                }
              else
                {
                  const long n_tags = numbers[2];
                  if (n_tags < 0 || n_tags > 100 ||
                      numbers.size() < 3 + static_cast<std::size_t>(n_tags))
                    fail("element " + std::to_string(id) +
                         " has a wrong number of tags");
                  element.physical = n_tags > 0 ? numbers[3] : 0;
                  first_node       = 3 + n_tags;
                }
              if (numbers.size() - first_node != expected)
                fail("element " + std::to_string(id) + " has " +
                     std::to_string(numbers.size() - first_node) +
                     " nodes; its type (" + std::to_string(element.type) +
                     ") has " + std::to_string(expected));
              if (!ids.insert(id).second)
                fail("element " + std::to_string(id) + " is defined twice");
              if (element.physical < 0 || element.physical > 1000000000)
                fail("element " + std::to_string(id) + " has physical tag " +
                     std::to_string(element.physical));
              element.nodes.assign(numbers.begin() + first_node, numbers.end());
              for (const long node : element.nodes)
                if (mesh.nodes.count(node) == 0)
                  fail("element " + std::to_string(id) + " refers to node " +
                       std::to_string(node) +
                       ", which the node section does not define");
              if (element.type == 8 || element.type == 10)
                mesh.quadratic = true;
              if (element.type != 15)
                mesh.elements.push_back(element);
            }
          if (ids.size() != declared)
            fail("the element section declares " + std::to_string(declared) +
                 " elements but lists " + std::to_string(ids.size()));
        }

        // No cell repeats a corner, is folded or flat; no edge is shared
        // by more than two cells; every line joins two corners of a cell.
        void
        check_cells() const
        {
          std::map<std::pair<long, long>, unsigned int> edge_use;
          bool any_cell = false, linear = false;
          for (const auto &e : mesh.elements)
            if (e.type == 3 || e.type == 10)
              {
                any_cell = true;
                linear   = linear || e.type == 3;
                const std::set<long> corners(e.nodes.begin(),
                                             e.nodes.begin() + 4);
                if (corners.size() != 4)
                  fail("a quadrilateral repeats a corner node", e.line);
                // gmsh numbers the corners around the cell: the turns at
                // the four corners must all have one sign.
                int sign = 0;
                for (unsigned int i = 0; i < 4; ++i)
                  {
                    const Point<2> a     = mesh.nodes.at(e.nodes[i]);
                    const Point<2> b     = mesh.nodes.at(e.nodes[(i + 1) % 4]);
                    const Point<2> c     = mesh.nodes.at(e.nodes[(i + 2) % 4]);
                    const double   cross = (b[0] - a[0]) * (c[1] - b[1]) -
                                         (b[1] - a[1]) * (c[0] - b[0]);
                    const double scale = (b - a).norm() * (c - b).norm();
                    const int    s     = cross > 1e-12 * scale  ? 1 :
                                         cross < -1e-12 * scale ? -1 :
                                                                  0;
                    if (s == 0 || (sign != 0 && s != sign))
                      fail("a quadrilateral that is flat, folded or not "
                           "convex",
                           e.line);
                    sign = s;
                  }
                for (unsigned int i = 0; i < 4; ++i)
                  {
                    const long a = e.nodes[i], b = e.nodes[(i + 1) % 4];
                    if (++edge_use[{std::min(a, b), std::max(a, b)}] > 2)
                      fail("an edge shared by more than two quadrilaterals",
                           e.line);
                  }
              }
          if (!any_cell)
            fail("no quadrilaterals (the rings are meshed with gmsh types 3 "
                 "or 10)");
          if (linear && mesh.quadratic)
            fail("linear and quadratic elements mixed");
          for (const auto &e : mesh.elements)
            if (e.type == 1 || e.type == 8)
              {
                const long a = e.nodes[0], b = e.nodes[1];
                if (edge_use.count({std::min(a, b), std::max(a, b)}) == 0)
                  fail("a line (physical tag " + std::to_string(e.physical) +
                         ") that is not an edge of a quadrilateral",
                       e.line);
              }
        }
      };
    } // namespace

    GmshMesh
    read_gmsh_file(const std::string &filename)
    {
      GmshMesh mesh;
      mesh.filename = filename;
      mesh.text = read_text_file(filename, "mesh file", max_mesh_file_bytes);
      Parser(mesh).parse();
      return mesh;
    }
  } // namespace Geometry
} // namespace RingContact
