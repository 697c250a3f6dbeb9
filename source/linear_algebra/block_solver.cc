// @sect3{The iterative solver: GMRES and a block preconditioner}
//
// `Newton/Linear solver = iterative` hands the Newton systems to this
// class instead of a factorization (direct_solver.cc, mumps_solver.cc):
// LinearSystem passes Trilinos's matrix, whose rows are distributed as the
// unknowns, and asks for x = K^-1 b, whole on every process. The method,
// the augmented Lagrangian that keeps bodies held only by the contact
// regular, and the measured iterations are in block_solver.h. This file is
// the work in the order it is done: analyse() once per sparsity pattern
// (the layout of the blocks, A's pattern), setup() once per Newton
// iteration (the blocks' values, Gamma, S factorized, the multigrid's
// operators), vmult() at every GMRES iteration. On these two-dimensional
// meshes it is slower than the direct solvers at every size, and needs somewhat
// less memory (doc/validation.md, "The iterative solver"): it is the option for
// a mesh whose factorization does not fit.
#include <ring_contact/linear_algebra/block_solver.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>

#include <Epetra_CrsMatrix.h>
#include <ml_MultiLevelPreconditioner.h>

#include <cmath>
#include <sstream>
#include <unordered_map>

namespace RingContact
{
  namespace
  {
    /// GMRES's restart length and iteration limit.
    // The 100 basis vectors are, with the matrix, most of the solver's memory
    // (doc/validation.md, "The iterative solver", where the finest rings
    // restart GMRES).
    constexpr unsigned int krylov_basis   = 100;
    constexpr unsigned int max_iterations = 1000;

    bool
    several_processes(const MPI_Comm communicator)
    {
      return dealii::Utilities::MPI::job_supports_mpi() &&
             dealii::Utilities::MPI::n_mpi_processes(communicator) > 1;
    }

    /// f(j, value) for the stored entries (global column j) of the owned
    /// row i of k.
    template <typename Function>
    void
    for_each_entry(const Epetra_CrsMatrix       &k,
                   const types::global_dof_index i,
                   const Function               &f)
    {
      int     n;
      double *values;
      int    *columns;
      k.ExtractMyRowView(k.LRID(static_cast<int>(i)), n, values, columns);
      for (int e = 0; e < n; ++e)
        f(static_cast<types::global_dof_index>(k.GCID(columns[e])), values[e]);
    }

    /// Every process's triplets (row, column, value), one after the other.
    // The indices travel as doubles beside the values, so that one gather
    // of one vector carries them: exact up to 2^53 unknowns.
    std::vector<double>
    gather_triplets(const std::vector<double> &mine,
                    const MPI_Comm             communicator)
    {
      if (!several_processes(communicator))
        return mine;
      std::vector<double> all;
      for (const auto &part :
           dealii::Utilities::MPI::all_gather(communicator, mine))
        all.insert(all.end(), part.begin(), part.end());
      return all;
    }
  } // namespace

  // gamma = 1, chosen among 0, 0.1, 1, 10 and 100: without the
  // augmentation the bodies held only by the contact (three blocks, Hertz)
  // fail, gamma = 1 solves them at the price of a few more iterations on the
  // rings, and 10 or more makes more (doc/validation.md, "The iterative
  // solver").
  BlockSolver::BlockSolver(const MPI_Comm communicator, const double tolerance)
      : communicator(communicator)
      , tolerance(tolerance)
      , augmentation(1.0)
  {}

  template <int dim>
  void
  BlockSolver::set_kinds(const std::vector<Kind>       &new_kinds,
                         const std::vector<Point<dim>> &new_positions)
  {
    kinds           = new_kinds;
    space_dimension = dim;
    positions.assign(new_positions.size(), Point<3>());
    for (std::size_t i = 0; i < new_positions.size(); ++i)
      for (unsigned int d = 0; d < dim; ++d)
        positions[i][d] = new_positions[i][d];
    // A new numbering of the unknowns: the layout must be made again even
    // if the pattern's version number happens to be the one analysed.
    analysed = false;
  }

