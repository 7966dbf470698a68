#include <signorini/input_error.h>

#include <regex>

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
    msg = std::regex_replace(msg, std::regex("[\\s-]*\\n[\\s-]*"), " ");
    msg = std::regex_replace(msg, std::regex("\\s+"), " ");
    while (!msg.empty() && (msg.back() == ' ' || msg.back() == '-'))
      msg.pop_back();
    while (!msg.empty() && msg.front() == ' ')
      msg.erase(msg.begin());
    return msg;
  }
} // namespace Signorini
