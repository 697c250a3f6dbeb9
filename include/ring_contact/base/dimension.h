// @sect3{The dimension}
//
// The program is two-dimensional: its bodies are plane (plane strain or
// plane stress) and its contact surfaces are curves. Every place where the
// dimension is meant writes `dim` rather than the literal 2, as the deal.II
// tutorials' template parameter does, so that the work of making the
// program three-dimensional is visible by grep (issue 47): the templates
// over dim of issue 48 replace this constant. A 2 that is not the
// dimension stays a 2: the two ends of a segment (a face's vertices in
// two dimensions), the two bodies or sides of a pair, the rank of a
// tensor.
#ifndef ring_contact_base_dimension_h
#define ring_contact_base_dimension_h

namespace RingContact
{
  /// The space dimension of the bodies.
  constexpr unsigned int dim = 2;
} // namespace RingContact

#endif
