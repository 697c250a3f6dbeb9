// The size of a Newton system's sparsity pattern, measured from the
// couplings that will make it before it is built (memory_estimate.cc).
#ifndef ring_contact_linear_algebra_memory_estimate_h
#define ring_contact_linear_algebra_memory_estimate_h

#include <deal.II/base/types.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <vector>

namespace RingContact
{
  using namespace dealii;

  /// The length of each row of the pattern that `bulk` becomes once every
  /// unknown of each of `blocks` (sorted) is coupled with every other
  /// unknown of that block, counted without building it. The cost is that
  /// of reading each block once per unknown that lies in two blocks or
  /// more, and of a binary search per bulk entry of a row that lies in one
  /// block.
  std::vector<types::global_dof_index>
  joined_row_lengths(
    const DynamicSparsityPattern                            &bulk,
    const std::vector<std::vector<types::global_dof_index>> &blocks);
} // namespace RingContact

#endif
