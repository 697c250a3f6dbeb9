#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/numerics/rtree.h>
#include <deal.II/numerics/vector_tools.h>

#include <algorithm>

#include <ring_contact/boundary_motion.h>
#include <ring_contact/components.h>
#include <ring_contact/equilibrium.h>
#include <ring_contact/geometry.h>
#include <ring_contact/ring_contact_problem.h>
#include <ring_contact/utilities.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <set>
#include <sstream>

namespace RingContact
{
  RingContactProblem::RingContactProblem(const Parameters        &parameters,
                                         const IntegrationScheme &scheme,
                                         std::ostream            &log,
                                         const MPI_Comm           communicator)
      : parameters(parameters)
      , scheme(scheme)
      , log(log)
      , communicator(communicator)
      , n_processes(RingContact::n_processes(communicator))
      , this_process(RingContact::this_process(communicator))
      , dof_handler(triangulation)
      , displacement(0)
      , scenario(make_scenario(parameters))
      , bodies(scenario->bodies())
      , boundary_loads(scenario->boundary_loads())
      , load_program(parameters.load)
      , previous_time(0)
      , current_time(0)
      , current_load{0, 0}
      // The summary is printed by run() when it ends, not by the
      // destructor: a run that ends by an error prints the error only.
      , timer(log, TimerOutput::never, TimerOutput::wall_times)
  {
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        materials.emplace(bodies[b].material_id, bodies[b].material);
        fe_index_of[bodies[b].material_id] = b;
      }
  }

  // The mesh: generated or read, checked, on the polar manifold (SSNP152).
  // The body of each contact surface: the slave bodies get the multiplier.
  void
  RingContactProblem::make_grid()
  {
    TimerOutput::Scope t(timer, "mesh");
    Geometry::create_mesh(triangulation, parameters);
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          body_of_boundary[face->boundary_id()] = cell->material_id();
    // The bodies share no vertex: each is its own mesh, and they meet
    // through the contact only. A mesh that joins two (one gmsh line as
    // the boundary of both) would glue them there, silently.
    std::vector<types::material_id> body_at(triangulation.n_vertices(),
                                            numbers::invalid_material_id);
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        {
          auto &id = body_at[cell->vertex_index(v)];
          if (id == numbers::invalid_material_id)
            id = cell->material_id();
          else if (id != cell->material_id())
            {
              const auto name = [&](const types::material_id m) {
                for (const Body &body : bodies)
                  if (body.material_id == m)
                    return body.name + " (material " + std::to_string(m) +
                           ")";
                return "material " + std::to_string(m);
              };
              std::ostringstream where;
              where << cell->vertex(v)[0] << ", " << cell->vertex(v)[1];
              throw std::runtime_error(
                "the mesh joins " + name(id) + " and " +
                name(cell->material_id()) + " at the vertex (" +
                where.str() +
                "): bodies meet through their contact surfaces only, each "
                "meshed on its own (in gmsh, points and lines of its own "
                "for each body, as meshes/two_blocks.geo)");
            }
        }
    slave_ring = body_of_boundary.at(parameters.contact.slave_boundary_id);
  }

  // The cells among the processes, by METIS on the graph of the cells that
  // share a face, with an edge across each contact interface too (from
  // each slave face to the master face nearest to it): the bodies share no
  // face, and without those edges METIS gives each process whole bodies,
  // one of them all the contact work (the slave ring of SSNP152 on one
  // process and the master on the other). With them the cut runs across the
  // interface and each process gets its share of both. A cell with a face
  // on a slave surface weighs as much as five others: its contact points
  // cost that much (measured at 640 x 48, Gauss 2).
  void
  RingContactProblem::partition_cells()
  {
    DynamicSparsityPattern graph;
    GridTools::get_face_connectivity_of_cells(triangulation, graph);
    std::vector<unsigned int> weights(triangulation.n_active_cells(), 1);
    using FaceCentre = std::pair<Point<2>, unsigned int>; // centre, cell
    for (const auto &[slave, master] : parameters.contact_pairs())
      {
        std::vector<FaceCentre> slave_faces, master_faces;
        for (const auto &cell : triangulation.active_cell_iterators())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary() && face->boundary_id() == slave)
              {
                slave_faces.emplace_back(face->center(),
                                         cell->active_cell_index());
                weights[cell->active_cell_index()] = 5;
              }
            else if (face->at_boundary() && face->boundary_id() == master)
              master_faces.emplace_back(face->center(),
                                        cell->active_cell_index());
        const auto tree = pack_rtree(master_faces);
        for (const auto &[centre, cell] : slave_faces)
          for (auto nearest =
                 tree.qbegin(boost::geometry::index::nearest(centre, 1));
               nearest != tree.qend();
               ++nearest)
            {
              graph.add(cell, nearest->second);
              graph.add(nearest->second, cell);
            }
      }
    SparsityPattern cell_graph;
    cell_graph.copy_from(graph);
    GridTools::partition_triangulation(n_processes,
                                       weights,
                                       cell_graph,
                                       triangulation);
  }

  // One FESystem per body: FE_Q(p)^2 for the displacement and FE_Nothing
  // for the contact pressure; and one more on the layer of the slave body's
  // cells with a face on the slave surface, with FE_Q(q) for the pressure
  // (its values off the slave surface, on the layer's inner faces, are
  // constrained to zero). The pressure has unknowns along the slave surface
  // only: with FE_Q(q) on the whole slave ring, a fifth of the unknowns of
  // the rings at 640 x 48 were zeros inside it (800 -> 720 unknowns on the
  // seed mesh, 156 800 -> 126 720 at 640 x 48). The displacement elements
  // of the layer and of
  // the rest of its body are the same FE_Q(p), continuous across (deal.II's
  // hp identities); the bodies share no vertex.
  void
  RingContactProblem::setup_system()
  {
    TimerOutput::Scope t(timer, "setup");
    const auto        &fe          = parameters.finite_elements;
    const auto         add_element = [&](const Body &body, const bool layer) {
      const unsigned int degree = body.degree;
      // The tangential traction: as the pressure with friction; without,
      // FE_Nothing, which adds no unknown.
      const std::unique_ptr<FiniteElement<2>> tangential =
        parameters.contact.friction_coefficient > 0 ?
                  std::unique_ptr<FiniteElement<2>>(
            std::make_unique<FE_Q<2>>(fe.multiplier_degree)) :
                  std::make_unique<FE_Nothing<2>>();
      if (layer)
        fe_collection.push_back(FESystem<2>(FE_Q<2>(degree),
                                            2,
                                            FE_Q<2>(fe.multiplier_degree),
                                            1,
                                            *tangential,
                                            1));
      else
        fe_collection.push_back(FESystem<2>(
          FE_Q<2>(degree), 2, FE_Nothing<2>(), 1, FE_Nothing<2>(), 1));
      q_collection.push_back(
        QGauss<2>(fe.reduced_integration ? degree : degree + 1));
      mapping_collection.push_back(MappingQ<2>(body.mapping_degree));
      body_of_fe_index.push_back(fe_index_of.at(body.material_id));
    };
    for (const Body &body : bodies)
      add_element(body, false);
    // A layer element for each slave body.
    const auto                   pairs = parameters.contact_pairs();
    std::set<types::boundary_id> slave_ids;
    std::map<types::material_id, unsigned int> layer_of;
    for (const auto &[slave, master] : pairs)
      {
        slave_ids.insert(slave);
        const auto body = body_of_boundary.at(slave);
        if (layer_of.count(body) == 0)
          {
            layer_of[body] = fe_collection.size();
            add_element(bodies[fe_index_of.at(body)], true);
          }
      }

    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        bool on_slave_surface = false;
        for (const auto &face : cell->face_iterators())
          on_slave_surface =
            on_slave_surface ||
            (face->at_boundary() && slave_ids.count(face->boundary_id()) > 0);
        cell->set_active_fe_index(on_slave_surface ?
                                    layer_of.at(cell->material_id()) :
                                    fe_index_of.at(cell->material_id()));
      }
    // Several processes: the cells partitioned (the same partition on
    // every process), the unknowns numbered process by process, each
    // process owning those of its cells (step-17).
    if (n_processes > 1)
      partition_cells();
    dof_handler.distribute_dofs(fe_collection);
    if (n_processes > 1)
      {
        DoFRenumbering::subdomain_wise(dof_handler);
        locally_owned_dofs =
          DoFTools::locally_owned_dofs_per_subdomain(dof_handler)[this_process];
      }
    else
      locally_owned_dofs = complete_index_set(dof_handler.n_dofs());
    system = std::make_unique<LinearSystem>(communicator,
                                            parameters.newton.linear_solver,
                                            parameters.newton.linear_tolerance);
    // A factorization of more than a gigabyte is said before it runs, with
    // what makes it large, once per size.
    system->estimate_observer = [this](const double bytes) {
      constexpr double gigabyte = 1e9;
      if (bytes > gigabyte && bytes > 2 * largest_estimate_said)
        {
          largest_estimate_said = bytes;
          log << "Note: the direct solver's factorization will need about "
              << std::setprecision(3) << bytes / gigabyte
              << " GB (UMFPACK's estimate) and take long" << describe_fill_in()
              << '\n'
              << std::setprecision(6);
        }
    };
    if (system->iterative())
      {
        // The iterative solver's blocks: each displacement component, and
        // the multipliers (pressure and tangential traction).
        std::vector<BlockSolver::Kind> kinds(dof_handler.n_dofs(),
                                             BlockSolver::multiplier);
        for (const auto i :
             DoFTools::extract_dofs(dof_handler,
                                    Components::displacement_mask(true, false)))
          kinds[i] = BlockSolver::displacement_x;
        for (const auto i :
             DoFTools::extract_dofs(dof_handler,
                                    Components::displacement_mask(false, true)))
          kinds[i] = BlockSolver::displacement_y;
        std::map<types::global_dof_index, Point<2>> support_points;
        DoFTools::map_dofs_to_support_points(mapping_collection,
                                             dof_handler,
                                             support_points,
                                             Components::displacement_mask());
        std::vector<Point<2>> positions(dof_handler.n_dofs());
        for (const auto &[i, point] : support_points)
          positions[i] = point;
        system->set_kinds(kinds, positions);
      }

    // Cyclic symmetry: the nodes of the sector's two sides, and the master
    // surface continued far enough for the rotation of the load program.
    CyclicSymmetry::Sector sector;
    if (parameters.mesh.sector_elements > 0)
      {
        const auto &mesh = parameters.mesh;
        sector.angle     = mesh.sector_angle();
        // The slave's motion along the master (elements): the inner ring
        // turns.
        const double rotation =
          parameters.load.program == LoadProgramType::rotation ?
            (slave_ring == Ids::inner_ring ? 1.0 : -1.0) *
              parameters.load.rotation_elements :
            0.0;
        CyclicSymmetry::set_master_window(sector,
                                          mesh.sector_elements *
                                            (1u << mesh.global_refinements),
                                          mesh.elements_around *
                                            (1u << mesh.global_refinements),
                                          rotation);
        cyclic_pairs = CyclicSymmetry::find_node_pairs(dof_handler,
                                                       mapping_collection,
                                                       sector.angle);
        sector.multiplier_twins =
          CyclicSymmetry::multiplier_pairs(cyclic_pairs);
      }

    // One interface per pair, each with the constants of subsection
    // Contact and its own surfaces. Geometrically linear only when no body
    // moves to a current configuration of its own.
    const bool geometrically_linear =
      std::all_of(bodies.begin(), bodies.end(), [](const Body &body) {
        return body.material.kinematics == Kinematics::small_strain;
      });
    contacts.clear();
    pair_of_node.clear();
    for (const auto &[slave, master] : pairs)
      {
        ContactParameters pair_parameters  = parameters.contact;
        pair_parameters.slave_boundary_id  = slave;
        pair_parameters.master_boundary_id = master;
        const Body &slave_body =
          bodies[fe_index_of.at(body_of_boundary.at(slave))];
        const Body &master_body =
          bodies[fe_index_of.at(body_of_boundary.at(master))];
        contacts.push_back(std::make_unique<ContactInterface>(
          dof_handler,
          pair_parameters,
          scheme,
          slave_body.mapping_degree,
          master_body.mapping_degree,
          std::max(slave_body.material.youngs_modulus,
                   master_body.material.youngs_modulus),
          geometrically_linear,
          sector));
        // Every scheme of the file suits this pair's surfaces: known now,
        // not after the schemes listed before it have run.
        const unsigned int surface_degree =
          std::max(contacts.back()->slave_surface().displacement_basis().size(),
                   contacts.back()
                     ->master_surface()
                     .displacement_basis()
                     .size()) -
          1;
        for (const auto &other : parameters.contact.schemes)
          try
            {
              contact_quadrature(other, surface_degree);
            }
          catch (const std::exception &e)
            {
              // Named with the file and line that list it (main.cc).
              throw ParameterError("Contact",
                                   "Integration schemes",
                                   "Contact/Integration schemes: " +
                                     one_line_message(e));
            }
        for (const auto node : contacts.back()->all_multiplier_dofs())
          pair_of_node[node] = contacts.size() - 1;
        for (const auto node : contacts.back()->tangential_dofs())
          pair_of_node[node] = contacts.size() - 1;
      }
    probe_dof = contact_node_nearest_to(parameters.contact.probe_point);

    solution.reinit(dof_handler.n_dofs());
    previous_solution.reinit(dof_handler.n_dofs());
    internal_force.reinit(dof_handler.n_dofs());
    external_force.reinit(dof_handler.n_dofs());
    residual_magnitude.reinit(dof_handler.n_dofs());

    make_constraints();
  }

  void
  RingContactProblem::make_constraints()
  {
    imposed_dofs.clear();
    const ImposedMotion motion = scenario->boundary_motion(dof_handler,
                                                           mapping_collection,
                                                           LoadState{0, 0, 0});
    for (const auto &[dof, value] : motion.values)
      imposed_dofs.push_back(dof);
    normal_target = motion.normal;
    normal_component.clear();
    for (const auto &line : normal_target)
      {
        const unsigned int a =
          std::abs(line.normal[0]) >= std::abs(line.normal[1]) ? 0 : 1;
        normal_component.push_back(a);
        imposed_dofs.push_back(line.dofs[a]);
      }
    add_constraints(constraints, {}, {}, &is_dirichlet);
    const IndexSet all_multipliers =
      DoFTools::extract_dofs(dof_handler, Components::contact_mask());
    is_multiplier.assign(dof_handler.n_dofs(), false);
    for (const auto i : all_multipliers)
      is_multiplier[i] = true;

    // The unknowns whose reaction a support takes (equilibrium.h): the
    // imposed ones, both of a node with a normal condition (its reaction is
    // along the normal), and the two sides of a cyclic sector (the rest of
    // the rings acts there).
    supported.assign(dof_handler.n_dofs(), false);
    for (const auto dof : imposed_dofs)
      supported[dof] = true;
    for (const auto &line : normal_target)
      supported[line.dofs[0]] = supported[line.dofs[1]] = true;
    for (const auto &pair : cyclic_pairs)
      for (const unsigned int c : {Components::ux, Components::uy})
        supported[pair.end[c]] = supported[pair.start[c]] = true;
  }

  // The constraints of a Newton update. The fixed displacements get the
  // values of `boundary_increment` (zero where it has none): homogeneous for
  // the iterations that correct a state, inhomogeneous for the update that
  // moves the boundary to a new load state.
  // A normal displacement N . u = g constrains the component a with the
  // larger |N_a|: du_a = -(N_b / N_a) du_b + (its increment).
  void
  RingContactProblem::add_constraints(
    AffineConstraints<double>                       &target,
    const std::map<types::global_dof_index, double> &boundary_increment,
    const std::vector<double>                       &normal_increment,
    std::vector<bool>                               *fixed_dofs)
  {
    target.clear();
    for (const auto dof : imposed_dofs)
      target.add_line(dof);
    for (const auto &[dof, increment] : boundary_increment)
      target.set_inhomogeneity(dof, increment);
    for (unsigned int k = 0; k < normal_target.size(); ++k)
      {
        const auto        &line = normal_target[k];
        const unsigned int a = normal_component[k], b = 1 - a;
        target.add_entry(line.dofs[a],
                         line.dofs[b],
                         -line.normal[b] / line.normal[a]);
        if (!normal_increment.empty())
          target.set_inhomogeneity(line.dofs[a], normal_increment[k]);
      }
    if (fixed_dofs)
      {
        fixed_dofs->assign(dof_handler.n_dofs(), false);
        for (types::global_dof_index i = 0; i < dof_handler.n_dofs(); ++i)
          (*fixed_dofs)[i] = target.is_constrained(i);
      }

    // The multiplier lives on the slave surface only.
    const IndexSet all_multipliers =
      DoFTools::extract_dofs(dof_handler, Components::contact_mask());
    std::set<types::global_dof_index> slave_multipliers;
    for (const auto &[node, pair] : pair_of_node)
      slave_multipliers.insert(node);
    for (const auto i : all_multipliers)
      if (slave_multipliers.count(i) == 0)
        target.add_line(i);

    // Cyclic symmetry: the end side of the sector follows the start side.
    if (!cyclic_pairs.empty())
      CyclicSymmetry::add_constraints(cyclic_pairs,
                                      parameters.mesh.sector_angle(),
                                      target);
    target.close();
  }

  // Surfaces that interpenetrate before any load: the contact pushes them
  // apart in the first step, a load that the problem does not state (a
  // curved slave against a faceted master starts inside it by up to the
  // sagitta, which is 2 % of the element size at 40 elements around a
  // circle; at E / p = 100 that is several times the pressure sought).
  // Measured by each node's mean gap g~_k / w_k in the reference state;
  // said when deeper than 1e-4 of the slave's shortest segment (round-off
  // of touching surfaces is 1e-16 of it). Not said when a body of the pair
  // is held by the contact only (report_rigid_body_modes): its motion
  // absorbs the overlap, which is then a way to start in contact (the
  // Hertz problem's cylinder).
  void
  RingContactProblem::report_initial_interpenetration()
  {
    // One interface per pair, in the order of the pairs (setup()).
    const auto pairs = parameters.contact_pairs();
    for (unsigned int i = 0; i < contacts.size(); ++i)
      {
        const auto &contact         = contacts[i];
        const auto &[slave, master] = pairs[i];
        if (held_by_contact.count(body_of_boundary.at(slave)) ||
            held_by_contact.count(body_of_boundary.at(master)))
          continue;
        contact->update(solution);
        const auto [depth, where] = contact->deepest_interpenetration();
        if (!(depth > 1e-4 * contact->slave_segment_length()))
          continue;
        log << "Warning: the contact surfaces interpenetrate before any "
               "load, by up to "
            << std::setprecision(3) << depth << " at (" << where[0] << ", "
            << where[1] << "), "
            << 100 * depth / contact->slave_segment_length()
            << " % of the slave's shortest segment: the contact pushes them "
               "apart in the first step, a load the problem does not state. "
               "A curved slave against a faceted master does this (Mapping "
               "degree = 0 with mixed element degrees: Mapping degree = 1 "
               "makes both faceted), as do bodies that overlap in the mesh.\n"
            << std::setprecision(6);
      }
  }

  // Which rigid-body motions of each body the imposed displacements leave
  // free (u = a + w e_z x (X - X_c) with a, w not all zero and u = 0 in
  // every imposed component): only the contact can hold a body there, and a
  // frictionless contact holds it along the contact normal only. Said once
  // per run, so that a body left free by mistake (a support forgotten) is
  // named, not only a Newton iteration that fails.
  unsigned int
  RingContactProblem::report_rigid_body_modes()
  {
    // A mode (translation x, y, rotation scaled by the size) in words.
    const auto describe_mode = [](const Tensor<1, 3> &mode,
                                  const Point<2>     &centre,
                                  const double        size) {
      std::ostringstream what;
      what << std::setprecision(3);
      const double sign =
        mode[0] < -1e-12 || (mode[0] <= 1e-12 && mode[1] < 0) ? -1 : 1;
      if (std::abs(mode[2]) < 1e-6)
        {
          // Whole numbers for the axes, no "-0".
          const auto shown = [&](const double v) {
            return std::abs(v) < 1e-12 ? 0.0 : sign * v;
          };
          what << "the translation along (" << shown(mode[0]) << ", "
               << shown(mode[1]) << ")";
        }
      else
        what << "a rotation about ("
             << centre[0] - mode[1] * size / mode[2] << ", "
             << centre[1] + mode[0] * size / mode[2] << ")";
      return what.str();
    };
    // Per body: its centre and size (the rotation's scale) and the matrix
    // of its supports' constraints on its rigid modes.
    struct Frame
    {
      Point<2>              centre;
      double                size;
      SymmetricTensor<2, 3> G;
    };
    std::map<types::material_id, Frame> frames;
    bool                                any_free = false;
    unsigned int                        n_free   = 0;
    held_by_contact.clear();
    std::map<types::global_dof_index, Point<2>> support_points;
    DoFTools::map_dofs_to_support_points(mapping_collection,
                                         dof_handler,
                                         support_points,
                                         Components::displacement_mask());
    // The unknowns imposed whole, and the nodes (their u_x) of the normal
    // conditions.
    std::set<types::global_dof_index> imposed(imposed_dofs.begin(),
                                              imposed_dofs.end());
    std::map<types::global_dof_index, Tensor<1, 2>> normal_at;
    for (unsigned int k = 0; k < normal_target.size(); ++k)
      {
        imposed.erase(normal_target[k].dofs[normal_component[k]]);
        normal_at[normal_target[k].dofs[0]] = normal_target[k].normal;
      }
    for (const Body &body : bodies)
      {
        // The body's extent and centre, to scale the rotation.
        Point<2>                                       lower, upper;
        bool                                           first = true;
        std::vector<std::pair<Point<2>, Tensor<1, 2>>> fixed;
        std::vector<types::global_dof_index>           dofs;
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->material_id() == body.material_id)
            {
              for (const unsigned int v : cell->vertex_indices())
                for (unsigned int d = 0; d < 2; ++d)
                  {
                    const double x = cell->vertex(v)[d];
                    lower[d]       = first ? x : std::min(lower[d], x);
                    upper[d]       = first ? x : std::max(upper[d], x);
                    first          = first && d == 0;
                  }
              dofs.resize(cell->get_fe().n_dofs_per_cell());
              cell->get_dof_indices(dofs);
              for (unsigned int i = 0; i < dofs.size(); ++i)
                {
                  const unsigned int c =
                    cell->get_fe().system_to_component_index(i).first;
                  if (!Components::is_displacement(c))
                    continue;
                  // An imposed component c: e_c . u = 0 for the motion.
                  if (imposed.count(dofs[i]))
                    fixed.emplace_back(support_points.at(dofs[i]),
                                       Point<2>::unit_vector(c));
                  // A normal condition: N . u = 0.
                  if (normal_at.count(dofs[i]))
                    fixed.emplace_back(support_points.at(dofs[i]),
                                       normal_at.at(dofs[i]));
                }
            }
        if (first)
          continue;
        const Point<2> centre = 0.5 * (lower + upper);
        const double size = std::max(upper[0] - lower[0], upper[1] - lower[1]);
        // G = M^T M, M the rigid modes (translation x, y, rotation scaled by
        // the body's size) along the imposed directions e: its null space is
        // the free motions.
        SymmetricTensor<2, 3> G;
        for (const auto &[X, e] : fixed)
          {
            const Tensor<1, 2> r      = X - centre;
            const double       row[3] = {e[0],
                                         e[1],
                                         (-e[0] * r[1] + e[1] * r[0]) / size};
            for (unsigned int i = 0; i < 3; ++i)
              for (unsigned int j = i; j < 3; ++j)
                G[i][j] += row[i] * row[j];
          }
        const auto describe = [&](const Tensor<1, 3> &mode) {
          return describe_mode(mode, centre, size);
        };
        frames[body.material_id] = {centre, size, G};
        const auto   modes   = eigenvectors(G);
        const double largest = std::max(modes[0].first, 1e-300);
        bool         free    = false;
        for (const auto &[value, mode] : modes)
          if (value <= 1e-10 * largest || fixed.empty())
            {
              log << "Note: " << body.name << " (material " << body.material_id
                  << "): no imposed displacement fixes " << describe(mode)
                  << "; only the contact holds it there\n";
              ++n_free;
              held_by_contact.insert(body.material_id);
              free = true;
            }
        any_free = any_free || free;
      }

    // A frictionless contact pushes along its normals only: a motion of
    // one body, or of several together, that changes no gap (a block
    // sliding along a flat interface, a disc turning in a ring, two blocks
    // held by the contact between them and both free along it) is held by
    // nothing, and the tangent is singular: its solution, if the solver
    // finds one, is arbitrary along that motion. The rigid modes of all
    // bodies, the supports' constraints of each, and per slave point the
    // normal relative motion n . (r_slave - r_master): their null space.
    // (With friction, sticking may hold such a motion.)
    if (!any_free || parameters.contact.friction_coefficient > 0 ||
        frames.size() < 2)
      return n_free;
    std::map<types::material_id, unsigned int> column;
    std::vector<types::material_id>            ids;
    for (const auto &[id, frame] : frames)
      {
        column[id] = 3 * ids.size();
        ids.push_back(id);
      }
    const unsigned int       n_modes = 3 * ids.size();
    LAPACKFullMatrix<double> H(n_modes, n_modes);
    for (const auto &[id, frame] : frames)
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          H(column[id] + i, column[id] + j) += frame.G[i][j];
    const auto mode_row = [&](const types::material_id id,
                              const Point<2>          &x,
                              const Tensor<1, 2>      &n) {
      const Frame       &frame = frames.at(id);
      const Tensor<1, 2> r     = x - frame.centre;
      return std::array<double, 3>{
        {n[0], n[1], (-n[0] * r[1] + n[1] * r[0]) / frame.size}};
    };
    for (const auto &contact : contacts)
      {
        const ContactSurface &slave  = contact->slave_surface();
        const ContactSurface &master = contact->master_surface();
        for (unsigned int k = 0; k < slave.segments().size(); ++k)
          {
            const auto &segment = slave.segments()[k];
            if (segment.is_copy)
              continue;
            for (const double t : {0.0, 0.5, 1.0})
              {
                const auto   p      = slave.reference_point(k, t);
                const double length = p.dx.norm();
                const auto   partner = master.project(p.x).segment;
                if (!(length > 0) || partner >= master.segments().size())
                  continue;
                const auto s_id = segment.cell->material_id();
                const auto m_id =
                  master.segments()[partner].cell->material_id();
                if (s_id == m_id || !frames.count(s_id) ||
                    !frames.count(m_id))
                  continue;
                const Tensor<1, 2> n({p.dx[1] / length, -p.dx[0] / length});
                std::vector<std::pair<unsigned int, double>> row;
                const auto a = mode_row(s_id, p.x, n);
                const auto b = mode_row(m_id, p.x, n);
                for (unsigned int i = 0; i < 3; ++i)
                  {
                    row.emplace_back(column[s_id] + i, a[i]);
                    row.emplace_back(column[m_id] + i, -b[i]);
                  }
                for (const auto &[i, v] : row)
                  for (const auto &[j, w] : row)
                    H(i, j) += v * w;
              }
          }
      }
    H.compute_svd();
    const double largest = std::max(H.singular_value(0), 1e-300);
    const auto  &vt      = H.get_svd_vt();
    for (unsigned int m = 0; m < n_modes; ++m)
      if (H.singular_value(m) <= 1e-10 * largest)
        {
          std::string  what, alone;
          unsigned int n_moving = 0;
          for (unsigned int b = 0; b < ids.size(); ++b)
            {
              Tensor<1, 3> mode;
              for (unsigned int i = 0; i < 3; ++i)
                mode[i] = vt(m, 3 * b + i);
              if (mode.norm() < 1e-6)
                continue;
              const auto body =
                std::find_if(bodies.begin(), bodies.end(), [&](const Body &x) {
                  return x.material_id == ids[b];
                });
              const std::string motion =
                describe_mode(mode / mode.norm(),
                              frames.at(ids[b]).centre,
                              frames.at(ids[b]).size);
              what += (what.empty() ? "" : ", ") + body->name + " " + motion;
              alone = body->name + " (material " +
                      std::to_string(body->material_id) + "): nothing holds " +
                      motion;
              ++n_moving;
            }
          if (n_moving == 1)
            throw std::runtime_error(
              alone +
              ": no imposed displacement fixes it, and the frictionless "
              "contact, which pushes along its normals only, does not resist "
              "it either; the problem has no unique solution (impose a "
              "displacement on a boundary of the body that fixes this "
              "motion)");
          throw std::runtime_error(
            "nothing holds the bodies' common motion (" + what +
            "): it changes no gap and no support fixes it, so the "
            "problem has no unique solution (impose a displacement that "
            "fixes it on one of these bodies)");
        }
    return n_free;
  }

  // The first update of a load step carries the boundary increment, the
  // difference between the displacements of the new load state and those
  // of the current solution (the last converged state, or the predictor's
  // extrapolation of it). Writing that increment into the solution instead
  // would concentrate it in the first layer of elements along r = R1 and
  // r = R3: at finite strain that state can be far from the one sought (27 %
  // strain in the first layer with 12 layers per ring at p = 1e7), and
  // Newton then converges to another solution, the rings apart. Imposed on
  // the linearised problem, the increment spreads over the rings (step-44).
  // Returns whether there is an increment to impose.
  bool
  RingContactProblem::make_lifting_constraints()
  {
    std::map<types::global_dof_index, double> increment;
    double largest_target = 0, largest_increment = 0;
    for (const auto &[dof, value] : boundary_target)
      {
        increment[dof] = value - solution(dof);
        largest_target = std::max(largest_target, std::abs(value));
        largest_increment =
          std::max(largest_increment, std::abs(increment[dof]));
      }
    std::vector<double> normal_increment;
    for (unsigned int k = 0; k < normal_target.size(); ++k)
      {
        const auto dof = normal_target[k].dofs[normal_component[k]];
        normal_increment.push_back(normal_constrained_value(k, solution) -
                                   solution(dof));
        largest_target =
          std::max(largest_target, std::abs(normal_target[k].value));
        largest_increment =
          std::max(largest_increment, std::abs(normal_increment.back()));
      }
    // The predictor hits the target up to round-off when the motion is
    // linear in the load: then there is nothing to lift.
    if (largest_increment <=
        1e3 * std::numeric_limits<double>::epsilon() * largest_target)
      {
        set_boundary_target();
        return false;
      }
    add_constraints(lifting_constraints, increment, normal_increment);
    return true;
  }

  double
  RingContactProblem::normal_constrained_value(const unsigned int    k,
                                               const Vector<double> &u) const
  {
    const auto        &line = normal_target[k];
    const unsigned int a = normal_component[k], b = 1 - a;
    return (line.value - line.normal[b] * u(line.dofs[b])) / line.normal[a];
  }

  // The boundary exactly at its target, not up to round-off: the imposed
  // values, then the normal conditions (a normal condition's other unknown
  // may be an imposed one).
  void
  RingContactProblem::set_boundary_target()
  {
    for (const auto &[dof, value] : boundary_target)
      solution(dof) = value;
    for (unsigned int k = 0; k < normal_target.size(); ++k)
      solution(normal_target[k].dofs[normal_component[k]]) =
        normal_constrained_value(k, solution);
  }

  // The bulk couplings, and those of the current contact pairs.
  void
  RingContactProblem::make_sparsity_pattern()
  {
    // This process's cells; the contact couplings are few and the same on
    // every process.
    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(
      dof_handler, dsp, constraints, false, this_process);
    for (const auto &contact : contacts)
      contact->add_couplings(dsp);
    system->reinit(dsp, locally_owned_dofs, dof_handler.n_dofs());
  }

  void
  RingContactProblem::setup()
  {
    make_grid();
    setup_system();
    for (const auto &contact : contacts)
      contact->update(solution);
    make_sparsity_pattern();
  }

  // The scenario's displacements at the load state become the target.
  void
  RingContactProblem::apply_boundary_motion(const LoadState &load)
  {
    ImposedMotion motion =
      scenario->boundary_motion(dof_handler, mapping_collection, load);
    boundary_target = std::move(motion.values);
    normal_target   = std::move(motion.normal);
    current_load    = load;
  }

  // What the total Lagrangian assembly needs of the reference
  // configuration, which does not move: per cell of this process and
  // quadrature point, JxW and the gradients of the displacement's scalar
  // shape functions (both components share them). Evaluated once, by
  // FEValues through the mapping, instead of at every assembly (a fifth
  // of an assembly at 640 x 48). 288 bytes per Q1 cell, 1.4 kB per Q2
  // cell: about a tenth of the memory of the factorization at 640 x 48.
  void
  RingContactProblem::store_reference_geometry()
  {
    auto &geometry = reference_geometry;
    geometry.layout.resize(fe_collection.size());
    for (unsigned int k = 0; k < fe_collection.size(); ++k)
      {
        const FiniteElement<2> &fe     = fe_collection[k];
        auto                   &layout = geometry.layout[k];
        layout.n_q_points              = q_collection[k].size();
        layout.component.resize(fe.n_dofs_per_cell());
        layout.u_dofs.clear();
        layout.base.clear();
        layout.n_bases = 0;
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          {
            layout.component[i] = fe.system_to_component_index(i).first;
            if (!Components::is_displacement(layout.component[i]))
              continue;
            // The index of the scalar shape function in its base element.
            layout.u_dofs.push_back(i);
            layout.base.push_back(fe.system_to_base_index(i).second);
            layout.n_bases = std::max(layout.n_bases, layout.base.back() + 1);
          }
      }
    hp::FEValues<2> hp_fe_values(mapping_collection,
                                 fe_collection,
                                 q_collection,
                                 update_gradients | update_JxW_values);
    geometry.start.assign(triangulation.n_active_cells(), {0, 0});
    geometry.JxW.clear();
    geometry.gradients.clear();
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        if (cell->subdomain_id() != this_process)
          continue;
        hp_fe_values.reinit(cell);
        const FEValues<2> &fe_values = hp_fe_values.get_present_fe_values();
        const auto        &layout    = geometry.layout[cell->active_fe_index()];
        geometry.start[cell->active_cell_index()] = {geometry.JxW.size(),
                                                     geometry.gradients.size()};
        for (unsigned int q = 0; q < layout.n_q_points; ++q)
          {
            geometry.JxW.push_back(fe_values.JxW(q));
            const std::size_t first = geometry.gradients.size();
            geometry.gradients.resize(first + layout.n_bases);
            for (unsigned int a = 0; a < layout.u_dofs.size(); ++a)
              geometry.gradients[first + layout.base[a]] =
                fe_values.shape_grad(layout.u_dofs[a], q);
          }
      }
    geometry.JxW.shrink_to_fit();
    geometry.gradients.shrink_to_fit();
  }

  // Bulk: total Lagrangian virtual work int P : Grad(delta u) dV and its
  // tangent int Grad(delta u) : A : Grad(du) dV; then the contact terms.
  // Without the tangent (Assembly::residual) the bulk's cells give their
  // residual alone, from the stress alone: a third of the work (the
  // contact terms are whole either way). The constraints of the lifting
  // update are not homogeneous and act on the right-hand side through the
  // matrix: that assembly always has its tangent.
  void
  RingContactProblem::assemble_system(Assembly what)
  {
    if (update_constraints().has_inhomogeneities())
      what = Assembly::residual_and_tangent;
    TimerOutput::Scope t(timer, "assembly");
    const bool         tangent = what == Assembly::residual_and_tangent;
    tangent_assembled          = tangent;
    system->set_zero();
    internal_force     = 0;
    external_force     = 0;
    residual_magnitude = 0;
    n_inverted         = 0;
    min_det_F          = std::numeric_limits<double>::max();

    // The contact terms first, on their own, to measure their magnitudes:
    // a contact row is computed from positions X + u (the gap, the normal),
    // so its round-off is eps |K_ij| (|X| + |u_j|), not eps |K_ij| |u_j|.
    // At p = 1e4 on steel this is a thousand times the bulk's.
    for (const auto &contact : contacts)
      contact->assemble(solution, update_constraints(), *system);
    system->compress();
    {
      double largest_position = 0;
      for (const auto &vertex : triangulation.get_vertices())
        largest_position = std::max(largest_position, vertex.norm());
      for (const auto i : locally_owned_dofs)
        {
          double magnitude = std::abs(system->rhs()(i));
          system->for_each_entry(i, [&](const auto j, const double value) {
            magnitude +=
              std::abs(value) * (std::abs(solution(j)) +
                                 (is_multiplier[j] ? 0 : largest_position));
          });
          residual_magnitude(i) = magnitude;
        }
    }

    if (reference_geometry.start.empty())
      store_reference_geometry();
    FullMatrix<double>                   cell_matrix;
    Vector<double>                       cell_rhs;
    std::vector<types::global_dof_index> dofs;
    std::vector<Tensor<2, 2>>            grad_u;
    std::vector<Tensor<1, 2>>            grad_phi;

    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        if (cell->subdomain_id() != this_process)
          continue;
        const FiniteElement<2> &fe       = cell->get_fe();
        const unsigned int      n        = fe.n_dofs_per_cell();
        const Material         &material = materials.at(cell->material_id());
        const auto &layout = reference_geometry.layout[cell->active_fe_index()];
        const auto &u_dofs = layout.u_dofs;
        const auto &component         = layout.component;
        const unsigned int n_q_points = layout.n_q_points;
        const auto start = reference_geometry.start[cell->active_cell_index()];
        const double       *JxW_values = &reference_geometry.JxW[start.first];
        const Tensor<1, 2> *gradients =
          &reference_geometry.gradients[start.second];
        cell_matrix.reinit(n, n);
        cell_rhs.reinit(n);
        dofs.resize(n);
        cell->get_dof_indices(dofs);

        // The displacement shape functions each have one nonzero component
        // c: Grad(phi) = e_c (x) grad(phi_c), so that Grad u = sum_i u_i
        // e_c (x) grad(phi_i), P : Grad(phi_i) = P_cJ d_J phi_i and the
        // tangent is d_J phi_i A_cJdL d_L phi_j.
        grad_phi.resize(u_dofs.size());
        grad_u.assign(n_q_points, Tensor<2, 2>());
        for (unsigned int q = 0; q < n_q_points; ++q)
          for (unsigned int a = 0; a < u_dofs.size(); ++a)
            grad_u[q][component[u_dofs[a]]] +=
              solution(dofs[u_dofs[a]]) *
              gradients[q * layout.n_bases + layout.base[a]];

        for (unsigned int q = 0; q < n_q_points; ++q)
          {
            // An inverted state (det F <= 0) has no physical meaning, in
            // either kinematics: it is counted, the material law is not
            // evaluated there, and the Newton loop rejects the state.
            const double det_F =
              determinant(unit_symmetric_tensor<2>() + grad_u[q]);
            min_det_F = std::min(min_det_F, det_F);
            if (!(det_F > 0))
              {
                ++n_inverted;
                continue;
              }
            Tensor<2, 2> P;
            Tensor<4, 2> A;
            if (tangent)
              material.stress_and_tangent(grad_u[q], P, A);
            else
              P = material.stress(grad_u[q]);
            const double JxW = JxW_values[q];
            for (unsigned int a = 0; a < u_dofs.size(); ++a)
              grad_phi[a] = gradients[q * layout.n_bases + layout.base[a]];
            for (unsigned int a = 0; a < u_dofs.size(); ++a)
              {
                const unsigned int i = u_dofs[a], c = component[i];
                cell_rhs(i) -= (P[c] * grad_phi[a]) * JxW;
                if (!tangent)
                  continue;
                // A_cJdL grad_phi_a[J], for each d and L.
                Tensor<2, 2> Ag;
                for (unsigned int J = 0; J < 2; ++J)
                  for (unsigned int d = 0; d < 2; ++d)
                    for (unsigned int L = 0; L < 2; ++L)
                      Ag[d][L] += grad_phi[a][J] * A[c][J][d][L];
                // The upper triangle: the laws are hyperelastic, A_cJdL =
                // A_dLcJ, and the bulk's tangent is symmetric.
                for (unsigned int b = a; b < u_dofs.size(); ++b)
                  {
                    const unsigned int j = u_dofs[b];
                    cell_matrix(i, j) += (Ag[component[j]] * grad_phi[b]) * JxW;
                  }
              }
          }
        if (tangent)
          for (unsigned int a = 0; a < u_dofs.size(); ++a)
            for (unsigned int b = 0; b < a; ++b)
              cell_matrix(u_dofs[a], u_dofs[b]) =
                cell_matrix(u_dofs[b], u_dofs[a]);
        add_local_system(cell_matrix,
                         cell_rhs,
                         dofs,
                         internal_force,
                         cell->active_cell_index());
      }

    // A load that is not a finite number at a face of one process fails the
    // load step on every process.
    std::string boundary_data_error;
    try
      {
        assemble_boundary_loads();
      }
    catch (const BoundaryDataError &e)
      {
        boundary_data_error = e.what();
      }
    system->compress();
    if (n_processes > 1)
      {
        // The sums over the processes' cells.
        for (Vector<double> *v :
             {&internal_force, &external_force, &residual_magnitude})
          sum_over_processes(*v, communicator);
        n_inverted = Utilities::MPI::sum(n_inverted, communicator);
        min_det_F  = Utilities::MPI::min(min_det_F, communicator);
        for (const BoundaryLoad &load : boundary_loads)
          for (unsigned int d = 0; d < 2; ++d)
            applied_resultant[load.boundary_id][d] = Utilities::MPI::sum(
              applied_resultant[load.boundary_id][d], communicator);
        for (const auto &message :
             Utilities::MPI::all_gather(communicator, boundary_data_error))
          if (!message.empty())
            {
              boundary_data_error = message;
              break;
            }
      }
    if (!boundary_data_error.empty())
      throw BoundaryDataError(boundary_data_error);
    // The magnitude of the terms of each row at the last assembly with the
    // tangent (the others have the contact's only): the round-off scale of
    // the forces for the invariants of the converged state, whose own
    // assembly may have skipped the tangent.
    if (tangent)
      tangent_magnitude = residual_magnitude;
  }

  // Add a cell's (or face's) matrix and right-hand side -R to the system,
  // its force R to `force` (internal or external), and to each row the
  // magnitude of its terms: computed from the displacement alone, their
  // round-off is eps sum_j |K_ij| |u_j| (see residual_measure()). Without
  // the tangent, the right-hand side and the force alone.
  void
  RingContactProblem::add_local_system(
    const FullMatrix<double>                   &matrix,
    const Vector<double>                       &rhs,
    const std::vector<types::global_dof_index> &dofs,
    Vector<double>                             &force,
    const unsigned int                          cell)
  {
    if (!tangent_assembled)
      {
        for (unsigned int i = 0; i < dofs.size(); ++i)
          force(dofs[i]) -= rhs(i);
        system->add_rhs(update_constraints(), rhs, dofs);
        return;
      }
    for (unsigned int i = 0; i < dofs.size(); ++i)
      {
        force(dofs[i]) -= rhs(i);
        double magnitude = std::abs(rhs(i));
        for (unsigned int j = 0; j < dofs.size(); ++j)
          magnitude += std::abs(matrix(i, j)) * std::abs(solution(dofs[j]));
        residual_magnitude(dofs[i]) += magnitude;
      }
    if (cell == numbers::invalid_unsigned_int)
      system->add(update_constraints(), matrix, rhs, dofs);
    else
      system->add_cell(cell, update_constraints(), matrix, rhs, dofs);
  }

  // The scenario's boundary loads.
  // A pressure p on the current configuration: the load -p n da, with
  // n da = cof(F) N dA (Nanson; in two dimensions the cofactor det(F) F^-T
  // is linear in F), adds int p phi_i . cof(F) N dA to the residual and,
  // F = I + Grad u, the tangent int p phi_i . cof(Grad phi_j) N dA (not
  // symmetric). A body in small strain: the dead load, cof(F) = I. p is
  // evaluated at the reference position of the quadrature point.
  // A traction t per reference length: the dead load, - int phi_i . t dA
  // in the residual, no tangent.
  void
  RingContactProblem::assemble_boundary_loads()
  {
    applied_resultant.clear();
    if (boundary_loads.empty())
      return;
    const auto cofactor = [](const Tensor<2, 2> &G) {
      Tensor<2, 2> C;
      C[0][0] = G[1][1];
      C[0][1] = -G[1][0];
      C[1][0] = -G[0][1];
      C[1][1] = G[0][0];
      return C;
    };
    hp::QCollection<1> face_q;
    for (unsigned int i = 0; i < q_collection.size(); ++i)
      face_q.push_back(QGauss<1>(fe_collection[i].degree + 1));
    hp::FEFaceValues<2>                  hp_face_values(mapping_collection,
                                       fe_collection,
                                       face_q,
                                       update_values | update_gradients |
                                         update_normal_vectors |
                                         update_quadrature_points |
                                         update_JxW_values);
    std::vector<types::global_dof_index> dofs;
    std::vector<Tensor<2, 2>>            grad_u;
    FullMatrix<double>                   face_matrix;
    Vector<double>                       face_rhs;
    for (const BoundaryLoad &load : boundary_loads)
      for (const auto &cell : dof_handler.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->subdomain_id() == this_process &&
              cell->face(f)->at_boundary() &&
              cell->face(f)->boundary_id() == load.boundary_id)
            {
              hp_face_values.reinit(cell, f);
              const FEFaceValues<2> &fv =
                hp_face_values.get_present_fe_values();
              const FiniteElement<2> &fe = cell->get_fe();
              const unsigned int      n  = fe.n_dofs_per_cell();
              const bool pressure = load.type == BoundaryLoad::Type::pressure;
              // Each body's kinematics: a body in finite (or logarithmic)
              // strain carries the pressure on its current surface.
              const bool follower =
                bodies[body_of_fe_index[cell->active_fe_index()]]
                  .material.kinematics != Kinematics::small_strain;
              dofs.resize(n);
              cell->get_dof_indices(dofs);
              face_matrix.reinit(n, n);
              face_rhs.reinit(n);
              grad_u.resize(fv.n_quadrature_points);
              fv[displacement].get_function_gradients(solution, grad_u);
              for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
                {
                  const Tensor<1, 2> value =
                    load.value(fv.quadrature_point(q), current_load);
                  const double       p  = value[0];
                  const Tensor<1, 2> N  = fv.normal_vector(q);
                  const double       dA = fv.JxW(q);
                  // The force per unit of the face's measure, times dA.
                  const Tensor<1, 2> force =
                    pressure ?
                      Tensor<1, 2>(
                        -p *
                        ((follower ?
                            cofactor(unit_symmetric_tensor<2>() + grad_u[q]) :
                            Tensor<2, 2>(unit_symmetric_tensor<2>())) *
                         N) *
                        dA) :
                      Tensor<1, 2>(value * dA);
                  applied_resultant[load.boundary_id] += force;
                  for (unsigned int i = 0; i < n; ++i)
                    {
                      const unsigned int c =
                        fe.system_to_component_index(i).first;
                      if (!Components::is_displacement(c))
                        continue;
                      face_rhs(i) += fv.shape_value(i, q) * force[c];
                      if (!pressure || !follower)
                        continue;
                      for (unsigned int j = 0; j < n; ++j)
                        {
                          const unsigned int d =
                            fe.system_to_component_index(j).first;
                          if (!Components::is_displacement(d))
                            continue;
                          Tensor<2, 2> G;
                          G[d] = fv.shape_grad(j, q);
                          face_matrix(i, j) += p * fv.shape_value(i, q) *
                                               (cofactor(G) * N)[c] * dA;
                        }
                    }
                }
              add_local_system(face_matrix, face_rhs, dofs, external_force);
            }
  }

  // Pair, choose the active set, and assemble the Newton system at the
  // current solution; a new sparsity pattern when the pairs left the old.
  unsigned int
  RingContactProblem::assemble_newton_system(
    const ContactInterface::Pairing pairing,
    const Assembly                  what)
  {
    // Only finite numbers in the state: an update that overflowed (a body
    // as soft as E = 1e-200, a diverging iterate) fails the iteration here,
    // with its reason, before the contact search computes with it.
    for (const double value : solution)
      if (!std::isfinite(value))
        throw NonFiniteState("the displacement or contact pressure is not a "
                             "finite number after the Newton update");
    unsigned int n_changed;
    {
      TimerOutput::Scope t(timer, "contact search");
      n_changed = 0;
      for (const auto &contact : contacts)
        n_changed += contact->update(solution, pairing);
    }
    if (!std::all_of(contacts.begin(),
                     contacts.end(),
                     [](const std::unique_ptr<ContactInterface> &contact) {
                       return contact->sparsity_covers_pairing();
                     }))
      make_sparsity_pattern();
    assemble_system(what);
    return n_changed;
  }

  // The Newton update by a direct solve. A singular tangent (UMFPACK
  // refuses it) or a nearly singular one (the solution does not satisfy
  // the system) is a failure of the iteration with its reason, not an
  // exception that ends the run: usually a body that nothing holds in some
  // direction (a missing support, or a contact that is open).
  bool
  RingContactProblem::solve_linear_system(Vector<double> &newton_update)
  {
    Assert(tangent_assembled, ExcMessage("The system has no tangent."));
    TimerOutput::Scope t(timer, "linear solver");
    const std::string  advice =
      ": a body may be free to move rigidly (check that its supports, "
      "and the contact, hold it in every direction)";
    double relative_residual;
    try
      {
        relative_residual = system->solve(newton_update);
        if (system->iterative())
          {
            linear_iterations += system->last_iterations();
            ++linear_solves;
            if (parameters.newton.verbose)
              log << "      GMRES: " << system->last_iterations()
                  << " iterations\n";
          }
      }
    catch (const FactorizationTooLarge &e)
      {
        // Cutting the step would not help: say what makes the system so
        // large to factorize.
        throw std::runtime_error(one_line_message(e) + describe_fill_in());
      }
    catch (const IterativeSolverFailure &e)
      {
        failure_reason = "the iterative linear solver failed (" +
                         one_line_message(e) +
                         "): a direct solver (Newton/Linear solver = auto) "
                         "tells whether the tangent is singular";
        return false;
      }
    catch (const std::exception &e)
      {
        failure_reason = "the tangent matrix is singular (" +
                         one_line_message(e) + ")" + advice;
        return false;
      }
    // A direct solve of a regular matrix, however ill-conditioned, leaves
    // K x - b a round-off of b. A singular one (a body free to slide) leaves
    // x without meaning: a residual of the order of b, or an x so large
    // that the next state is nonsense.
    if (!(relative_residual <= 1e-6))
      {
        std::ostringstream reason;
        reason << "the tangent matrix is singular to working precision (the "
               << (system->iterative() ? "iterative" : "direct")
               << " solve leaves a relative residual of "
               << std::setprecision(3) << relative_residual << ")" << advice;
        failure_reason = reason.str();
        return false;
      }
    update_constraints().distribute(newton_update);
    return true;
  }

  bool
  ResidualMeasure::converged(const double tolerance) const
  {
    return force <= std::max(tolerance, force_floor) &&
           gap <= std::max(tolerance, gap_floor);
  }

  bool
  ResidualMeasure::undecided(const double tolerance) const
  {
    return !force_floor_known && !converged(tolerance) &&
           gap <= std::max(tolerance, gap_floor);
  }

  // The convergence measures of the assembled system, each relative to the
  // problem's own scale, so that one tolerance fits E = 1e6 as well as
  // E = 1e12, p = 1e2 as well as p = 1e9, and rings of any size:
  // - free displacement rows (forces): |R| over the reaction forces on the
  //   fixed boundaries;
  // - active contact rows c int Phi_k g dS: divided by the sum of their
  //   row's |K_kj| (about 2 c w_k), a length, over the largest displacement;
  //   open contact rows w_k lambda_k: lambda_k over the largest |lambda|.
  // Each has a floor: what double precision resolves at this state,
  // round_off_factor * eps * sum_j |K_ij| |z_j| (see residual_magnitude).
  // A fixed tolerance cannot do this: the contact rows are evaluated from
  // positions of size R, so their noise does not scale with the load, and
  // at p = 1e4 on steel it is 1e-9 of the reactions.
  ResidualMeasure
  RingContactProblem::residual_measure() const
  {
    // Several roundings per term, the linear solver's backward error, and
    // the row sums of the noise: a factor of ten over eps |K| |z|,
    // measured on the variants of scripts/studies/variants (the stalled residuals
    // of steel/aluminium at p = 1e2 are 0.05 to 0.3 of eps |K| |z|).
    constexpr double round_off_factor = 10;
    const double     eps              = std::numeric_limits<double>::epsilon();

    // The norms with a running scale (EuclideanNorm): squares of forces
    // of 1e-200 would underflow to zero, and every ratio below with them.
    EuclideanNorm reaction;
    double        largest_displacement = 0, largest_pressure = 0;
    for (types::global_dof_index i = 0; i < solution.size(); ++i)
      {
        if (is_dirichlet[i] && !is_multiplier[i])
          reaction.add(internal_force(i));
        reaction.add(external_force(i));
        if (is_multiplier[i])
          largest_pressure = std::max(largest_pressure, std::abs(solution(i)));
        else
          largest_displacement =
            std::max(largest_displacement, std::abs(solution(i)));
      }
    // Under the pressure load the reactions vanish: the scale of the forces
    // is then the load itself (both are in `reaction`).
    const double reaction_norm = reaction.value() > 0 ? reaction.value() :
                                                        1e-300;
    ResidualMeasure measure;
    measure.at_rest      = largest_displacement == 0;
    largest_displacement = std::max(largest_displacement, 1e-300);
    largest_pressure     = std::max(largest_pressure, 1e-300);

    EuclideanNorm force, force_floor, merit;
    for (types::global_dof_index i = 0; i < solution.size(); ++i)
      {
        if (constraints.is_constrained(i))
          continue;
        const double r = system->rhs()(i);
        merit.add(r);
        if (!is_multiplier[i])
          {
            force.add(r);
            force_floor.add(residual_magnitude(i));
            continue;
          }
        // A contact row: active when it depends on displacements. Its
        // entries are on the process that owns it.
        if (!locally_owned_dofs.is_element(i))
          continue;
        // A gap or a stick row (c s~_k) measures a length; an open node's
        // row or a sliding node's (w lambda_t - sign mu w lambda) a
        // traction.
        double row_sum = 0;
        bool   active  = false;
        system->for_each_entry(i, [&](const auto j, const double value) {
          row_sum += std::abs(value);
          active = active || (!is_multiplier[j] && value != 0);
        });
        if (row_sum == 0)
          continue;
        const double scale = active ? largest_displacement : largest_pressure;
        measure.gap = std::max(measure.gap, std::abs(r) / row_sum / scale);
        measure.gap_floor =
          std::max(measure.gap_floor,
                   round_off_factor * eps *
                     (active ? residual_magnitude(i) / row_sum / scale : 1.0));
      }
    if (n_processes > 1)
      {
        measure.gap = Utilities::MPI::max(measure.gap, communicator);
        measure.gap_floor =
          Utilities::MPI::max(measure.gap_floor, communicator);
      }
    // The floor estimates the round-off of positions |X| over the
    // displacement, but the gap is computed with its reference part apart
    // (zero where node-matching surfaces face each other), so that it
    // stays accurate far below that: displacements of 1e-210 on bodies of
    // 1 m gave a floor of 1e195, which accepted any iterate. A gap residual
    // of 1e-4 of the displacement is never a round-off worth accepting.
    measure.gap_floor = std::min(measure.gap_floor, 1e-4);
    measure.force             = force.value() / reaction_norm;
    measure.force_floor_known = tangent_assembled;
    measure.force_floor =
      tangent_assembled ?
        round_off_factor * eps * force_floor.value() / reaction_norm :
        0;
    measure.merit = merit.value();
    return measure;
  }

  // Semi-smooth Newton: pair, choose the active set, assemble, solve, and
  // move along the update as far as the residual decreases (line search).
  // Converged when the active set did not change, and both the force rows
  // and the contact rows are below the tolerance relative to their own
  // scales, or at their round-off floor (see residual_measure()).
  // A state with an inverted element (det F <= 0) is never accepted.
  // After how many iterations of a Newton solve the pairing is held.
  constexpr unsigned int hold_pairing_after = 4;

  ContactInterface::Pairing
  RingContactProblem::accepted_pairing() const
  {
    return keep_partners ? ContactInterface::Pairing::hold_within_segments :
                           ContactInterface::Pairing::search;
  }

  bool
  RingContactProblem::solve_newton_step(unsigned int &iterations,
                                        double       &final_residual)
  {
    const auto    &newton = parameters.newton;
    Vector<double> newton_update(dof_handler.n_dofs());
    iterations = 0;
    failure_reason.clear();
    keep_partners = false;
    // The first update moves the boundary to the new load state.
    lifting                = make_lifting_constraints();
    unsigned int n_changed = assemble_newton_system();
    // The update that led to the current iterate: none yet, or whether it
    // imposed the boundary increment and the residual it started from.
    bool   updated = false, update_lifted = false;
    double update_from = 0;
    for (unsigned int it = 0;; ++it)
      {
        // A signal ends the step here, not after it (and its cuts): the
        // converged steps are on disk already.
        if (stop_requested())
          {
            failure_reason = "interrupted by a signal";
            final_residual = std::numeric_limits<double>::infinity();
            return false;
          }
        if (n_inverted > 0)
          {
            std::ostringstream reason;
            reason << "inverted elements: det F = " << min_det_F << " <= 0 at "
                   << n_inverted << " quadrature points";
            failure_reason = reason.str();
            final_residual = std::numeric_limits<double>::infinity();
            if (newton.verbose)
              log << "    Newton " << std::setw(2) << it << "  "
                  << failure_reason << '\n';
            return false;
          }
        ResidualMeasure measure = residual_measure();
        // An iterate assembled without its tangent: the tangent now, at the
        // same state and pairing, unless the iterate has converged. The
        // update needs it, and so may the test of convergence (the round-off
        // floor of the forces).
        if (!tangent_assembled && !(!lifting && n_changed == 0 &&
                                    measure.converged(newton.tolerance)))
          {
            assemble_system();
            measure = residual_measure();
          }
        const bool converged =
          !lifting && n_changed == 0 && measure.converged(newton.tolerance);
        final_residual = std::max(measure.force, measure.gap);
        if (updated)
          convergence_record.record(update_lifted,
                                    update_from,
                                    final_residual,
                                    converged);
        // Before the update that moves the boundary, the measures are those
        // of the previous load state (the reactions may be zero): not shown.
        if (newton.verbose && lifting)
          log << "    Newton " << std::setw(2) << it
              << "  boundary increment imposed on the update  active "
              << n_active_nodes() << "/" << n_contact_nodes() << '\n';
        else if (newton.verbose)
          {
            log << "    Newton " << std::setw(2) << it << "  relative residual "
                << std::scientific << std::setprecision(3) << measure.force;
            // Converged before the tangent (and the floor) was assembled.
            if (measure.force_floor_known)
              log << " (floor " << measure.force_floor << ")";
            else
              log << " (floor not needed)";
            if (measure.at_rest)
              log << "  gap (nothing has moved yet)";
            else
              log << "  gap " << measure.gap << " (floor "
                  << measure.gap_floor << ")";
            log << std::defaultfloat << "  active " << n_active_nodes()
                << "/" << n_contact_nodes() << "  changed " << n_changed
                << '\n';
          }
        if (!std::isfinite(measure.merit))
          {
            failure_reason = "the residual is not finite";
            return false;
          }
        if (converged)
          return true;
        if (it == newton.max_iterations)
          {
            failure_reason = "no convergence in " +
                             std::to_string(newton.max_iterations) +
                             " iterations";
            return false;
          }

        // A slave point in a groove of a faceted master (a master vertex seen
        // from the slave side, where the normal turns by the angle between
        // the segments) has no position with one normal where the residual
        // vanishes: the pairing flips between the two segments at every
        // iteration and Newton cycles. After a few iterations every point
        // keeps its partner (on the segment's extension if need be): the
        // residual is smooth, and the step converges to the state with that
        // pairing. The next step pairs afresh.
        if (it + 1 == hold_pairing_after)
          keep_partners = true;

        if (!solve_linear_system(newton_update))
          {
            final_residual = std::numeric_limits<double>::infinity();
            return false;
          }
        ++iterations;
        // The next iterate without its tangent first when it is expected to
        // converge (see ConvergenceRecord).
        updated             = true;
        update_lifted       = lifting;
        update_from         = final_residual;
        const Assembly next = convergence_record.expects(lifting,
                                                         final_residual,
                                                         newton.tolerance) ?
                                Assembly::residual :
                                Assembly::residual_and_tangent;
        // The update that imposes the boundary increment is taken whole: a
        // fraction of it would leave the boundary short of the load state,
        // and the merit of the state before it does not see the increment.
        // An inverted state is rejected at the next iteration (the load
        // step is then cut).
        if (lifting)
          {
            solution += newton_update;
            set_boundary_target(); // exactly, not up to round-off
            lifting   = false;
            n_changed = assemble_newton_system(accepted_pairing(), next);
            continue;
          }
        double step_length = 1;
        if (!line_search(newton_update, measure, next, n_changed, step_length))
          {
            if (keep_partners)
              return false;
            // No decrease along the update: the pairing is the suspect.
            keep_partners = true;
            n_changed     = assemble_newton_system(accepted_pairing());
            if (newton.verbose)
              log << "      line search failed: pairing held\n";
            continue;
          }
        if (newton.verbose && step_length < 1)
          log << "      line search: step length " << step_length << '\n';
        // The trials followed held partners onto their extensions.
        if (keep_partners)
          n_changed = assemble_newton_system(accepted_pairing(), next);
      }
  }

  // Globalisation of the semi-smooth Newton method: u + a du with a = 1,
  // 1/2, 1/4, ... until the merit |R|^2 decreases (Armijo) and no element is
  // inverted; the system at the accepted state is left assembled. With
  // faceted master surfaces the residual jumps where a contact point
  // crosses a master vertex (its normal turns by the angle between the
  // segments), and a full step can jump back and forth between two
  // pairings forever; the line search stops on the lower side.
  bool
  RingContactProblem::line_search(const Vector<double>  &newton_update,
                                  const ResidualMeasure &before,
                                  const Assembly         assembly,
                                  unsigned int          &n_changed,
                                  double                &step_length)
  {
    constexpr unsigned int max_halvings = 6;
    constexpr double       armijo       = 1e-4;
    const Vector<double>   start        = solution;
    for (unsigned int halving = 0;; ++halving)
      {
        solution = start;
        solution.add(step_length, newton_update);
        n_changed = assemble_newton_system(keep_partners ?
                                             ContactInterface::Pairing::hold :
                                             ContactInterface::Pairing::search,
                                           assembly);
        if (n_inverted == 0)
          {
            const double    tolerance = parameters.newton.tolerance;
            ResidualMeasure trial     = residual_measure();
            // At the round-off floor the merit is noise: take the step.
            const auto accept = [&]() {
              return trial.merit <= (1 - armijo * step_length) * before.merit ||
                     trial.converged(tolerance) || before.converged(tolerance);
            };
            // The floor of the forces, which needs the tangent, may decide.
            if (!accept() && trial.undecided(tolerance))
              {
                assemble_system();
                trial = residual_measure();
              }
            if (accept())
              return true;
          }
        if (halving == max_halvings)
          {
            if (n_inverted > 0)
              return true; // rejected by the Newton loop with its message
            failure_reason = "the line search found no decrease of the "
                             "residual";
            solution       = start;
            return false;
          }
        step_length /= 2;
      }
  }

  // Why a factorization may need so much memory: the contact couples each
  // slave segment to every master segment it faces, and a slave segment
  // facing many (a coarse slave on a fine master) makes a dense block of
  // their unknowns, whose factor fills in.
  std::string
  RingContactProblem::describe_fill_in() const
  {
    std::ostringstream text;
    text << std::setprecision(3);
    for (unsigned int k = 0; k < contacts.size(); ++k)
      {
        const double slave  = contacts[k]->slave_surface().min_segment_length();
        const double master = contacts[k]->master_surface().min_segment_length();
        if (slave > 4 * master)
          text << "; contact pair " << k + 1 << ": the slave surface's "
               << "segments are up to " << slave / master
               << " times longer than the master's, and each couples to "
                  "every master segment it faces (a dense block): make the "
                  "slave the finer surface, or mesh them alike";
      }
    const std::string causes = text.str();
    return causes.empty() ? "; a coarser mesh, or Newton/Linear solver = "
                            "iterative, needs less" :
                            causes;
  }

  // Whether a signal asked the run to stop, on any process (all of them
  // leave their Newton loop at the same iteration).
  bool
  RingContactProblem::stop_requested() const
  {
    const bool here = stop_signal != 0;
    return n_processes > 1 ? Utilities::MPI::logical_or(here, communicator) :
                             here;
  }

  // One step of the load program, cut in halves while Newton fails.
  bool
  RingContactProblem::solve_load_step(const unsigned int step)
  {
    const double t_end = load_program.time(step);
    double       dt    = t_end - current_time;
    unsigned int cuts = 0, total_iterations = 0;
    Timer        wall;
    // Whether the increment being tried starts from the last converged
    // state itself: after a failure from the extrapolated state, the same
    // increment is tried from there before it is cut.
    bool from_converged = false;
    while (current_time < t_end - 1e-12 * std::abs(t_end))
      {
        const double         t_next    = std::min(current_time + dt, t_end);
        const Vector<double> converged = solution;

        // Predictor: extrapolate the last increment when it was of the
        // same kind (pressure only, or rotation only), in the parameter the
        // state is linear in: the pressure of the rings' ramp, the rotation,
        // or else the pseudo-time, in which a general problem's boundary
        // data are written (its load states carry no pressure or rotation:
        // it was never extrapolated).
        const LoadState next  = load_program.state(t_next);
        const LoadState now   = current_load;
        const LoadState prev  = load_program.state(previous_time);
        double          scale = 0;
        if (parameters.newton.extrapolate && current_time > previous_time &&
            !from_converged)
          {
            const double dp0 = now.pressure - prev.pressure,
                         dp1 = next.pressure - now.pressure;
            const double ds0 = now.rotation_elements - prev.rotation_elements,
                         ds1 = next.rotation_elements - now.rotation_elements;
            if (ds0 == 0 && ds1 == 0 && dp0 != 0)
              scale = dp1 / dp0;
            else if (dp0 == 0 && dp1 == 0 && ds0 != 0)
              scale = ds1 / ds0;
            else if (dp0 == 0 && dp1 == 0 && ds0 == 0 && ds1 == 0)
              scale = (t_next - current_time) / (current_time - previous_time);
          }
        if (scale != 0)
          solution.add(scale, converged, -scale, previous_solution);
        unsigned int iterations = 0;
        double       residual   = std::numeric_limits<double>::infinity();
        bool         ok         = false;
        try
          {
            apply_boundary_motion(next);
            ok = solve_newton_step(iterations, residual);
          }
        catch (const BoundaryDataError &e)
          {
            failure_reason = e.what();
          }
        catch (const NonFiniteState &e)
          {
            failure_reason = e.what();
          }
        lifting = false;
        total_iterations += iterations;
        if (ok)
          {
            for (const auto &contact : contacts)
              contact->accept_state(solution);
            previous_solution = converged;
            previous_time     = current_time;
            current_time      = t_next;
            from_converged    = false;
            continue;
          }
        // Failed: back to the last converged state, half the increment.
        solution     = converged;
        current_load = load_program.state(current_time);
        for (const auto &contact : contacts)
          contact->update(solution);
        if (stop_requested())
          {
            log << "Interrupted by a signal in step " << step
                << ": stopping with the last converged state (t = "
                << current_time << ")\n";
            return false;
          }
        // The extrapolation is a guess: a state off the path (a body held
        // by the contact whose first step removed an initial overlap, not
        // in proportion to the load, was extrapolated apart from it) is
        // not a reason to cut the step.
        if (scale != 0)
          {
            from_converged = true;
            log << "  step " << step << ": Newton failed from the extrapolated "
                << "state (" << failure_reason
                << "); trying again from the last converged state\n";
            continue;
          }
        from_converged = false;
        if (cuts == parameters.newton.max_step_cuts)
          {
            log << "Step " << step << ": Newton did not converge after " << cuts
                << " step cuts (" << failure_reason
                << "; last relative residual " << residual
                << " at t = " << t_next << ", increment " << dt
                << "); stopping with the last converged state (t = "
                << current_time << ")\n";
            return false;
          }
        ++cuts;
        dt /= 2;
        log << "  step " << step << ": Newton failed (" << failure_reason
            << "; relative residual " << residual
            << "), cutting the increment to " << dt << '\n';
      }
    postprocess_step(step, total_iterations, cuts, wall.wall_time());
    return true;
  }

  std::vector<types::global_dof_index>
  RingContactProblem::contact_nodes() const
  {
    std::vector<types::global_dof_index> nodes;
    for (const auto &contact : contacts)
      nodes.insert(nodes.end(),
                   contact->multiplier_dofs().begin(),
                   contact->multiplier_dofs().end());
    return nodes;
  }

  unsigned int
  RingContactProblem::n_contact_nodes() const
  {
    unsigned int n = 0;
    for (const auto &contact : contacts)
      n += contact->multiplier_dofs().size();
    return n;
  }

  unsigned int
  RingContactProblem::n_active_nodes() const
  {
    unsigned int n = 0;
    for (const auto &contact : contacts)
      n += contact->n_active();
    return n;
  }

  types::global_dof_index
  RingContactProblem::contact_node_nearest_to(const Point<2> &point) const
  {
    double                  best = std::numeric_limits<double>::infinity();
    types::global_dof_index node = numbers::invalid_dof_index;
    for (const auto &contact : contacts)
      {
        double     distance = 0;
        const auto nearest =
          contact->multiplier_dof_nearest_to(point, &distance);
        if (distance < best)
          {
            best = distance;
            node = nearest;
          }
      }
    return node;
  }

  double
  RingContactProblem::reported_pressure(const types::global_dof_index dof) const
  {
    const double lambda = solution(dof);
    return parameters.contact.reported_pressure == PressureMeasure::cauchy ?
             lambda :
             lambda * contact_of(dof).stretch_at(dof);
  }

  // The quantities after a step: the pressure at the probe (node A of
  // SSNP152) against the scenario's reference, the L2 error over the slave
  // surface, extreme pressures, and the quantities a general problem checks.
  void
  RingContactProblem::postprocess_step(const unsigned int step,
                                       const unsigned int iterations,
                                       const unsigned int cuts,
                                       const double       wall_time)
  {
    TimerOutput::Scope    t(timer, "postprocessing");
    const PressureMeasure measure = parameters.contact.reported_pressure;
    HistoryRow            row;
    row.scheme         = scheme.name();
    row.step           = step;
    row.time           = current_time;
    row.load_factor    = current_load.pressure;
    row.rotation       = current_load.rotation_elements;
    row.pressure_A     = reported_pressure(probe_dof);
    row.analytic       = scenario->reference_pressure(current_load);
    row.relative_error = (row.pressure_A - row.analytic) / row.analytic;
    row.l2_relative_error =
      contacts[0]->l2_relative_error(solution, row.analytic, measure);
    row.pressure_min = std::numeric_limits<double>::max();
    row.pressure_max = -std::numeric_limits<double>::max();
    for (const auto dof : contact_nodes())
      {
        row.pressure_min = std::min(row.pressure_min, reported_pressure(dof));
        row.pressure_max = std::max(row.pressure_max, reported_pressure(dof));
      }
    row.newton_iterations = iterations;
    row.step_cuts         = cuts;
    row.active_nodes      = n_active_nodes();
    row.wall_time         = wall_time;
    for (const auto &check : parameters.problem.checks)
      row.quantities.push_back(checked_quantity(check));
    // Friction: the tangential traction at the probe (Cauchy, the
    // multiplier itself) and the number of sliding nodes.
    const bool friction = parameters.contact.friction_coefficient > 0;
    if (friction)
      {
        row.quantities.push_back(
          solution(contact_of(probe_dof).tangential_dof(probe_dof)));
        unsigned int n_slipping = 0;
        for (const auto &contact : contacts)
          n_slipping += contact->n_slipping();
        row.quantities.push_back(n_slipping);
      }
    // A state that fails an invariant is reported, not recorded.
    const bool balanced = measure_balance_of_forces(row);
    if (balanced)
      history_rows.push_back(row);

    if (parameters.output.print_steps && parameters.general())
      {
        log << "Step " << std::setw(3) << step << "  t " << std::setw(6)
            << std::setprecision(4) << row.time << "  Newton " << iterations
            << (cuts > 0 ? " (" + std::to_string(cuts) + " cuts)" : "")
            << "  active " << row.active_nodes << "  p_probe "
            << std::setprecision(7) << row.pressure_A;
        for (unsigned int k = 0; k < parameters.problem.checks.size(); ++k)
          log << "  " << parameters.problem.checks[k].description() << " "
              << std::setprecision(7) << row.quantities[k];
      }
    else if (parameters.output.print_steps)
      log << "Step " << std::setw(3) << step << "  t " << std::setw(6)
          << std::setprecision(4) << row.time << "  p " << std::setw(10)
          << std::setprecision(6) << row.load_factor << "  s " << std::setw(5)
          << std::setprecision(3) << row.rotation << "  Newton " << iterations
          << (cuts > 0 ? " (" + std::to_string(cuts) + " cuts)" : "")
          << "  p_A " << std::setprecision(7) << std::setw(12) << row.pressure_A
          << "  analytic " << std::setw(12) << row.analytic;
    // Errors relative to a zero analytic pressure (an input as soft as
    // E = 1e-300 gives one) have no meaning: said so, not inf or nan.
    if (parameters.output.print_steps && !parameters.general() &&
        (!std::isfinite(row.relative_error) ||
         !std::isfinite(row.l2_relative_error)))
      log << "  error     n/a  L2    n/a";
    else if (parameters.output.print_steps && !parameters.general())
      log << "  error " << std::fixed << std::setprecision(3) << std::setw(7)
          << 100 * row.relative_error << "%  L2 " << std::setw(6)
          << 100 * row.l2_relative_error << '%' << std::defaultfloat;
    if (parameters.output.print_steps && friction)
      log << "  q_A " << std::setprecision(7) << row.quantities.end()[-2]
          << "  sliding " << row.quantities.back();
    // The invariants: the larger of the equilibrium and the action-reaction
    // errors (equilibrium.h).
    if (parameters.output.print_steps)
      log << "  balance " << std::setprecision(2)
          << (std::isnan(row.action_reaction_error) ?
                row.equilibrium_error :
                std::max(row.equilibrium_error, row.action_reaction_error))
          << std::setprecision(6) << '\n';
    if (!balanced)
      throw UntrustedState(unbalanced_forces);

    // A converged state with every contact node open under a load that
    // closes the contact (analytic pressure > 0) is another solution of the
    // discrete problem, not the one sought: say so, it is otherwise silent.
    if (row.analytic > 0 && row.active_nodes == 0)
      log << "Warning: step " << step
          << ": Newton converged with the contact open at every node, while "
             "the analytic solution is closed contact (pressure "
          << row.analytic << ")\n";

    const unsigned int interval = parameters.output.vtu_interval;
    if (interval > 0 &&
        (step % interval == 0 || step == load_program.n_steps()))
      output_results(step);
  }

  // The invariants of the converged state (equilibrium.h): each body in
  // equilibrium, and each contact pair's action equal to its reaction, both
  // relative to the forces involved. Recorded in the history; a warning
  // beyond what the Newton tolerance leaves, and false (the state cannot be
  // trusted: its reason in unbalanced_forces) beyond 1e-3.
  bool
  RingContactProblem::measure_balance_of_forces(HistoryRow &row)
  {
    NodalForces forces;
    forces.internal = internal_force;
    forces.applied  = external_force;
    forces.applied *= -1; // external_force is the loads' part of R
    forces.supported = supported;
    // As the Newton loop's floor of the forces (residual_measure()).
    forces.round_off = tangent_magnitude;
    forces.round_off *= 10 * std::numeric_limits<double>::epsilon();
    std::vector<std::pair<types::material_id, types::material_id>> pairs;
    for (const auto &contact : contacts)
      {
        forces.contact.emplace_back(dof_handler.n_dofs());
        contact->add_forces(solution, forces.contact.back());
        pairs.emplace_back(
          contact->slave_surface().segments().front().cell->material_id(),
          contact->master_surface().segments().front().cell->material_id());
      }
    std::vector<std::pair<types::material_id, std::string>> names;
    for (const Body &body : bodies)
      names.emplace_back(body.material_id, body.name);
    // A cyclic sector's master copies carry the master's forces turned:
    // their sum is not the slave's.
    const Balance balance =
      measure_balance(dof_handler, forces, names, pairs, cyclic_pairs.empty());
    row.equilibrium_error     = balance.worst_body();
    row.action_reaction_error = balance.worst_pair();

    constexpr double warn_body = 1e-6, warn_pair = 1e-8, fail = 1e-3;
    std::ostringstream what;
    what << std::setprecision(3);
    bool failed = false;
    for (unsigned int b = 0; b < balance.bodies.size(); ++b)
      {
        const auto &[name, error] = balance.bodies[b];
        if (!balance.beyond_round_off[b] || error <= warn_body)
          continue;
        what << (what.tellp() > 0 ? "; " : "") << name
             << " is out of equilibrium by " << error
             << " of its forces (applied loads, reactions and contact)";
        failed = failed || !(error <= fail);
      }
    for (unsigned int k = 0; k < balance.pairs.size(); ++k)
      if (!std::isnan(balance.pairs[k]) && !(balance.pairs[k] <= warn_pair))
        what << (what.tellp() > 0 ? "; " : "") << "contact pair " << k + 1
             << "'s forces on its two bodies differ by " << balance.pairs[k]
             << " of their magnitude";
    if (what.tellp() == 0)
      return true;
    const bool trusted = !failed && !(row.action_reaction_error > fail);
    if (trusted)
      {
        log << "Warning: step " << row.step << ": " << what.str() << '\n';
        return true;
      }
    unbalanced_forces = "step " + std::to_string(row.step) + ": " +
                        what.str() + ": the state cannot be trusted";
    return false;
  }

  // A general problem's checked quantity at the current (converged) state.
  double
  RingContactProblem::checked_quantity(
    const ProblemCheckParameters &check) const
  {
    // The pair whose slave surface is nearest to the point.
    const auto            nearest = contact_node_nearest_to(check.point);
    const ContactSurface &slave   = contact_of(nearest).slave_surface();
    // A traction is read at a contact node: the point must be on a slave
    // surface (the nearest node within a segment of it), not anywhere.
    if (check.quantity == ProblemQuantity::contact_pressure ||
        check.quantity == ProblemQuantity::tangential_traction)
      {
        double distance = 0, longest = 0;
        contact_of(nearest).multiplier_dof_nearest_to(check.point, &distance);
        for (unsigned int k = 0; k < slave.segments().size(); ++k)
          longest = std::max(longest,
                             slave.reference_point(k, 0).x.distance(
                               slave.reference_point(k, 1).x));
        if (!(distance <= longest))
          {
            std::ostringstream where;
            where << check.point[0] << ", " << check.point[1] << ") is "
                  << distance;
            throw std::runtime_error(
              check.name + ": the point (" + where.str() +
              " from the nearest contact node, farther than a segment of "
              "its slave surface: give a point on a slave surface");
          }
      }
    switch (check.quantity)
      {
        case ProblemQuantity::contact_pressure:
          return reported_pressure(nearest);

        case ProblemQuantity::tangential_traction:
          {
            const auto dof = contact_of(nearest).tangential_dof(nearest);
            return dof == numbers::invalid_dof_index ? 0.0 : solution(dof);
          }

          // The farthest slave node in contact (active, with a positive
          // pressure) from the point, or, where a node in contact is next to
          // an open one on a segment, the midpoint between the two: the edge
          // of the contact to half a node spacing. (An open node's pressure
          // is zero to the linear solver's accuracy, of either sign.)
        case ProblemQuantity::contact_half_width:
          {
            double              width = 0;
            const auto         &nodes = slave.multiplier_nodes();
            std::vector<double> t(nodes.begin(), nodes.end());
            std::sort(t.begin(), t.end());
            for (unsigned int s = 0; s < slave.segments().size(); ++s)
              {
                const auto &segment = slave.segments()[s];
                if (segment.is_copy)
                  continue;
                const auto dof_at = [&](const double t_node) {
                  for (unsigned int k = 0; k < nodes.size(); ++k)
                    if (nodes[k] == t_node)
                      return segment.multiplier_dofs[k];
                  return segment.multiplier_dofs[0];
                };
                for (unsigned int k = 0; k < t.size(); ++k)
                  {
                    const Point<2> x = slave.reference_point(s, t[k]).x;
                    const auto     in_contact =
                      [&](const types::global_dof_index dof) {
                        return contact_of(dof).is_active(dof) &&
                               reported_pressure(dof) > 0;
                      };
                    const bool in = in_contact(dof_at(t[k]));
                    if (in)
                      width = std::max(width, x.distance(check.point));
                    for (const int side : {-1, 1})
                      {
                        const int j = static_cast<int>(k) + side;
                        if (!in || j < 0 || j >= static_cast<int>(t.size()))
                          continue;
                        if (in_contact(dof_at(t[j])))
                          continue;
                        const Point<2> edge =
                          slave.reference_point(s, 0.5 * (t[k] + t[j])).x;
                        width = std::max(width, edge.distance(check.point));
                      }
                  }
              }
            return width;
          }

          // The sum of the nodal forces of the boundary's unknowns: the
          // internal force less the contact's (at a node the boundary
          // shares with a contact surface, the other body pushes too),
          // which at a converged state balances what acts there from
          // outside (a support's reaction, an applied load).
        case ProblemQuantity::resultant_force_x:
        case ProblemQuantity::resultant_force_y:
          {
            if (!boundary_resultants)
              {
                // The directions each boundary's displacement holds.
                std::vector<SupportCondition> supports;
                for (const auto &condition :
                     parameters.problem.boundary_conditions)
                  if (condition.type == BoundaryConditionType::displacement)
                    supports.push_back(
                      {static_cast<types::boundary_id>(condition.boundary_id),
                       condition.normal ? SupportCondition::Kind::normal :
                       condition.polar  ? SupportCondition::Kind::polar :
                                          SupportCondition::Kind::cartesian,
                       condition.components});
                boundary_resultants =
                  std::make_unique<BoundaryResultants>(dof_handler,
                                                       mapping_collection,
                                                       supports);
              }
            NodalForces forces;
            forces.internal = internal_force;
            forces.applied  = external_force;
            forces.applied *= -1;
            forces.supported = supported;
            for (const auto &contact : contacts)
              {
                forces.contact.emplace_back(dof_handler.n_dofs());
                contact->add_forces(solution, forces.contact.back());
              }
            const Tensor<1, 2> force = boundary_resultants->resultant(
              check.boundary_id, forces.reactions(), applied_resultant);
            return check.quantity == ProblemQuantity::resultant_force_x ?
                     force[0] :
                     force[1];
          }

        case ProblemQuantity::displacement_x:
        case ProblemQuantity::displacement_y:
          {
            Vector<double> value(Components::n_components);
            try
              {
                VectorTools::point_value(mapping_collection,
                                         dof_handler,
                                         solution,
                                         check.point,
                                         value);
              }
            catch (...)
              {
                std::ostringstream where;
                where << check.point[0] << ", " << check.point[1];
                throw std::runtime_error(check.name + ": the point (" +
                                         where.str() +
                                         ") is in no cell of the mesh");
              }
            return value(check.quantity == ProblemQuantity::displacement_x ?
                           Components::ux :
                           Components::uy);
          }
        case ProblemQuantity::none:
          break;
      }
    return std::nan("");
  }

  void
  RingContactProblem::output_results(const unsigned int step)
  {
    TimerOutput::Scope t(timer, "output");
    if (!vtu_writer)
      {
        const unsigned int subdivisions =
          parameters.output.vtu_subdivisions > 0 ?
            parameters.output.vtu_subdivisions :
            std::max(parameters.finite_elements.mapping_degree,
                     std::max_element(bodies.begin(),
                                      bodies.end(),
                                      [](const Body &a, const Body &b) {
                                        return a.degree < b.degree;
                                      })
                       ->degree);
        vtu_writer = std::make_unique<VtuWriter>(parameters.output.directory,
                                                 scheme.tag(),
                                                 subdivisions,
                                                 communicator);
      }
    Vector<double> nodal_gap(dof_handler.n_dofs());
    for (const auto &contact : contacts)
      for (const auto dof : contact->multiplier_dofs())
        nodal_gap(dof) = contact->gap_at(dof, solution);
    std::set<types::boundary_id> slave_ids;
    for (const auto &[slave, master] : parameters.contact_pairs())
      slave_ids.insert(slave);
    vtu_writer->write(dof_handler,
                      mapping_collection,
                      solution,
                      nodal_gap,
                      materials,
                      slave_ids,
                      step,
                      current_time);
  }

  bool
  RingContactProblem::run()
  {
    setup();
    {
      std::vector<double> times;
      for (unsigned int step = 1; step <= load_program.n_steps(); ++step)
        times.push_back(load_program.time(step));
      scenario->check_boundary_data(dof_handler, mapping_collection, times);
    }
    report_rigid_body_modes();
    log << "Scheme " << scheme.name() << ": " << triangulation.n_active_cells()
        << " cells, " << dof_handler.n_dofs() << " unknowns, "
        << n_contact_nodes() << " contact pressure nodes, "
        << load_program.n_steps() << " steps\n";
    report_initial_interpenetration();
    // Every checked quantity can be evaluated (a point outside the mesh is
    // an error now, not after the first step has been solved).
    for (const auto &check : parameters.problem.checks)
      checked_quantity(check);
    if (start_observer)
      start_observer();
    // The undeformed state, step 0: the start of every animation.
    if (parameters.output.vtu_interval > 0)
      output_results(0);
    bool ok = true;
    for (unsigned int step = 1; step <= load_program.n_steps() && ok; ++step)
      {
        ok = solve_load_step(step);
        if (ok && step_observer && !step_observer(history_rows.back()))
          break;
      }
    if (!ok && parameters.output.vtu_interval > 0)
      output_results(history_rows.empty() ? 0 : history_rows.back().step);
    if (system->iterative() && linear_solves > 0)
      log << "GMRES: " << linear_iterations << " iterations in "
          << linear_solves << " solves (" << std::fixed << std::setprecision(1)
          << double(linear_iterations) / linear_solves << " per solve)\n"
          << std::defaultfloat;
    // The direct solver's work, with the timing summary.
    else if (const auto done = system->direct_statistics();
             parameters.output.print_timing && done.factorizations > 0)
      log << system->direct_solver_name() << ": " << done.factorizations
          << (done.factorizations == 1 ? " factorization, " :
                                         " factorizations, ")
          << done.analyses
          << (done.analyses == 1 ? " analysis, " : " analyses, ")
          << std::setprecision(3) << done.flops << " flops in the last\n"
          << std::defaultfloat << std::setprecision(6);
    if (parameters.output.print_timing)
      timer.print_summary();
    return ok;
  }
} // namespace RingContact
