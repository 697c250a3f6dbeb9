// @sect3{The Lagrange basis of a contact segment}
//
// The one-dimensional Lagrange bases on which a contact segment's geometry,
// displacement and multiplier are interpolated (LagrangeBasis1D,
// contact_surface.h), apart from the surface that uses them.
#include <ring_contact/contact/contact_surface.h>

#include <vector>

namespace RingContact
{
  // @sect4{The Lagrange basis of a segment}
  //
  // Along a segment, t in [0, 1], the reference geometry interpolates the
  // mapping's support points, the displacement the face's displacement nodes
  // and the multiplier its own nodes: three one-dimensional Lagrange bases,
  // each evaluated as a product of linear factors (contact_surface.h says why
  // not with deal.II's Polynomial).

  LagrangeBasis1D::LagrangeBasis1D(const std::vector<double> &nodes)
      : n_nodes(nodes.size())
  {
    // At most five nodes (degree 4): the arrays of the allocation-free curve
    // evaluation below have that size, and the contact element's AD numbers
    // are sized for displacements of at most that degree (contact_assembly.cc).
    AssertThrow(nodes.size() <= max_size,
                ExcMessage("a segment's basis has at most " +
                           std::to_string(max_size) + " nodes"));
    // The divisions 1 / (t_i - t_j) are done once, here: evaluating a basis is
    // then multiplications only.
    for (unsigned int i = 0; i < n_nodes; ++i)
      {
        this->nodes[i] = nodes[i];
        for (unsigned int j = 0; j < n_nodes; ++j)
          if (j != i)
            {
              AssertThrow(nodes[i] != nodes[j],
                          ExcMessage("the nodes of a basis must differ"));
              inverse_differences[i][j] = 1. / (nodes[i] - nodes[j]);
            }
      }
  }

  void
  LagrangeBasis1D::evaluate(const double         t,
                            std::vector<double> &values,
                            std::vector<double> &first,
                            std::vector<double> &second) const
  {
    values.resize(size());
    first.resize(size());
    second.resize(size());
    evaluate(t, values.data(), first.data(), second.data());
  }

  // Values, first and second derivatives at any t, inside the segment or beyond
  // it: the projection onto a held partner's extension evaluates the
  // polynomials from t = -1 to t = 2.
  void
  LagrangeBasis1D::evaluate(const double t,
                            double      *values,
                            double      *first,
                            double      *second) const
  {
    for (unsigned int i = 0; i < n_nodes; ++i)
      {
        // (v, v', v'') of the product so far, times each linear factor
        // f = (t - t_j) w with f' = w, f'' = 0.
        double v = 1, d1 = 0, d2 = 0;
        for (unsigned int j = 0; j < n_nodes; ++j)
          if (j != i)
            {
              const double w = inverse_differences[i][j];
              const double f = (t - nodes[j]) * w;
              d2             = d2 * f + 2 * d1 * w;
              d1             = d1 * f + v * w;
              v              = v * f;
            }
        values[i] = v;
        first[i]  = d1;
        second[i] = d2;
      }
  }

  // Values alone: the weighted gaps, the multiplier values and the weights w_k
  // need no derivatives.
  void
  LagrangeBasis1D::evaluate(const double t, std::vector<double> &values) const
  {
    values.resize(size());
    for (unsigned int i = 0; i < n_nodes; ++i)
      {
        double v = 1;
        for (unsigned int j = 0; j < n_nodes; ++j)
          if (j != i)
            v *= (t - nodes[j]) * inverse_differences[i][j];
        values[i] = v;
      }
  }
} // namespace RingContact
