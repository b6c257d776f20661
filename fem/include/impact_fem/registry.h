#ifndef IMPACT_FEM_REGISTRY_H
#define IMPACT_FEM_REGISTRY_H

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <map>
#include <memory>
#include <string>

namespace impact_fem
{
  /**
   * The kinds of one interchangeable component (materials, time steppers,
   * postprocessors), each registered under the name used in the parameter
   * file by a static initialiser in its own file (ASPECT's pattern): adding
   * a kind is one new file.
   */
  template <typename Interface>
  class Registry
  {
  public:
    struct Entry
    {
      std::string                                     name;
      std::string                                     description;
      std::function<void(dealii::ParameterHandler &)> declare_parameters;
      std::function<std::unique_ptr<Interface>()>     create;
    };

    /// Add a kind; returns true (for use in a static initialiser).
    static bool
    add(const Entry &entry)
    {
      entries()[entry.name] = entry;
      return true;
    }

    /// All kinds, ordered by name.
    static const std::map<std::string, Entry> &
    all()
    {
      return entries();
    }

    /// The kind called @p name; an error that lists the known ones if none.
    static const Entry &
    get(const std::string &name)
    {
      const auto kind = entries().find(name);
      AssertThrow(kind != entries().end(),
                  dealii::ExcMessage("Unknown kind <" + name +
                                     ">; known: " + selection() + "."));
      return kind->second;
    }

    /// "a|b|c": the pattern of a selection entry.
    static std::string
    selection()
    {
      std::string names;
      for (const auto &kind : entries())
        names += (names.empty() ? "" : "|") + kind.first;
      return names;
    }

    /// One line "  name: description" per kind, for help texts.
    static std::string
    descriptions()
    {
      std::string help;
      for (const auto &kind : entries())
        help += "\n  " + kind.first + ": " + kind.second.description;
      return help;
    }

  private:
    // Function-local static: safe to use from other translation units'
    // static initialisers (the registrations).
    static std::map<std::string, Entry> &
    entries()
    {
      static std::map<std::string, Entry> kinds;
      return kinds;
    }
  };
} // namespace impact_fem

/**
 * Register @p classname (default constructible, with a static
 * declare_parameters(ParameterHandler &)) as a kind of @p interface under
 * @p name. Used inside the class's namespace.
 */
#define IMPACT_FEM_REGISTER(interface, classname, name, description) \
  namespace                                                          \
  {                                                                  \
    const bool impact_fem_registered_##classname =                   \
      impact_fem::Registry<interface>::add(                          \
        {name,                                                       \
         description,                                                \
         &classname::declare_parameters,                             \
         []() -> std::unique_ptr<interface> {                        \
           return std::make_unique<classname>();                     \
         }});                                                        \
  }

#endif
