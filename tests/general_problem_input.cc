// A general problem (Problem/Scenario = general) with bad input gets a
// one-line error that names what is wrong, never a crash or a silently
// ignored entry: each case changes one thing in prm/two_blocks.prm (or, for
// the 3D cases, prm/two_blocks_3d.prm; each solves itself, see the tests
// two_blocks and two_blocks_3d) and runs the real executable.
#include "run_program.h"

#include <fstream>
#include <sstream>

using RingContactTests::check;

namespace
{
  // prm/two_blocks.prm (or `model`.prm) with the mesh found from the
  // test's folder, without output, and `changes` after it.
  void
  expect_error(const std::string &name,
               const std::string &changes,
               const std::string &expected,
               const std::string &model = "two_blocks")
  {
    {
      std::ofstream prm(name + ".prm");
      prm << "include " SOURCE_DIR "/../prm/" << model << ".prm\n"
          << "subsection Mesh\n set Mesh file = " SOURCE_DIR "/../meshes/"
          << model << ".geo\nend\n"
          << "subsection Output\n set VTU interval = 0\n"
             " set Write history = false\n set Print timing = false\n"
             " set Print steps = false\nend\n"
          << "subsection Newton\n set Verbose = false\nend\n"
          << changes;
    }
    const auto  result = RingContactTests::run_program(name + ".prm");
    std::string last;
    for (const auto &line : result.lines)
      if (!line.empty())
        last = line;
    // The message may name the source folder: show it from "error:",
    // without the folder.
    const auto  shown = last.find("error:");
    std::string text  = shown == std::string::npos ? last : last.substr(shown);
    for (const std::string folder : {std::string(SOURCE_DIR "/../"),
                                     std::string(RING_CONTACT_SOURCE_DIR "/")})
      for (auto at = text.find(folder); at != std::string::npos;
           at      = text.find(folder))
        text.erase(at, folder.size());
    RingContactTests::deallog_file << name << ": exit code " << result.exit_code
                                   << ": " << text << std::endl;
    check(result.signal == 0 && result.exit_code == 2,
          name + ": the program must fail with exit code 2");
    check(shown != std::string::npos &&
            last.find(expected) != std::string::npos,
          name + ": message must mention '" + expected + "', got: " + last);
  }
} // namespace

namespace
{
  // A factorization beyond the memory the process can have (here an
  // address-space limit of 4 GB): a fine master under a coarse slave (6000
  // against 7 cells along the interface) makes dense blocks, 4.2 GB by
  // UMFPACK's estimate. Said at once, naming the mesh ratio, instead of
  // a factorization that runs out of memory, or for minutes (5.5 GB and
  // 150 s at 10 000 cells).
  void
  factorization_too_large()
  {
    {
      std::ofstream prm("fill_in.prm");
      prm << "include " SOURCE_DIR "/../prm/two_blocks.prm\n"
          << "subsection Mesh\n set Mesh file = " SOURCE_DIR
             "/../meshes/two_blocks.geo\n"
             " set Geo parameters = nl = 6000, nu = 7, nh = 1\nend\n"
          << "subsection Output\n set VTU interval = 0\n"
             " set Write history = false\n set Print timing = false\n"
             " set Print steps = false\nend\n"
          << "subsection Newton\n set Verbose = false\nend\n";
    }
    // An AddressSanitizer build reserves terabytes of address space for
    // its shadow memory at start, which no address-space limit of 4 GB
    // allows: the program could not start. There the case is not run; the
    // Release suite runs it, and tests/memory_guard the guard without a
    // limit.
#ifdef __SANITIZE_ADDRESS__
    const bool run_it = false;
#else
    const bool run_it = true;
#endif
    if (run_it)
      {
        const auto result = RingContactTests::run_command(
          {"/bin/sh",
           "-c",
           "ulimit -v 4000000; exec " RING_CONTACT_EXECUTABLE " fill_in.prm"});
        check(result.exit_code == 2, "fill_in: exit code 2");
        check(result.printed("error: the direct solver's factorization of "
                             "the 24052 unknowns would need about"),
              "fill_in: the estimate is said");
        check(result.printed("the slave surface's segments are up to 857 "
                             "times longer than the master's"),
              "fill_in: the mesh ratio is named");
      }
    else
      std::cerr << "fill_in: not run under AddressSanitizer (no "
                   "address-space limit possible)"
                << std::endl;
    RingContactTests::deallog_file
      << "fill_in: exit code 2: error: the direct solver's factorization "
         "... would need about ... GB ...; contact pair 1: the slave "
         "surface's segments are up to 857 times longer than the master's ..."
      << std::endl;
  }
} // namespace

