#include <signorini/archive_io.h>
#include <signorini/driver/checkpoint.h>
#include <signorini/input_error.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>

namespace Signorini
{
  namespace Checkpoint
  {
    namespace
    {
      const std::string prefix = "checkpoint-";

      /// "Section > Entry" -> value of a ShortPRM text.
      std::map<std::string, std::string>
      flatten(const std::string &text)
      {
        std::map<std::string, std::string> entries;
        std::vector<std::string>           path;
        std::istringstream                 in(text);
        for (std::string line; std::getline(in, line);)
          {
            const auto first = line.find_first_not_of(" \t");
            if (first == std::string::npos)
              continue;
            line.erase(0, first);
            while (!line.empty() && (line.back() == ' ' || line.back() == '\r'))
              line.pop_back();
            if (line.rfind("subsection ", 0) == 0)
              path.push_back(line.substr(11));
            else if (line == "end")
              {
                if (!path.empty())
                  path.pop_back();
              }
            else if (line.rfind("set ", 0) == 0)
              {
                const auto eq = line.find('=');
                if (eq == std::string::npos)
                  continue;
                std::string name  = line.substr(4, eq - 4);
                std::string value = line.substr(eq + 1);
                while (!name.empty() && name.back() == ' ')
                  name.pop_back();
                value.erase(0, value.find_first_not_of(' '));
                std::string key;
                for (const auto &p : path)
                  key += p + " > ";
                entries[key + name] = value;
              }
          }
        return entries;
      }

      bool
      may_change(const std::string &key)
      {
        return key == "Load stepping > End time" ||
               key == "Mesh refinement > Number of cycles" ||
               key == "Output directory" || key.rfind("Output > ", 0) == 0 ||
               key.rfind("Checkpoint > ", 0) == 0;
      }
    } // namespace

    std::string
    root(const std::string &output_directory)
    {
      return output_directory + "/checkpoints";
    }

    std::string
    folder(const std::string &output_directory, const unsigned int sequence)
    {
      std::ostringstream name;
      name << root(output_directory) << "/" << prefix << std::setw(6)
           << std::setfill('0') << sequence;
      return name.str();
    }

    std::string
    state_file(const std::string &checkpoint_folder, const unsigned int rank)
    {
      return checkpoint_folder + "/state-" + std::to_string(rank) + ".bin";
    }

    std::string
    mesh_file(const std::string &checkpoint_folder)
    {
      return checkpoint_folder + "/mesh";
    }

    std::vector<std::string>
    list(const std::string &output_directory)
    {
      std::vector<std::string> found;
      std::error_code          ec;
      for (const auto &entry :
           std::filesystem::directory_iterator(root(output_directory), ec))
        {
          const std::string name = entry.path().filename().string();
          std::error_code   type_ec; // the overload that cannot throw
          if (entry.is_directory(type_ec) && name.rfind(prefix, 0) == 0 &&
              name.size() == prefix.size() + 6 &&
              std::all_of(name.begin() + prefix.size(), name.end(),
                          [](const char c) { return std::isdigit(c); }))
            found.push_back(entry.path().string());
        }
      std::sort(found.begin(), found.end());
      return found;
    }

    std::string
    newest(const std::string &directory)
    {
      if (!std::filesystem::is_directory(directory))
        throw InputError("--restart", "'" + directory + "' is not a folder");
      if (std::filesystem::exists(state_file(directory, 0)))
        return directory; // a checkpoint folder itself
      const auto found = list(directory);
      if (found.empty())
        throw InputError("--restart",
                         "no checkpoint in '" + root(directory) +
                           "': the run wrote none (Checkpoint > Write "
                           "checkpoints) or this is not its output directory");
      return found.back();
    }

    Header
    read_header(const std::string &checkpoint_folder)
    {
      const std::string file = state_file(checkpoint_folder, 0);
      std::ifstream     in(file, std::ios::binary);
      if (!in)
        throw InputError("--restart", "cannot read '" + file + "'");
      Header header;
      try
        {
          InputArchive archive(in);
          archive >> header;
        }
      catch (const std::exception &e)
        {
          throw InputError(file, std::string("not a signorini checkpoint (") +
                                   e.what() + ")");
        }
      if (header.format != format_version)
        throw InputError(file, "checkpoint format " + std::to_string(header.format) +
                                 ", this program reads format " +
                                 std::to_string(format_version));
      return header;
    }

    std::vector<std::string>
    incompatible_changes(const std::string &saved, const ParameterHandler &restarted)
    {
      std::ostringstream now;
      restarted.print_parameters(now, ParameterHandler::ShortPRM);
      const auto before = flatten(saved);
      const auto after  = flatten(now.str());
      std::vector<std::string> changes;
      for (const auto &[key, value] : after)
        {
          if (may_change(key))
            continue;
          const auto old = before.find(key);
          const std::string old_value = (old == before.end() ? "(none)" : old->second);
          if (old_value != value)
            changes.push_back(key + ": '" + old_value + "' -> '" + value + "'");
        }
      return changes;
    }
  } // namespace Checkpoint
} // namespace Signorini
