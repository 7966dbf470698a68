// AtomicFile: a reader sees the previous version of a file until commit()
// renames the complete new one into place; a file abandoned without
// commit() (an exception, a failed write) leaves the previous version and
// no temporary behind; a commit that cannot write says why.
#include <signorini/output/atomic_file.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace
{
  std::string
  contents(const std::string &file)
  {
    std::ifstream     in(file);
    std::stringstream text;
    text << in.rdbuf();
    return in ? text.str() : std::string("<absent>");
  }
} // namespace

int
main()
{
  namespace fs = std::filesystem;
  std::ofstream out("output");
  const std::string file = "summary.json";
  fs::remove(file);

  {
    Signorini::AtomicFile f(file);
    f.stream() << "first version\n";
    out << "before the first commit: " << contents(file) << "\n";
    out << "temporary beside it: "
        << (fs::path(f.temporary_path()).parent_path() == fs::path(file).parent_path() ?
              "yes" :
              "no")
        << "\n";
    out << "commit: " << (f.commit() ? "ok" : "failed") << "\n";
  }
  out << "after the commit: " << contents(file);

  std::string temporary;
  {
    Signorini::AtomicFile f(file);
    temporary = f.temporary_path();
    f.stream() << "second version, half writ";
    out << "while the second is written: " << contents(file);
    // Abandoned: no commit.
  }
  out << "after an abandoned write: " << contents(file);
  out << "temporary left behind: " << (fs::exists(temporary) ? "yes" : "no")
      << "\n";

  {
    Signorini::AtomicFile f("no such folder/summary.json");
    f.stream() << "text\n";
    std::string reason;
    const bool  ok = f.commit(&reason);
    out << "commit into a missing folder: " << (ok ? "ok" : "failed")
        << (reason.find("no such folder/summary.json") != std::string::npos ?
              ", the reason names the file" :
              ", no reason")
        << (reason.find("No such file or directory") != std::string::npos ?
              " and the system's reason" :
              "")
        << "\n";
  }
}
