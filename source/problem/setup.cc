// @sect3{Set-up: the mesh, the finite elements, the contact interfaces}
//
// What run() needs before the first step: the scenario's mesh, checked;
// the finite elements of each body and of the slave surfaces' layers, and
// their degrees of freedom (numbered process by process under MPI); the
// linear solver; one contact interface per pair; the constraints
// (constraints.cc); and the sparsity pattern of the tangent, the bulk's
// couplings and those of the current contact pairs.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/numerics/rtree.h>

#include <ring_contact/base/components.h>
#include <ring_contact/base/dimension.h>
#include <ring_contact/base/utilities.h>
#include <ring_contact/problem/contact_problem.h>

#include <algorithm>
#include <iomanip>
#include <set>
#include <sstream>

namespace RingContact
{
  // The order is forced by what each piece needs: the elements need the
  // mesh (which boundary belongs to which body), the constraints need the
  // contact interfaces (which multipliers lie on a slave surface, the
  // cyclic node pairs), and the sparsity pattern needs both the
  // constraints (constrained unknowns get no couplings) and a first
  // pairing: the contact couples each slave segment to the master segments
  // its points are paired with, here those of the unloaded state. Later
  // pairings that leave this pattern get a new one (assembly.cc).
  template <int dim>
  void
  ContactProblem<dim>::setup()
  {
    make_grid();
    // A sector's two sides are tied node to node (cyclic_symmetry.h):
    // refined apart, their nodes would no longer face each other.
    if (parameters.refinement.adaptive_cycles > 0 && scenario->cyclic_sector())
      throw ParameterError("Mesh refinement",
                           "Adaptive cycles",
                           "Mesh refinement/Adaptive cycles: adaptive "
                           "refinement needs the whole rings, not a sector "
                           "(cyclic symmetry ties the sides' nodes, which "
                           "refinement would part)");
    setup_system();
    for (const auto &contact : contacts)
      contact->update(solution);
    make_sparsity_pattern();
  }

