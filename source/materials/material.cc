// @sect3{Materials: the elastic constants and the choice of a law}
//
// Every body of a problem carries a Material: its Young's modulus, Poisson's
// ratio, the two-dimensional assumption (plane stress or plane strain) and
// the law chosen by name. The laws themselves live one per
// file (saint_venant_kirchhoff.cc, linear_elasticity.cc,
// logarithmic_strain.cc, neo_hookean.cc) behind the MaterialLaw interface;
// this file holds what they share: the Lame constants of the 2d
// assumption, det F - 1 without cancellation, the Material that finds its
// law among the registered ones, and the two outputs that are the same
// formula for every finite-strain law, the Cauchy stress and the von Mises
// stress written to the VTU files. Each is a template on the dimension,
// instantiated at the end of the file for 2 and 3.
#include <deal.II/base/symmetric_tensor.h>

#include <ring_contact/materials/material.h>

#include <algorithm>
#include <cmath>

namespace RingContact
{
  namespace
  {
    // The three-dimensional Lame constants of an isotropic material, E in
    // Pa and nu dimensionless; lambda diverges as nu -> 1/2, which the
    // parameters refuse.
    double
    lame_lambda(const double E, const double nu)
    {
      return E * nu / ((1 + nu) * (1 - 2 * nu));
    }

    double
    lame_mu(const double E, const double nu)
    {
      return E / (2 * (1 + nu));
    }
  } // namespace

  // @sect4{The constants of the 2d assumption}
  //
  // Plane strain keeps the 3d lambda: eps33 = 0 removes the out-of-plane
  // strain from the law. Plane stress eliminates it instead: sigma33 = 0
  // gives eps33 = -lambda / (lambda + 2 mu) (eps11 + eps22), and the
  // in-plane law keeps its form with lambda* = 2 lambda mu / (lambda + 2 mu)
  // = E nu / (1 - nu^2), mu unchanged. This holds for every law that is
  // linear in its strain measure (small strain, Saint Venant-Kirchhoff on
  // E, Hencky on ln(C) / 2). The 3d lambda is kept as well: the thickness
  // stretch, sigma33 in plane strain, and the neo-Hookean law, whose
  // plane-stress F33 is found by Newton's method, need it.
  ElasticConstants::ElasticConstants(const double          E,
                                     const double          nu,
                                     const PlaneAssumption plane)
      : youngs_modulus(E)
      , poissons_ratio(nu)
      , plane(plane)
      , lambda(plane == PlaneAssumption::plane_strain ?
                 lame_lambda(E, nu) :
                 2 * lame_lambda(E, nu) * lame_mu(E, nu) /
                   (lame_lambda(E, nu) + 2 * lame_mu(E, nu)))
      , mu(lame_mu(E, nu))
      , lambda_3d(lame_lambda(E, nu))
  {}

  // @sect4{det F - 1}
  //
  // det(I + H) = 1 + tr H + I2(H) + det H in 3d, I2 = ((tr H)^2 - tr(H^2))
  // / 2 the second invariant; in 2d I2(H) = det H and there is no third
  // term. The 2d form is the one every 2d law used before (its digits).
  template <int dim>
  double
  det_F_minus_one(const Tensor<2, dim> &H)
  {
    if constexpr (dim == 2)
      return trace(H) + determinant(H);
    else
      {
        const double tr = trace(H);
        return tr + 0.5 * (tr * tr - trace(H * H)) + determinant(H);
      }
  }

  // A law holds only its constants (no state at the quadrature points:
  // the laws are hyperelastic, without history), so one instance is shared
  // by every copy of the Material: the problem and the VTU writer keep
  // them by value in maps from the material id.
  // The name is one the parameters admitted (their pattern is the
  // registry's selection), possibly an old one: the registration found by
  // it gives the registered name.
  // A three-dimensional body has no plane assumption: it takes plane
  // strain's constants, the 3d ones, with which no law takes a branch of
  // plane stress.
  template <int dim>
  Material<dim>::Material(const double          E,
                          const double          nu,
                          const PlaneAssumption plane_assumption,
                          const std::string    &law)
      : youngs_modulus(E)
      , poissons_ratio(nu)
      , plane(dim == 3 ? PlaneAssumption::plane_strain : plane_assumption)
      , law_name(MaterialLaws::get(law).name)
      , geometrically_linear(MaterialLaws::get(law).geometrically_linear)
      , law(MaterialLaws::get(law).template make<dim>(
          ElasticConstants(E, nu, plane)))
  {}

