// The iterative solver of the Newton systems, for meshes where a direct
// factorization costs too much time or memory: GMRES on the whole system,
// right-preconditioned by a block triangular approximation of its inverse.
//
// Ordered by kind, the Newton matrix of a contact problem is
//
//   K = [ A  B ]   A: displacement rows and columns (bulk, contact stiffness)
//       [ C  D ]   B, C: the couplings of multipliers and displacements
//                  D: multiplier rows' multiplier columns (w_k on the open
//                     and inactive rows, the friction rows' regularisation)
//
// where A is an elasticity operator and the multiplier block is small (the
// slave surface's nodes). A body that only the contact holds in some
// direction (a cylinder pressed on a block, a stack of blocks) makes A
// singular, so the preconditioner works on the equivalent augmented system
// (the multiplier rows, times Gamma, added to the displacement rows through
// B: an augmented Lagrangian)
//
//   [ A + B Gamma C   B + B Gamma D ] [u]   [ r_u + B Gamma r_l ]
//   [ C               D             ] [l] = [ r_l               ]
//
// with Gamma_k = gamma / sum_j B_jk C_kj / A_jj (gamma = 1): the
// augmentation adds to the displacement rows about the stiffness they have
// where a multiplier holds them, zero where the contact is open. Its
// preconditioner is the upper block triangle
//
//   P = [ A_g  B ]    P^-1 r:  y_l = S^-1 r_l,
//       [ 0    S ]             y_u = A_g^-1 (r_u + B Gamma r_l - B y_l),
//
// with A_g = A + B Gamma C, S = D - C diag(A_g)^-1 B, an approximation of
// the Schur complement that is sparse (a multiplier couples to its
// neighbours only) and factorized directly (it has a few thousand unknowns
// at most), and A_g^-1 approximated by one V-cycle of algebraic multigrid
// (Trilinos ML, smoothed aggregation, the rigid-body modes of elasticity as
// its near-null space: in 2d the two translations and the rotation, in 3d
// the three translations and the three rotations).
// (B Gamma D, zero but for the friction's regularisation on sticking rows,
// is left out of the preconditioner.) With exact inverses GMRES would
// converge in two iterations. Measured (bench/scale, tests/iterative_solver;
// doc/validation.md, "The iterative solver"): few iterations per solve on the
// seed meshes, but more with every refinement of the rings: the diagonal
// approximation of A^-1 in S misses the long-range compliance of the
// bodies, and the V-cycle's error multiplies it. On these two-dimensional
// meshes a direct factorization is faster; the iterative solver needs less
// memory. gamma = 1 was chosen among 0, 0.1, 1, 10 and 100: without the
// augmentation three blocks and Hertz fail (singular A), with 10 or more
// the iterations grow.
//
// The multigrid hierarchy is built once per sparsity pattern; while the
// pattern does not change only its operators are recomputed from the new
// values (ML's ReComputePreconditioner, deal.II's PreconditionAMG::reinit).
// (The hierarchy is built on A_g, whose pattern includes B Gamma C's.)
//
// Like MUMPS it runs on one process or on several: A_g's rows are
// distributed as the Newton matrix's (each process keeps B's entries of its
// rows), and the small blocks C and D are gathered on every process, which
// builds and factorizes S whole (the contact surfaces are whole on every
// process already).
#ifndef ring_contact_linear_algebra_block_solver_h
#define ring_contact_linear_algebra_block_solver_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <cstdint>
#include <stdexcept>
#include <unordered_map>
#include <vector>

namespace RingContact
{
  using namespace dealii;

  /// GMRES did not reach its tolerance (a failure of the Newton iteration,
  /// which cuts the step; not an error of the input).
  class IterativeSolverFailure : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  class BlockSolver
  {
  public:
    /// Kinds of unknowns: the displacement's components, a multiplier.
    enum Kind : unsigned char
    {
      displacement_x = 0,
      displacement_y = 1,
      displacement_z = 2,
      multiplier     = 3
    };

    /// `tolerance`: GMRES stops when |K x - b| <= tolerance |b|.
    BlockSolver(const MPI_Comm communicator, const double tolerance);

    /// The kind of every unknown (whole, the same on every process), and
    /// the position of every displacement unknown's node (the multigrid's
    /// rigid-body modes; the entries of the multipliers are not used), in
    /// dimension 2 or 3.
    template <int dim>
    void
    set_kinds(const std::vector<Kind>       &kinds,
              const std::vector<Point<dim>> &positions);

