// The bare deal.II 3D elasticity solve that bench/hertz_3d sets beside the
// program's (issue 48, item 8): the program of the 3D study
// (../shared/research/3d-anchors.md, section 9, "bench3d"), unchanged but
// for this note. 3D linear elasticity on a cube: p::d::Triangulation, Q1
// or Q2, Trilinos matrix, CG + ML smoothed aggregation with the 6
// rigid-body modes, or a direct solve (Amesos_Mumps / KLU). Timings per
// phase, peak memory.
// Usage: bare_elasticity_3d <degree> <cells per edge> <amg | mumps | klu>
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/numerics/vector_tools.h>
#include <ml_MultiLevelPreconditioner.h>
#include <Teuchos_ParameterList.hpp>
#include <iostream>
#include <fstream>
#include <string>
using namespace dealii;
constexpr int dim = 3;

static double peak_mb()
{
  Utilities::System::MemoryStats s;
  Utilities::System::get_memory_stats(s);
  return s.VmHWM / 1024.;
}

int main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm comm = MPI_COMM_WORLD;
  const unsigned int degree = std::stoi(argv[1]);
  const unsigned int n      = std::stoi(argv[2]);   // cells per edge
  const std::string  solver = argv[3];              // amg | mumps | klu
  const unsigned int rank   = Utilities::MPI::this_mpi_process(comm);
  const unsigned int nproc  = Utilities::MPI::n_mpi_processes(comm);
  ConditionalOStream pcout(std::cout, rank == 0);
  Timer total;
  Timer t;
  std::map<std::string, double> time, cpu;
  double load0 = 0; { std::ifstream f("/proc/loadavg"); f >> load0; }

  parallel::distributed::Triangulation<dim> tria(comm);
  GridGenerator::subdivided_hyper_cube(tria, n, 0., 1., /*colorize*/ true);
  time["mesh"] = t.wall_time(); cpu["mesh"] = t.cpu_time(); t.restart();

  FESystem<dim> fe(FE_Q<dim>(degree), dim);
  DoFHandler<dim> dof(tria);
  dof.distribute_dofs(fe);
  const IndexSet owned = dof.locally_owned_dofs();
  IndexSet relevant;
  DoFTools::extract_locally_relevant_dofs(dof, relevant);
  AffineConstraints<double> constraints(relevant);
  DoFTools::make_hanging_node_constraints(dof, constraints);
  // bottom z=0 clamped (boundary id 4), top z=1 (id 5) pressed down by 1e-3
  VectorTools::interpolate_boundary_values(dof, 4, Functions::ZeroFunction<dim>(dim), constraints);
  {
    std::vector<double> v(dim, 0.); v[2] = -1e-3;
    VectorTools::interpolate_boundary_values(dof, 5, Functions::ConstantFunction<dim>(v), constraints);
  }
  constraints.close();
  TrilinosWrappers::SparsityPattern sp(owned, owned, relevant, comm);
  DoFTools::make_sparsity_pattern(dof, sp, constraints, false, rank);
  sp.compress();
  TrilinosWrappers::SparseMatrix A;
  A.reinit(sp);
  TrilinosWrappers::MPI::Vector b(owned, comm), x(owned, comm);
  time["setup"] = t.wall_time(); cpu["setup"] = t.cpu_time(); t.restart();

  // assembly: linear isotropic elasticity, E = 1, nu = 0.3
  const double E = 1., nu = 0.3, lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  QGauss<dim> quad(degree + 1);
  FEValues<dim> fv(fe, quad, update_gradients | update_JxW_values);
  const unsigned int dpc = fe.n_dofs_per_cell();
  FullMatrix<double> cm(dpc, dpc);
  Vector<double> cr(dpc);
  std::vector<types::global_dof_index> idx(dpc);
  std::vector<unsigned int> comp(dpc);
  for (unsigned int i = 0; i < dpc; ++i) comp[i] = fe.system_to_component_index(i).first;
  for (const auto &cell : dof.active_cell_iterators())
    if (cell->is_locally_owned())
      {
        fv.reinit(cell);
        cm = 0; cr = 0;
        for (unsigned int q = 0; q < quad.size(); ++q)
          for (unsigned int i = 0; i < dpc; ++i)
            {
              const Tensor<1, dim> gi = fv.shape_grad(i, q);
              for (unsigned int j = i; j < dpc; ++j)
                {
                  const Tensor<1, dim> gj = fv.shape_grad(j, q);
                  cm(i, j) += (gi[comp[i]] * gj[comp[j]] * lambda + gi[comp[j]] * gj[comp[i]] * mu +
                               ((comp[i] == comp[j]) ? (gi * gj) * mu : 0.)) * fv.JxW(q);
                }
            }
        for (unsigned int i = 0; i < dpc; ++i)
          for (unsigned int j = 0; j < i; ++j) cm(i, j) = cm(j, i);
        cell->get_dof_indices(idx);
        constraints.distribute_local_to_global(cm, cr, idx, A, b);
      }
  A.compress(VectorOperation::add);
  b.compress(VectorOperation::add);
  time["assemble"] = t.wall_time(); cpu["assemble"] = t.cpu_time(); t.restart();

  unsigned int its = 0;
  if (solver == "amg")
    {
      std::map<types::global_dof_index, Point<dim>> pts;
      DoFTools::map_dofs_to_support_points(MappingQ1<dim>(), dof, pts);
      const unsigned int nl = owned.n_elements();
      std::vector<double> modes(6 * nl, 0.);
      unsigned int l = 0;
      for (const auto i : owned)
        {
          const Point<dim> p = pts.at(i);
          // component of dof i: FESystem numbering; find via cell loop is costly,
          // use the fact that for FE_Q^dim with default numbering the
          // component is fixed per dof: build map below
          (void)p; ++l;
        }
      // component per owned dof
      std::vector<int> dcomp(nl, -1);
      for (const auto &cell : dof.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_indices(idx);
            for (unsigned int i = 0; i < dpc; ++i)
              if (owned.is_element(idx[i])) dcomp[owned.index_within_set(idx[i])] = comp[i];
          }
      l = 0;
      for (const auto i : owned)
        {
          const Point<dim> p = pts.at(i);
          const int c = dcomp[l];
          modes[c * nl + l] = 1.;
          // rotations: about z (-y, x, 0), about x (0, -z, y), about y (z, 0, -x)
          modes[3 * nl + l] = (c == 0) ? -p[1] : (c == 1) ? p[0] : 0.;
          modes[4 * nl + l] = (c == 1) ? -p[2] : (c == 2) ? p[1] : 0.;
          modes[5 * nl + l] = (c == 0) ? p[2] : (c == 2) ? -p[0] : 0.;
          ++l;
        }
      Teuchos::ParameterList list;
      ML_Epetra::SetDefaults("SA", list);
      list.set("smoother: type", "Chebyshev");
      list.set("smoother: sweeps", 2);
      list.set("coarse: type", "Amesos-KLU");
      list.set("coarse: max size", 2000);
      list.set("aggregation: threshold", 1e-4);
      list.set("ML output", 0);
      list.set("PDE equations", 3);
      list.set("null space: type", "pre-computed");
      list.set("null space: dimension", 6);
      list.set("null space: vectors", modes.data());
      TrilinosWrappers::PreconditionAMG amg;
      amg.initialize(A, list);
      time["amg setup"] = t.wall_time(); cpu["amg setup"] = t.cpu_time(); t.restart();
      SolverControl control(2000, 1e-8 * b.l2_norm());
      SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
      cg.solve(A, x, b, amg);
      its = control.last_step();
      time["solve"] = t.wall_time(); cpu["solve"] = t.cpu_time(); t.restart();
      // a Newton-like second solve: same pattern, new values, hierarchy recomputed by reinit()
      A *= 1.01;
      amg.reinit();
      time["amg reinit"] = t.wall_time(); cpu["amg reinit"] = t.cpu_time(); t.restart();
    }
  else
    {
      SolverControl control(1, 0);
      TrilinosWrappers::SolverDirect::AdditionalData ad(false, solver == "mumps" ? "Amesos_Mumps" : "Amesos_Klu");
      TrilinosWrappers::SolverDirect direct(control, ad);
      direct.solve(A, x, b);
      time["solve"] = t.wall_time(); cpu["solve"] = t.cpu_time(); t.restart();
    }
  constraints.distribute(x);
  const double mem = Utilities::MPI::max(peak_mb(), comm);
  const double T = total.wall_time();
  const double tmax_solve = Utilities::MPI::max(time["solve"] + time["amg setup"], comm);
  const double tmax_asm = Utilities::MPI::max(time["assemble"], comm);
  pcout << "RESULT dim=3 Q" << degree << " n=" << n << " solver=" << solver << " np=" << nproc
        << " cells=" << tria.n_global_active_cells() << " dofs=" << dof.n_dofs()
        << " nnz=" << A.n_nonzero_elements()
        << " setup=" << time["setup"] << " assemble=" << tmax_asm
        << " amgsetup=" << time["amg setup"] << " solve=" << time["solve"] << " its=" << its
        << " solver_total=" << tmax_solve << " total=" << T
        << " dofs_per_s_solver=" << dof.n_dofs() / tmax_solve
        << " dofs_per_s_total=" << dof.n_dofs() / T
        << " peakMB_per_rank=" << mem
        << " cpu_assemble=" << Utilities::MPI::max(cpu["assemble"], comm)
        << " cpu_amgsetup=" << Utilities::MPI::max(cpu["amg setup"], comm)
        << " cpu_solve=" << Utilities::MPI::max(cpu["solve"], comm)
        << " amgreinit=" << time["amg reinit"] << " cpu_amgreinit=" << Utilities::MPI::max(cpu["amg reinit"], comm)
        << " load_at_start=" << load0 << std::endl;
}
