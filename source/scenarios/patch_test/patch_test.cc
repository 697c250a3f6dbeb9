// @sect3{The contact patch test}
//
// Two elastic blocks, the lower one [0, 1] x [-0.5, 0] (the master body)
// and the upper one [0, 1] x [0, 0.5] (the slave body), with non-matching
// meshes along their interface y = 0, pressed together: the bottom held
// vertically, the top moved down by the shortening of the two blocks under
// the uniaxial pressure p (small strain), p (H1 / E1* + H2 / E2*); the
// horizontal displacement held at the left corner of each block (no rigid
// sliding). The exact solution is a uniform contact pressure p, which a
// contact discretisation should transmit exactly (the contact patch test):
// the pressure checks of subsection Checks hold it to round-off. The
// pressure follows the ramp of the load program. Its entries are those of
// subsection Patch test (they were in subsection Mesh, with Mesh source =
// patch test, before the patch test became a scenario).
//
// On non-matching meshes only a rule that integrates the products of the two
// surfaces' shape functions exactly passes: segment-based integration does, to
// round-off; the other schemes leave a spread (doc/validation.md). The check is
// the spread of the nodal pressures: in small strain the pressure is p itself,
// but in any kinematics the exact state is uniform, so the spread is zero
// whatever the law, and the finite-strain variant of the test checks that too.
//
// With Dimension = 3 the blocks are [0, 1] x [-0.5, 0] x [0, 1] and
// [0, 1] x [0, 0.5] x [0, 1], meshed n x 2 x n with the same n as in 2D,
// and in uniaxial stress: each block shortens by H p / E (no plane factor).
// Each block is held horizontally at two vertices of its outer face
// (u_x = u_z = 0 at x = z = 0, u_z = 0 at x = 1, z = 0), which removes its
// three rigid motions in the plane of the interface without resisting the
// Poisson expansion.
#include <deal.II/base/function.h>
#include <deal.II/grid/tria_description.h>
#include <deal.II/numerics/vector_tools.h>

#include <ring_contact/base/components.h>
#include <ring_contact/input/gmsh_mesh.h>
#include <ring_contact/input/parameter_checks.h>
#include <ring_contact/scenarios/reference_pressure.h>
#include <ring_contact/scenarios/scenario.h>

#include <algorithm>
#include <cmath>

namespace RingContact
{
  namespace
  {
    using namespace ParameterChecks;

    // The blocks' material and boundary ids: those of the rings' outer
    // (master) and inner (slave) bodies, so that the defaults of subsection
    // Contact (slave 400, master 300) fit.
    namespace Ids
    {
      constexpr unsigned int lower_block     = 100;
      constexpr unsigned int upper_block     = 101;
      constexpr unsigned int bottom          = 200;
      constexpr unsigned int lower_interface = 300;
      constexpr unsigned int upper_interface = 400;
      constexpr unsigned int top             = 500;
    } // namespace Ids

    // @sect4{The entries of subsection Patch test}
    //
    // The blocks' discretisation and materials. The default 5 and 7 elements
    // along the interface have no common divisor, so the two meshes match at
    // the ends only and every slave segment meets master vertices inside it.
    // Degrees go up to 4: the quartic patch test checks that the contact rules
    // integrate quartic surfaces exactly. Its pressure follows the ramp, and
    // its reference pressure is known everywhere: it declares the ramp, the
    // probe and the checks as the rings do (reference_pressure_entries.h).
    struct PatchTestParameters : public ScenarioParameters
    {
      ReferencePressureEntries reference;

      unsigned int elements_lower, elements_upper;
      double       youngs_modulus_lower, poissons_ratio_lower;
      double       youngs_modulus_upper, poissons_ratio_upper;
      unsigned int degree_lower, degree_upper;
      /// 2 or 3 (Patch test/Dimension).
      unsigned int space_dimension;

      unsigned int
      dimension() const override
      {
        return space_dimension;
      }

      unsigned int
      highest_displacement_degree() const override
      {
        return std::max(degree_lower, degree_upper);
      }

      std::vector<std::pair<std::string, std::string>>
      load_programs() const override
      {
        return {PressureRamp::program_choice()};
      }