  // @sect4{The layout, once per sparsity pattern}
  //
  // The layout of the owned rows, and A's sparsity pattern: the
  // displacement columns of the displacement rows. Nothing here depends on
  // the matrix's values, so a Newton iteration whose pairing stays within
  // the pattern keeps it, and with it the multigrid hierarchy built on A.
  void
  BlockSolver::analyse(const TrilinosWrappers::SparseMatrix &K,
                       const IndexSet                       &owned)
  {
    AssertThrow(kinds.size() == K.m(),
                ExcMessage("BlockSolver: the unknowns' kinds are not set"));
    const Epetra_CrsMatrix &k = K.trilinos_matrix();
    block_index.resize(kinds.size());
    n_displacements = 0;
    n_multipliers   = 0;
    // Counted in the global order: the unknowns are numbered process by
    // process, so each process's rows of A stay together, as its rows of K.
    for (std::size_t i = 0; i < kinds.size(); ++i)
      block_index[i] =
        kinds[i] == multiplier ? n_multipliers++ : n_displacements++;
    owned_displacement_local.clear();
    owned_multiplier_local.clear();
    owned_multiplier_index.clear();
    owned_in_A         = IndexSet(n_displacements);
    unsigned int local = 0;
    for (const auto i : owned)
      {
        if (kinds[i] == multiplier)
          {
            owned_multiplier_local.push_back(local);
            owned_multiplier_index.push_back(block_index[i]);
          }
        else
          {
            owned_displacement_local.push_back(local);
            owned_in_A.add_index(block_index[i]);
          }
        ++local;
      }
    owned_in_A.compress();

    // A's pattern, and that of the augmentation B Gamma C: row j of A
    // couples to the columns of C's rows k where B_jk is stored (C's
    // pattern gathered whole: the multiplier row k may belong to another
    // process than the displacement row j it couples to). The pattern holds
    // every entry of B Gamma C, zero or not, so that it does not change
    // when the active set does (Gamma_k is zero on an open node).
    std::vector<double> C_pattern;
    for (const auto i : owned)
      if (kinds[i] == multiplier)
        for_each_entry(k, i, [&](const auto j, double) {
          if (kinds[j] != multiplier)
            C_pattern.insert(C_pattern.end(),
                             {static_cast<double>(block_index[i]),
                              static_cast<double>(block_index[j]),
                              0.0});
        });
    std::unordered_map<types::global_dof_index,
                       std::vector<types::global_dof_index>>
                              C_columns_of_row;
    const std::vector<double> all_C = gather_triplets(C_pattern, communicator);
    for (std::size_t t = 0; t < all_C.size(); t += 3)
      C_columns_of_row[static_cast<types::global_dof_index>(all_C[t])]
        .push_back(static_cast<types::global_dof_index>(all_C[t + 1]));

    DynamicSparsityPattern dsp(n_displacements, n_displacements, owned_in_A);
    for (const auto i : owned)
      if (kinds[i] != multiplier)
        for_each_entry(k, i, [&](const auto j, double) {
          if (kinds[j] != multiplier)
            dsp.add(block_index[i], block_index[j]);
          else if (const auto row = C_columns_of_row.find(block_index[j]);
                   row != C_columns_of_row.end())
            for (const auto l : row->second)
              dsp.add(block_index[i], l);
        });
    // The old hierarchy was built on the old pattern.
    A.reinit(owned_in_A, owned_in_A, dsp, communicator, false);
    amg.clear();
    amg_built = false;
    analysed  = true;
  }

