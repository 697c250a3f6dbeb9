// @sect3{The registry of scenarios}
//
// The scenarios register themselves: each one's .cc file holds one
// ScenarioRegistration::Add, a static object whose constructor adds it to the
// table below as the library loads. The parameters (Problem/Scenario's choices
// and documentation, every scenario's own entries) and make_scenario() read the
// table, so that a new scenario touches no file outside its folder. This relies
// on every scenario's object file being loaded: the library is built shared
// (CMakeLists.txt), whereas a static archive would let the linker drop an
// object file that nothing refers to, and its scenario with it.
#include <ring_contact/scenarios/scenario.h>

#include <stdexcept>

namespace RingContact
{
  namespace
  {
    // The table of scenarios, filled by the registration line of each as
    // the library loads (a function's static, so that it exists before the
    // first registration whatever the order of the files).
    std::vector<ScenarioRegistration> &
    registry()
    {
      static std::vector<ScenarioRegistration> scenarios;
      return scenarios;
    }
  } // namespace

  ScenarioRegistration::Add::Add(ScenarioRegistration registration)
  {
    registry().push_back(std::move(registration));
  }

  const std::vector<ScenarioRegistration> &
  registered_scenarios()
  {
    return registry();
  }

  template <>
  std::unique_ptr<Scenario<2>>
  make_scenario<2>(const Parameters &parameters)
  {
    for (const auto &scenario : registered_scenarios())
      if (scenario.name == parameters.scenario)
        return scenario.make(parameters);
    // Problem/Scenario's pattern admits only registered names, so this is a
    // program error, not a user's.
    throw std::logic_error("no scenario named '" + parameters.scenario + "'");
  }

  template <>
  std::unique_ptr<Scenario<3>>
  make_scenario<3>(const Parameters &parameters)
  {
    for (const auto &scenario : registered_scenarios())
      if (scenario.name == parameters.scenario)
        {
          if (!scenario.make_3d)
            throw std::runtime_error("Problem/Scenario = " + scenario.name +
                                     ": " + scenario.description +
                                     " is two-dimensional only");
          return scenario.make_3d(parameters);
        }
    // Problem/Scenario's pattern admits only registered names, so this is a
    // program error, not a user's.
    throw std::logic_error("no scenario named '" + parameters.scenario + "'");
  }
} // namespace RingContact
