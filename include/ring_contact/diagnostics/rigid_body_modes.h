// @sect3{Diagnostics: the rigid motions that only the contact holds}
//
// Which rigid-body motions of each body the imposed displacements leave
// free (u = a + w e_z x (X - X_c), in 3D u = a + w x (X - X_c), with a, w
// not all zero and u = 0 in every imposed component): only the contact can hold
// a body there, and a frictionless contact holds it along the contact normal
// only. Said once per run, so that a body left free by mistake (a support
// forgotten) is named, not only a Newton iteration that fails; and a motion
// that nothing holds, of one body or of several together, is refused before the
// first step: the problem has no unique solution.
#ifndef ring_contact_diagnostics_rigid_body_modes_h
#define ring_contact_diagnostics_rigid_body_modes_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/hp/mapping_collection.h>

#include <ring_contact/base/dimension.h>
#include <ring_contact/contact/contact_interface.h>
#include <ring_contact/scenarios/scenario.h>

#include <ostream>
#include <set>
#include <vector>

namespace RingContact
{
  namespace Diagnostics
  {
    using namespace dealii;

    /// Note in `log` each body's rigid motion that no imposed displacement
    /// fixes (`imposed_dofs`, and the normal conditions `normal` on the
    /// components `normal_component`), and return the bodies (material ids)
    /// that some motion leaves held by the contact only. Throws a one-line
    /// error if a motion of one body, or of several together, changes no
    /// gap of the `contacts` either (frictionless only: sticking may hold
    /// it).
    template <int dim>
    std::set<types::material_id>
    rigid_body_modes(const DoFHandler<dim>                      &dof_handler,
                     const hp::MappingCollection<dim>           &mapping,
                     const std::vector<Body<dim>>               &bodies,
                     const std::vector<types::global_dof_index> &imposed_dofs,
                     const std::vector<NormalDisplacement<dim>> &normal,
                     const std::vector<unsigned int> &normal_component,
                     const std::vector<const ContactInterface<dim> *> &contacts,
                     const bool                                        friction,
                     std::ostream                                     &log);
  } // namespace Diagnostics
} // namespace RingContact

#endif