  // @sect4{The preconditioner's blocks}
  //
  // Once per Newton iteration (the values change, the pattern may not): B's
  // entries of the owned rows, C gathered whole, the augmentation Gamma,
  // A + B Gamma C, S = D - C diag(A + B Gamma C)^-1 B assembled from every
  // process's rows and factorized, and the multigrid operators for the new
  // A + B Gamma C. Each step is a function of its own below. The order
  // matters: Gamma needs diag(A) and C, and S divides by the diagonal of
  // the augmented block, not of A. The hierarchy's aggregates are kept
  // while the pattern stands (ML's ReComputePreconditioner through
  // reinit()): only its operators are recomputed from the new values.
  void
  BlockSolver::setup(const TrilinosWrappers::SparseMatrix &K)
  {
    CouplingBlocks blocks = split_blocks(K);
    compute_augmentation(blocks);
    assemble_augmented_displacement_block(K, blocks);
    factorize_schur_approximation(blocks);
    if (!amg_built)
      build_multigrid(K.locally_owned_range_indices());
    else
      amg.reinit();
  }


  // The entry C_ij of the gathered C (zero where it stores none). A
  // displacement unknown couples to the few multipliers of the slave
  // segments around it: a column of C is short, and a linear search in it
  // is enough.
  double
  BlockSolver::CouplingBlocks::C_entry(const types::global_dof_index i,
                                       const types::global_dof_index j) const
  {
    if (const auto column = C_column.find(j); column != C_column.end())
      for (const auto &[row, value] : column->second)
        if (row == i)
          return value;
    return 0.0;
  }


  // B's entries of the owned rows (kept as members: the preconditioner
  // applies B), C's and D's as triplets, diag(A) where B couples; C gathered
  // whole on every process, by rows and by columns.
  BlockSolver::CouplingBlocks
  BlockSolver::split_blocks(const TrilinosWrappers::SparseMatrix &K)
  {
    const Epetra_CrsMatrix &k = K.trilinos_matrix();
    B_row.clear();
    B_column.clear();
    B_value.clear();
    CouplingBlocks blocks;
    // C's entries (multiplier row, displacement column in A, value) and D's
    // (multiplier row, multiplier column, value) of the owned rows.
    // D's entries go straight into S's triplets: S starts as D, and the
    // products - C diag^-1 B are added to it later.
    std::vector<double> C_triplets;
    unsigned int        q = 0; // A's local row
    for (const auto i : K.locally_owned_range_indices())
      {
        for_each_entry(k, i, [&](const auto j, const double value) {
          if (kinds[i] != multiplier && kinds[j] == multiplier)
            {
              B_row.push_back(q);
              B_column.push_back(block_index[j]);
              B_value.push_back(value);
            }
          else if (kinds[i] != multiplier && j == i)
            blocks.A_diagonal[block_index[i]] = value;
          else if (kinds[i] == multiplier)
            {
              auto &target =
                kinds[j] == multiplier ? blocks.S_triplets : C_triplets;
              target.insert(target.end(),
                            {static_cast<double>(block_index[i]),
                             static_cast<double>(block_index[j]),
                             value});
            }
        });
        if (kinds[i] != multiplier)
          ++q;
      }

    // C is small (one row per multiplier) and needed whole twice: by rows
    // for the products B Gamma C of a displacement row, by columns for
    // Gamma_k and for S, where a process has B's column in its own rows.
    const std::vector<double> all_C = gather_triplets(C_triplets, communicator);
    for (std::size_t t = 0; t < all_C.size(); t += 3)
      {
        const auto i = static_cast<types::global_dof_index>(all_C[t]);
        const auto j = static_cast<types::global_dof_index>(all_C[t + 1]);
        blocks.C_row[i].emplace_back(j, all_C[t + 2]);
        blocks.C_column[j].emplace_back(i, all_C[t + 2]);
      }
    return blocks;
  }


