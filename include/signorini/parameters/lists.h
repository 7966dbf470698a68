#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace Signorini
{
  /**
   * The first @p n entries of the comma-separated list @p key of the
   * current subsection, converted to T (double or unsigned int). Throws
   * InputError naming "@p context > @p key" if the list is shorter, an
   * entry is not a number, or a double is not finite.
   */
  template <typename T>
  std::vector<T>
  get_list(dealii::ParameterHandler &prm,
           const std::string        &key,
           const unsigned int        n,
           const std::string        &context);

  /**
   * Throws InputError "@p context > @p key: must be set ..." unless the
   * scene states the entry @p key of the current subsection, whose path is
   * @p context ("Body 1 > Material"). For entries declared with
   * has_to_be_set = true: a default that no scene should rely on (a
   * material's modulus) is then never taken silently.
   */
  void
  require_set(const dealii::ParameterHandler &prm,
              const std::string              &key,
              const std::string              &context);
} // namespace Signorini
