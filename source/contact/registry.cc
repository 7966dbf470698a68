#include <signorini/contact/model.h>
#include <signorini/contact/registry.h>

#include <algorithm>
#include <stdexcept>

namespace Signorini
{
  namespace Contact
  {
    // The registered models, in the order of the Type selection: one line
    // each, naming the function of the model's source file that describes
    // it (ModelEntry NAME() in namespace Contact).
#define SIGNORINI_CONTACT_MODELS(X) \
  X(rigid_foundation_model)         \
  X(two_body_model)                 \
  X(pairs_model)

#define SIGNORINI_DECLARE_MODEL(function) ModelEntry function();
    SIGNORINI_CONTACT_MODELS(SIGNORINI_DECLARE_MODEL)
#undef SIGNORINI_DECLARE_MODEL

    namespace
    {
      std::vector<ModelEntry>
      library_models()
      {
#define SIGNORINI_LIST_MODEL(function) function(),
        return {SIGNORINI_CONTACT_MODELS(SIGNORINI_LIST_MODEL)};
#undef SIGNORINI_LIST_MODEL
      }

      void
      check(const ModelEntry &entry, const std::vector<ModelEntry> &others)
      {
        const auto fail = [&](const std::string &what) {
          throw std::logic_error("contact model '" + entry.name + "': " + what);
        };
        if (entry.name.empty() || entry.name == "none" ||
            entry.name.find_first_of("|,") != std::string::npos)
          fail("the name must be non-empty, not 'none', without '|' or ','");
        for (const auto &other : others)
          if (other.name == entry.name)
            fail("registered twice");
        if (entry.help.rfind(entry.name, 0) != 0)
          fail("its help must start with its name");
        if (!entry.declare_parameters || !entry.parse_parameters || !entry.create_2d ||
            !entry.create_3d)
          fail("declare_parameters, parse_parameters, create_2d and create_3d are required");
        if (entry.capabilities.bodies < 1 || entry.capabilities.bodies > 2)
          fail("a model acts on 1 or 2 bodies");
      }

      std::vector<ModelEntry> &
      models()
      {
        static std::vector<ModelEntry> list = [] {
          std::vector<ModelEntry> checked;
          for (auto &entry : library_models())
            {
              check(entry, checked);
              checked.push_back(std::move(entry));
            }
          return checked;
        }();
        return list;
      }
    } // namespace

    const std::vector<ModelEntry> &
    registered_models()
    {
      return models();
    }

    const ModelEntry *
    find_model(const std::string &name)
    {
      const auto &list = models();
      const auto  it   = std::find_if(list.begin(), list.end(), [&](const ModelEntry &e) {
        return e.name == name;
      });
      return it == list.end() ? nullptr : &*it;
    }

    void
    register_model(ModelEntry entry)
    {
      auto &list = models();
      check(entry, list);
      list.push_back(std::move(entry));
    }
  } // namespace Contact
} // namespace Signorini