  // Gamma_k = gamma / sum_j B_jk C_kj / A_jj: the augmentation B Gamma C
  // adds to A's diagonal about gamma times the stiffness it has where a
  // multiplier constrains it. Only where B's column and C's row are
  // (nearly) parallel, the sum without cancellation: not on the open and
  // inactive rows (C zero), nor on the sliding rows of friction (C along
  // the normal, B along the tangent), where 1 / sum would be large and of
  // either sign.
  //
  // Scaled so, B Gamma C is about gamma times A's own diagonal where it
  // acts, whatever the units of the contact row (a gap row times c, a
  // stick row): one gamma serves every material and mesh.
  void
  BlockSolver::compute_augmentation(CouplingBlocks &blocks)
  {
    gamma_k.reinit(n_multipliers);
    // Beside the sum, the sum of magnitudes: their ratio says whether the
    // terms cancel (B and C not parallel).
    Vector<double> magnitude(n_multipliers);
    for (std::size_t e = 0; e < B_row.size(); ++e)
      {
        const auto   j = owned_in_A.nth_index_in_set(B_row[e]);
        const double d = blocks.A_diagonal[j];
        // A row without a usable diagonal adds nothing rather than an
        // infinity that would poison Gamma_k.
        if (d != 0 && std::isfinite(d))
          {
            const double product =
              B_value[e] * blocks.C_entry(B_column[e], j) / d;
            gamma_k[B_column[e]] += product;
            magnitude[B_column[e]] += std::abs(product);
          }
      }
    // A multiplier's column of B spans displacement rows of several
    // processes: the partial sums are added, and every process then holds
    // the same Gamma.
    if (several_processes(communicator))
      for (auto *v : {&gamma_k, &magnitude})
        dealii::Utilities::MPI::sum(
          dealii::ArrayView<const double>(v->begin(), n_multipliers),
          communicator,
          dealii::ArrayView<double>(v->begin(), n_multipliers));
    // At least half the magnitude survives the sum: the terms mostly share
    // a sign. The inverse must be finite too: a subnormal sum would give
    // an infinite Gamma_k.
    for (unsigned int m = 0; m < n_multipliers; ++m)
      gamma_k[m] =
        (gamma_k[m] != 0 && std::abs(gamma_k[m]) >= 0.5 * magnitude[m] &&
         std::isfinite(1 / gamma_k[m])) ?
          augmentation / gamma_k[m] :
          0.0;
  }


  // A + B Gamma C, row by row, into the matrix whose pattern analyse()
  // made; its diagonal recorded where B couples (the Schur approximation
  // divides by it). Only the rows that B couples are summed by column
  // through a map; the others, the bulk of the bodies, are copied in
  // Epetra's own order, as they were before the augmentation existed.
  void
  BlockSolver::assemble_augmented_displacement_block(
    const TrilinosWrappers::SparseMatrix &K,
    CouplingBlocks                       &blocks)
  {
    const Epetra_CrsMatrix                             &k = K.trilinos_matrix();
    std::vector<types::global_dof_index>                columns_A;
    std::vector<double>                                 values_A;
    std::unordered_map<types::global_dof_index, double> row_sum;
    std::size_t                                         e = 0;
    unsigned int                                        q = 0;
    for (const auto i : K.locally_owned_range_indices())
      if (kinds[i] != multiplier)
        {
          // A's row; where B couples it, plus B Gamma C (summed by column).
          columns_A.clear();
          values_A.clear();
          for_each_entry(k, i, [&](const auto j, const double value) {
            if (kinds[j] != multiplier)
              {
                columns_A.push_back(block_index[j]);
                values_A.push_back(value);
              }
          });
          if (e < B_row.size() && B_row[e] == q)
            {
              row_sum.clear();
              for (std::size_t c = 0; c < columns_A.size(); ++c)
                row_sum[columns_A[c]] += values_A[c];
              for (; e < B_row.size() && B_row[e] == q; ++e)
                if (const auto row = blocks.C_row.find(B_column[e]);
                    row != blocks.C_row.end() && gamma_k[B_column[e]] != 0)
                  for (const auto &[l, c] : row->second)
                    row_sum[l] += B_value[e] * gamma_k[B_column[e]] * c;
              columns_A.clear();
              values_A.clear();
              for (const auto &[l, value] : row_sum)
                {
                  columns_A.push_back(l);
                  values_A.push_back(value);
                }
              blocks.A_diagonal[block_index[i]] = row_sum[block_index[i]];
            }
          // Zeros are written too (no eliding): set() leaves the entries it
          // is not given as they were, so a value that became zero must
          // replace the last iteration's.
          A.set(block_index[i],
                columns_A.size(),
                columns_A.data(),
                values_A.data(),
                false);
          ++q;
        }
    A.compress(VectorOperation::insert);
  }


