// The layout of the unknowns of every body's FESystem in `dim` dimensions:
// the dim displacement components, then the contact pressure (the Lagrange
// multiplier: FE_Q on the layer of slave cells along the slave surface,
// constrained to zero off it; FE_Nothing elsewhere), then the tangential
// traction (the friction multiplier: as the pressure with friction,
// FE_Nothing everywhere without, where it adds no unknown; 2D only). Names
// for the indices and masks, instead of 2, 3 and
// ComponentMask({false, false, true}) in the code; each a template over
// dim, so that one name serves both dimensions.
#ifndef ring_contact_base_components_h
#define ring_contact_base_components_h

#include <deal.II/fe/component_mask.h>

#include <vector>

namespace RingContact
{
  namespace Components
  {
    using namespace dealii;

    /// u_x, u_y and (3D) u_z.
    constexpr unsigned int ux = 0;
    constexpr unsigned int uy = 1;
    constexpr unsigned int uz = 2;
    /// The contact pressure.
    template <int dim>
    constexpr unsigned int multiplier = dim;
    /// The tangential traction (friction).
    template <int dim>
    constexpr unsigned int tangential = dim + 1;
    template <int dim>
    constexpr unsigned int n_components = dim + 2;

    template <int dim>
    constexpr bool
    is_displacement(const unsigned int c)
    {
      return c < multiplier<dim>;
    }

    /// The displacement components chosen (z: 3D only, held only when
    /// named: a 2D pair (x, y) means those two in 3D as well).
    template <int dim>
    inline ComponentMask
    displacement_mask(const bool x, const bool y, const bool z = false)
    {
      std::vector<bool> mask(n_components<dim>, false);
      mask[ux] = x;
      mask[uy] = y;
      if (dim == 3)
        mask[uz] = z;
      return ComponentMask(mask);
    }

    /// Every displacement component.
    template <int dim>
    inline ComponentMask
    displacement_mask()
    {
      return displacement_mask<dim>(true, true, true);
    }

    template <int dim>
    inline ComponentMask
    multiplier_mask()
    {
      std::vector<bool> mask(n_components<dim>, false);
      mask[multiplier<dim>] = true;
      return ComponentMask(mask);
    }

    template <int dim>
    inline ComponentMask
    contact_mask()
    {
      std::vector<bool> mask(n_components<dim>, false);
      mask[multiplier<dim>] = true;
      mask[tangential<dim>] = true;
      return ComponentMask(mask);
    }
  } // namespace Components
} // namespace RingContact

#endif
