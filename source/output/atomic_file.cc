#include <signorini/output/atomic_file.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <system_error>

#include <unistd.h>

namespace Signorini
{
  std::string
  write_failure(const std::string &path)
  {
    return "cannot write " + path +
           (errno != 0 ? std::string(": ") + std::strerror(errno) : "");
  }

  AtomicFile::AtomicFile(const std::string &path)
    : path(path)
    , temporary(path + ".tmp." + std::to_string(::getpid()))
    // errno cleared before the file is opened: commit() reports the
    // system's reason for a failed open or write.
    , out((errno = 0, temporary))
  {}

  AtomicFile::~AtomicFile()
  {
    if (!committed)
      {
        out.close();
        std::error_code ec;
        std::filesystem::remove(temporary, ec);
      }
  }

  bool
  AtomicFile::commit(std::string *reason)
  {
    out.flush();
    const bool written = static_cast<bool>(out);
    out.close();
    std::error_code ec;
    if (written && !out.fail())
      std::filesystem::rename(temporary, path, ec);
    if (!written || out.fail() || ec)
      {
        if (reason)
          *reason = ec ? "cannot write " + path + ": " + ec.message() :
                         write_failure(path);
        std::filesystem::remove(temporary, ec);
        return false;
      }
    committed = true;
    return true;
  }
} // namespace Signorini