  // S = D - C diag(A + B Gamma C)^-1 B: each process adds
  // - C_ik B_kj / (A + B Gamma C)_kk for its owned rows k of A; the
  // triplets are gathered and S assembled and factorized whole on every
  // process (it has one row per multiplier: small).
  //
  // S approximates the Schur complement of the augmented matrix, whose
  // first block is A_g (the one the multigrid approximates): hence A_g's
  // diagonal. That diagonal approximation of A_g^-1 is what limits the
  // preconditioner: it misses the bodies' long-range compliance, and the
  // iterations grow with the mesh (block_solver.h). Tried without a gain
  // (validation.md, section 7): a strip of 2-16 layers of displacements
  // beside the contact factorized with the multipliers (fewer iterations,
  // more time), row sums instead of the diagonal, more smoothing, other
  // aggregation, a W-cycle.
  void
  BlockSolver::factorize_schur_approximation(CouplingBlocks &blocks)
  {
    std::vector<double> &S_triplets = blocks.S_triplets;
    for (std::size_t e = 0; e < B_row.size(); ++e)
      {
        const types::global_dof_index kA =
          owned_in_A.nth_index_in_set(B_row[e]);
        const auto column = blocks.C_column.find(kA);
        if (column == blocks.C_column.end())
          continue;
        const double d = blocks.A_diagonal.at(kA);
        const double scale =
          (d != 0 && std::isfinite(d)) ? B_value[e] / d : 0.0;
        for (const auto &[row, c] : column->second)
          S_triplets.insert(S_triplets.end(),
                            {static_cast<double>(row),
                             static_cast<double>(B_column[e]),
                             -c * scale});
      }
    const std::vector<double> all_S = gather_triplets(S_triplets, communicator);

    // S is made anew at every setup: it is small, and its pattern follows
    // the contact couplings of K. Duplicate triplets (a product from each
    // process's rows) are summed by add().
    DynamicSparsityPattern dsp(n_multipliers, n_multipliers);
    for (types::global_dof_index i = 0; i < n_multipliers; ++i)
      dsp.add(i, i);
    for (std::size_t t = 0; t < all_S.size(); t += 3)
      dsp.add(static_cast<types::global_dof_index>(all_S[t]),
              static_cast<types::global_dof_index>(all_S[t + 1]));
    S.clear();
    S_pattern.copy_from(dsp);
    S.reinit(S_pattern);
    for (std::size_t t = 0; t < all_S.size(); t += 3)
      S.add(static_cast<types::global_dof_index>(all_S[t]),
            static_cast<types::global_dof_index>(all_S[t + 1]),
            all_S[t + 2]);
    // A singular S fails the Newton iteration (the step is cut) instead of
    // ending the run with UMFPACK's code.
    try
      {
        S_inverse.initialize(S);
      }
    catch (const std::exception &)
      {
        throw IterativeSolverFailure(
          "the approximate Schur complement of the multipliers is singular");
      }
  }


