// @sect3{The SSNP152 scenario}
//
// The rings of SSNP152 as a scenario (ssnp152.h): their entries of the
// parameter file, their bodies, mesh and loads, and what they report.
// The problem class asks a Scenario every question whose answer depends
// on the problem posed (scenario.h); this file gives the rings' answers,
// and leans on its neighbours for the substance: the closed-form (Lame)
// solution in analytic_solution.cc, the imposed radial and turning motion
// in boundary_motion.cc, the generated mesh and the checks of any mesh of
// the rings in ring_mesh.cc. The entries are checked here, each refusal
// naming its entry: whatever the rings cannot run (a sector of a gmsh
// mesh, a rotation under the pressure load, friction with cyclic
// symmetry) is said before anything is computed, not found mid-run.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/numerics/vector_tools.h>

#include <ring_contact/base/components.h>
#include <ring_contact/base/dimension.h>
#include <ring_contact/input/gmsh_mesh.h>
#include <ring_contact/input/parameter_checks.h>
#include <ring_contact/scenarios/reference_pressure.h>
#include <ring_contact/scenarios/scenario.h>
#include <ring_contact/scenarios/ssnp152/analytic_solution.h>
#include <ring_contact/scenarios/ssnp152/boundary_motion.h>
#include <ring_contact/scenarios/ssnp152/ssnp152.h>

#include <array>
#include <cmath>
#include <iomanip>

namespace RingContact
{
  namespace Ssnp152
  {
    using namespace ParameterChecks;

    // @sect4{The rings' entries}
    //
    // Counted on the unrefined mesh: refinement splits every element, so
    // k elements of Ne span the same angle at every level.
    double
    RingParameters::sector_angle() const
    {
      return 2 * numbers::PI * sector_elements / elements_around;
    }

    // Mapping degree = 0 gives each ring its displacement degree, as the
    // original's meshes are: a linear ring faceted, a quadratic one curved.
    // With rings of different degrees that puts a curved surface against a
    // faceted one, which overlap before any load (the initial
    // interpenetration diagnostic warns of it).
    unsigned int
    RingParameters::mapping_degree_of(const unsigned int             ring,
                                      const FiniteElementParameters &fe) const
    {
      if (fe.mapping_degree > 0)
        return fe.mapping_degree;
      return ring == Ids::outer_ring ? degree_outer : degree_inner;
    }

    // Each entry declared once, bound to its member, with its default,
    // range and documentation (parameter_checks.h); the defaults are
    // SSNP152's seed mesh and materials. The ranges refuse only the absurd:
    // fewer than three elements around make no ring, and the memory
    // estimate (Geometry::check_size<dim>()) stops a mesh too large long before
    // the upper bounds.
    void
    RingParameters::add_parameters(ParameterHandler &prm)
    {
      add_mesh_parameters(prm);
      // -1 < nu < 0.5 is where the isotropic elastic energy is positive
      // definite: lambda = E nu / ((1 + nu)(1 - 2 nu)) is infinite at 0.5,
      // mu = E / (2 (1 + nu)) at -1.
      {
        Subsection      s(prm, "Materials", &declared);
        const Condition poisson = {[](const double nu) {
                                     return nu > -1 && nu < 0.5;
                                   },
                                   "must satisfy -1 < nu < 0.5"};
        s.add("Young's modulus outer ring",
              youngs_modulus_outer,
              "1e9",
              "E1 [Pa], > 0.",
              positive());
        s.add("Poisson's ratio outer ring",
              poissons_ratio_outer,
              "0.2",
              "nu1 [-], -1 < nu1 < 0.5.",
              poisson);
        s.add("Young's modulus inner ring",
              youngs_modulus_inner,
              "1e9",
              "E2 [Pa], > 0.",
              positive());
        s.add("Poisson's ratio inner ring",
              poissons_ratio_inner,
              "0.2",
              "nu2 [-], -1 < nu2 < 0.5.",
              poisson);
      }
      // The original's elements: Q1 and Q2 (a mesh of 8- or 9-node
      // quadrilaterals is read by its vertices; the cells are then
      // deal.II's 9-node Q2).
      {
        Subsection s(prm, "Finite elements", &declared);
        s.add("Displacement degree outer ring",
              degree_outer,
              "1",
              1,
              2,
              "Polynomial degree of the displacement on the outer "
              "ring (1: Q1, 2: 9-node Q2).");
        s.add("Displacement degree inner ring",
              degree_inner,
              "1",
              1,
              2,
              "Polynomial degree of the displacement on the inner "
              "ring.");
      }
      add_load_parameters(prm);
      // The ramp, the probe and the checks, which the patch test declares
      // too (scenarios/reference_pressure_entries.cc).
      reference.add_parameters(prm, declared);
    }


