#include <signorini/driver/mpi_environment.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace Signorini
{
  namespace MpiEnvironment
  {
    namespace
    {
      /// The parameters the decision reads.
      const char *const names[] = {"mtl",
                                   "pml",
                                   "ess_singleton_isolated",
                                   "sharedfp",
                                   "orte_create_session_dirs"};

      /// The matching-transport components that drive RDMA adapters only.
      const std::vector<std::string> rdma_transports = {"psm", "psm2", "ofi"};

      std::string
      trimmed(const std::string &text)
      {
        const auto first = text.find_first_not_of(" \t\r");
        if (first == std::string::npos)
          return "";
        const auto last = text.find_last_not_of(" \t\r");
        return text.substr(first, last - first + 1);
      }

      std::vector<std::string>
      split(const std::string &text, const char separator)
      {
        std::vector<std::string> parts;
        std::istringstream       in(text);
        for (std::string part; std::getline(in, part, separator);)
          if (!trimmed(part).empty())
            parts.push_back(trimmed(part));
        return parts;
      }

      /// The files Open MPI reads its parameters from, first ones first.
      std::vector<std::string>
      parameter_files()
      {
        if (const char *files = std::getenv("OMPI_MCA_mca_base_param_files"))
          return split(files, ':');
        std::vector<std::string> files;
        if (const char *home = std::getenv("HOME"))
          files.push_back(std::string(home) + "/.openmpi/mca-params.conf");
        files.push_back("/etc/openmpi/openmpi-mca-params.conf");
        return files;
      }

      /// The value a parameter file gives to @p name, "" if none.
      std::string
      value_in_file(const std::string &file, const std::string &name)
      {
        std::ifstream in(file);
        for (std::string line; std::getline(in, line);)
          {
            line = trimmed(line.substr(0, line.find('#')));
            const auto equals = line.find('=');
            if (equals != std::string::npos &&
                trimmed(line.substr(0, equals)) == name)
              return trimmed(line.substr(equals + 1));
          }
        return "";
      }

      std::string &
      applied_settings()
      {
        static std::string text;
        return text;
      }
    } // namespace

    Facts
    facts_of_this_process()
    {
      Facts facts;
      facts.launched = std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr ||
                       std::getenv("PMIX_RANK") != nullptr ||
                       std::getenv("PMI_RANK") != nullptr;
      std::error_code error;
      const std::filesystem::path rdma("/sys/class/infiniband");
      facts.rdma_device = std::filesystem::exists(rdma, error) &&
                          !std::filesystem::is_empty(rdma, error);
      const std::vector<std::string> files = parameter_files();
      for (const std::string name : names)
        {
          if (const char *value = std::getenv(("OMPI_MCA_" + name).c_str()))
            {
              facts.values[name] = trimmed(value);
              continue;
            }
          for (const auto &file : files)
            {
              const std::string value = value_in_file(file, name);
              if (!value.empty())
                {
                  facts.values[name] = value;
                  break;
                }
            }
        }
      return facts;
    }

    std::vector<std::pair<std::string, std::string>>
    settings(const Facts &facts)
    {
      std::vector<std::pair<std::string, std::string>> result;
      const auto value = [&facts](const std::string &name) -> std::string {
        const auto it = facts.values.find(name);
        return it == facts.values.end() ? std::string() : it->second;
      };

      // An exclusion list for @p name that also names @p components: set
      // when nothing is set, widened when an exclusion list ('^...') is,
      // left alone when the user chose components (a list without '^').
      const auto exclude = [&](const std::string              &name,
                               const std::vector<std::string> &components) {
        const std::string current = value(name);
        if (!current.empty() && current[0] != '^')
          return;
        std::vector<std::string> excluded =
          current.empty() ? std::vector<std::string>() : split(current.substr(1), ',');
        bool widened = false;
        for (const auto &component : components)
          if (std::find(excluded.begin(), excluded.end(), component) == excluded.end())
            {
              excluded.push_back(component);
              widened = true;
            }
        if (!widened)
          return;
        std::string list = "^";
        for (const auto &component : excluded)
          list += (list.size() > 1 ? "," : "") + component;
        result.emplace_back(name, list);
      };

      // Transports: only without an adapter, and only where nobody chose
      // the point-to-point layer itself (pml = cm, ob1, ...).
      const std::string pml = value("pml");
      if (!facts.rdma_device && (pml.empty() || pml[0] == '^'))
        exclude("mtl", rdma_transports);

      // Without the daemon there is no session directory, where the
      // shared-memory shared-file-pointer component of MPI-IO keeps its
      // files: when several one-rank runs opened files at once (HDF5
      // output, checkpoints), it printed "unable to open file for mmap"
      // (tests/singleton_mpi_io). One process needs no shared memory.
      if (!facts.launched && value("ess_singleton_isolated").empty())
        {
          result.emplace_back("ess_singleton_isolated", "1");
          exclude("sharedfp", {"sm"});
          // Every isolated process is job family 0, so all of them used one
          // session directory (/tmp/ompi.HOST.UID/jf.0): a process ending
          // removed it while another was creating it, whose MPI_Init then
          // failed ("A call to mkdir was unable to create the desired
          // directory"; 3 of 480 concurrent starts, 5 of 200 runs of
          // tests/prm_mutation under load). One process needs no session
          // directory (tests/mpi_environment starts 360, 6 at a time).
          if (value("orte_create_session_dirs").empty())
            result.emplace_back("orte_create_session_dirs", "0");
        }
      return result;
    }

    std::string
    prepare()
    {
      std::string text;
      for (const auto &[name, value] : settings(facts_of_this_process()))
        {
          setenv(("OMPI_MCA_" + name).c_str(), value.c_str(), /*overwrite=*/1);
          text += (text.empty() ? "" : " ") + name + "=" + value;
        }
      applied_settings() = text;
      return text;
    }

    const std::string &
    applied()
    {
      return applied_settings();
    }
  } // namespace MpiEnvironment
} // namespace Signorini
