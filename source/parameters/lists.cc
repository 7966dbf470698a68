#include <signorini/input_error.h>
#include <signorini/parameters/lists.h>

#include <deal.II/base/utilities.h>

#include <cctype>
#include <cmath>
#include <type_traits>

namespace Signorini
{
  namespace
  {
    // ParameterHandler's own spelling of a name in an entry's path: every
    // character but letters and digits as '_' and its two hex digits.
    std::string
    mangled(const std::string &name)
    {
      static const char *hex = "0123456789abcdef";
      std::string        out;
      for (const unsigned char c : name)
        if (std::isalnum(c))
          out += static_cast<char>(c);
        else
          {
            out += '_';
            out += hex[c / 16];
            out += hex[c % 16];
          }
      return out;
    }
  } // namespace

  void
  require_set(const dealii::ParameterHandler &prm,
              const std::string              &key,
              const std::string              &context)
  {
    std::string path;
    const std::string separator = " > ";
    for (std::size_t start = 0; start <= context.size();)
      {
        const std::size_t end = context.find(separator, start);
        path += mangled(context.substr(start, end - start)) + ".";
        if (end == std::string::npos)
          break;
        start = end + separator.size();
      }
    path += mangled(key);
    if (prm.get_entries_wrongly_not_set().count(path) > 0)
      throw InputError(context + " > " + key,
                       "must be set: the scene states no value, and the "
                       "declared default is not meant to be used");
  }

  template <typename T>
  std::vector<T>
  get_list(dealii::ParameterHandler &prm,
           const std::string        &key,
           const unsigned int        n,
           const std::string        &context)
  {
    const std::vector<std::string> items =
      dealii::Utilities::split_string_list(prm.get(key));
    if (items.size() < n)
      throw InputError(context + " > " + key,
                       "needs " + std::to_string(n) + " value(s), got '" +
                         prm.get(key) + "'");
    std::vector<T> values;
    for (unsigned int i = 0; i < n; ++i)
      {
        try
          {
            if constexpr (std::is_same_v<T, double>)
              values.push_back(dealii::Utilities::string_to_double(items[i]));
            else
              values.push_back(dealii::Utilities::string_to_int(items[i]));
          }
        catch (...)
          {
            throw InputError(context + " > " + key,
                             "'" + items[i] + "' is not a number");
          }
        if constexpr (std::is_same_v<T, double>)
          if (!std::isfinite(values.back()))
            throw InputError(context + " > " + key,
                             "'" + items[i] + "' is not finite");
      }
    return values;
  }

  template std::vector<double>
  get_list<double>(dealii::ParameterHandler &, const std::string &,
                   const unsigned int, const std::string &);
  template std::vector<unsigned int>
  get_list<unsigned int>(dealii::ParameterHandler &, const std::string &,
                         const unsigned int, const std::string &);
} // namespace Signorini