    // The entries of subsection Load program: how the load reaches the
    // rings, and the rotation program. The rotation (C-G): p = 1e7 Pa held
    // while s goes from 0 to 1 in 100 equal steps, the document's N_t (the
    // newest published inputs take 10). At s = 1 the inner ring has turned
    // through one element and the meshes face each other again.
    void
    RingParameters::add_load_parameters(ParameterHandler &prm)
    {
      Subsection s(prm, "Load program", &declared);
      s.add(
        "Loading",
        loading,
        "imposed displacements",
        {{"imposed displacements", Loading::imposed_displacements},
         {"pressure", Loading::pressure}},
        "imposed displacements: the analytic displacements of pressure p on "
        "r = R1 and r = R3 (the original's loading, the only one the "
        "rotation program takes); pressure: the pressure p on r = R1 as "
        "the problem states it, on the current configuration (a follower "
        "load; a dead load in small strain), r = R3 free, and each ring's "
        "rigid-body modes removed by u_y = 0 at (+-r, 0) and u_x = 0 at "
        "(0, r) of r = R1 and r = R3 (the symmetric solution satisfies "
        "them; the mesh needs nodes there).");
      s.add("Rotation pressure",
            rotation_pressure,
            "1e7",
            "Equivalent pressure p [Pa] held during the rotation.",
            positive());
      s.add("Rotation steps",
            rotation_steps,
            "100",
            1,
            LoadParameters::max_steps,
            "Nt, number of equal rotation steps.");
      s.add("Rotation in elements",
            rotation_elements,
            "1",
            "Final rotation parameter s: the angle is "
            "2 pi s / (elements around).");
    }

    // The ramp and the rotation. Rotation: the full pressure from the first
    // step on (reached linearly within the first step if that step has to
    // be cut), s = s_end t, t = k / N_t: the pseudo-time runs from 0 to 1
    // over the steps, not s itself, so that a program of zero rotation
    // still advances. The document's program: the first step both loads the
    // rings and turns them by s_end / N_t; at s_end = 1 the inner ring has
    // turned through exactly one element when t = 1.
    std::vector<std::pair<std::string, std::string>>
    RingParameters::load_programs() const
    {
      return {PressureRamp::program_choice(),
              {rotation_program,
               "the pressure fixed, a boundary turned through s elements (the "
               "rings' C-G)"}};
    }

    bool
    RingParameters::rotating(const Parameters &parameters)
    {
      return parameters.load.program == rotation_program;
    }

    LoadProgram
    RingParameters::load_program(const Parameters &parameters) const
    {
      if (!rotating(parameters))
        return reference.ramp.program();
      std::vector<double> times;
      for (unsigned int step = 1; step <= rotation_steps; ++step)
        times.push_back(static_cast<double>(step) / rotation_steps);
      const double p = rotation_pressure, s_end = rotation_elements,
                   t1 = times.front();
      return LoadProgram(times, [p, s_end, t1](const double t) {
        return LoadState{t,
                         {{"pressure", p * std::min(1.0, t / t1)},
                          {"rotation", s_end * t}}};
      });
    }