  // Smoothed aggregation for an elliptic operator, as deal.II's
  // PreconditionAMG sets it up, with the rigid-body modes of elasticity
  // as near-null space: in 2d the two translations and the rotation (-y,
  // x), in 3d the three translations and the three rotations. Without the
  // rotations the iterations grew with the mesh (thin rings bend; a 3d
  // block, tests/block_solver_3d). Built once per sparsity pattern; reinit()
  // updates its operators for new values. deal.II's
  // PreconditionAMG::AdditionalData takes only the constant modes (the
  // translations, as flags per component), so the list is written for ML
  // directly, with deal.II's settings for an elliptic operator (Chebyshev
  // smoother, two sweeps, KLU on a coarse level of at most 2000 unknowns) and
  // the rotations added.
  void
  BlockSolver::build_multigrid(const IndexSet &rows)
  {
    Teuchos::ParameterList list;
    ML_Epetra::SetDefaults("SA", list);
    list.set("smoother: type", "Chebyshev");
    list.set("smoother: sweeps", 2);
    list.set("smoother: Chebyshev alpha", 10.);
    list.set("coarse: type", "Amesos-KLU");
    list.set("coarse: max size", 2000);
    list.set("aggregation: threshold", 1e-4);
    list.set("initialize random seed", true);
    list.set("prec type", "MGV");
    list.set("ML output", 0);
    // The modes of the owned rows, one vector after the other (ML's
    // layout): a translation is 1 on its component's unknowns, a rotation
    // about the axis e_a is e_a x X at each unknown's node X, in the
    // reference configuration: the rotation about the deformed nodes
    // differs from it by the displacement, and a near-null space need only
    // be near. In 2d the rotation about z, (-y, x); in 3d the rotations
    // about z, x and y.
    const unsigned int n_local     = owned_in_A.n_elements();
    const unsigned int n_rotations = space_dimension == 2 ? 1 : 3;
    const unsigned int n_modes     = space_dimension + n_rotations;
    rigid_body_modes.assign(n_modes * n_local, 0.0);
    unsigned int local = 0;
    for (const auto i : rows)
      if (kinds[i] != multiplier)
        {
          rigid_body_modes[kinds[i] * n_local + local] = 1;
          for (unsigned int r = 0; r < n_rotations; ++r)
            {
              // The axis: z, then x, then y.
              Tensor<1, 3> axis;
              axis[(r + 2) % 3]         = 1;
              const Tensor<1, 3> motion = cross_product_3d(axis, positions[i]);
              rigid_body_modes[(space_dimension + r) * n_local + local] =
                motion[kinds[i]];
            }
          ++local;
        }
    // The dim unknowns of a node aggregated together.
    list.set("PDE equations", static_cast<int>(space_dimension));
    list.set("null space: type", "pre-computed");
    list.set("null space: dimension", static_cast<int>(n_modes));
    list.set("null space: vectors", rigid_body_modes.data());
    amg.initialize(A, list);
    amg_built = true;
  }

  // @sect4{Applying the preconditioner}
  //
  // y = P^-1 r at every GMRES iteration. GMRES iterates on K itself; the
  // preconditioner first turns r into the augmented system's right-hand
  // side (the row operation [I, B Gamma; 0, I] that makes K the augmented
  // matrix), then solves with the upper block triangle: the multipliers
  // first, by the factorized S, then the displacements by one V-cycle.
  // Their composition approximates K^-1, which is all GMRES needs.
  void
  BlockSolver::vmult(TrilinosWrappers::MPI::Vector       &y,
                     const TrilinosWrappers::MPI::Vector &r) const
  {
    // The multiplier part of r, whole on every process (each owns disjoint
    // entries: a sum assembles it), and y_l = S^-1 r_l: S is whole on
    // every process, which solves it itself, without further messages.
    Vector<double> r_multipliers(n_multipliers);
    for (std::size_t m = 0; m < owned_multiplier_local.size(); ++m)
      r_multipliers[owned_multiplier_index[m]] =
        r.begin()[owned_multiplier_local[m]];
    if (several_processes(communicator))
      dealii::Utilities::MPI::sum(
        dealii::ArrayView<const double>(r_multipliers.begin(), n_multipliers),
        communicator,
        dealii::ArrayView<double>(r_multipliers.begin(), n_multipliers));
    Vector<double> y_multipliers(n_multipliers);
    S_inverse.vmult(y_multipliers, r_multipliers);

    // The displacement part in A's distributed layout: B's entries are
    // those of the owned rows, so the product with B is local.
    TrilinosWrappers::MPI::Vector t(owned_in_A, communicator),
      z(owned_in_A, communicator);
    for (std::size_t q = 0; q < owned_displacement_local.size(); ++q)
      t.begin()[q] = r.begin()[owned_displacement_local[q]];
    // r_u + B Gamma r_l (the augmented system's right-hand side) - B y_l.
    for (std::size_t e = 0; e < B_row.size(); ++e)
      t.begin()[B_row[e]] +=
        B_value[e] * (gamma_k[B_column[e]] * r_multipliers[B_column[e]] -
                      y_multipliers[B_column[e]]);
    // y_u = A_g^-1 t, approximated by one V-cycle.
    amg.vmult(z, t);

    for (std::size_t q = 0; q < owned_displacement_local.size(); ++q)
      y.begin()[owned_displacement_local[q]] = z.begin()[q];
    for (std::size_t m = 0; m < owned_multiplier_local.size(); ++m)
      y.begin()[owned_multiplier_local[m]] =
        y_multipliers[owned_multiplier_index[m]];
  }