int
main()
{
  factorization_too_large();
  // The problem itself solves: exit code 0, every check passes.
  {
    std::ofstream prm("valid.prm");
    prm << "include " SOURCE_DIR "/../prm/two_blocks.prm\n"
        << "subsection Mesh\n set Mesh file = " SOURCE_DIR
           "/../meshes/two_blocks.geo\nend\n"
        << "subsection Output\n set VTU interval = 1\n"
           " set Directory = results_valid\nend\n";
    prm.close();
    const auto result = RingContactTests::run_program("valid.prm");
    check(result.exit_code == 0 && result.printed("7 of 7 checks pass"),
          "two_blocks.prm must solve and pass its checks");
    // Its results read back whole: history.csv with the checked
    // quantities' columns, verdicts.csv whose quantities hold commas
    // ("pressure at (0.3, 0)"), the VTU files of steps 0, 1 and 2.
    check(RingContactTests::check_results(
            "results_valid", "--quiet --all-listed --vtu-every-step --rows 2"),
          "valid: its results read back whole");
    RingContactTests::deallog_file
      << "valid: 7 of 7 checks pass; history.csv (with the checks' columns), "
         "verdicts.csv and the VTU files read back whole"
      << std::endl;
  }

  expect_error("unknown_body",
               "subsection Body 2\n set Material id = 7\nend\n",
               "has cells of physical group 2, which is no body's");
  expect_error("same_body_twice",
               "subsection Body 2\n set Material id = 1\nend\n",
               "is that of Body 1");
  expect_error("missing_boundary",
               "subsection Boundary condition 5\n set Type = traction\n"
               " set Boundary id = 99\nend\n",
               "no boundary with tag 99 (Boundary condition 5)");
  expect_error("condition_on_contact_surface",
               "subsection Boundary condition 5\n set Type = traction\n"
               " set Boundary id = 10\nend\n",
               "is a contact surface");
  expect_error("two_loads_on_one_boundary",
               "subsection Boundary condition 5\n set Type = pressure\n"
               " set Boundary id = 11\n set Value = 1\nend\n",
               "has two loads");
  // Both blocks loaded by balanced tractions: the contact holds their
  // relative motion, nothing their common one.
  expect_error("bodies_free_together",
               "subsection Boundary condition 4\n set Type = traction\n"
               " set Value = 0; p * t\nend\n",
               "nothing holds the bodies' common motion (Body 1 the "
               "translation along (0, 1), Body 2 the translation along (0, "
               "1))");
  // The blocks drawn on shared corner points: the mesh joins them there.
  std::ofstream("glued.geo")
    << "Point(1) = {0, -0.5, 0}; Point(2) = {1, -0.5, 0};\n"
       "Point(3) = {1, 0, 0}; Point(4) = {0, 0, 0};\n"
       "Point(7) = {1, 0.5, 0}; Point(8) = {0, 0.5, 0};\n"
       "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4};\n"
       "Line(4) = {4, 1}; Line(5) = {4, 3}; Line(6) = {3, 7};\n"
       "Line(7) = {7, 8}; Line(8) = {8, 4};\n"
       "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n"
       "Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};\n"
       "Transfinite Curve{1, 3} = 6; Transfinite Curve{5, 7} = 8;\n"
       "Transfinite Curve{2, 4, 6, 8} = 4;\n"
       "Transfinite Surface{1, 2}; Recombine Surface{1, 2};\n"
       "Physical Surface(1) = {1}; Physical Surface(2) = {2};\n"
       "Physical Curve(20) = {3}; Physical Curve(21) = {1};\n"
       "Physical Curve(22) = {4}; Physical Curve(23) = {2};\n"
       "Physical Curve(10) = {5}; Physical Curve(11) = {7};\n"
       "Physical Curve(12) = {8}; Physical Curve(13) = {6};\n";
  expect_error("glued_bodies",
               "subsection Mesh\n set Mesh file = glued.geo\nend\n",
               "the mesh joins Body 1 (material 1) and Body 2 (material 2)");
  // A 3D script that stops on an error of its own (Lz too short for the
  // end's layers) before its extrusion: gmsh's message, not a 2D model's
  // refusal of the file's three components.
  expect_error("script_error_3d",
               "subsection Mesh\n set Geo parameters = Lz = 0.2\nend\n",
               "Lz must exceed 4 a0",
               "hertz_cylinder_3d");
  expect_error("pressure_point_off_the_surface",
               "subsection Check 1\n set Point = 100, 100\nend\n",
               "give a point on a slave surface");
  expect_error("two_displacements_on_one_component",
               "subsection Boundary condition 5\n set Type = displacement\n"
               " set Boundary id = 21\n set Components = y\n"
               " set Value = 0; 1e-3 * t\nend\n",
               "impose each component of a boundary once");
  expect_error("bad_expression",
               "subsection Boundary condition 1\n set Value = 0; -p * (t\n"
               "end\n",
               "is not a usable function");
  expect_error("unknown_variable",
               "subsection Boundary condition 1\n set Value = 0; -p * z\n"
               "end\n",
               "is not a usable function");
  expect_error("wrong_number_of_expressions",
               "subsection Boundary condition 1\n set Value = -p\nend\n",
               "a traction needs 2");
  expect_error("bad_constant",
               "subsection Problem\n set Constants = p = 1e6, q = 2 * r\n"
               "end\n",
               "not a number nor an expression");
  expect_error("constant_named_t",
               "subsection Problem\n set Constants = t = 1\nend\n",
               "every expression already has");
  expect_error("one_polar_component",
               "subsection Boundary condition 2\n set Components = r\nend\n",
               "a polar condition imposes both");
  expect_error("unknown_component",
               "subsection Boundary condition 2\n set Components = w\nend\n",
               "the components are x, y");
  expect_error("z_in_two_dimensions",
               "subsection Boundary condition 2\n set Components = z\nend\n",
               "names z, but the model is two-dimensional");
  expect_error("three_coordinates_in_two_dimensions",
               "subsection Check 1\n set Point = 0.3, 0, 0\nend\n",
               "has 3 coordinates, but the model is two-dimensional");
  expect_error("quantity_along_z_in_two_dimensions",
               "subsection Check 1\n set Quantity = displacement z\nend\n",
               "is along z, but the model is two-dimensional");
  // The same language on a model of volumes (prm/two_blocks_3d.prm):
  // three coordinates and three components, and the mesh's checks.
  expect_error("two_coordinates_in_three_dimensions",
               "subsection Check 1\n set Point = 0.3, 0.6\nend\n",
               "has 2 coordinates, but the model is three-dimensional",
               "two_blocks_3d");
  expect_error("two_expressions_in_three_dimensions",
               "subsection Boundary condition 1\n set Value = 0; -p * t\n"
               "end\n",
               "a traction needs 3",
               "two_blocks_3d");
  expect_error("constant_named_z_in_three_dimensions",
               "subsection Problem\n set Constants = p = 1e6, z = 1\nend\n",
               "gives a value to 'z'",
               "two_blocks_3d");
  expect_error("missing_boundary_of_a_resultant_in_three_dimensions",
               "subsection Check 3\n set Boundary id = 99\nend\n",
               "has no boundary with tag 99 (Check 3)",
               "two_blocks_3d");
  expect_error("quadratic_pressure_in_three_dimensions",
               "subsection Body 2\n set Displacement degree = 2\nend\n"
               "subsection Finite elements\n set Multiplier degree = 2\nend\n",
               "must be bilinear (Multiplier degree = 1) in 3D",
               "two_blocks_3d");
  expect_error("nodal_on_quadratic_faces_in_three_dimensions",
               "subsection Body 2\n set Displacement degree = 2\nend\n"
               "subsection Contact\n set Integration schemes = nodal\nend\n",
               "the nodal scheme takes bilinear (Q1)",
               "two_blocks_3d");
  expect_error("normal_with_another_component",
               "subsection Boundary condition 2\n set Components = n, x\nend\n",
               "the normal component n is imposed alone");
  expect_error("normal_with_two_values",
               "subsection Boundary condition 2\n set Components = n\n"
               " set Value = 0; 0\nend\n",
               "a normal displacement needs 1");
  expect_error("body_kinematics_unknown",
               "subsection Body 1\n set Material law = large strain\nend\n",
               "Material law");
  // Boundary data that gives no number is named, with where and when.
  expect_error("displacement_not_finite",
               "subsection Boundary condition 2\n set Value = sqrt(-1); 0\n"
               "end\n",
               "Boundary condition 2 (displacement on boundary 12): its value "
               "is not a finite number");
  expect_error("third_body_not_read",
               "subsection Body 3\n set Material id = 3\nend\n",
               "is not read: Problem/Number of bodies is 2");
  expect_error("second_pair_not_read",
               "subsection Contact pair 2\n set Slave boundary = 13\nend\n",
               "is not read: Problem/Number of contact pairs is 1");
  expect_error("second_pair_same_slave",
               "subsection Problem\n set Number of contact pairs = 2\nend\n"
               "subsection Contact pair 2\n set Slave boundary = 10\n"
               " set Master boundary = 23\nend\n",
               "is the slave surface of subsection Contact too");
  expect_error("slave_surfaces_share_a_vertex",
               "subsection Problem\n set Number of contact pairs = 2\nend\n"
               "subsection Contact pair 2\n set Slave boundary = 13\n"
               " set Master boundary = 23\nend\n",
               "of two contact pairs share the vertex");
  expect_error("time_points_not_increasing",
               "subsection Load program\n set Time points = 0.5, 0.2\nend\n",
               "must be increasing");
  expect_error("checked_step_beyond_the_program",
               "subsection Check 1\n set Steps = 3\nend\n",
               "names step 3, but the load program has 2 steps");
  expect_error("point_outside_the_mesh",
               "subsection Check 2\n set Point = 5, 5\nend\n",
               "is in no cell of the mesh");
  expect_error("bad_reference",
               "subsection Check 1\n set Reference = p *\nend\n",
               "is not a usable function");
  expect_error("ring_entry_in_a_general_problem",
               "subsection Materials\n set Young's modulus outer ring = 2e11\n"
               "end\n",
               "is read for SSNP152 only");
  expect_error("ssnp152_checks_in_a_general_problem",
               "subsection Checks\n set Tolerance = 0.1\nend\n",
               "is read for SSNP152 and the patch test only");
  expect_error("ramp_for_a_general_problem",
               "subsection Load program\n set Program = ramp\nend\n",
               "must be 'steps'");
  expect_error("generated_mesh_for_a_general_problem",
               "subsection Mesh\n set Mesh source = generated\nend\n",
               "must be 'gmsh file'");
  expect_error("slave_and_master_on_one_body",
               "subsection Contact\n set Master boundary = 13\nend\n",
               "belong to the same body");
  expect_error("multiplier_above_the_slave_degree",
               "subsection Finite elements\n set Multiplier degree = 2\nend\n",
               "exceeds the displacement degree of the slave body");
  // The mesh audit: two unit blocks as a gmsh 2.2 file written here, with
  // one line changed in each case. An untagged slave line (it was dropped
  // from the contact surface, the pressure reading 0.36-3.1 MPa for 1 MPa),
  // a face given two tags by two lines of two entities (one silently won),
  // and a tagged line inside a body (its tag would apply nowhere: deal.II
  // refuses it).
  const auto write_blocks = [](const std::string &name,
                               const std::string &slave_line,
                               const std::string &extra_line) {
    std::ofstream msh(name);
    msh << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n8\n"
           "1 0 -1 0\n2 1 -1 0\n3 1 0 0\n4 0 0 0\n"
           "5 0 0 0\n6 1 0 0\n7 1 1 0\n8 0 1 0\n$EndNodes\n$Elements\n"
        << (extra_line.empty() ? 10 : 11)
        << "\n1 3 2 1 1 1 2 3 4\n2 3 2 2 2 5 6 7 8\n"
           "3 1 2 21 11 1 2\n4 1 2 23 12 2 3\n5 1 2 20 13 3 4\n"
           "6 1 2 22 14 4 1\n"
        << slave_line
        << "\n8 1 2 13 16 6 7\n9 1 2 11 17 7 8\n10 1 2 12 18 8 5\n"
        << (extra_line.empty() ? "" : extra_line + "\n") << "$EndElements\n";
  };
  write_blocks("untagged_slave.msh", "7 1 2 0 15 5 6", "");
  write_blocks("two_tags.msh", "7 1 2 10 15 5 6", "11 1 2 14 19 7 8");
  {
    // The upper block in two cells, the line between them tagged.
    std::ofstream msh("inner_line.msh");
    msh << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n10\n"
           "1 0 -1 0\n2 1 -1 0\n3 1 0 0\n4 0 0 0\n5 0 0 0\n6 1 0 0\n"
           "7 1 1 0\n8 0 1 0\n9 0.5 0 0\n10 0.5 1 0\n$EndNodes\n"
           "$Elements\n14\n1 3 2 1 1 1 2 3 4\n2 3 2 2 2 5 9 10 8\n"
           "3 3 2 2 2 9 6 7 10\n4 1 2 21 11 1 2\n5 1 2 23 12 2 3\n"
           "6 1 2 20 13 3 4\n7 1 2 22 14 4 1\n8 1 2 10 15 5 9\n"
           "9 1 2 10 15 9 6\n10 1 2 13 16 6 7\n11 1 2 11 17 7 10\n"
           "12 1 2 11 17 10 8\n13 1 2 12 18 8 5\n14 1 2 14 19 9 10\n"
           "$EndElements\n";
  }
  expect_error("untagged_slave_line",
               "subsection Mesh\n set Mesh file = untagged_slave.msh\nend\n",
               "the boundary line element 7 (gmsh entity 15) near (0.5, 0) "
               "has no physical tag");
  expect_error("face_with_two_tags",
               "subsection Mesh\n set Mesh file = two_tags.msh\nend\n",
               "carries two physical tags, 11 (element 9 (gmsh entity 17)) "
               "and 14 (element 11 (gmsh entity 19))");
  expect_error("tagged_line_inside_a_body",
               "subsection Mesh\n set Mesh file = inner_line.msh\nend\n",
               "specified a boundary id for an internal face");

  // A traction on a boundary whose displacement is held along it: the
  // support took that part of the load, silently.
  expect_error("traction_along_a_held_direction",
               "subsection Boundary condition 5\n set Boundary id = 11\n"
               " set Type = displacement\n set Components = x\n"
               " set Value = 0; 0\nend\n"
               "subsection Boundary condition 1\n"
               " set Value = 0.1 * p * t; -p * t\nend\n",
               "along a direction (1, 0) that Boundary condition 5 holds");
  // The rings' probe (node A) has no meaning in a general problem: its
  // checks name their points.
  expect_error("probe_point",
               "subsection Contact\n set Probe point = 0.3, 0\nend\n",
               "'Probe point' in subsection 'Contact' has no meaning in a "
               "general problem");
  // gmsh 4.8's quad mesher (Mesh.Algorithm = 8) crashes on any script,
  // even a unit square: named as gmsh's crash with its algorithm, not as a
  // damaged file.
  {
    std::ofstream geo("algorithm_8.geo");
    geo << "Mesh.Algorithm = 8;\n"
           "Point(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.1};\n"
           "Point(3) = {1, 1, 0, 0.1}; Point(4) = {0, 1, 0, 0.1};\n"
           "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4};\n"
           "Line(4) = {4, 1}; Curve Loop(1) = {1, 2, 3, 4};\n"
           "Plane Surface(1) = {1}; Recombine Surface{1};\n"
           "Physical Surface(1) = {1}; Physical Curve(10) = {1, 2, 3, 4};\n";
  }
  expect_error("gmsh_mesher_crash",
               "subsection Mesh\n set Mesh file = algorithm_8.geo\nend\n",
               "crashed (signal 11, Segmentation fault) while meshing it "
               "with Mesh.Algorithm = 8 (Frontal-Delaunay for quads): a fault "
               "of gmsh's mesher, not of the script");
  expect_error("curved_quadratic_mesh",
               "subsection Mesh\n set Mesh file = " SOURCE_DIR
               "/../meshes/ssnp152g.msh\nend\n",
               "curved quadratic mesh is refused");

  // A body that nothing holds along the contact, pushed along it: the
  // run names the free motions and refuses to start, because a
  // frictionless contact along a flat interface cannot hold the body
  // sideways (the tangent is singular; before, a load along it failed
  // every Newton iteration, and without that load the solver returned an
  // arbitrary sideways position with exit code 0).
  {
    std::ofstream prm("floating_body.prm");
    prm << "include " SOURCE_DIR "/../prm/two_blocks.prm\n"
        << "subsection Mesh\n set Mesh file = " SOURCE_DIR
           "/../meshes/two_blocks.geo\nend\n"
        << "subsection Output\n set VTU interval = 0\n"
           " set Write history = false\nend\n"
        << "subsection Newton\n set Verbose = false\nend\n"
        << "subsection Boundary condition 1\n set Value = 0.1 * p * t; -p * "
           "t\nend\n"
        << "subsection Boundary condition 2\n set Type = none\nend\n";
  }
  {
    const auto floating = RingContactTests::run_program("floating_body.prm");
    check(floating.exit_code == 2 &&
            floating.printed("Note: Body 2 (material 2): no imposed "
                             "displacement fixes the translation along (1, "
                             "0); only the contact holds it there") &&
            floating.printed("error: Body 2 (material 2): nothing holds "
                             "the translation along (1, 0)") &&
            floating.steps_printed() == 0,
          "floating_body: the free motion named, the run refused");
    RingContactTests::deallog_file
      << "floating_body: exit code 2: Body 2's translation along (1, 0) "
         "named; nothing holds it, no step solved"
      << std::endl;
  }

  // Stiffnesses too far apart for double precision, named as such before
  // the first step: a body 1e9 times stiffer than the other, and a body
  // 1e-9 thick (its cells 4.3e8 times longer than thick). Both failed
  // every step with "a body may be free to move rigidly" (the direct
  // solve's residual, about 6 eps times the spread, above its 1e-6).
  expect_error("stiffness_ratio_1e9",
               "subsection Body 2\n set Young's modulus = 1e18\nend\n",
               "the bodies' stiffnesses are too far apart for double "
               "precision: the cells' stiffnesses (Young's modulus times a "
               "cell's length over its thickness) differ by a factor 1.17e+09 "
               "(Body 2 (material 2), E = 1e+18; Body 1 (material 1), E = "
               "1e+09)");
  {
    std::ifstream      blocks(SOURCE_DIR "/../meshes/two_blocks.geo");
    std::ostringstream thin;
    thin << blocks.rdbuf();
    std::string geo = thin.str();
    // The upper block 1e-9 thick: its top corners at y = 1e-9.
    for (const std::string corner :
         {"c - 0.5 * s + gx, s + 0.5 * c + gy", "-0.5 * s + gx, 0.5 * c + gy"})
      {
        std::string moved = corner;
        for (auto at = moved.find("0.5"); at != std::string::npos;
             at      = moved.find("0.5", at + 4))
          moved.replace(at, 3, "1e-9");
        geo.replace(geo.find(corner), corner.size(), moved);
      }
    std::ofstream("thin_block.geo") << geo;
  }
  expect_error("body_1e_minus_9_thick",
               "subsection Mesh\n set Mesh file = thin_block.geo\nend\n"
               "subsection Check 2\n set Point = 0.5, 1e-9\nend\n",
               "differ by a factor 8.57e+08 (Body 2 (material 2), E = 2e+09, "
               "has cells 4.29e+08 times longer than thick, 0.143 by "
               "3.33e-10; Body 1 (material 1), E = 1e+09)");

  // An entry of a general problem in an SSNP152 file is refused, not
  // ignored.
  {
    std::ofstream prm("general_entry_in_ssnp152.prm");
    prm << "include " SOURCE_DIR "/../prm/ssnp152a.prm\n"
        << "subsection Boundary condition 1\n set Type = traction\nend\n";
  }
  const auto result =
    RingContactTests::run_program("general_entry_in_ssnp152.prm");
  check(result.exit_code == 2 &&
          result.printed("is read only when Problem/Scenario = general"),
        "general_entry_in_ssnp152: refused");
  RingContactTests::deallog_file
    << "general_entry_in_ssnp152: exit code 2: is read only when "
       "Problem/Scenario = general"
    << std::endl;

  // A traction that stops being a number during the run (sqrt(0.6 - t)):
  // step 1 (t = 0.5) is solved and kept, step 2 fails after its step cuts
  // with the condition named, and the run ends with exit code 3.
  {
    std::ofstream prm("traction_not_finite.prm");
    prm << "include " SOURCE_DIR "/../prm/two_blocks.prm\n"
        << "subsection Mesh\n set Mesh file = " SOURCE_DIR
           "/../meshes/two_blocks.geo\nend\n"
        << "subsection Output\n set VTU interval = 0\n"
           " set Print timing = false\nend\n"
        << "subsection Newton\n set Verbose = false\nend\n"
        << "subsection Boundary condition 1\n"
           " set Value = 0; -p * t * sqrt(0.6 - t) / sqrt(0.1)\nend\n";
    prm.close();
    const auto result =
      RingContactTests::run_program("traction_not_finite.prm");
    const bool named = result.printed(
      "Boundary condition 1 (traction on boundary 11): its value is not a "
      "finite number");
    const bool stopped = result.printed("Step 2: Newton did not converge");
    const bool kept    = result.printed_step(1);
    RingContactTests::deallog_file
      << "traction_not_finite: exit code " << result.exit_code
      << ", the condition named: " << (named ? "yes" : "no")
      << ", step 1 solved: " << (kept ? "yes" : "no")
      << ", step 2 stopped: " << (stopped ? "yes" : "no") << std::endl;
    check(result.exit_code == 3 && named && stopped && kept,
          "traction_not_finite: step 1 solved, step 2 stopped with the "
          "condition named");
  }
  // A reference that gives no number fails its check, with a note.
  {
    std::ofstream prm("reference_not_finite.prm");
    prm << "include " SOURCE_DIR "/../prm/two_blocks.prm\n"
        << "subsection Mesh\n set Mesh file = " SOURCE_DIR
           "/../meshes/two_blocks.geo\nend\n"
        << "subsection Output\n set VTU interval = 0\n"
           " set Print timing = false\n set Print steps = false\nend\n"
        << "subsection Newton\n set Verbose = false\nend\n"
        << "subsection Check 1\n set Reference = sqrt(t - 2)\nend\n";
    prm.close();
    const auto result =
      RingContactTests::run_program("reference_not_finite.prm");
    const bool noted = result.printed(
      "Note: the reference of 'pressure at (0.3, 0)' is not a finite number");
    RingContactTests::deallog_file
      << "reference_not_finite: exit code " << result.exit_code
      << ", noted: " << (noted ? "yes" : "no") << ", "
      << (result.printed("5 of 7 checks pass") ? "5 of 7 checks pass" : "?")
      << std::endl;
    check(result.exit_code == 1 && noted &&
            result.printed("5 of 7 checks pass"),
          "reference_not_finite: its two verdicts fail, with a note");
  }
}