    // The rings' entries of subsection Mesh: their sizes and elements.
    void
    RingParameters::add_mesh_parameters(ParameterHandler &prm)
    {
      {
        Subsection s(prm, "Mesh", &declared);
        s.add("Elements around",
              elements_around,
              "40",
              3,
              10000000,
              "Number of elements around every circle (generated mesh).");
        s.add("Radial elements outer ring",
              radial_elements_outer,
              "3",
              1,
              10000000,
              "Elements across the outer ring (generated mesh).");
        s.add("Radial elements inner ring",
              radial_elements_inner,
              "3",
              1,
              10000000,
              "Elements across the inner ring (generated mesh).");

        // Its bound k <= Ne involves another entry: it is checked in
        // finish(), once both are read.
        s.add(
          "Sector elements",
          sector_elements,
          "0",
          0,
          10000000,
          "Cyclic symmetry (generated mesh): model only a sector of this many "
          "elements around, from angle 0, with the displacements of its two "
          "radial sides tied by the rotation through the sector angle and the "
          "master surface continued by rotated copies. The rings, their "
          "meshes and the loads repeat every element, so the solution is the "
          "whole rings' (to round-off) at a fraction of the cost. 0: the "
          "whole rings.");

        // The radii are ordered against each other in finish(), when all
        // three are read: an entry's own check sees that entry alone.
        s.add("Outer radius",
              outer_radius,
              "1.0",
              "R1, outer radius of the outer ring [m].");
        s.add("Interface radius",
              interface_radius,
              "0.6",
              "R2, radius of the contact interface [m].");
        s.add("Inner radius",
              inner_radius,
              "0.2",
              "R3, inner radius of the inner ring [m].",
              positive("must be positive (R3 > 0)"));
      }
    }

    // Once the whole file is read: the entries against each other and
    // against the common ones. Each check throws a ParameterError naming
    // its entry, which Parameters::read() locates at the line that set it.
    void
    RingParameters::finish(Parameters &parameters)
    {
      // Node A of SSNP152 is the slave node at (R2, 0): a file that
      // changes the radii and not the probe point still checks node A.
      // (Before, such a file was refused: the default probe point was no
      // longer near the slave surface.)
      if (parameters.origins.count(entry_key("Contact", "Probe point")) == 0)
        reference.probe = {interface_radius, 0};
      check_geometry(parameters);
      // The rings' load states carry a pressure and a rotation, which only
      // the ramp and the rotation program give.
      require(parameters.load.program == PressureRamp::program_name ||
                rotating(parameters),
              "Load program",
              "Program",
              "= steps takes Problem/Scenario = general (SSNP152 is loaded by "
              "the ramp or the rotation)");
      if (!rotating(parameters))
        reference.ramp.finish();
      check_contact_surfaces(parameters);
      check_loading(parameters);
      check_probe_point(parameters);
      check_sector_and_steps(parameters);
    }


    // The rings' radii in order, each ring thick enough, a sector no wider
    // than the rings. A sector of all Ne elements is allowed: it is the
    // rings cut open at angle 0, their master surface closed across the
    // cut, with no rotated copy.
    void
    RingParameters::check_geometry(const Parameters &parameters) const
    {
      require(sector_elements == 0 ||
                parameters.mesh.source == MeshSource::generated,
              "Mesh",
              "Sector elements",
              "needs 'Mesh source' = generated (a sector is built in code)");
      require(sector_elements <= elements_around,
              "Mesh",
              "Sector elements",
              "must be at most 'Elements around' (0: the whole rings)");
      require(inner_radius < interface_radius,
              "Mesh",
              "Inner radius",
              "must be smaller than 'Interface radius' (R3 < R2)");
      require(interface_radius < outer_radius,
              "Mesh",
              "Interface radius",
              "must be smaller than 'Outer radius' (R2 < R1)");
      // The meshes identify their circles to 1e-8 R1: each ring must be
      // much thicker than that.
      require(interface_radius - inner_radius >= 1e-4 * outer_radius &&
                outer_radius - interface_radius >= 1e-4 * outer_radius,
              "Mesh",
              "Interface radius",
              "leaves a ring thinner than 1e-4 R1 (R1 = " +
                to_text(outer_radius) + ", R2 = " + to_text(interface_radius) +
                ", R3 = " + to_text(inner_radius) + ")");
    }


