// The slave surface's VTU file lists its points along the surface, piece
// after piece, so that ParaView's Plot Data over arc_length (the recipe
// of doc/output.md), which joins the points in the file's order, draws the
// pressure along the interface. The points used to come in the order of the
// cells: on a gmsh mesh (Hertz, prm/hertz.prm) that is no order along the
// surface, and the plot was a zigzag. The files are read back with VTK
// (slave_pieces.py): in each piece arc_length starts at 0 and increases
// from point to point by its chord (to 1 %), a closed surface running to
// its length where it meets its start again.
// - Hertz (gmsh, an open surface): one piece;
// - the rings of modelisation A on a gmsh mesh (meshes/rings-40.msh) and
//   those of H (Q2, curved, two segments a face): one closed piece each;
// - three blocks (two contact pairs, prm/three_blocks.prm, its own
//   segment-based scheme): two pieces.
#include "run_program.h"

#include <fstream>

using RingContactTests::check;

namespace
{
  // `tag`: the file tag of the run's integration scheme.
  void
  check_pieces(const std::string &name,
               const std::string &prm_text,
               const std::string &tag = "nodal")
  {
    {
      std::ofstream prm(name + ".prm");
      prm << prm_text << "subsection Output\n set Directory = " << name
          << "\n set Print timing = false\n set Print steps = false\nend\n"
             "subsection Newton\n set Verbose = false\nend\n";
    }
    const auto result = RingContactTests::run_program(name + ".prm");
    check(result.exit_code == 0, name + ": the run");
    const std::string command = "/usr/bin/python3 " SOURCE_DIR
                                "/slave_pieces.py " +
                                name + "/slave-" + tag + "-0001.vtu 2>&1";
    FILE *in = ::popen(command.c_str(), "r");
    check(in != nullptr, "popen " + command);
    std::string text;
    for (int c; (c = std::fgetc(in)) != EOF;)
      text += static_cast<char>(c);
    check(::pclose(in) == 0, name + ": " + text);
    RingContactTests::deallog_file << name << ":\n" << text;
  }

  // A shipped parameter file with `extra` (the nodal scheme by default),
  // its mesh file (if any) given with its path.
  std::string
  shipped(const std::string &prm,
          const std::string &mesh,
          const std::string &extra =
            "subsection Contact\n set Integration schemes = nodal\nend\n")
  {
    std::string text = "include " SOURCE_DIR "/../prm/" + prm + "\n";
    if (!mesh.empty())
      text += "subsection Mesh\n set Mesh source = gmsh file\n"
              " set Mesh file = " SOURCE_DIR "/../meshes/" +
              mesh + "\nend\n";
    return text + extra;
  }
} // namespace

int
main()
{
  check_pieces("hertz", shipped("hertz.prm", "hertz.geo"));
  const std::string nodal_one_step =
    "subsection Contact\n set Integration schemes = nodal\nend\n"
    "subsection Load program\n set Ramp steps = 1\nend\n";
  check_pieces("rings_gmsh",
               shipped("ssnp152a.prm", "rings-40.msh", nodal_one_step));
  check_pieces("rings_q2", shipped("ssnp152h.prm", "", nodal_one_step));
  // Its own scheme (segment-based 2), exact on these non-matching meshes.
  check_pieces("three_blocks",
               shipped("three_blocks.prm", "three_blocks.geo", ""),
               "segment-based-2");
}
