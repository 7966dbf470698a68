// The order in which this process's libraries were loaded, which is the order
// the dynamic loader searches them for symbols (cmake/symbol_scope.cmake):
// deal.II's most referenced libraries come first, libdeal.ii itself before
// every other library, and Gmsh and OpenBLAS among the first ten, where a
// plain link loads them 45th and 75th. The parallel MUMPS must still come
// before the sequential one that Ipopt links (CMakeLists.txt), or every
// MUMPS factorisation on several ranks runs as if each rank were alone.

#include <signorini/driver/mpi_environment.h>

#include <dlfcn.h>
#include <link.h>

#include <iostream>
#include <string>
#include <vector>

namespace
{
  int
  collect(struct dl_phdr_info *info, size_t, void *data)
  {
    auto &names = *static_cast<std::vector<std::string> *>(data);
    const std::string path = info->dlpi_name ? info->dlpi_name : "";
    if (!path.empty() && path.find("linux-vdso") == std::string::npos)
      names.push_back(path.substr(path.find_last_of('/') + 1));
    return 0;
  }

  int
  position(const std::vector<std::string> &names, const std::string &prefix)
  {
    for (unsigned int i = 0; i < names.size(); ++i)
      if (names[i].rfind(prefix, 0) == 0)
        return static_cast<int>(i);
    return -1;
  }
} // namespace

int
main()
{
  // A call into the library, so that a link with --as-needed keeps it (and
  // with it deal.II and its closure) among this program's libraries.
  (void)Signorini::MpiEnvironment::facts_of_this_process();

  std::vector<std::string> names; // the executable itself has no name here
  dl_iterate_phdr(collect, &names);

  std::cout << "libraries loaded: " << (names.size() > 150 ? "> 150" : "<= 150")
            << '\n';
  std::cout << "first library is libdeal.ii: "
            << (position(names, "libdeal.ii.so") == 0 ? "yes" : "no") << '\n';
  for (const std::string library : {"libgmsh.so", "libopenblas.so"})
    {
      const int p = position(names, library);
      std::cout << library << " among the first ten: "
                << (p >= 0 && p < 10 ? "yes" : "no (" + std::to_string(p) + ")")
                << '\n';
    }
  const int parallel   = position(names, "libdmumps-");
  const int sequential = position(names, "libdmumps_seq");
  // The symbol both MUMPS builds define, as every caller in this process
  // binds it.
  Dl_info     info{};
  void *const entry = dlsym(RTLD_DEFAULT, "dmumps_c");
  const std::string defined_in =
    (entry != nullptr && dladdr(entry, &info) != 0 && info.dli_fname != nullptr) ?
      info.dli_fname :
      "";
  std::cout << "dmumps_c from the parallel MUMPS: "
            << (defined_in.find("libdmumps-") != std::string::npos ? "yes" :
                                                                     "no (" + defined_in + ")")
            << '\n';
  std::cout << "parallel MUMPS before the sequential one: "
            << (parallel >= 0 && (sequential < 0 || parallel < sequential) ?
                  "yes" :
                  "no")
            << '\n';
}
