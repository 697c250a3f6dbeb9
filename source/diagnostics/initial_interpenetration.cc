// @sect3{Diagnostics: surfaces that interpenetrate before any load}
//
// A warning, not an error (initial_interpenetration.h says when and why):
// an overlap at rest is pushed out elastically in the first step, a load
// the problem does not state. The depth is each node's mean gap g~_k / w_k,
// so a curved slave against a faceted master reports 2/3 of the sagitta
// (the mean of a parabolic gap under a linear multiplier), not its
// maximum. It was added when modelisation H with a Q1 outer ring and
// Mapping degree = 0 failed all 63 of its checks without a word. update()
// pairs the surfaces at `solution`, the unloaded state, before the depth
// is read.
#include <ring_contact/diagnostics/initial_interpenetration.h>

#include <iomanip>

namespace RingContact
{
  namespace Diagnostics
  {
    void
    report_initial_interpenetration(ContactInterface     &contact,
                                    const Vector<double> &solution,
                                    std::ostream         &log)
    {
      contact.update(solution);
      const auto [depth, where] = contact.deepest_interpenetration();
      if (!(depth > 1e-4 * contact.slave_segment_length()))
        return;
      log << "Warning: the contact surfaces interpenetrate before any "
             "load, by up to "
          << std::setprecision(3) << depth << " at (" << where[0] << ", "
          << where[1] << "), " << 100 * depth / contact.slave_segment_length()
          << " % of the slave's shortest segment: the contact pushes them "
             "apart in the first step, a load the problem does not state. "
             "A curved slave against a faceted master does this (Mapping "
             "degree = 0 with mixed element degrees: Mapping degree = 1 "
             "makes both faceted), as do bodies that overlap in the mesh.\n"
          << std::setprecision(6);
    }
  } // namespace Diagnostics
} // namespace RingContact
