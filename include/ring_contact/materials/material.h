// The material law of each body, behind one interface: a law maps the
// displacement gradient H = Grad u to the stress conjugate to it in the
// virtual work (the first Piola-Kirchhoff stress P, or sigma in small
// strain) and its consistent tangent A = dP/dH, and gives the Cauchy stress
// for output. Four laws, each in its own file:
// - Saint Venant-Kirchhoff in total Lagrangian form (Green-Lagrange strain
//   E, second Piola-Kirchhoff stress S, the linear isotropic law;
//   saint_venant_kirchhoff.cc), the original's GROT_GDEP;
// - small-strain linear elasticity (linear_elasticity.cc);
// - Hencky: the linear law on the logarithmic strain ln(C) / 2, the
//   current Code_Aster's GDEF_LOG (logarithmic_strain.cc);
// - compressible neo-Hookean, W = mu/2 (tr C - 3 - 2 ln J) + lambda/2
//   (ln J)^2, the law of the published large-sliding benchmarks
//   (neo_hookean.cc).
// In two dimensions each in plane stress (the out-of-plane stress zero) or
// plane strain (E33 = 0); in three dimensions the same laws without an
// assumption (their constants are those of plane strain, the 3d ones). Every
// class is a template on the dimension, instantiated for 2 and 3 (issue 48).
// The laws are registered (base/registry.h): each file ends with the
// law's registration, its name in Materials/Material law, its documentation
// and its factory. Adding a law is one new file and its line in
// CMakeLists.txt.
#ifndef ring_contact_materials_material_h
#define ring_contact_materials_material_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <ring_contact/base/registry.h>
#include <ring_contact/input/parameters.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace RingContact
{
  using namespace dealii;

  /// The elastic constants of an isotropic body and its 2d assumption (a
  /// three-dimensional body takes plane strain's: its lambda is the 3d one
  /// and no branch of plane stress is taken).
  struct ElasticConstants
  {
    ElasticConstants(const double          youngs_modulus,
                     const double          poissons_ratio,
                     const PlaneAssumption plane);

    double          youngs_modulus; ///< E [Pa]
    double          poissons_ratio; ///< nu [-]
    PlaneAssumption plane;
    /// Lamé constants of the in-plane law: in plane stress lambda* = 2
    /// lambda mu / (lambda + 2 mu), which follows from S33 = 0.
    double lambda, mu;
    /// The 3d lambda (the out-of-plane strain or stress).
    double lambda_3d;
  };

  /// det F - 1 of F = I + H, written in H without the cancellation of
  /// det F ~ 1 (tr H + det H in 2d, tr H + I2(H) + det H in 3d): the laws
  /// take ln J = log1p() of it, so that the strains of 1e-8 that a stiff
  /// body under a small load has keep their digits.
  template <int dim>
  double
  det_F_minus_one(const Tensor<2, dim> &H);

  /// What the assembly and the output need of a material law.
  template <int dim>
  class MaterialLaw
  {
  public:
    virtual ~MaterialLaw() = default;

    /// The stress conjugate to Grad u in the virtual work.
    virtual Tensor<2, dim>
    stress(const Tensor<2, dim> &grad_u) const = 0;

    /// Stress and its consistent tangent A = dP/dH (A_iJkL = dP_iJ/dH_kL),
    /// which has the major symmetry A_iJkL = A_kLiJ of a hyperelastic law
    /// (the assembly computes the upper triangle of the cell matrices).
    virtual void
    stress_and_tangent(const Tensor<2, dim> &grad_u,
                       Tensor<2, dim>       &P,
                       Tensor<4, dim>       &A) const = 0;

    /// Cauchy stress (in 2d its in-plane part). By default that of a
    /// finite-strain law, sigma = P F^T / det F, det F including the thickness
    /// stretch F33 of plane stress; small strain overrides it (sigma is its
    /// stress).
    virtual Tensor<2, dim>
    cauchy_stress(const Tensor<2, dim> &grad_u) const;

    /// Out-of-plane Cauchy stress sigma_33 (0 in plane stress); in 3d
    /// the Cauchy stress has it (Material asks only in 2d).
    virtual double
    out_of_plane_stress(const Tensor<2, dim> &grad_u) const = 0;

    /// Out-of-plane stretch F33 (1 in plane strain, small strain and 3d,
    /// where F is whole).
    /// Throws a one-line std::domain_error where the law has none (see
    /// in_range()).
    virtual double
    thickness_stretch(const Tensor<2, dim> &grad_u) const = 0;

    /// Whether the law has a state at grad_u, beyond det F > 0, which the
    /// assembly checks first: Saint Venant-Kirchhoff in plane stress has
    /// no thickness stretch past an in-plane stretch (sigma33 = 0 asks
    /// F33^2 <= 0 there). A state with a point outside is rejected as an
    /// inverted one is. By default every state with det F > 0.
    virtual bool
    in_range(const Tensor<2, dim> &grad_u) const;

    /// What in_range() requires, for the message that rejects a state
    /// ("" for a law without a bound).
    virtual std::string
    range_condition() const;
  };

  /// A material law as the parameter file names it (Materials/Material law,
  /// a body's Material law), and how it is made from the elastic constants.
  struct MaterialLawRegistration
  {
    /// Its value of Material law.
    std::string name;
    /// The values of the former entry Kinematics that chose it, still read.
    std::vector<std::string> old_names;
    /// What it is, for the entry's documentation.
    std::string documentation;
    /// Whether the law is geometrically linear (small strain): the problem
    /// is then written on the reference configuration, the contact paired
    /// and measured there and a pressure load dead (design.md).
    bool geometrically_linear;
    /// The law with its constants, in two and in three dimensions.
    std::function<std::shared_ptr<const MaterialLaw<2>>(
      const ElasticConstants &)>
      make_2d;
    std::function<std::shared_ptr<const MaterialLaw<3>>(
      const ElasticConstants &)>
      make_3d;

    /// The law in dimension dim.
    template <int dim>
    std::shared_ptr<const MaterialLaw<dim>>
    make(const ElasticConstants &constants) const
    {
      if constexpr (dim == 2)
        return make_2d(constants);
      else
        return make_3d(constants);
    }

    /// The registration of a law written as a class template Law<dim>
    /// with a constructor from the constants: its two factories.
    template <template <int> class Law>
    static MaterialLawRegistration
    of(const std::string              &name,
       const std::vector<std::string> &old_names,
       const std::string              &documentation,
       const bool                      geometrically_linear)
    {
      return {name,
              old_names,
              documentation,
              geometrically_linear,
              [](const ElasticConstants &c) {
                return std::make_shared<const Law<2>>(c);
              },
              [](const ElasticConstants &c) {
                return std::make_shared<const Law<3>>(c);
              }};
    }
  };

  /// Every registered law, by name (base/registry.h).
  using MaterialLaws = Registry<MaterialLawRegistration>;

  /// The name of the small-strain law: a problem linearised (the first
  /// step's start, FirstStepStrategy) runs it in place of every body's.
  extern const char *const linear_elasticity_law;

  /// A body's material: its constants and its law, a value that can be
  /// copied and stored (the law is shared, it has no state).
  template <int dim>
  class Material
  {
  public:
    /// E [Pa], nu [-], the 2d assumption (ignored in 3d) and the name of a
    /// registered law (or one of its old names).
    Material(const double          youngs_modulus,
             const double          poissons_ratio,
             const PlaneAssumption plane,
             const std::string    &law_name);

    Tensor<2, dim>
    stress(const Tensor<2, dim> &grad_u) const
    {
      return law->stress(grad_u);
    }

    void
    stress_and_tangent(const Tensor<2, dim> &grad_u,
                       Tensor<2, dim>       &P,
                       Tensor<4, dim>       &A) const
    {
      law->stress_and_tangent(grad_u, P, A);
    }

    Tensor<2, dim>
    cauchy_stress(const Tensor<2, dim> &grad_u) const
    {
      return law->cauchy_stress(grad_u);
    }

    /// sigma_33: of a plane body the out-of-plane stress, of a 3d body
    /// the zz component of its Cauchy stress.
    double
    out_of_plane_stress(const Tensor<2, dim> &grad_u) const
    {
      if constexpr (dim == 3)
        return law->cauchy_stress(grad_u)[2][2];
      else
        return law->out_of_plane_stress(grad_u);
    }

    double
    thickness_stretch(const Tensor<2, dim> &grad_u) const
    {
      return law->thickness_stretch(grad_u);
    }

    bool
    in_range(const Tensor<2, dim> &grad_u) const
    {
      return law->in_range(grad_u);
    }

    std::string
    range_condition() const
    {
      return law->range_condition();
    }

    /// The von Mises stress of the Cauchy stress (in 2d with sigma_33).
    double
    von_mises_stress(const Tensor<2, dim> &grad_u) const;

    double          youngs_modulus;
    double          poissons_ratio;
    PlaneAssumption plane;
    /// The law's registered name.
    std::string law_name;
    /// Whether the law is geometrically linear (small strain).
    bool geometrically_linear;

  private:
    std::shared_ptr<const MaterialLaw<dim>> law;
  };
} // namespace RingContact

#endif
