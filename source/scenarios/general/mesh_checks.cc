// @sect4{The checks of a general problem's mesh}
//
// The checks of a general problem's mesh against its parameter file. The two
// are written apart, by hand, and refer to each other only through numbers, the
// tags of the model's physical groups. A tag mistyped on either side still
// gives a mesh that runs: a condition on a tag that no face carries is never
// applied, a surface that spans two bodies makes a contact pair of neither.
// Every such mismatch is refused here, before the first step, with the tag and
// the entry that names it. The audit of the file itself (every boundary face
// tagged once) has run before, in Geometry::check_boundary_tags().
#include <ring_contact/base/dimension.h>
#include <ring_contact/scenarios/general/general.h>

#include <map>
#include <set>
#include <stdexcept>
#include <string>

namespace RingContact
{
  namespace General
  {
    namespace
    {
      // The slave surfaces of two pairs share no vertex: a pressure node
      // belongs to one pair. The multiplier is one field on every slave layer
      // (doc/design.md), so a shared vertex would be one pressure unknown with
      // a complementarity row from each pair.
      // Vertices are compared by index. In a mesh whose bodies share no vertex,
      // as the contact problem requires (it refuses the others after this), the
      // slave surfaces of two pairs meet only on one body, where two of its
      // boundaries join.
      template <int dim>
      void
      check_slave_surfaces_apart(
        const Triangulation<dim>                                 &triangulation,
        const std::vector<std::pair<unsigned int, unsigned int>> &pairs,
        const std::string                                        &name)
      {
        std::map<unsigned int, unsigned int> pair_of_vertex;
        for (const auto &cell : triangulation.active_cell_iterators())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary())
              for (unsigned int k = 0; k < pairs.size(); ++k)
                if (face->boundary_id() == pairs[k].first)
                  for (const unsigned int v : face->vertex_indices())
                    {
                      const auto [at, inserted] =
                        pair_of_vertex.emplace(face->vertex_index(v), k);
                      if (!inserted && at->second != k)
                        {
                          std::string where;
                          for (unsigned int d = 0; d < dim; ++d)
                            where += (d > 0 ? ", " : "") +
                                     std::to_string(face->vertex(v)[d]);
                          throw std::runtime_error(
                            name + ": the slave surfaces " +
                            std::to_string(pairs[at->second].first) + " and " +
                            std::to_string(pairs[k].first) +
                            " of two contact pairs share the vertex (" + where +
                            "); a pressure node belongs to one pair");
                        }
                    }
      }
    } // namespace

    template <int dim>
    void
    check_bodies(const Triangulation<dim> &triangulation,
                 const Parameters         &parameters)
    {
      const std::string name = "mesh '" + parameters.mesh.mesh_file + "'";
      const auto &problem    = parameters.scenario_entries<ProblemParameters>();
      // The bodies by material id, and their ids listed for the messages.
      std::map<types::material_id, unsigned int> body_of;
      std::string                                ids;
      for (unsigned int b = 0; b < problem.bodies.size(); ++b)
        {
          body_of[problem.bodies[b].material_id] = b;
          ids += (b == 0 ? "" : ", ") +
                 std::to_string(problem.bodies[b].material_id);
        }

      std::set<types::material_id>                               materials;
      std::map<types::boundary_id, std::set<types::material_id>> bodies_of;
      for (const auto &cell : triangulation.active_cell_iterators())
        {
          materials.insert(cell->material_id());
          // A cell of a physical group that no body names (a surface of the
          // model left over, or a mistyped 'Material id') would have no
          // material and no element.
          if (body_of.count(cell->material_id()) == 0)
            throw std::runtime_error(name + " has cells of physical group " +
                                     std::to_string(cell->material_id()) +
                                     ", which is no body's 'Material id' (" +
                                     ids + ")");
          // Only boundary faces say which bodies a tag touches: a tag is a
          // boundary's, and its bodies are those of the cells behind its faces.
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary())
              bodies_of[face->boundary_id()].insert(cell->material_id());
        }
      // A body's 'Material id' that no cell carries would make a body of
      // nothing, without unknowns, whose conditions and checks mean nothing.
      for (unsigned int b = 0; b < problem.bodies.size(); ++b)
        if (materials.count(problem.bodies[b].material_id) == 0)
          throw std::runtime_error(
            name + " has no cells of physical group " +
            std::to_string(problem.bodies[b].material_id) + " (Body " +
            std::to_string(b + 1) + "'s 'Material id')");

      // Every tag that a boundary condition, a resultant-force check or a
      // contact pair names must be on some boundary face: a condition on a tag
      // that no face carries would never be applied, and a resultant would be
      // zero.
      const auto require_boundary = [&](const unsigned int id,
                                        const std::string &role) {
        if (bodies_of.count(id) == 0)
          throw std::runtime_error(name + " has no boundary with tag " +
                                   std::to_string(id) + " (" + role + ")");
      };
      for (const auto &condition : problem.boundary_conditions)
        require_boundary(condition.boundary_id, condition.name);
      for (const auto &check : problem.checks)
        if (check.quantity == ProblemQuantity::resultant_force_x ||
            check.quantity == ProblemQuantity::resultant_force_y ||
            check.quantity == ProblemQuantity::resultant_force_z ||
            check.quantity == ProblemQuantity::resultant_moment_x ||
            check.quantity == ProblemQuantity::resultant_moment_y ||
            check.quantity == ProblemQuantity::resultant_moment_z)
          require_boundary(check.boundary_id, check.name);
      const auto pairs = parameters.contact_pairs();
      for (unsigned int k = 0; k < pairs.size(); ++k)
        {
          // The first pair is subsection Contact's, the others are 'Contact
          // pair k': the messages name the subsection where the tag was given.
          const std::string subsection =
            k == 0 ? "Contact" : "Contact pair " + std::to_string(k + 1);
          const auto [slave, master] = pairs[k];
          require_boundary(slave, subsection + "/Slave boundary");
          require_boundary(master, subsection + "/Master boundary");
          // Each surface on one body, the two on different bodies (the program
          // has no self-contact), and the multiplier no richer than the slave
          // body's displacement, for the inf-sup condition (doc/intro.md). The
          // bodies of a pair are found from its surfaces, not named in the
          // file.
          for (const auto &[id, role] : {std::make_pair(slave, "slave"),
                                         std::make_pair(master, "master")})
            if (bodies_of.at(id).size() != 1)
              throw std::runtime_error(name + ": the " + role + " surface " +
                                       std::to_string(id) + " of " +
                                       subsection +
                                       " touches two bodies; it must belong "
                                       "to one");
          const auto slave_body  = *bodies_of.at(slave).begin();
          const auto master_body = *bodies_of.at(master).begin();
          if (slave_body == master_body)
            throw std::runtime_error(
              name + ": the slave and master surfaces of " + subsection +
              " belong to the same body (" + std::to_string(slave_body) + ")");
          if (parameters.finite_elements.multiplier_degree >
              problem.bodies[body_of.at(slave_body)].degree)
            throw std::runtime_error(
              "Finite elements/Multiplier degree (" +
              std::to_string(parameters.finite_elements.multiplier_degree) +
              ") exceeds the displacement degree of the slave body of " +
              subsection + " (Body " +
              std::to_string(body_of.at(slave_body) + 1) + ")");
        }
      check_slave_surfaces_apart(triangulation, pairs, name);
    }

    // The two dimensions of the program (issue 48).
    template void
    check_bodies<2>(const Triangulation<2> &, const Parameters &);
    template void
    check_bodies<3>(const Triangulation<3> &, const Parameters &);

  } // namespace General
} // namespace RingContact
