// Values below single precision's range reach the VTU files: the patch
// test of two blocks (general problem, prm/two_blocks.prm) at p = 1e-200,
// whose pressure is p times the load factor. deal.II's writer, which the
// program used, holds its output in float: every field of such a run was
// zero in ParaView (and the von Mises stress underflowed before, in its
// squares). The files are read back with VTK (Debian's python3-vtk9):
// - at p = 1e-200 the slave surface's contact pressure is p t to 1e-8 at
//   every point (t = 0.5 at step 1), the bodies' sigma_yy is -p t to 1e-8
//   and their von Mises stress is nonzero, all three arrays written as
//   Float64; the arrays whose values fit (the points, the material ids,
//   the arc length) stay Float32;
// - at p = 1e6 every array is Float32, as before: double precision is
//   written where a value needs it only.
#include "run_program.h"

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

using RingContactTests::check;

namespace
{
  // Each array of a VTU file: its type in VTK's words, and the smallest
  // and largest value of one of its components (the yy one of a tensor).
  struct ArrayRange
  {
    std::string type;
    double      min = 0, max = 0;
  };

  std::map<std::string, ArrayRange>
  read_arrays(const std::string &file)
  {
    const std::string script =
      "import sys\n"
      "from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader\n"
      "r = vtkXMLUnstructuredGridReader()\n"
      "r.SetFileName(sys.argv[1])\n"
      "r.Update()\n"
      "g = r.GetOutput()\n"
      "arrays = [('Points', g.GetPoints().GetData())]\n"
      "d = g.GetPointData()\n"
      "arrays += [(d.GetArrayName(i), d.GetArray(i))\n"
      "           for i in range(d.GetNumberOfArrays())]\n"
      "for name, a in arrays:\n"
      "    c = 4 if a.GetNumberOfComponents() == 9 else 0\n"
      "    v = [a.GetComponent(t, c) for t in range(a.GetNumberOfTuples())]\n"
      "    print(name, a.GetDataTypeAsString(), repr(min(v)), repr(max(v)))\n";
    {
      std::ofstream out("read_arrays.py");
      out << script;
    }
    const std::string command = "/usr/bin/python3 read_arrays.py " + file;
    FILE             *in      = ::popen(command.c_str(), "r");
    check(in != nullptr, "popen " + command);
    std::string text;
    for (int c; (c = std::fgetc(in)) != EOF;)
      text += static_cast<char>(c);
    check(::pclose(in) == 0, command + ": " + text);
    std::map<std::string, ArrayRange> arrays;
    std::istringstream                lines(text);
    std::string                       name;
    ArrayRange                        range;
    while (lines >> name >> range.type >> range.min >> range.max)
      arrays[name] = range;
    check(!arrays.empty(), command + " read no array: " + text);
    return arrays;
  }

  // The two blocks at pressure p, VTU files at each of the two steps.
  std::string
  run(const std::string &name, const std::string &p)
  {
    {
      std::ofstream prm(name + ".prm");
      prm << "include " SOURCE_DIR "/../prm/two_blocks.prm\n"
          << "subsection Mesh\n set Mesh file = " SOURCE_DIR
             "/../meshes/two_blocks.geo\nend\n"
          << "subsection Problem\n set Constants = p = " << p
          << ", E1 = 1e9, nu1 = 0.3, E2 = 2e9, nu2 = 0.25, H = 0.5\nend\n"
          << "subsection Output\n set Directory = " << name
          << "\n set Print timing = false\n set Print steps = false\nend\n"
          << "subsection Newton\n set Verbose = false\nend\n";
    }
    const auto result = RingContactTests::run_program(name + ".prm");
    check(result.exit_code == 0, name + ": the run");
    return name + "/";
  }

  bool
  within(const double value, const double expected, const double tolerance)
  {
    return std::abs(value - expected) <= tolerance * std::abs(expected);
  }
} // namespace

int
main()
{
  auto &out = RingContactTests::deallog_file;
  {
    const double p      = 1e-200;
    const auto   folder = run("tiny", "1e-200");
    const auto surface = read_arrays(folder + "slave-segment-based-2-0001.vtu");
    const auto bodies =
      read_arrays(folder + "solution-segment-based-2-0001.vtu");
    const auto &pressure = surface.at("contact_pressure");
    check(pressure.type == "double" && within(pressure.min, 0.5 * p, 1e-8) &&
            within(pressure.max, 0.5 * p, 1e-8),
          "the contact pressure: " + pressure.type + " from " +
            std::to_string(pressure.min) + " to " +
            std::to_string(pressure.max));
    const auto &stress = bodies.at("cauchy_stress");
    check(stress.type == "double" && within(stress.min, -0.5 * p, 1e-8),
          "sigma_yy: " + stress.type + ", down to " +
            std::to_string(stress.min));
    const auto &von_mises = bodies.at("von_Mises_stress");
    check(von_mises.type == "double" && von_mises.min > 0,
          "the von Mises stress: " + von_mises.type + ", from " +
            std::to_string(von_mises.min));
    for (const auto &[arrays, name] : {std::make_pair(&bodies, "Points"),
                                       std::make_pair(&bodies, "material_id"),
                                       std::make_pair(&surface, "Points"),
                                       std::make_pair(&surface, "arc_length")})
      check(arrays->at(name).type == "float",
            std::string(name) + " in single precision");
    out << "p = 1e-200: the contact pressure p t and sigma_yy -p t to 1e-8, "
           "the von Mises stress nonzero, in double precision; the points, "
           "the material ids and the arc length in single"
        << std::endl;
  }
  {
    const auto folder = run("ordinary", "1e6");
    for (const std::string file : {"slave-segment-based-2-0001.vtu",
                                   "solution-segment-based-2-0001.vtu"})
      for (const auto &[name, range] : read_arrays(folder + file))
        check(range.type == "float",
              file + ": " + name + " in single precision, not " + range.type);
    out << "p = 1e6: every array in single precision" << std::endl;
  }
}
