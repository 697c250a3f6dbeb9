// @sect3{The rings of SSNP152}
//
// Code_Aster's validation case SSNP152 (doc/intro.md): two concentric
// elastic rings, R2 <= r <= R1 (the outer one) and R3 <= r <= R2 (the
// inner one), in frictionless contact at r = R2, loaded by the
// displacements of their closed-form (Lame) solution on r = R1 and r = R3,
// the inner boundary turned through whole elements in the rotation
// program. This scenario owns the rings' entries of the parameter file
// (their radii and elements around in subsection Mesh, their materials and
// degrees, the loading), makes their mesh (generated, or read from gmsh
// with the original's physical tags), and reports and checks the contact
// pressure at node A against the closed form.
#ifndef ring_contact_scenarios_ssnp152_ssnp152_h
#define ring_contact_scenarios_ssnp152_ssnp152_h

#include <deal.II/grid/tria.h>

#include <ring_contact/base/dimension.h>
#include <ring_contact/input/parameters.h>
#include <ring_contact/problem/load_program.h>
#include <ring_contact/scenarios/reference_pressure_entries.h>

#include <algorithm>

namespace RingContact
{
  namespace Ssnp152
  {
    using namespace dealii;

    /// Boundary and material ids of the original mesh (gmsh physical tags).
    namespace Ids
    {
      constexpr unsigned int outer_ring         = 100; // C1
      constexpr unsigned int inner_ring         = 101; // C2
      constexpr unsigned int outer_boundary     = 200; // S1R1, r = R1
      constexpr unsigned int outer_ring_contact = 300; // S1R2, r = R2
      constexpr unsigned int inner_ring_contact = 400; // S2R2, r = R2
      constexpr unsigned int inner_boundary     = 500; // S2R3, r = R3
      /// Cyclic sector: the radial sides at angle 0 and at the sector angle.
      constexpr unsigned int sector_start = 600;
      constexpr unsigned int sector_end   = 601;
    } // namespace Ids

    /// How the load reaches the rings.
    enum class Loading
    {
      /// The analytic displacements imposed on r = R1 and r = R3 (the
      /// original's loading; the rotation turns r = R3).
      imposed_displacements,
      /// The pressure p on r = R1, on the current configuration (a follower
      /// load; a dead load in small strain), r = R3 free; each ring's
      /// rigid-body modes removed by u_y = 0 at (+-r, 0) and u_x = 0 at
      /// (0, r) of its outer boundary, which the symmetric solution
      /// satisfies.
      pressure
    };

    /// The rings' entries of the parameter file.
    struct RingParameters : public ScenarioParameters
    {
      // Mesh
      unsigned int elements_around;
      unsigned int radial_elements_outer;
      unsigned int radial_elements_inner;
      /// Cyclic symmetry: elements around in the modelled sector (0: the
      /// whole rings). See cyclic_symmetry.h.
      unsigned int sector_elements = 0;
      double       outer_radius;     ///< R1
      double       interface_radius; ///< R2
      double       inner_radius;     ///< R3
      // Materials
      double youngs_modulus_outer;
      double poissons_ratio_outer;
      double youngs_modulus_inner;
      double poissons_ratio_inner;
      // Finite elements
      unsigned int degree_outer;
      unsigned int degree_inner;
      // Load program
      Loading loading;
      /// The ramp, the probe (node A) and the checks against the closed
      /// form.
      ReferencePressureEntries reference;
      /// The rotation program: p [Pa] held, s from 0 to its final value in
      /// equal steps.
      double       rotation_pressure;
      unsigned int rotation_steps;
      double       rotation_elements; ///< final s

      /// The rotation program's value of Load program/Program.
      static constexpr const char *rotation_program = "rotation";

      /// Whether the file chose the rotation program (else the ramp).
      static bool
      rotating(const Parameters &parameters);

      /// The load program the file chose: the ramp or the rotation.
      LoadProgram
      load_program(const Parameters &parameters) const;

      /// The angle of the sector, 2 pi k / Ne (0: the whole rings).
      double
      sector_angle() const;

      /// The mapping degree of a ring (material id 100 or 101): the
      /// common Mapping degree, or (0) its displacement degree.
      unsigned int
      mapping_degree_of(const unsigned int             ring,
                        const FiniteElementParameters &fe) const;

      void
      add_parameters(ParameterHandler &prm) override;
      void
      finish(Parameters &parameters) override;

      /// The original's default, the nodal scheme (its modelisations name
      /// their schemes in prm/), which Code_Aster's values are reproduced
      /// with.
      std::string
      default_integration_schemes() const override
      {
        return "nodal";
      }

      /// The ramp (A, B, H) and the rotation (C to G).
      std::vector<std::pair<std::string, std::string>>
      load_programs() const override;

      /// The original's: the inner ring's S2R2 is the slave, the outer
      /// ring's S1R2 the master (all modelisations but E).
      std::pair<unsigned int, unsigned int>
      default_contact_surfaces() const override
      {
        return {Ids::inner_ring_contact, Ids::outer_ring_contact};
      }

      unsigned int
      highest_displacement_degree() const override
      {
        return std::max(degree_outer, degree_inner);
      }

    private:
      /// The entries of subsection Mesh.
      void
      add_mesh_parameters(ParameterHandler &prm);
      /// The entries of subsection Load program.
      void
      add_load_parameters(ParameterHandler &prm);
      /// The radii and the sector.
      void
      check_geometry(const Parameters &parameters) const;
      /// The contact surfaces and the multiplier degree.
      void
      check_contact_surfaces(const Parameters &parameters) const;
      /// The rotation and the pressure load.
      void
      check_loading(const Parameters &parameters) const;
      /// Node A near the slave surface.
      void
      check_probe_point(const Parameters &parameters) const;
      /// A sector under the rotation; the checked steps.
      void
      check_sector_and_steps(const Parameters &parameters) const;
    };

    /// Build the structured rings in code: `elements_around` cells around
    /// every circle (first vertex at angle 0), uniform radial spacing,
    /// material ids 100 (outer) / 101 (inner), boundary ids 200/300/400/500
    /// (and 600/601 on the sides of a sector).
    void
    make_rings(Triangulation<dim> &triangulation, const RingParameters &rings);

    /// Throw a one-line error if the mesh lacks what the rings need: the
    /// two ring material ids, the boundaries 200 and 500 and the slave and
    /// master boundaries, each on its circle, covering it once, and in one
    /// ring.
    void
    check_rings(const Triangulation<dim> &triangulation,
                const Parameters         &parameters);
  } // namespace Ssnp152
} // namespace RingContact

#endif
