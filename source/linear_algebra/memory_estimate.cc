// @sect3{The size of a sparsity pattern before it is built}
//
// The Newton system's pattern joins the bulk's couplings (a few dozen
// entries a row) and the contact's: one block per slave segment that
// couples all the unknowns of that segment and of every master segment it
// faces (ContactInterface::coupling_blocks()). A slave segment that faces
// thousands of master segments (a coarse slave on a fine master) makes a
// block of thousands of unknowns, and the pattern then holds the square of
// that: a hundred million entries, gigabytes in the pattern, the matrix and
// the direct solver's copies, long before the factorization, whose fill is
// larger still. So the pattern is measured here from the blocks
// themselves, which hold each unknown once, and the memory is judged
// (LinearSystem::check_memory()) before any of it is allocated.
#include <ring_contact/linear_algebra/memory_estimate.h>

#include <algorithm>
#include <iterator>
#include <utility>

namespace RingContact
{
  std::vector<types::global_dof_index>
  joined_row_lengths(
    const DynamicSparsityPattern                            &bulk,
    const std::vector<std::vector<types::global_dof_index>> &blocks)
  {
    using Index = types::global_dof_index;
    // The blocks of each unknown, as (unknown, block) pairs sorted by
    // unknown: one pair per unknown of each block, not per entry.
    std::vector<std::pair<Index, unsigned int>> membership;
    for (unsigned int b = 0; b < blocks.size(); ++b)
      for (const Index i : blocks[b])
        membership.emplace_back(i, b);
    std::sort(membership.begin(), membership.end());

    std::vector<Index> lengths(bulk.n_rows());
    std::vector<Index> row, joined;
    auto               member = membership.begin();
    for (Index i = 0; i < bulk.n_rows(); ++i)
      {
        const Index bulk_length = bulk.row_length(i);
        const auto  first       = member;
        while (member != membership.end() && member->first == i)
          ++member;
        const auto n_blocks = std::distance(first, member);
        if (n_blocks == 0)
          lengths[i] = bulk_length;
        else if (n_blocks == 1)
          {
            // Most rows of a block: the block, and the bulk entries that
            // are not in it (a binary search each).
            const auto &block  = blocks[first->second];
            Index       length = block.size();
            for (Index k = 0; k < bulk_length; ++k)
              length += !std::binary_search(block.begin(),
                                            block.end(),
                                            bulk.column_number(i, k));
            lengths[i] = length;
          }
        else
          {
            // An unknown where blocks overlap (a master segment that two
            // slave segments face): the union, merged in full. Such rows
            // are few, a handful per pair of neighbouring slave segments.
            row.clear();
            for (Index k = 0; k < bulk_length; ++k)
              row.push_back(bulk.column_number(i, k));
            for (auto m = first; m != member; ++m)
              {
                const auto &block = blocks[m->second];
                joined.clear();
                std::set_union(row.begin(),
                               row.end(),
                               block.begin(),
                               block.end(),
                               std::back_inserter(joined));
                std::swap(row, joined);
              }
            lengths[i] = row.size();
          }
      }
    return lengths;
  }
} // namespace RingContact
