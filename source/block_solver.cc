#include <ring_contact/block_solver.h>

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

  BlockSolver::BlockSolver(const MPI_Comm communicator, const double tolerance)
      : communicator(communicator)
      , tolerance(tolerance)
      , augmentation(1.0)
  {}

  void
  BlockSolver::set_kinds(const std::vector<Kind>     &new_kinds,
                         const std::vector<Point<2>> &new_positions)
  {
    kinds     = new_kinds;
    positions = new_positions;
    analysed  = false;
  }

  // The layout of the owned rows, and A's sparsity pattern: the
  // displacement columns of the displacement rows.
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
    // pattern gathered whole).
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
    A.reinit(owned_in_A, owned_in_A, dsp, communicator, false);
    amg.clear();
    amg_built = false;
    analysed  = true;
  }

  // B's entries of the owned rows; C gathered whole; the augmentation
  // Gamma; A + B Gamma C; S = D - C diag(A + B Gamma C)^-1 B assembled from
  // every process's rows and factorized; the multigrid operators for the
  // new A + B Gamma C.
  void
  BlockSolver::setup(const TrilinosWrappers::SparseMatrix &K)
  {
    const Epetra_CrsMatrix &k = K.trilinos_matrix();
    B_row.clear();
    B_column.clear();
    B_value.clear();
    // C's entries (multiplier row, displacement column in A, value) and D's
    // (multiplier row, multiplier column, value) of the owned rows.
    std::vector<double> C_triplets, S_triplets;
    // diag(A) of the owned displacement rows that B couples (A's index).
    std::unordered_map<types::global_dof_index, double> A_diagonal;
    const IndexSet &rows = K.locally_owned_range_indices();
    {
      unsigned int q = 0; // A's local row
      for (const auto i : rows)
        {
          for_each_entry(k, i, [&](const auto j, const double value) {
            if (kinds[i] != multiplier && kinds[j] == multiplier)
              {
                B_row.push_back(q);
                B_column.push_back(block_index[j]);
                B_value.push_back(value);
              }
            else if (kinds[i] != multiplier && j == i)
              A_diagonal[block_index[i]] = value;
            else if (kinds[i] == multiplier)
              {
                auto &target = kinds[j] == multiplier ? S_triplets : C_triplets;
                target.insert(target.end(),
                              {static_cast<double>(block_index[i]),
                               static_cast<double>(block_index[j]),
                               value});
              }
          });
          if (kinds[i] != multiplier)
            ++q;
        }
    }

    // C whole, by rows and by columns.
    using Entries = std::vector<std::pair<types::global_dof_index, double>>;
    std::unordered_map<types::global_dof_index, Entries> C_row, C_column;
    const std::vector<double> all_C = gather_triplets(C_triplets, communicator);
    for (std::size_t t = 0; t < all_C.size(); t += 3)
      {
        const auto i = static_cast<types::global_dof_index>(all_C[t]);
        const auto j = static_cast<types::global_dof_index>(all_C[t + 1]);
        C_row[i].emplace_back(j, all_C[t + 2]);
        C_column[j].emplace_back(i, all_C[t + 2]);
      }
    const auto C_entry = [&](const types::global_dof_index i,
                             const types::global_dof_index j) {
      if (const auto column = C_column.find(j); column != C_column.end())
        for (const auto &[row, value] : column->second)
          if (row == i)
            return value;
      return 0.0;
    };

    // Gamma_k = gamma / sum_j B_jk C_kj / A_jj: the augmentation B Gamma C
    // adds to A's diagonal about gamma times the stiffness it has where a
    // multiplier constrains it. Only where B's column and C's row are
    // (nearly) parallel, the sum without cancellation: not on the open and
    // inactive rows (C zero), nor on the sliding rows of friction (C along
    // the normal, B along the tangent), where 1 / sum would be large and of
    // either sign.
    gamma_k.reinit(n_multipliers);
    Vector<double> magnitude(n_multipliers);
    for (std::size_t e = 0; e < B_row.size(); ++e)
      {
        const auto   j = owned_in_A.nth_index_in_set(B_row[e]);
        const double d = A_diagonal[j];
        if (d != 0 && std::isfinite(d))
          {
            const double product = B_value[e] * C_entry(B_column[e], j) / d;
            gamma_k[B_column[e]] += product;
            magnitude[B_column[e]] += std::abs(product);
          }
      }
    if (several_processes(communicator))
      for (auto *v : {&gamma_k, &magnitude})
        dealii::Utilities::MPI::sum(
          dealii::ArrayView<const double>(v->begin(), n_multipliers),
          communicator,
          dealii::ArrayView<double>(v->begin(), n_multipliers));
    for (unsigned int m = 0; m < n_multipliers; ++m)
      gamma_k[m] =
        (gamma_k[m] != 0 && std::abs(gamma_k[m]) >= 0.5 * magnitude[m] &&
         std::isfinite(1 / gamma_k[m])) ?
          augmentation / gamma_k[m] :
          0.0;

    // A + B Gamma C, row by row; its diagonal where B couples.
    {
      std::vector<types::global_dof_index>                columns_A;
      std::vector<double>                                 values_A;
      std::unordered_map<types::global_dof_index, double> row_sum;
      std::size_t                                         e = 0;
      unsigned int                                        q = 0;
      for (const auto i : rows)
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
                  if (const auto row = C_row.find(B_column[e]);
                      row != C_row.end() && gamma_k[B_column[e]] != 0)
                    for (const auto &[l, c] : row->second)
                      row_sum[l] += B_value[e] * gamma_k[B_column[e]] * c;
                columns_A.clear();
                values_A.clear();
                for (const auto &[l, value] : row_sum)
                  {
                    columns_A.push_back(l);
                    values_A.push_back(value);
                  }
                A_diagonal[block_index[i]] = row_sum[block_index[i]];
              }
            A.set(block_index[i],
                  columns_A.size(),
                  columns_A.data(),
                  values_A.data(),
                  false);
            ++q;
          }
    }
    A.compress(VectorOperation::insert);

    // - C_ik B_kj / (A + B Gamma C)_kk for the owned rows k of A.
    for (std::size_t e = 0; e < B_row.size(); ++e)
      {
        const types::global_dof_index kA =
          owned_in_A.nth_index_in_set(B_row[e]);
        const auto column = C_column.find(kA);
        if (column == C_column.end())
          continue;
        const double d = A_diagonal.at(kA);
        const double scale =
          (d != 0 && std::isfinite(d)) ? B_value[e] / d : 0.0;
        for (const auto &[row, c] : column->second)
          S_triplets.insert(S_triplets.end(),
                            {static_cast<double>(row),
                             static_cast<double>(B_column[e]),
                             -c * scale});
      }
    const std::vector<double> all_S = gather_triplets(S_triplets, communicator);

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
    try
      {
        S_inverse.initialize(S);
      }
    catch (const std::exception &)
      {
        throw IterativeSolverFailure(
          "the approximate Schur complement of the multipliers is singular");
      }

    if (!amg_built)
      {
        // Smoothed aggregation for an elliptic operator, as deal.II's
        // PreconditionAMG sets it up, with the rigid-body modes of plane
        // elasticity as near-null space: the two translations and the
        // rotation (-y, x). Without the rotation the iterations grew with
        // the mesh (thin rings bend).
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
        const unsigned int     n_local = owned_in_A.n_elements();
        constexpr unsigned int n_modes = 3;
        rigid_body_modes.assign(n_modes * n_local, 0.0);
        unsigned int local = 0;
        for (const auto i : rows)
          if (kinds[i] != multiplier)
            {
              rigid_body_modes[kinds[i] * n_local + local] = 1;
              rigid_body_modes[2 * n_local + local] =
                kinds[i] == displacement_x ? -positions[i][1] : positions[i][0];
              ++local;
            }
        list.set("PDE equations", 2);
        list.set("null space: type", "pre-computed");
        list.set("null space: dimension", static_cast<int>(n_modes));
        list.set("null space: vectors", rigid_body_modes.data());
        amg.initialize(A, list);
        amg_built = true;
      }
    else
      amg.reinit();
  }

  void
  BlockSolver::vmult(TrilinosWrappers::MPI::Vector       &y,
                     const TrilinosWrappers::MPI::Vector &r) const
  {
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

    TrilinosWrappers::MPI::Vector t(owned_in_A, communicator),
      z(owned_in_A, communicator);
    for (std::size_t q = 0; q < owned_displacement_local.size(); ++q)
      t.begin()[q] = r.begin()[owned_displacement_local[q]];
    // r_u + B Gamma r_l (the augmented system's right-hand side) - B y_l.
    for (std::size_t e = 0; e < B_row.size(); ++e)
      t.begin()[B_row[e]] +=
        B_value[e] * (gamma_k[B_column[e]] * r_multipliers[B_column[e]] -
                      y_multipliers[B_column[e]]);
    amg.vmult(z, t);

    for (std::size_t q = 0; q < owned_displacement_local.size(); ++q)
      y.begin()[owned_displacement_local[q]] = z.begin()[q];
    for (std::size_t m = 0; m < owned_multiplier_local.size(); ++m)
      y.begin()[owned_multiplier_local[m]] =
        y_multipliers[owned_multiplier_index[m]];
  }

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
    catch (const SolverControl::NoConvergence &e)
      {
        std::ostringstream message;
        message << "GMRES did not reach the relative residual " << tolerance
                << " in " << e.last_step << " iterations (it reached "
                << e.last_residual / std::max(rhs.l2_norm(), 1e-300) << ")";
        throw IterativeSolverFailure(message.str());
      }

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
} // namespace RingContact