    // The contact surfaces at r = R2, and the multiplier no richer than the
    // slave ring's displacement.
    void
    RingParameters::check_contact_surfaces(const Parameters &parameters) const
    {
      // A linear multiplier against quadratic displacements satisfies the
      // inf-sup (LBB) condition; a multiplier as rich as a quadratic
      // slave's displacement would not, and neither can one richer than a
      // linear slave's.
      const FiniteElementParameters &fe = parameters.finite_elements;
      const unsigned int             slave_degree =
        (parameters.contact.slave_boundary_id == Ids::outer_ring_contact) ?
                      degree_outer :
                      degree_inner;
      require(fe.multiplier_degree <= slave_degree,
              "Finite elements",
              "Multiplier degree",
              "must not exceed the displacement degree of the slave ring");
      // The rings' loaded boundaries are not contact surfaces. Said here,
      // at the entry's line: otherwise the mesh check found the real
      // contact boundary (400) missing, and said so with no line.
      for (const auto &[entry, id] :
           {std::pair<const char *, unsigned int>{
              "Slave boundary", parameters.contact.slave_boundary_id},
            {"Master boundary", parameters.contact.master_boundary_id}})
        require(id != Ids::outer_boundary && id != Ids::inner_boundary,
                "Contact",
                entry,
                "= " + std::to_string(id) + " is " +
                  (id == Ids::outer_boundary ?
                     std::string("the outer ring's loaded boundary r = R1") :
                     std::string("the inner ring's loaded boundary r = R3")) +
                  ", not a contact surface (SSNP152's are 300, the outer "
                  "ring's, and 400, the inner ring's, at r = R2)");
    }


    // What the rotation and the pressure load allow.
    void
    RingParameters::check_loading(const Parameters &parameters) const
    {
      // Rotations: at most ten turns (the angle is 2 pi s over the elements
      // around the refined mesh); beyond, the rotated copies of the master
      // surface a sector needs would grow without bound.
      const double elements_around_refined =
        static_cast<double>(elements_around) *
        (1u << parameters.mesh.global_refinements);
      require(!rotating(parameters) ||
                std::abs(rotation_elements) <= 10 * elements_around_refined,
              "Load program",
              "Rotation in elements",
              "must be at most ten turns (|s| <= 10 x " +
                to_text(elements_around_refined) +
                " elements around the refined mesh), got " +
                to_text(rotation_elements));

      // The pressure load: the ramp on the whole rings. r = R3 is free
      // there, so the rotation has nothing to turn; and each ring is held
      // only at three points (add_rigid_body_points()), of which a sector
      // lacks some, leaving its rigid rotation free.
      require(loading != Loading::pressure || !rotating(parameters),
              "Load program",
              "Loading",
              "= pressure takes the ramp program only: the rotation turns an "
              "imposed displacement of r = R3");
      require(loading != Loading::pressure || sector_elements == 0,
              "Load program",
              "Loading",
              "= pressure needs the whole rings: a sector leaves its rigid "
              "rotation free (set Mesh/Sector elements = 0)");
      // The slip of a point is measured from its partner in the last
      // converged state; on a rotated copy of the master that old state
      // would have to be turned too, which is not done.
      require(!parameters.contact.frictional() || sector_elements == 0,
              "Contact",
              "Friction coefficient",
              "> 0 needs the whole rings: friction is not implemented with "
              "cyclic symmetry (set Mesh/Sector elements = 0)");
    }


    void
    RingParameters::check_probe_point(const Parameters &parameters) const
    {
      // The probe point (node A) must be on the slave surface, or near it:
      // the nearest slave node is used, and a point far away names a node
      // the user did not mean.
      // The slave surface is the circle r = R2 in the reference state: the
      // distance is radial, and 5 % of R2 accepts any point meant to be on
      // the interface, not one meant elsewhere.
      {
        const Point<dim> x = reference.probe_point<dim>();
        double           distance;
        double           scale;
        distance = std::abs(x.norm() - interface_radius);
        scale    = interface_radius;
        require(distance <= 0.05 * scale,
                "Contact",
                "Probe point",
                "(" + to_text(x[0]) + ", " + to_text(x[1]) +
                  ") is not near the slave surface: it is " +
                  to_text(distance) + " m from it (at most " +
                  to_text(0.05 * scale) + " m accepted)");
      }
    }


