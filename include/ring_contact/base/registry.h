// @sect3{Registered families}
//
// The families of choices a parameter file makes by name (the material
// laws, the contact integration schemes, the refinement estimators; the
// scenarios have their own table, scenarios/scenario.h) register
// themselves as the scenarios do: each member's .cc file holds one
// Registry<Entry>::Add, a static object whose constructor adds the member
// to its family's table as the library loads. The entry that chooses among
// them takes its pattern and documentation from the table, and the factory
// of the member chosen is found in it by name: adding a member is one file
// (and its line in CMakeLists.txt), nothing else.
//
// An Entry is a struct with at least
//   std::string              name;          // its value in the .prm
//   std::vector<std::string> old_names;     // values still read for it
//   std::string              documentation; // for the entry's reference
// and whatever its family needs besides (a factory, properties).
//
// As with the scenarios, this relies on every member's object file being
// loaded: the library is built shared (CMakeLists.txt).
#ifndef ring_contact_base_registry_h
#define ring_contact_base_registry_h

#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <string>
#include <vector>

namespace RingContact
{
  template <typename Entry>
  class Registry
  {
  public:
    /// Register a member: in its .cc file,
    ///   const Registry<Entry>::Add registration{Entry{...}};
    struct Add
    {
      explicit Add(Entry entry)
      {
        auto &entries = table();
        entries.insert(std::upper_bound(entries.begin(),
                                        entries.end(),
                                        entry,
                                        [](const Entry &a, const Entry &b) {
                                          return before(a.name, b.name);
                                        }),
                       std::move(entry));
      }
    };

    /// Every member, sorted by name in the order of a dictionary (case
    /// aside: "Gauss, nodal, Simpson"), kept so as each registers: the order
    /// of the object files, in which they do, is the linker's).
    static const std::vector<Entry> &
    members()
    {
      return table();
    }

    /// The member of a name, or of one of its old names; nullptr if none.
    static const Entry *
    find(const std::string &name)
    {
      for (const Entry &entry : members())
        if (entry.name == name ||
            std::find(entry.old_names.begin(), entry.old_names.end(), name) !=
              entry.old_names.end())
          return &entry;
      return nullptr;
    }

    /// The member of a name that the entry's pattern has admitted.
    static const Entry &
    get(const std::string &name)
    {
      if (const Entry *entry = find(name))
        return *entry;
      // The pattern admits only registered names: a program error.
      throw std::logic_error("nothing registered as '" + name + "'");
    }

    /// The names and old names, as Patterns::Selection takes them
    /// ("a|b|c").
    static std::string
    selection()
    {
      std::string names;
      for (const Entry &entry : members())
        {
          names += (names.empty() ? "" : "|") + entry.name;
          for (const std::string &old_name : entry.old_names)
            names += "|" + old_name;
        }
      return names;
    }

    /// "name: documentation; name: ..." (with the old names said), for
    /// the documentation of the entry that chooses.
    static std::string
    documentation()
    {
      std::string text;
      for (const Entry &entry : members())
        {
          text += (text.empty() ? "" : " ") + entry.name + ": " +
                  entry.documentation;
          // "Also read as 'a' or 'b'.", a sentence of its own.
          for (unsigned int k = 0; k < entry.old_names.size(); ++k)
            text += (k == 0 ? " Also read as '" : " or '") +
                    entry.old_names[k] +
                    (k + 1 == entry.old_names.size() ? "'." : "'");
        }
      return text;
    }

  private:
    // Whether name a comes before name b in a dictionary: letters compared
    // without their case, and a name before its longer versions.
    static bool
    before(const std::string &a, const std::string &b)
    {
      return std::lexicographical_compare(
        a.begin(), a.end(), b.begin(), b.end(), [](const char x, const char y) {
          return std::tolower(static_cast<unsigned char>(x)) <
                 std::tolower(static_cast<unsigned char>(y));
        });
    }

    // A function's static, so that the table exists before the first
    // registration whatever the order of the files.
    static std::vector<Entry> &
    table()
    {
      static std::vector<Entry> entries;
      return entries;
    }
  };
} // namespace RingContact

#endif