  // @sect4{The solve}
  //
  // The layout is made again only for a new sparsity pattern; the blocks
  // for every matrix. GMRES is right-preconditioned: it then minimises the
  // residual of K x = b itself, not of the preconditioned system, so that
  // its stopping test |K x - b| <= tolerance |b| is the one the Newton
  // loop checks after the solve (solve_linear_system()).
  unsigned int
  BlockSolver::solve(const TrilinosWrappers::SparseMatrix &K,
                     const IndexSet                       &owned,
                     const std::uint64_t                   pattern_version,
                     const Vector<double>                 &b,
                     Vector<double>                       &x)
  {
    if (!analysed || pattern_version != analysed_version)
      {
        analyse(K, owned);
        analysed_version = pattern_version;
      }
    setup(K);

    TrilinosWrappers::MPI::Vector rhs(owned, communicator),
      solution(owned, communicator);
    {
      unsigned int local = 0;
      for (const auto i : owned)
        rhs.begin()[local++] = b[i];
    }
    // deal.II's GMRES restarts after (vectors - 2) iterations: two more
    // than the basis length are asked for.
    SolverControl control(max_iterations, tolerance * rhs.l2_norm());
    SolverGMRES<TrilinosWrappers::MPI::Vector> gmres(
      control,
      SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData(krylov_basis +
                                                                   2,
                                                                 true));
    try
      {
        gmres.solve(K, solution, rhs, *this);
      }
    // Not converged: a failure of the Newton iteration, which cuts the
    // step, with the residual GMRES reached (the 1e-300 for a zero b).
    catch (const SolverControl::NoConvergence &e)
      {
        std::ostringstream message;
        message << "GMRES did not reach the relative residual " << tolerance
                << " in " << e.last_step << " iterations (it reached "
                << e.last_residual / std::max(rhs.l2_norm(), 1e-300) << ")";
        throw IterativeSolverFailure(message.str());
      }

    // Each process writes its owned entries into a zero vector, and the
    // sum makes x whole on every process, as the Newton loop needs it.
    x.reinit(b.size());
    unsigned int local = 0;
    for (const auto i : owned)
      x[i] = solution.begin()[local++];
    if (several_processes(communicator))
      dealii::Utilities::MPI::sum(
        dealii::ArrayView<const double>(x.begin(), x.size()),
        communicator,
        dealii::ArrayView<double>(x.begin(), x.size()));
    return control.last_step();
  }
  // The two dimensions of the program (issue 48).
  template void
  BlockSolver::set_kinds<2>(const std::vector<Kind> &,
                            const std::vector<Point<2>> &);
  template void
  BlockSolver::set_kinds<3>(const std::vector<Kind> &,
                            const std::vector<Point<3>> &);
} // namespace RingContact