  // @sect4{The Cauchy stress of the finite-strain laws}
  //
  // sigma = P F^T / J with the 3d deformation gradient F = [F2 0; 0 F33]:
  // its in-plane block is P2 F2^T, and J = det F2 F33. In plane stress the
  // body thins (F33 < 1 under tension), so the thickness stretch enters J;
  // in plane strain F33 = 1. Written once here for Saint Venant-Kirchhoff,
  // Hencky and neo-Hookean alike (each had its own copy before); small
  // strain overrides it, its stress being sigma already. In 3d F is whole
  // and F33 = 1 in this formula.
  template <int dim>
  Tensor<2, dim>
  MaterialLaw<dim>::cauchy_stress(const Tensor<2, dim> &H) const
  {
    const Tensor<2, dim> F = unit_symmetric_tensor<dim>() + H;
    return stress(H) * transpose(F) / (determinant(F) * thickness_stretch(H));
  }

  // Every law has a state wherever det F > 0, but one: Saint Venant-
  // Kirchhoff in plane stress (saint_venant_kirchhoff.cc) overrides these.
  template <int dim>
  bool
  MaterialLaw<dim>::in_range(const Tensor<2, dim> &) const
  {
    return true;
  }

  template <int dim>
  std::string
  MaterialLaw<dim>::range_condition() const
  {
    return "";
  }

  // @sect4{The von Mises stress}
  //
  // The 3d formula, sqrt(((s11 - s22)^2 + (s22 - s33)^2 + (s33 - s11)^2) / 2
  // + 3 s12^2), with the law's sigma33: zero in plane stress, but not in
  // plane strain, where the plane-stress formula that every run once used
  // misstated it. The components are scaled by the largest of them before
  // they are squared: at a load of 1e-200 Pa the squares underflowed, and
  // the VTU files showed a von Mises stress of zero beside stresses of
  // 1e-200. In 3d the two further shears enter as s12 does.
  template <int dim>
  double
  Material<dim>::von_mises_stress(const Tensor<2, dim> &grad_u) const
  {
    const Tensor<2, dim> s = cauchy_stress(grad_u);
    const double         s33 =
      dim == 3 ? s[dim - 1][dim - 1] : law->out_of_plane_stress(grad_u);
    // The shears beyond s12: s13 and s23 in 3d.
    double s13 = 0, s23 = 0;
    if constexpr (dim == 3)
      {
        s13 = s[0][2];
        s23 = s[1][2];
      }
    const double scale = std::max({std::abs(s[0][0]),
                                   std::abs(s[1][1]),
                                   std::abs(s33),
                                   std::abs(s[0][1]),
                                   std::abs(s13),
                                   std::abs(s23)});
    if (!(scale > 0))
      return scale; // zero, or not a number
    const double s11 = s[0][0] / scale, s22 = s[1][1] / scale,
                 s12 = s[0][1] / scale, z = s33 / scale;
    // 3 s12^2 as it was written in 2d (its digits), the 3d shears added.
    double shear = 3 * s12 * s12;
    if constexpr (dim == 3)
      shear +=
        3 * ((s13 / scale) * (s13 / scale) + (s23 / scale) * (s23 / scale));
    return scale *
           std::sqrt(0.5 * ((s11 - s22) * (s11 - s22) + (s22 - z) * (s22 - z) +
                            (z - s11) * (z - s11)) +
                     shear);
  }

  // The two dimensions of the program (issue 48).
  template double
  det_F_minus_one<2>(const Tensor<2, 2> &);
  template double
  det_F_minus_one<3>(const Tensor<2, 3> &);
  template class MaterialLaw<2>;
  template class MaterialLaw<3>;
  template class Material<2>;
  template class Material<3>;
} // namespace RingContact
