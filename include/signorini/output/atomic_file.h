#pragma once

#include <fstream>
#include <string>

namespace Signorini
{
  /**
   * "cannot write @p path", with the system's reason (errno) if the failed
   * call of this thread set one: for a stream that has failed, where the
   * caller cleared errno before writing to it.
   */
  std::string
  write_failure(const std::string &path);

  /**
   * An output file that is never seen half written: the text goes to a
   * temporary file beside it (same folder, so the rename cannot cross
   * file systems), and commit() renames that over the final name in one
   * step. Until then a reader sees the previous version of the file or
   * none; a file that is destroyed without commit() (an exception, a
   * failed write) removes its temporary and leaves the previous version.
   */
  class AtomicFile
  {
  public:
    explicit AtomicFile(const std::string &path);
    ~AtomicFile();

    AtomicFile(const AtomicFile &) = delete;
    AtomicFile &
    operator=(const AtomicFile &) = delete;

    /// Where to write the text.
    std::ostream &
    stream()
    {
      return out;
    }

    /**
     * Flush, close and rename the temporary over the final path. Returns
     * false, with the reason in @p reason if given, if writing or renaming
     * failed; the previous version of the file then stays.
     */
    bool
    commit(std::string *reason = nullptr);

    /// The name the text is written under until commit().
    const std::string &
    temporary_path() const
    {
      return temporary;
    }

  private:
    std::string   path;
    std::string   temporary;
    std::ofstream out;
    bool          committed = false;
  };
} // namespace Signorini