      void
      add_parameters(ParameterHandler &prm) override
      {
        reference.add_parameters(prm, declared);
        Subsection s(prm, "Patch test", &declared);
        // -1 < nu < 0.5 is the range of a positive definite isotropic law:
        // lambda = E nu / ((1 + nu) (1 - 2 nu)) grows without bound as nu tends
        // to 0.5, and mu = E / (2 (1 + nu)) as nu tends to -1.
        const Condition poisson = {[](const double nu) {
                                     return nu > -1 && nu < 0.5;
                                   },
                                   "must satisfy -1 < nu < 0.5"};
        s.add("Elements lower block",
              elements_lower,
              "5",
              1,
              100000,
              "Elements along the interface of the lower (master) block.");
        s.add("Elements upper block",
              elements_upper,
              "7",
              1,
              100000,
              "Elements along the interface of the upper (slave) block.");
        s.add("Young's modulus lower block",
              youngs_modulus_lower,
              "1e9",
              "E1 [Pa], > 0.",
              positive());
        s.add("Poisson's ratio lower block",
              poissons_ratio_lower,
              "0.2",
              "nu1 [-], -1 < nu1 < 0.5.",
              poisson);
        s.add("Young's modulus upper block",
              youngs_modulus_upper,
              "1e9",
              "E2 [Pa], > 0.",
              positive());
        s.add("Poisson's ratio upper block",
              poissons_ratio_upper,
              "0.2",
              "nu2 [-], -1 < nu2 < 0.5.",
              poisson);
        s.add("Displacement degree lower block",
              degree_lower,
              "1",
              1,
              4,
              "Polynomial degree of the displacement in the lower block.");
        s.add("Dimension",
              space_dimension,
              "2",
              2,
              3,
              "The space dimension: 2 (the blocks in the plane) or 3 (the "
              "blocks as cubes, meshed n x 2 x n, first-order elements).");
        s.add("Displacement degree upper block",
              degree_upper,
              "1",
              1,
              4,
              "Polynomial degree of the displacement in the upper block.");
      }

      void
      finish(Parameters &parameters) override
      {
        // The blocks are driven by the load state's pressure p: the steps
        // program carries none (p = 0 there), and the rotation's turn means
        // nothing to blocks.
        require(parameters.load.program == PressureRamp::program_name,
                "Load program",
                "Program",
                "must be 'ramp' for Problem/Scenario = patch test (its "
                "pressure follows the ramp)");
        reference.ramp.finish();
        // The multiplier lives on the upper block, the slave: no richer than
        // its displacement, for the inf-sup condition (doc/intro.md).
        require(parameters.finite_elements.multiplier_degree <= degree_upper,
                "Finite elements",
                "Multiplier degree",
                "must not exceed the displacement degree of the upper "
                "(slave) block");
        // In 3D the faces are bilinear or biquadratic (the 3D contact's)
        // with a bilinear pressure, and a probe the file leaves alone is at
        // (0.6, 0, 0.5), on the interface.
        if (space_dimension == 3)
          {
            for (const auto &[degree, block] :
                 {std::make_pair(degree_lower, "lower"),
                  std::make_pair(degree_upper, "upper")})
              require(degree <= 2,
                      "Patch test",
                      std::string("Displacement degree ") + block + " block",
                      "must be 1 or 2 in 3D (the 3D contact takes bilinear "
                      "and biquadratic faces)");
            require(parameters.finite_elements.multiplier_degree == 1,
                    "Finite elements",
                    "Multiplier degree",
                    "must be 1 in 3D (a bilinear contact pressure)");
            if (parameters.origins.count(entry_key("Contact", "Probe point")) ==
                0)
              reference.probe = {0.6, 0, 0.5};
          }
        // The probe must be on the interface, 0 <= x (and z) <= 1, y = 0,
        // or near. The default probe, the rings' (0.6, 0), lies on it.
        const std::vector<double> x =
          space_dimension == 2 ?
            std::vector<double>{reference.probe_point<2>()[0],
                                reference.probe_point<2>()[1]} :
            std::vector<double>{reference.probe_point<3>()[0],
                                reference.probe_point<3>()[1],
                                reference.probe_point<3>()[2]};
        double distance2 = x[1] * x[1];
        for (const unsigned int d : {0u, 2u})
          if (d < x.size())
            {
              const double nearest = std::min(1.0, std::max(0.0, x[d]));
              distance2 += (x[d] - nearest) * (x[d] - nearest);
            }
        const double distance = std::sqrt(distance2);
        std::string  text     = to_text(x[0]);
        for (unsigned int d = 1; d < x.size(); ++d)
          text += ", " + to_text(x[d]);
        require(distance <= 0.05,
                "Contact",
                "Probe point",
                "(" + text + ") is not near the slave surface: it is " +
                  to_text(distance) + " m from it (at most 0.05 m accepted)");
        // A checked step beyond the ramp's last is a typo.
        reference.checks.check_steps(reference.ramp.steps);
      }