    /// x = K^-1 b, b and x whole on every process; `owned` the rows this
    /// process stores. The multigrid hierarchy is rebuilt when
    /// `pattern_version` differs from the last call's. Returns GMRES's
    /// iterations; throws IterativeSolverFailure when it does not converge.
    unsigned int
    solve(const TrilinosWrappers::SparseMatrix &K,
          const IndexSet                       &owned,
          const std::uint64_t                   pattern_version,
          const Vector<double>                 &b,
          Vector<double>                       &x);

    /// y = P^-1 r (GMRES's preconditioner).
    void
    vmult(TrilinosWrappers::MPI::Vector       &y,
          const TrilinosWrappers::MPI::Vector &r) const;

  private:
    /// A's pattern and the local layout, once per sparsity pattern.
    void
    analyse(const TrilinosWrappers::SparseMatrix &K, const IndexSet &owned);
    /// A's values, the small blocks gathered, S factorized, AMG updated.
    void
    setup(const TrilinosWrappers::SparseMatrix &K);

    /// What one setup() passes between its steps: C whole (by rows and by
    /// columns), D's and then S's entries as (row, column, value)
    /// triplets, the diagonal of A (later of A + B Gamma C) where B couples.
    struct CouplingBlocks
    {
      using Entries = std::vector<std::pair<types::global_dof_index, double>>;
      std::unordered_map<types::global_dof_index, Entries> C_row, C_column;
      std::vector<double>                                  S_triplets;
      std::unordered_map<types::global_dof_index, double>  A_diagonal;

      double
      C_entry(const types::global_dof_index i,
              const types::global_dof_index j) const;
    };
    /// B's entries (members), C and D of the owned rows, diag(A).
    CouplingBlocks
    split_blocks(const TrilinosWrappers::SparseMatrix &K);
    /// Gamma_k.
    void
    compute_augmentation(CouplingBlocks &blocks);
    /// A + B Gamma C into A.
    void
    assemble_augmented_displacement_block(
      const TrilinosWrappers::SparseMatrix &K,
      CouplingBlocks                       &blocks);
    /// S assembled whole and factorized.
    void
    factorize_schur_approximation(CouplingBlocks &blocks);
    /// ML's hierarchy for A, with the rigid-body modes.
    void
    build_multigrid(const IndexSet &rows);

    const MPI_Comm communicator;
    const double   tolerance;
    /// gamma of the augmentation.
    const double augmentation;
    /// Gamma_k, whole.
    Vector<double>    gamma_k;
    std::vector<Kind> kinds;
    /// The positions, in three coordinates whatever the dimension (z = 0
    /// in 2d), and the dimension.
    std::vector<Point<3>> positions;
    unsigned int          space_dimension = 2;
    /// The rigid-body modes of the owned rows of A (translations, rotations),
    /// one after the other: ML reads them while it builds the hierarchy.
    std::vector<double> rigid_body_modes;
    /// Each unknown's index within its block (displacement or multiplier).
    std::vector<types::global_dof_index> block_index;
    types::global_dof_index              n_displacements = 0;
    types::global_dof_index              n_multipliers   = 0;

    bool          analysed         = false;
    std::uint64_t analysed_version = 0;
    /// The owned rows: their positions in the whole system's local vector,
    /// and (displacement rows) in A's.
    std::vector<unsigned int>            owned_displacement_local;
    std::vector<unsigned int>            owned_displacement_in_A;
    std::vector<unsigned int>            owned_multiplier_local;
    std::vector<types::global_dof_index> owned_multiplier_index;
    IndexSet                             owned_in_A;

    TrilinosWrappers::SparseMatrix    A;
    TrilinosWrappers::PreconditionAMG amg;
    bool                              amg_built = false;

    /// B's entries in A's owned rows: (local row of A, multiplier, value).
    std::vector<unsigned int>            B_row;
    std::vector<types::global_dof_index> B_column;
    std::vector<double>                  B_value;

    /// S, whole on every process.
    SparsityPattern      S_pattern;
    SparseMatrix<double> S;
    SparseDirectUMFPACK  S_inverse;
  };
} // namespace RingContact

#endif
