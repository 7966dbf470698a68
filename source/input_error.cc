#include <signorini/input_error.h>

#include <regex>
#include <sstream>

namespace Signorini
{
  std::string
  essential_message(const std::string &what)
  {
    std::string msg = what;
    const auto  pos = msg.find("Additional information:");
    if (pos != std::string::npos)
      msg = msg.substr(pos + 23);
    const auto stack = msg.find("Stacktrace:");
    if (stack != std::string::npos)
      msg = msg.substr(0, stack);
    // Drop deal.II's separator lines (dashes only), join the rest: a dash
    // inside the text (a minus sign) stays.
    std::istringstream lines(msg);
    std::string        joined;
    for (std::string line; std::getline(lines, line);)
      if (!std::regex_match(line, std::regex("\\s*-*\\s*")))
        joined += line + " ";
    msg = std::regex_replace(joined, std::regex("\\s+"), " ");
    while (!msg.empty() && msg.back() == ' ')
      msg.pop_back();
    while (!msg.empty() && msg.front() == ' ')
      msg.erase(msg.begin());
    return msg;
  }
} // namespace Signorini
