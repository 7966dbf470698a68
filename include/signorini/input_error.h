#pragma once

#include <stdexcept>
#include <string>

namespace Signorini
{
  /**
   * Bad input in a parameter file or a mesh file. The message names the
   * entry as "Subsection > Entry" (or the file and line) and says what is
   * wrong; the program prints it and exits with status 2, before writing
   * any result.
   */
  class InputError : public std::runtime_error
  {
  public:
    InputError(const std::string &where, const std::string &what)
      : std::runtime_error(where + ": " + what)
    {}
  };

  /**
   * The part of a deal.II exception text that says what went wrong (its
   * "Additional information"), on one line, without the stack trace; the
   * whole text if it has no such part.
   */
  std::string
  essential_message(const std::string &what);

  /**
   * A solve that did not succeed (Newton did not converge after every
   * allowed step cut, an inverted element could not be avoided, ...).
   * The run keeps the last converged state on disk, writes
   * status "failed" with this reason into summary.json and exits with
   * status 3.
   */
  class SolveFailure : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /**
   * A result file that could not be written (a full disk, a folder that
   * became read-only, ...). The run stops there, keeps the files written
   * before, writes status "failed" with this reason (which names the
   * file) into summary.json and exits with status 3.
   */
  class OutputFailure : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };
} // namespace Signorini