    // A sector under the rotation, and the checked steps.
    void
    RingParameters::check_sector_and_steps(const Parameters &parameters) const
    {
      // k, s and Ne all in elements of the refined mesh, as the sector is
      // built and turned.
      const double elements_around_refined =
        static_cast<double>(elements_around) *
        (1u << parameters.mesh.global_refinements);
      // Cyclic symmetry: the master surface seen by a sector of k < Ne
      // elements covers the circle at most once (CyclicSymmetry::
      // set_master_window()). A rotation that slides the slave sector all
      // the way round to its own start side, k + |s| >= Ne, makes it meet
      // the master surface across the seam of that window, where the pairing
      // relies on a symmetry the sector does not impose: Newton fails or
      // finds another solution (k = 9..11 of 12 with s = 3). Refuse those.
      // When k divides Ne the sector tiles the circle, and the master across
      // the seam is the same copy of the same segments (turned by a multiple
      // of 2 pi): any rotation is consistent (k = 1 through a whole turn).
      if (sector_elements > 0 && elements_around % sector_elements != 0 &&
          rotating(parameters))
        {
          const double k = static_cast<double>(sector_elements) *
                           (1u << parameters.mesh.global_refinements);
          require(k + std::abs(rotation_elements) < elements_around_refined,
                  "Mesh",
                  "Sector elements",
                  "= " + std::to_string(sector_elements) +
                    " is too wide for a rotation of " +
                    to_text(rotation_elements) +
                    " elements: the sector would slide round to its own start "
                    "side (k + |s| must stay below " +
                    to_text(elements_around_refined) +
                    " elements around, unless k divides the elements around)");
        }

      // A checked step beyond the last one of the load program is a typo.
      reference.checks.check_steps(rotating(parameters) ? rotation_steps :
                                                          reference.ramp.steps);
    }

    // @sect4{The scenario}
    //
    // The object the problem class asks. It holds copies of what it needs:
    // the parameters, the closed form of this material pair and plane
    // (evaluated at each load state's pressure), and the load program.
    namespace
    {
      class Rings : public ReferencePressureScenario<dim>
      {
      public:
        // The closed form is made once: its constants depend on the radii,
        // the materials and the plane assumption, and Lame's solution is
        // linear in the pressure, which each load state gives.
        explicit Rings(const Parameters &parameters)
            : parameters(parameters)
            , rings(parameters.scenario_entries<RingParameters>())
            , analytic(rings, parameters.materials.plane)
            , pressure_loading(rings.loading == Loading::pressure)
            , program(rings.load_program(parameters))
        {}

        // The mesh: generated, or read from a gmsh file or script with the
        // original's physical tags, checked; on the polar manifold, so that
        // refinement puts new vertices on the circles and a mapping of
        // degree >= 2 makes the element edges arcs.
        void
        create_mesh(Triangulation<dim> &triangulation) const override
        {
          // The size is estimated before the generated mesh exists (from
          // its counts), and after a gmsh mesh is read (from its cells),
          // but always before refinement and the unknowns: a mesh that
          // would not fit in memory is refused before it is allocated.
          if (parameters.mesh.source == MeshSource::generated)
            {
              // A sector's mesh has only its own k columns of cells.
              const std::size_t columns = rings.sector_elements > 0 ?
                                            rings.sector_elements :
                                            rings.elements_around;
              Geometry::check_size<dim>(
                std::size_t(columns) *
                  (rings.radial_elements_outer + rings.radial_elements_inner),
                std::max(rings.degree_outer, rings.degree_inner),
                parameters.mesh.global_refinements);
              make_rings(triangulation, rings);
              check_rings(triangulation, parameters);
            }
          else
            {
              // A script is meshed with the elements the rings use: linear
              // if both rings are, quadratic otherwise (the cells take only
              // the vertices; quadratic nodes on the circles are checked).
              const unsigned order =
                rings.degree_outer == 1 && rings.degree_inner == 1 ? 1 : 2;
              const Geometry::GmshMesh<dim> mesh =
                Geometry::read_gmsh(triangulation,
                                    parameters.mesh.mesh_file,
                                    parameters.mesh.geo_numbers,
                                    order);
              check_rings(triangulation, parameters);
              Geometry::check_boundary_tags(triangulation, mesh);
              Geometry::check_size<dim>(triangulation.n_active_cells(),
                                        std::max(rings.degree_outer,
                                                 rings.degree_inner),
                                        parameters.mesh.global_refinements);
            }
          // Every cell and face, the radial sides of a sector included: on
          // a radial line the polar manifold is straight anyway.
          triangulation.set_all_manifold_ids(0);
          triangulation.set_manifold(0, PolarManifold<dim>(Point<dim>()));
          triangulation.refine_global(parameters.mesh.global_refinements);
        }

