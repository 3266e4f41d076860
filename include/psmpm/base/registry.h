// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_base_registry_h
#define psmpm_base_registry_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

namespace psmpm
{
  using namespace dealii;

  /**
   * Name -> factory table of the variants of one concept (bases, mass
   * strategies, materials, references, transfer schemes). Every variant
   * registers itself from its own source file with a static Registration
   * object, so that adding a variant is one new file plus one registration
   * line; every Patterns::Selection of a variant name is built from here,
   * so the list the user sees is the list that exists. (ASPECT's plugin
   * system is the model; this is a smaller, header-only take on it.)
   *
   * @tparam Base the interface; @tparam Args the arguments of the factory.
   */
  template <typename Base, typename... Args>
  class Registry
  {
  public:
    using Factory = std::function<std::unique_ptr<Base>(Args...)>;

    struct Entry
    {
      std::string name;
      std::string description;
      Factory     create;
      /// Declares the variant's own entries (may be empty).
      std::function<void(ParameterHandler &)> declare_parameters;
    };

    /// The one registry of this kind (created on first use, so
    /// registrations from static objects of any translation unit or
    /// library are safe).
    static Registry &
    instance()
    {
      static Registry registry;
      return registry;
    }

    void
    add(const Entry &entry)
    {
      AssertThrow(entries.find(entry.name) == entries.end(),
                  ExcMessage("psmpm: variant '" + entry.name +
                             "' is registered twice."));
      entries[entry.name] = entry;
    }

    bool
    has(const std::string &name) const
    {
      return entries.find(name) != entries.end();
    }

    /// "a|b|c" for Patterns::Selection.
    std::string
    selection() const
    {
      return join("|");
    }

    /// "a, b, c" for messages.
    std::string
    names() const
    {
      return join(", ");
    }

    /// The variants' names, sorted.
    std::vector<std::string>
    variant_names() const
    {
      std::vector<std::string> names;
      for (const auto &e : entries)
        names.push_back(e.first);
      return names;
    }

    /// The description of the variant @p name, which must exist.
    const std::string &
    description(const std::string &name) const
    {
      return entries.at(name).description;
    }

    /// One line per variant: "name: description".
    std::string
    documentation() const
    {
      std::string s;
      for (const auto &e : entries)
        s += (s.empty() ? "" : "; ") + e.first + ": " + e.second.description;
      return s;
    }

    /// Declare the entries of every variant.
    void
    declare_parameters(ParameterHandler &prm) const
    {
      for (const auto &e : entries)
        if (e.second.declare_parameters)
          e.second.declare_parameters(prm);
    }

    /// Declare the entries of the variant @p name only (none if it is
    /// unknown or has none): which entries a variant reads.
    void
    declare_parameters(const std::string &name, ParameterHandler &prm) const
    {
      const auto it = entries.find(name);
      if (it != entries.end() && it->second.declare_parameters)
        it->second.declare_parameters(prm);
    }

    /**
     * Create variant @p name; @p entry ("Subsection/Entry") names the
     * parameter in the error for an unknown name.
     */
    std::unique_ptr<Base>
    create(const std::string &name,
           const std::string &entry,
           Args... args) const
    {
      const auto it = entries.find(name);
      AssertThrow(it != entries.end(),
                  ExcMessage(entry + " = " + name +
                             ": unknown (known: " + names() + ")."));
      return it->second.create(args...);
    }

  private:
    std::string
    join(const std::string &separator) const
    {
      std::string s;
      for (const auto &e : entries)
        s += (s.empty() ? "" : separator) + e.first;
      return s;
    }

    std::map<std::string, Entry> entries;
  };

  /**
   * Registers a variant when constructed: one static object per variant,
   * in the variant's source file, e.g.
   * @code
   * static Registration<MaterialRegistry<2>> reg({"my law", "doc", f, d});
   * @endcode
   */
  template <typename RegistryType>
  struct Registration
  {
    explicit Registration(const typename RegistryType::Entry &entry)
    {
      RegistryType::instance().add(entry);
    }
  };

  /**
   * Registers the dim = 1 and dim = 2 instances of a dimension-templated
   * variant in RegistryOf<1> and RegistryOf<2>: the one line a variant
   * file needs, e.g.
   * @code
   * RegisterForDims<MassStrategyRegistry, Lumped> reg("lumped", "doc");
   * @endcode
   * The variant is constructed from the factory's arguments if it can
   * be, else by default.
   */
  template <template <int> class RegistryOf, template <int> class Variant>
  struct RegisterForDims
  {
    RegisterForDims(
      const std::string                             &name,
      const std::string                             &description,
      const std::function<void(ParameterHandler &)> &declare = nullptr)
    {
      add<1>(name, description, declare);
      add<2>(name, description, declare);
    }

  private:
    template <int dim>
    static void
    add(const std::string                             &name,
        const std::string                             &description,
        const std::function<void(ParameterHandler &)> &declare)
    {
      using Entry = typename RegistryOf<dim>::Entry;
      Entry e;
      e.name               = name;
      e.description        = description;
      e.declare_parameters = declare;
      e.create             = [](auto &&...args) {
        if constexpr (std::is_constructible_v<Variant<dim>, decltype(args)...>)
          return std::make_unique<Variant<dim>>(args...);
        else
          return std::make_unique<Variant<dim>>();
      };
      RegistryOf<dim>::instance().add(e);
    }
  };
} // namespace psmpm

#endif
