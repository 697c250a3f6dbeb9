// The curves of a gmsh model as the bodies' geometry: each curve of a
// script, sampled by gmsh's CAD kernel (gmsh_process.cc), recognised as a
// straight line, a circle or another curve, and attached to the boundary
// faces that lie on it as a deal.II manifold. Refinement then puts new
// vertices on the curve, and a mapping of degree >= 2 gives curved cells
// and curved contact surfaces, as the rings have.
#ifndef ring_contact_input_model_curves_h
#define ring_contact_input_model_curves_h

#include <deal.II/base/point.h>
#include <deal.II/grid/manifold.h>
#include <deal.II/grid/tria.h>

#include <ring_contact/base/dimension.h>
#include <ring_contact/input/gmsh_file.h>

#include <memory>
#include <string>
#include <vector>

namespace RingContact
{
  using namespace dealii;

  namespace Geometry
  {
    /// One curve of a gmsh model, recognised from its samples.
    struct ModelCurve
    {
      enum class Kind
      {
        straight, ///< a segment of a line: the faces' default, flat
        circle,   ///< an arc of a circle: deal.II's PolarManifold
        sampled   ///< anything else: interpolated between the samples
      };
      int                     tag  = 0;
      Kind                    kind = Kind::straight;
      Point<dim>              centre;     ///< of a circle
      double                  radius = 0; ///< of a circle
      std::vector<Point<dim>> samples;    ///< even in gmsh's parameter
    };

    /// What the points, evenly spaced in a curve's parameter from one end
    /// to the other, describe: a straight line, a circle (to 1e-9 of its
    /// radius), or another curve.
    ModelCurve
    recognise_curve(int tag, const std::vector<Point<dim>> &samples);

    /// A curve known by its samples, evenly spaced in its parameter: the
    /// chart t in [0, 1] (periodic on a closed curve) and a cubic Hermite
    /// interpolation with Catmull-Rom tangents between the samples, whose
    /// error is O(h^4) in the spacing h: with gmsh's 513 samples far below
    /// the discretisation error of any mesh.
    class SampledCurveManifold : public ChartManifold<2, 2, 1>
    {
    public:
      explicit SampledCurveManifold(const std::vector<Point<dim>> &samples);

      std::unique_ptr<Manifold<dim, dim>>
      clone() const override;

      Point<1>
      pull_back(const Point<dim> &space_point) const override;

      Point<dim>
      push_forward(const Point<1> &chart_point) const override;

      DerivativeForm<1, dim - 1, dim>
      push_forward_gradient(const Point<1> &chart_point) const override;

    private:
      std::vector<Point<dim>> samples;
      bool                    closed;
      /// The interval i and the local s in [0, 1] of a chart point.
      std::pair<unsigned int, double>
      locate(double t) const;
      Tensor<1, dim>
      tangent_at_sample(unsigned int i) const;
    };

    /// The curves of `mesh` (a script's, see GmshMesh::curves) attached to
    /// `triangulation` made from it (read_gmsh()): every boundary face on a
    /// circle or another curve gets that curve's manifold; straight curves
    /// and the cells keep the flat default. Returns the curves found, by
    /// kind.
    std::vector<ModelCurve>
    attach_model_curves(Triangulation<dim>  &triangulation,
                        const GmshMesh<dim> &mesh);
  } // namespace Geometry
} // namespace RingContact

#endif