      // The two entries that lived in subsection Mesh while the patch test was
      // a mesh source: an old file that sets them is told where they are now.
      std::map<std::string, std::string>
      moved_entries() const override
      {
        return {{"Mesh/Patch test elements lower block",
                 "set 'Elements lower block' in subsection 'Patch test' "
                 "(and Scenario = patch test in subsection Problem)"},
                {"Mesh/Patch test elements upper block",
                 "set 'Elements upper block' in subsection 'Patch test' "
                 "(and Scenario = patch test in subsection Problem)"}};
      }
    };

    // @sect4{The mesh of the blocks}
    //
    // The vertices on y = 0 exist twice, once in each block: the blocks are two
    // bodies and meet through the contact only. The boundary ids come from the
    // height of the face, exact here since the heights are multiples of 0.25:
    // the bottom (200) held vertically, the top (500) moved, the interface 300
    // on the lower block's side and 400 on the upper's, the vertical sides 0,
    // free.
    template <int dim>
    void
    make_blocks(Triangulation<dim>        &triangulation,
                const PatchTestParameters &blocks)
    {
      // Lower block [0, 1] x [-0.5, 0] (master body, material 100), upper
      // block [0, 1] x [0, 0.5] (slave body, 101), two layers of cells each,
      // different numbers of cells along the interface: non-matching.
      std::vector<Point<dim>>    vertices;
      std::vector<CellData<dim>> cells;
      const auto                 add_block = [&](const double       y0,
                                 const unsigned int nx,
                                 const unsigned int material_id) {
        // Vertices row by row, x fastest; each cell's vertices in deal.II's
        // lexicographic order (bottom left, bottom right, top left, top
        // right), which gives every cell a positive measure.
        // In 3D the layers along z, nx of them, each as the 2D block.
        const unsigned int offset = vertices.size(), ny = 2;
        const unsigned int nz = dim == 3 ? nx : 0;
        for (unsigned int k = 0; k <= nz; ++k)
          for (unsigned int j = 0; j <= ny; ++j)
            for (unsigned int i = 0; i <= nx; ++i)
              {
                Point<dim> x;
                x[0] = 1.0 * i / nx;
                x[1] = y0 + 0.5 * j / ny;
                if constexpr (dim == 3)
                  x[2] = 1.0 * k / nz;
                vertices.push_back(x);
              }
        const auto v = [&](const unsigned int a,
                           const unsigned int b,
                           const unsigned int c) {
          return offset + (c * (ny + 1) + b) * (nx + 1) + a;
        };
        for (unsigned int k = 0; k < std::max(nz, 1u); ++k)
          for (unsigned int j = 0; j < ny; ++j)
            for (unsigned int i = 0; i < nx; ++i)
              {
                CellData<dim> cell;
                cell.vertices = {v(i, j, k),
                                 v(i + 1, j, k),
                                 v(i, j + 1, k),
                                 v(i + 1, j + 1, k)};
                if constexpr (dim == 3)
                  for (const unsigned int top : {v(i, j, k + 1),
                                                 v(i + 1, j, k + 1),
                                                 v(i, j + 1, k + 1),
                                                 v(i + 1, j + 1, k + 1)})
                    cell.vertices.push_back(top);
                cell.material_id = material_id;
                cells.push_back(cell);
              }
      };
      add_block(-0.5, blocks.elements_lower, Ids::lower_block);
      add_block(0.0, blocks.elements_upper, Ids::upper_block);
      // No boundary lines are given: the ids are set on the faces afterwards,
      // from their position.
      triangulation.create_triangulation(vertices, cells, SubCellData());
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            {
              const double y     = face->center()[1];
              const bool   lower = cell->material_id() == Ids::lower_block;
              if (std::abs(y + 0.5) < 1e-12)
                face->set_boundary_id(Ids::bottom);
              else if (std::abs(y - 0.5) < 1e-12)
                face->set_boundary_id(Ids::top);
              else if (std::abs(y) < 1e-12)
                face->set_boundary_id(lower ? Ids::lower_interface :
                                              Ids::upper_interface);
              else
                face->set_boundary_id(0); // free sides
            }
    }