  // @sect4{The mesh}
  //
  // The scenario's mesh, with its geometry and its checks; then the body of
  // each boundary (the slave bodies get the multiplier), and the check that
  // the bodies share no vertex.
  //
  // The mesh arrives with gmsh's physical tags as ids: a cell's material id
  // names its body, a boundary face's id its boundary (the rings' 200 to
  // 500, or a general problem's tags). A boundary tag belongs to the body
  // of the cells along it; the contact pairs are given as pairs of
  // boundary tags, and this map turns them into pairs of bodies.
  template <int dim>
  void
  ContactProblem<dim>::make_grid()
  {
    TimerOutput::Scope t(timer, "mesh");
    scenario->create_mesh(triangulation);
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          body_of_boundary[face->boundary_id()] = cell->material_id();
    // The bodies share no vertex: each is its own mesh, and they meet
    // through the contact only. A mesh that joins two (one gmsh line as
    // the boundary of both) would glue them there, silently: deal.II
    // numbers the unknowns of a vertex once, whichever cells share it, and
    // such a mesh was solved with the bodies glued, without a word, until
    // this check (found by probing). Each vertex records the first body
    // that uses it; a second body is the error.
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
                for (const Body<dim> &body : bodies)
                  if (body.material_id == m)
                    return body.name + " (material " + std::to_string(m) + ")";
                return "material " + std::to_string(m);
              };
              std::ostringstream where;
              where << cell->vertex(v)[0] << ", " << cell->vertex(v)[1];
              throw std::runtime_error(
                "the mesh joins " + name(id) + " and " +
                name(cell->material_id()) + " at the vertex (" + where.str() +
                "): bodies meet through their contact surfaces only, each "
                "meshed on its own (in gmsh, points and lines of its own "
                "for each body, as meshes/two_blocks.geo)");
            }
        }
  }

  // The cells among the processes, by METIS on the graph of the cells that
  // share a face, with an edge across each contact interface too (from
  // each slave face to the master face nearest to it): the bodies share no
  // face, and without those edges METIS gives each process whole bodies,
  // one of them all the contact work (the slave ring of the rings on one
  // process and the master on the other). With them the cut runs across the
  // interface and each process gets its share of both. A cell with a face
  // on a slave surface weighs as much as five others: its contact points
  // cost that much (measured at 640 x 48, Gauss 2).
  template <int dim>
  void
  ContactProblem<dim>::partition_cells()
  {
    // The face graph joins the cells within each body, every cell weighing
    // one; the edges across the interfaces and the slave cells' weights are
    // added below, pair by pair.
    DynamicSparsityPattern graph;
    GridTools::get_face_connectivity_of_cells(triangulation, graph);
    std::vector<unsigned int> weights(triangulation.n_active_cells(), 1);
    using FaceCentre = std::pair<Point<dim>, unsigned int>; // centre, cell
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
        // The nearest master face by the centres of the reference faces:
        // the partition is made once, before any motion, and only has to
        // put facing cells near each other. METIS takes an undirected
        // graph, so each edge goes in both directions.
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

  // @sect4{The finite elements and their degrees of freedom}
  //
  // One FESystem per body: FE_Q(p)^2 for the displacement and FE_Nothing
  // for the contact pressure; and one more on the layer of the slave body's
  // cells with a face on the slave surface, with FE_Q(q) for the pressure
  // (its values off the slave surface, on the layer's inner faces, are
  // constrained to zero). The pressure has unknowns along the slave surface
  // only: with FE_Q(q) on the whole slave ring, a fifth of the unknowns of
  // the rings at 640 x 48 were zeros inside it (800 -> 720 unknowns on the
  // seed mesh, 156 800 -> 126 720 at 640 x 48). The displacement elements
  // of the layer and of the rest of its body are the same FE_Q(p),
  // continuous across (deal.II's hp identities); the bodies share no vertex.
  template <int dim>
  void
  ContactProblem<dim>::setup_system()
  {
    TimerOutput::Scope t(timer, "setup");
    make_finite_elements();
    distribute_dofs();
    make_linear_system();
    make_contact_interfaces();

    solution.reinit(dof_handler.n_dofs());
    previous_solution.reinit(dof_handler.n_dofs());
    internal_force.reinit(dof_handler.n_dofs());
    external_force.reinit(dof_handler.n_dofs());
    residual_magnitude.reinit(dof_handler.n_dofs());

    make_constraints();
  }

  // The element of a body, or of its slave layer when `layer` is true.
  // Every FESystem has the same four components in the same order (u_x,
  // u_y, the pressure, the tangential traction; components.h), so that one
  // DoFHandler and one component mask reach them on every cell; only the
  // base elements differ.
  template <int dim>
  void
  ContactProblem<dim>::make_finite_elements()
  {
    const auto &fe          = parameters.finite_elements;
    const auto  add_element = [&](const Body<dim> &body, const bool layer) {
      const unsigned int degree = body.degree;
      // The tangential traction: as the pressure with friction; without,
      // FE_Nothing, which adds no unknown. A frictionless run then has the
      // same unknowns, numbering and digits as before friction existed.
      const std::unique_ptr<FiniteElement<dim>> tangential =
        parameters.contact.frictional() ?
           std::unique_ptr<FiniteElement<dim>>(
            std::make_unique<FE_Q<dim>>(fe.multiplier_degree)) :
           std::make_unique<FE_Nothing<dim>>();
      // The multiplier's degree q is at most the slave's displacement
      // degree (the scenario checks it): a linear multiplier against
      // quadratic displacements satisfies the inf-sup (LBB) condition,
      // where a multiplier as rich as a quadratic slave's displacement
      // would not.
      if (layer)
        fe_collection.push_back(FESystem<dim>(FE_Q<dim>(degree),
                                              dim,
                                              FE_Q<dim>(fe.multiplier_degree),
                                              1,
                                              *tangential,
                                              1));
      else
        fe_collection.push_back(FESystem<dim>(
          FE_Q<dim>(degree), dim, FE_Nothing<dim>(), 1, FE_Nothing<dim>(), 1));
      // (p+1) x (p+1) Gauss points are the full rule; p x p is
      // the reduced integration of modelisation H (Code_Aster's
      // C_PLAN_SI: 2 x 2 points on Q2), whose zero-energy modes the test
      // reduced_integration looks at. The layer takes its body's rule and
      // mapping: it is part of that body, only its multiplier differs.
      q_collection.push_back(
        QGauss<dim>(fe.reduced_integration ? degree : degree + 1));
      // One mapping per body: with Mapping degree = 0 each body takes its
      // displacement degree, a linear ring faceted and a quadratic one
      // curved, as the original's meshes are.
      mapping_collection.push_back(MappingQ<dim>(body.mapping_degree));
      body_of_fe_index.push_back(fe_index_of.at(body.material_id));
    };
    for (const Body<dim> &body : bodies)
      add_element(body, false);
    // A layer element for each slave body, not for each pair: a body that
    // is the slave of two pairs (the middle block of three) has one layer,
    // and its multiplier nodes belong to the pair of their surface.
    for (const auto &[slave, master] : parameters.contact_pairs())
      {
        const auto body = body_of_boundary.at(slave);
        if (layer_of.count(body) == 0)
          {
            layer_of[body] = fe_collection.size();
            add_element(bodies[fe_index_of.at(body)], true);
          }
      }
  }

  // Each cell takes its body's element, or the layer's where it has a face
  // on a slave surface. Several processes: the cells partitioned (the same
  // partition on every process), the unknowns numbered process by process,
  // each process owning those of its cells (step-17).
  template <int dim>
  void
  ContactProblem<dim>::distribute_dofs()
  {
    std::set<types::boundary_id> slave_ids;
    for (const auto &[slave, master] : parameters.contact_pairs())
      slave_ids.insert(slave);
    // A cell that touches the slave surface at a vertex only keeps its
    // body's element: the multiplier is a trace on the surface's faces.
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
    // The partition comes first: subdomain_wise() numbers the unknowns by
    // the cells' subdomain ids, so that each process owns one contiguous
    // range of rows of the distributed matrix.
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
  }

  // @sect4{The linear solver}
  //
  // The tangent's solver (LinearSystem): direct by default, UMFPACK on one
  // process and MUMPS on several, or GMRES with a block preconditioner,
  // which needs to know the kind of each unknown and where it sits.
  template <int dim>
  void
  ContactProblem<dim>::make_linear_system()
  {
    system = std::make_unique<LinearSystem>(communicator,
                                            parameters.newton.linear_solver,
                                            parameters.newton.linear_tolerance);
    // A factorization of more than a gigabyte is said before it runs, with
    // what makes it large, once per size. The estimate comes from UMFPACK's
    // analysis, which is redone for every new sparsity pattern (every new
    // pairing that leaves the old one): only an estimate twice as large as
    // the last one said is said again.
    system->estimate_observer = [this](const double bytes) {
      constexpr double gigabyte = 1e9;
      if (bytes > gigabyte && bytes > 2 * largest_estimate_said)
        {
          largest_estimate_said = bytes;
          log << "Note: the direct solver's factorization will need about "
              << std::setprecision(3) << bytes / gigabyte
              << " GB (UMFPACK's estimate";
          // Beside it the estimate the memory check made before the
          // pattern was built, so that the two can be compared.
          if (system->estimated_factorization_memory() > 0)
            log << "; " << system->estimated_factorization_memory() / gigabyte
                << " GB estimated from the couplings";
          log << ") and take long" << describe_fill_in() << '\n'
              << std::setprecision(6);
        }
    };
    // ML's smoothed aggregation on the displacement block is given the
    // rigid-body modes, the rotation's from the unknowns' positions below.
    if (system->iterative())
      {
        // The iterative solver's blocks: each displacement component, and
        // the multipliers (pressure and tangential traction).
        std::vector<BlockSolver::Kind> kinds(dof_handler.n_dofs(),
                                             BlockSolver::multiplier);
        for (unsigned int d = 0; d < dim; ++d)
          for (const auto i : DoFTools::extract_dofs(
                 dof_handler,
                 Components::displacement_mask<dim>(d == 0, d == 1, d == 2)))
            kinds[i] =
              static_cast<BlockSolver::Kind>(BlockSolver::displacement_x + d);
        // The reference position of each displacement unknown, through
        // the bodies' mappings; the multipliers keep the origin, which the
        // preconditioner does not read.
        std::map<types::global_dof_index, Point<dim>> support_points;
        DoFTools::map_dofs_to_support_points(
          mapping_collection,
          dof_handler,
          support_points,
          Components::displacement_mask<dim>());
        std::vector<Point<dim>> positions(dof_handler.n_dofs());
        for (const auto &[i, point] : support_points)
          positions[i] = point;
        system->set_kinds(kinds, positions);
      }
  }

  // @sect4{The contact interfaces}
  //
  // Cyclic symmetry: the nodes of the sector's two sides, and the master
  // surface continued far enough for the slave's motion. Then one interface
  // per pair, each with the constants of subsection Contact and its own
  // surfaces; geometrically linear only when no body moves to a current
  // configuration of its own.
  template <int dim>
  void
  ContactProblem<dim>::make_contact_interfaces()
  {
    // deal.II's make_periodicity_constraints() pairs faces by a
    // translation; the sides of a sector are images of each other by a
    // rotation, so their nodes are paired here by their support points
    // turned through the sector angle. The master window (how far the
    // rotated copies of the master surface reach on each side) leans
    // towards the side the slave slides to, so that its nodes stay inside.
    // (Cyclic symmetry is 2D: a 3D scenario has no sector.)
    if constexpr (dim == 2)
      if (const auto cyclic = scenario->cyclic_sector())
        {
          sector.angle = cyclic->angle;
          CyclicSymmetry::set_master_window(sector,
                                            cyclic->sector_elements,
                                            cyclic->elements_around,
                                            cyclic->slave_rotation);
          cyclic_pairs = CyclicSymmetry::find_node_pairs(dof_handler,
                                                         mapping_collection,
                                                         sector.angle,
                                                         cyclic->start_side,
                                                         cyclic->end_side);
          sector.multiplier_twins =
            CyclicSymmetry::multiplier_pairs(cyclic_pairs);
        }

    // Small strain means geometrically linear throughout: pairing, normal
    // and length element of the reference configuration, a gap linear in
    // the displacement. That is only consistent when no body has a current
    // configuration of its own; one body in finite strain makes every
    // pair's contact follow the current configuration.
    const bool geometrically_linear =
      std::all_of(bodies.begin(), bodies.end(), [](const Body<dim> &body) {
        return body.material.geometrically_linear;
      });
    contacts.clear();
    pair_of_node.clear();
    for (const auto &[slave, master] : parameters.contact_pairs())
      {
        contacts.push_back(
          make_contact_interface(slave, master, scheme, geometrically_linear));
        // In 3D the faces are bilinear or biquadratic (FaceContact refuses
        // others, and the nodal scheme on biquadratic ones) and every 3D
        // scheme integrates them as its own rule says.
        if constexpr (dim == 2)
          {
            refuse_slave_corners(contacts.back()->slave_surface(), slave);
            // Every scheme of the file suits this pair's surfaces: known now,
            // not after the schemes listed before it have run. A rule must
            // integrate the surfaces' shape functions exactly (the contact
            // patch test): segment-based 1 on quadratic rings once failed only
            // after the schemes before it in the list had run, and without
            // naming the entry. The degree is that of the richer surface.
            const unsigned int surface_degree =
              std::max(
                contacts.back()->slave_surface().displacement_basis().size(),
                contacts.back()->master_surface().displacement_basis().size()) -
              1;
            for (const auto &other : parameters.contact.schemes)
              try
                {
                  contact_quadrature(
                    other,
                    surface_degree,
                    parameters.finite_elements.multiplier_degree);
                }
              catch (const std::exception &e)
                {
                  // Named with the file and line that list it (driver/run.cc).
                  throw ParameterError("Contact",
                                       "Integration schemes",
                                       "Contact/Integration schemes: " +
                                         one_line_message(e));
                }
          }
        // Each multiplier node belongs to one pair (two pairs' slave
        // surfaces may not share a vertex: the mesh checks refuse it), which
        // answers contact_of() and keeps the node free in
        // add_constraints(); cyclic twins are included.
        for (const auto node : contacts.back()->nodes().all_dofs())
          pair_of_node[node] = contacts.size() - 1;
        for (const auto node : contacts.back()->nodes().tangential_dofs)
          pair_of_node[node] = contacts.size() - 1;
      }
  }

  // A slave surface that turns sharply at a node: that node's pressure is one
  // unknown for both faces, and its weighted gap the mean of the gaps along
  // both. Where one face is pressed and the other turns away (a block's base
  // and its side tagged together), the side's gaps open the node while the
  // corner penetrates, and the pressure beside it is wrong without a word
  // (doc/validation.md, "Silent wrong answers"). A curved surface turns by
  // its segments' angle, 360 / n degrees for n segments around a circle:
  // the limit of 45 degrees admits a circle of 8 segments or more (the
  // cyclic test's 12 turn by 30), and refuses a block's corner (90) and a
  // wedge's. The margin keeps an octagon's round-off on the right side.
  template <int dim>
  void
  ContactProblem<dim>::refuse_slave_corners(
    const ContactSurface    &slave,
    const types::boundary_id slave_id) const
  {
    const auto [turn, corner] = slave.sharpest_turn();
    const double degrees      = turn * 180 / numbers::PI;
    if (degrees <= 45 + 1e-6)
      return;
    std::ostringstream message;
    message << std::setprecision(3) << "the slave surface (boundary "
            << slave_id << ") has a corner: it turns by " << degrees
            << " degrees at (" << corner[0] << ", " << corner[1]
            << "), where the node's one contact pressure would hold both "
               "faces and average their gaps, so that it could penetrate "
               "while open; give the faces on either side of the corner "
               "tags of their own and make only the face that meets the "
               "master the slave (or one contact pair per face), or mesh a "
               "rounded corner with segments that turn by at most 45 degrees "
               "(a circle: 8 segments around it or more, or curved cells, "
               "Mapping degree 2)";
    throw std::runtime_error(message.str());
  }

  // One pair's interface under `scheme`. Every pair shares subsection
  // Contact's schemes and constants; only its surfaces are its own. The
  // automatic complementarity constant c = E / h takes the stiffer body's
  // modulus; c decides the active set only, not the converged solution.
  // Also called for the diagnostics before the first step, which compare a
  // point-wise scheme's load transfer with the mortar one's on the same
  // surfaces (diagnostics/surfaces_at_rest.h).
  template <int dim>
  std::unique_ptr<ContactInterface<dim>>
  ContactProblem<dim>::make_contact_interface(
    const types::boundary_id slave,
    const types::boundary_id master,
    const IntegrationScheme &scheme,
    const bool               geometrically_linear) const
  {
    ContactParameters pair_parameters  = parameters.contact;
    pair_parameters.slave_boundary_id  = slave;
    pair_parameters.master_boundary_id = master;
    const Body<dim> &slave_body =
      bodies[fe_index_of.at(body_of_boundary.at(slave))];
    const Body<dim> &master_body =
      bodies[fe_index_of.at(body_of_boundary.at(master))];
    if constexpr (dim == 3)
      return std::make_unique<ContactInterface<dim>>(
        dof_handler,
        pair_parameters,
        scheme,
        std::max(slave_body.material.youngs_modulus,
                 master_body.material.youngs_modulus),
        geometrically_linear,
        &mapping_collection);
    else
      return std::make_unique<ContactInterface<dim>>(
        dof_handler,
        pair_parameters,
        scheme,
        slave_body.mapping_degree,
        master_body.mapping_degree,
        std::max(slave_body.material.youngs_modulus,
                 master_body.material.youngs_modulus),
        geometrically_linear,
        sector);
  }

  // The bulk couplings, and those of the current contact pairs.
  //
  // Called at the set-up and again whenever a pairing reaches master
  // segments outside the pattern (assemble_newton_system()): the contact
  // couplings are those of the pairs and their neighbours, so that small
  // slips need no new pattern, and a new pattern costs a new symbolic
  // analysis of the direct solver.
  template <int dim>
  void
  ContactProblem<dim>::make_sparsity_pattern()
  {
    // This process's cells; the contact couplings are few and the same on
    // every process. The couplings of constrained unknowns are left out
    // (keep_constrained_dofs = false): AffineConstraints condenses them
    // away in the assembly, and dropping them made UMFPACK much faster
    // (doc/validation.md, "Time and memory behind the code's choices").
    system->release();
    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(
      dof_handler, dsp, constraints, false, this_process);
    // The contact's blocks, each all with all, are judged before they join
    // the pattern: a coarse slave on a fine master makes blocks whose
    // pattern alone would take gigabytes (LinearSystem::check_memory()).
    // The old pattern's matrix and factorization were freed first
    // (release()): they are replaced, and must not count against the new.
    std::vector<std::vector<types::global_dof_index>> blocks;
    for (const auto &contact : contacts)
      for (auto &block : contact->coupling_blocks())
        blocks.push_back(std::move(block));
    try
      {
        system->check_memory(dsp, blocks);
      }
    catch (const FactorizationTooLarge &e)
      {
        throw FactorizationTooLarge(e.what() + describe_fill_in(), e.bytes);
      }
    for (const auto &block : blocks)
      for (const auto row : block)
        dsp.add_entries(row, block.begin(), block.end(), true);
    blocks.clear();
    system->reinit(dsp, locally_owned_dofs, dof_handler.n_dofs());
  }

  // Why a factorization may need so much memory: the contact couples each
  // slave segment to every master segment it faces, and a slave segment
  // facing many (a coarse slave on a fine master) makes a dense block of
  // their unknowns, whose factor fills in. The message names the pair and
  // the remedy instead of leaving the user with a memory figure, and the
  // ways to need less memory for the same mesh: MUMPS orders the unknowns
  // by METIS's nested dissection, which makes no dense block of such rows
  // (UMFPACK's AMD leaves them to the end, where they fill in together),
  // and the iterative solver factorizes no matrix of the whole system.
  template <int dim>
  std::string
  ContactProblem<dim>::describe_fill_in() const
  {
    std::ostringstream text;
    text << std::setprecision(3);
    if constexpr (dim == 2)
      for (unsigned int k = 0; k < contacts.size(); ++k)
        {
          const double slave =
            contacts[k]->slave_surface().min_segment_length();
          const double master =
            contacts[k]->master_surface().min_segment_length();
          if (slave > 4 * master)
            text << "; contact pair " << k + 1 << ": the slave surface's "
                 << "segments are up to " << slave / master
                 << " times longer than the master's, and each couples to "
                    "every master segment it faces (a dense block): make the "
                    "slave the finer surface, or mesh them alike";
        }
    // The other solvers, those this run does not use already.
    text << "; ways to need less memory: ";
    if (system->direct_solver_name() == "UMFPACK")
      text << "Newton/Linear solver = MUMPS (METIS's order, on one process "
              "or shared by several under mpirun), ";
    else if (system->direct_solver_name() == "MUMPS")
      text << "more processes under mpirun (MUMPS shares the factors "
              "among them), ";
    if (!system->iterative())
      text << "Newton/Linear solver = iterative (no factorization), ";
    text << "or a coarser mesh";
    return text.str();
  }


  // This chapter's members for the dimensions the program runs in: the
  // explicit instantiation of the class in a chapter instantiates the
  // members defined here (see contact_problem.cc).
  template class ContactProblem<2>;
  template class ContactProblem<3>;
} // namespace RingContact