        // The two rings, outer (100) and inner (101). Both have the common
        // plane assumption and material law (subsection Materials): SSNP152's
        // rings differ only in their constants and degrees.
        std::vector<Body<dim>>
        bodies() const override
        {
          const auto &m  = parameters.materials;
          const auto &fe = parameters.finite_elements;
          return {Body<dim>{Ids::outer_ring,
                            "outer ring",
                            rings.degree_outer,
                            rings.mapping_degree_of(Ids::outer_ring, fe),
                            Material<dim>(rings.youngs_modulus_outer,
                                          rings.poissons_ratio_outer,
                                          m.plane,
                                          m.law)},
                  Body<dim>{Ids::inner_ring,
                            "inner ring",
                            rings.degree_inner,
                            rings.mapping_degree_of(Ids::inner_ring, fe),
                            Material<dim>(rings.youngs_modulus_inner,
                                          rings.poissons_ratio_inner,
                                          m.plane,
                                          m.law)}};
        }

        // The ramp (the pressure raised step by step) or the rotation (the
        // pressure fixed, the inner boundary turned), made once from
        // subsection Load program.
        const LoadProgram &
        load_program() const override
        {
          return program;
        }

        // Imposed displacements: the analytic ones on r = R1 and r = R3, the
        // inner boundary turned through the rotation. Pressure loading:
        // nothing is imposed, but nothing holds the rings in place either:
        // each can translate and turn (frictionless contact transmits no
        // torque). Three displacement components per ring fix them without
        // constraining the solution sought, which is radial: u_y = 0 at
        // (r, 0) and (-r, 0), u_x = 0 at (0, r), on r = R1 for the outer ring
        // and r = R3 for the inner one.
        ImposedMotion<dim>
        boundary_motion(const DoFHandler<dim>            &dof_handler,
                        const hp::MappingCollection<dim> &mapping,
                        const LoadState                  &load) const override
        {
          std::map<types::global_dof_index, double> values;
          if (pressure_loading)
            {
              add_rigid_body_points(dof_handler, values);
              return {values, {}};
            }
          // The rotation is counted in elements of the refined mesh, so that
          // s = 1 always brings the meshes face to face again.
          const double angle = 2 * numbers::PI * load("rotation") /
                               (rings.elements_around *
                                (1u << parameters.mesh.global_refinements));
          // The closed form's radial displacements of r = R1 and r = R3 at
          // this load's pressure; the inner boundary contracted to its loaded
          // radius and turned rigidly through the angle.
          // Functions of every component of the system, the multiplier's
          // too; the mask of the interpolation picks the displacement.
          const BoundaryMotion outer(analytic.f_R1(load("pressure")),
                                     0.0,
                                     Components::n_components<dim>);
          const BoundaryMotion inner(analytic.f_R3(load("pressure")),
                                     angle,
                                     Components::n_components<dim>);
          const std::map<types::boundary_id, const Function<dim> *> motion = {
            {Ids::outer_boundary, &outer}, {Ids::inner_boundary, &inner}};
          // Interpolated at the support points of the boundaries' unknowns
          // (through the mapping, so on the circles where the mapping is
          // curved); the displacement only, never the multipliers.
          VectorTools::interpolate_boundary_values(
            mapping,
            dof_handler,
            motion,
            values,
            Components::displacement_mask<dim>());
          return {values, {}};
        }

        // Pressure loading: p on r = R1, the ramp's pressure, uniform; the
        // value of a pressure load is its first component.
        std::vector<BoundaryLoad<dim>>
        boundary_loads() const override
        {
          if (!pressure_loading)
            return {};
          return {
            BoundaryLoad<dim>{Ids::outer_boundary,
                              BoundaryLoad<dim>::Type::pressure,
                              [](const Point<dim> &, const LoadState &load) {
                                return Tensor<1, dim>({load("pressure"), 0.0});
                              }}};
        }