    // @sect4{The scenario}
    //
    // The blocks pressed together by an imposed shortening, reported and
    // checked as the rings are (reference_pressure.cc) with the uniform p as
    // the reference.
    template <int dim>
    class PatchTest : public ReferencePressureScenario<dim>
    {
    public:
      // `blocks` refers to the scenario's entries, which the copy of the
      // parameters shares (scenario_parameters holds shared pointers): the
      // reference lives as long as the scenario.
      explicit PatchTest(const Parameters &parameters)
          : parameters(parameters)
          , blocks(parameters.scenario_entries<PatchTestParameters>())
          , program(blocks.reference.ramp.program())
      {}

      void
      create_mesh(Triangulation<dim> &triangulation) const override
      {
        // The size is checked before the blocks exist: the elements along each
        // block go up to 100000 and each refinement multiplies the cells by 4.
        const std::size_t layers = dim == 3 ? 1 : 0;
        Geometry::check_size<dim>(
          2 * (blocks.elements_lower *
                 (layers * blocks.elements_lower + 1 - layers) +
               blocks.elements_upper *
                 (layers * blocks.elements_upper + 1 - layers)),
          std::max(blocks.degree_lower, blocks.degree_upper),
          parameters.mesh.global_refinements);
        make_blocks<dim>(triangulation, blocks);
        // Refined without a manifold: the blocks' edges stay straight. The size
        // check above assumed the higher degree for both blocks, erring on the
        // safe side.
        triangulation.refine_global(parameters.mesh.global_refinements);
      }

      std::vector<Body<dim>>
      bodies() const override
      {
        // The lower block is the master body, the upper the slave, as
        // subsection Contact's defaults say (400 on 300). The blocks are
        // straight-sided, so every mapping degree gives the same geometry; 0
        // keeps the meaning it has for the rings, each block's own degree.
        const auto &m       = parameters.materials;
        const auto  mapping = [&](const unsigned int degree) {
          return parameters.finite_elements.mapping_degree > 0 ?
                    parameters.finite_elements.mapping_degree :
                    degree;
        };
        return {Body<dim>{Ids::lower_block,
                          "lower block",
                          blocks.degree_lower,
                          mapping(blocks.degree_lower),
                          Material<dim>(blocks.youngs_modulus_lower,
                                        blocks.poissons_ratio_lower,
                                        m.plane,
                                        m.law)},
                Body<dim>{Ids::upper_block,
                          "upper block",
                          blocks.degree_upper,
                          mapping(blocks.degree_upper),
                          Material<dim>(blocks.youngs_modulus_upper,
                                        blocks.poissons_ratio_upper,
                                        m.plane,
                                        m.law)}};
      }

      const LoadProgram &
      load_program() const override
      {
        return program;
      }

