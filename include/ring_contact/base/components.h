// The layout of the unknowns of every body's FESystem: the two displacement
// components, then the contact pressure (the Lagrange multiplier: FE_Q on
// the layer of slave cells along the slave surface, constrained to zero off
// it; FE_Nothing elsewhere), then the tangential traction (the friction
// multiplier: as the pressure with friction, FE_Nothing everywhere without,
// where it adds no unknown). Names for the indices and masks, instead of 2, 3
// and ComponentMask({false, false, true}) in the code.
#ifndef ring_contact_base_components_h
#define ring_contact_base_components_h

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
    /// The tangential traction (Coulomb friction).
    constexpr unsigned int tangential = 3;
    /// All of them.
    constexpr unsigned int n_components = 4;

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
      return ComponentMask({x, y, false, false});
    }

    /// The contact pressure.
    inline ComponentMask
    multiplier_mask()
    {
      return ComponentMask({false, false, true, false});
    }

    /// The contact pressure and the tangential traction: the unknowns of
    /// the slave surface.
    inline ComponentMask
    contact_mask()
    {
      return ComponentMask({false, false, true, true});
    }
  } // namespace Components
} // namespace RingContact

#endif
