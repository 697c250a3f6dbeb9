// The layout of the unknowns of every body's FESystem: the two displacement
// components, then the contact pressure (the Lagrange multiplier: FE_Q on
// the slave body, constrained to zero off the slave surface; FE_Nothing on
// the master body). Names for the indices and masks, instead of 2, 3 and
// ComponentMask({false, false, true}) in the code.
#ifndef ring_contact_components_h
#define ring_contact_components_h

#include <deal.II/fe/component_mask.h>

namespace RingContact
{
  namespace Components
  {
    using namespace dealii;

    /// u_x and u_y.
    constexpr unsigned int ux = 0;
    constexpr unsigned int uy = 1;
    /// The contact pressure.
    constexpr unsigned int multiplier = 2;
    /// All of them.
    constexpr unsigned int n_components = 3;

    /// Whether component c is one of the displacement's.
    constexpr bool
    is_displacement(const unsigned int c)
    {
      return c < multiplier;
    }

    /// The displacement components, or one of them.
    inline ComponentMask
    displacement_mask(const bool x = true, const bool y = true)
    {
      return ComponentMask({x, y, false});
    }

    /// The contact pressure.
    inline ComponentMask
    multiplier_mask()
    {
      return ComponentMask({false, false, true});
    }
  } // namespace Components
} // namespace RingContact

#endif