      ImposedMotion<dim>
      boundary_motion(const DoFHandler<dim>            &dof_handler,
                      const hp::MappingCollection<dim> &mapping,
                      const LoadState                  &load) const override
      {
        const auto &m       = parameters.materials;
        const auto  modulus = [&](const double E, const double nu) {
          return dim == 3 || m.plane == PlaneAssumption::plane_stress ?
                    E :
                    E / (1 - nu * nu);
        };
        // The exact solution is uniaxial: sigma_yy = -p in both blocks and
        // sigma_xx = 0 (free sides), so each block of height H = 0.5 m shortens
        // by H p / E*, with E* = E in plane stress and E / (1 - nu^2) in plane
        // strain (sigma_zz = nu sigma_yy keeps eps_zz = 0 there). The top is
        // moved down by the two shortenings, the bottom held: only the vertical
        // components, so that the blocks expand sideways freely. This is the
        // small-strain shortening: in finite strain the state stays uniform but
        // its pressure is not exactly p.
        const double shortening =
          load("pressure") * (0.5 / modulus(blocks.youngs_modulus_lower,
                                            blocks.poissons_ratio_lower) +
                              0.5 / modulus(blocks.youngs_modulus_upper,
                                            blocks.poissons_ratio_upper));
        // The same unknowns are held at every load state, since they define the
        // constraints; only the shortening changes with p.
        std::map<types::global_dof_index, double> values;
        const ComponentMask                       vertical =
          Components::displacement_mask<dim>(false, true);
        VectorTools::interpolate_boundary_values(
          mapping,
          dof_handler,
          Ids::bottom,
          Functions::ZeroFunction<dim>(Components::n_components<dim>),
          values,
          vertical);
        // The top's function has as many components as the finite element (u_x,
        // u_y and the two multipliers): deal.II checks the count in Debug mode.
        std::vector<double> top(Components::n_components<dim>, 0.);
        top[Components::uy] = -shortening;
        VectorTools::interpolate_boundary_values(
          mapping,
          dof_handler,
          Ids::top,
          Functions::ConstantFunction<dim>(top), // u, the multipliers
          values,
          vertical);
        // Horizontally each block is held at one vertex, its outer left corner,
        // (0, -0.5) and (0, 0.5). Without friction the interface transmits no
        // tangential force, so each block has a rigid sliding of its own to
        // remove, and one point removes it without resisting the Poisson
        // expansion: the blocks expand sideways by different amounts when their
        // materials differ, and slide against each other along the interface.
        // In 3D at two vertices of the block's outer face, (0, +-0.5, 0)
        // held in x and z, (1, +-0.5, 0) in z: no rigid motion in the
        // interface's plane, the expansion u_x = e x, u_z = e z free.
        for (const auto &cell : dof_handler.active_cell_iterators())
          for (const unsigned int v : cell->vertex_indices())
            {
              const Point<dim> &x     = cell->vertex(v);
              const auto        index = [&](const unsigned int c) {
                return cell->vertex_dof_index(v, c, cell->active_fe_index());
              };
              if (std::abs(std::abs(x[1]) - 0.5) > 1e-12 ||
                  std::abs(x[dim - 1] * (dim - 2)) > 1e-12)
                continue;
              if (std::abs(x[0]) < 1e-12)
                {
                  values[index(Components::ux)] = 0;
                  if constexpr (dim == 3)
                    values[index(Components::uz)] = 0;
                }
              else if (dim == 3 && std::abs(x[0] - 1) < 1e-12)
                values[index(Components::uz)] = 0;
            }
        // No normal conditions: every held unknown is fixed whole.
        return {values, {}};
      }

      // What it reports: the pressure at the probe against the uniform p,
      // as the rings report theirs against the closed form
      // (ReferencePressureScenario). The reference is the load state's
      // pressure itself.
      double
      reference_pressure(const LoadState &load) const override
      {
        return load("pressure");
      }

      const Parameters &
      run_parameters() const override
      {
        return parameters;
      }

      const ReferencePressureEntries &
      reference_entries() const override
      {
        return blocks.reference;
      }

    private:
      const Parameters           parameters;
      const PatchTestParameters &blocks;
      const LoadProgram          program;
    };

    // The registration line: Problem/Scenario = patch test.
    const ScenarioRegistration::Add registration{ScenarioRegistration{
      "patch test",
      "the patch test",
      "two blocks with non-matching meshes pressed together, whose uniform "
      "contact pressure a contact discretisation transmits exactly "
      "(subsection Patch test; the ramp of the load program and the checks "
      "of subsection Checks).",
      false,
      "",
      []() { return std::make_shared<PatchTestParameters>(); },
      [](const Parameters &parameters) {
        return std::make_unique<PatchTest<2>>(parameters);
      },
      [](const Parameters &parameters) {
        return std::make_unique<PatchTest<3>>(parameters);
      }}};
  } // namespace
} // namespace RingContact