        // A sector of the rings (Mesh/Sector elements): the slave's turn
        // along the master is the inner ring's, or (the outer ring slave)
        // its opposite. The master window of the rotated copies leads in
        // the direction the slave slides (CyclicSymmetry), so the sign
        // matters; every count is of the refined mesh.
        std::optional<CyclicSector>
        cyclic_sector() const override
        {
          if (rings.sector_elements == 0)
            return {};
          const unsigned int refined = 1u << parameters.mesh.global_refinements;
          const bool         inner_slave =
            parameters.contact.slave_boundary_id == Ids::inner_ring_contact;
          return CyclicSector{
            rings.sector_angle(),
            static_cast<types::boundary_id>(Ids::sector_start),
            static_cast<types::boundary_id>(Ids::sector_end),
            rings.sector_elements * refined,
            rings.elements_around * refined,
            RingParameters::rotating(parameters) ?
              (inner_slave ? 1.0 : -1.0) * rings.rotation_elements :
              0.0};
        }

        // What the rings report: the pressure at node A against the closed
        // form (and the L2 error over the slave surface, the extreme
        // pressures), and with friction the tangential traction; printed,
        // warned about and checked as by every scenario checked against a
        // reference pressure (ReferencePressureScenario). The reference is
        // the closed form at the load state's pressure, the same pressure
        // whose displacements were imposed (the rotation program keeps it
        // fixed, the ramp raises it step by step).
        double
        reference_pressure(const LoadState &load) const override
        {
          return analytic.contact_pressure(load("pressure"));
        }

        const Parameters &
        run_parameters() const override
        {
          return parameters;
        }

        const ReferencePressureEntries &
        reference_entries() const override
        {
          return rings.reference;
        }

      private:
        void
        add_rigid_body_points(
          const DoFHandler<dim>                     &dof_handler,
          std::map<types::global_dof_index, double> &values) const
        {
          for (const auto &[boundary, r] :
               {std::make_pair(Ids::outer_boundary, rings.outer_radius),
                std::make_pair(Ids::inner_boundary, rings.inner_radius)})
            {
              // The radial solution has u_y = 0 on the x axis and u_x = 0
              // on the y axis: holding those components at three points
              // removes the two translations and the rotation of the ring and
              // constrains nothing the solution does not satisfy.
              // (point, component)
              const std::array<std::pair<Point<dim>, unsigned int>, 3> fixed = {
                {{Point<dim>(r, 0), 1},
                 {Point<dim>(-r, 0), 1},
                 {Point<dim>(0, r), 0}}};
              // The points are found among the vertices of the boundary's
              // faces (to 1e-8 r); a vertex's unknown on both of its faces is
              // set twice to the same zero.
              std::array<bool, 3> found = {{false, false, false}};
              for (const auto &cell : dof_handler.active_cell_iterators())
                for (const auto &face : cell->face_iterators())
                  if (face->at_boundary() && face->boundary_id() == boundary)
                    for (const unsigned int v : face->vertex_indices())
                      for (unsigned int k = 0; k < 3; ++k)
                        if (face->vertex(v).distance(fixed[k].first) < 1e-8 * r)
                          {
                            values[face->vertex_dof_index(
                              v, fixed[k].second, cell->active_fe_index())] = 0;
                            found[k] = true;
                          }
              for (unsigned int k = 0; k < 3; ++k)
                AssertThrow(found[k],
                            ExcMessage(
                              "Loading = pressure: no mesh node at (" +
                              Utilities::to_string(fixed[k].first[0]) + ", " +
                              Utilities::to_string(fixed[k].first[1]) +
                              ") on boundary " + std::to_string(boundary) +
                              ", where a rigid-body mode of its ring is fixed "
                              "(the number of elements around must be a "
                              "multiple of 4, with a node at angle 0)"));
            }
        }

        const Parameters       parameters;
        const RingParameters  &rings;
        const AnalyticSolution analytic;
        const bool             pressure_loading;
        const LoadProgram      program;
      };
    } // namespace

    // The registration line of the scenario: Problem/Scenario = ssnp152,
    // the default. Registered at static initialisation: nothing outside
    // this folder names the rings' class.
    const ScenarioRegistration::Add registration{ScenarioRegistration{
      "SSNP152",
      "SSNP152",
      "the rings of Code_Aster's validation case, loaded by the "
      "displacements of their closed-form solution (subsections Mesh, "
      "Materials, Finite elements, Load program, Checks).",
      true,
      "",
      []() { return std::make_shared<RingParameters>(); },
      [](const Parameters &parameters) {
        return std::make_unique<Rings>(parameters);
      }}};
  } // namespace Ssnp152
} // namespace RingContact
