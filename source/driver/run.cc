#include <signorini/driver/checkpoint.h>
#include <signorini/driver/mpi_environment.h>
#include <signorini/driver/rank_agreement.h>
#include <signorini/driver/run.h>
#include <signorini/driver/study.h>
#include <signorini/input_error.h>
#include <signorini/interruption.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <new>
#include <iostream>
#include <sstream>
#include <vector>

namespace Signorini
{
  namespace
  {
    /// Where a line of the expanded text of a parameter file comes from.
    struct SourceLine
    {
      std::string  file;
      unsigned int line;
    };

    /**
     * The text of a parameter file with its 'include' lines replaced by the
     * text of the files they name, and for each line of that text the file
     * and line it comes from.
     */
    struct ExpandedFile
    {
      std::string             text;
      std::vector<SourceLine> lines;
      std::vector<std::string> open_files; // canonical paths, for cycles
      // The first included file whose 'subsection' and 'end' lines do not
      // balance, and how many lines of the text precede its end (where
      // ParameterHandler, reading it alone, would have stopped).
      std::string unbalanced_file;
      std::size_t unbalanced_after = 0;
    };

    bool
    starts_with(const std::string &text, const std::string &prefix)
    {
      return text.compare(0, prefix.size(), prefix) == 0;
    }

    /**
     * A logical line as ParameterHandler::scan_line() reads it: without
     * its comment, tabs as spaces, trimmed.
     */
    std::string
    statement(std::string line)
    {
      if (const auto hash = line.find('#'); hash != std::string::npos)
        line.erase(hash);
      std::replace(line.begin(), line.end(), '\t', ' ');
      return Utilities::trim(line);
    }

    /**
     * The path under which @p included, written in an 'include' line of
     * @p including, is opened: relative paths are relative to the folder
     * of @p including (as the path of @p including is relative to the
     * working directory, so is the result). Written without '..' when
     * that names the same file (no symbolic link in between), also when
     * the file does not exist (for the message that says so).
     */
    std::string
    include_path(const std::string &including, const std::string &included)
    {
      const std::filesystem::path path(included);
      if (path.is_absolute())
        return included;
      const std::filesystem::path joined =
        std::filesystem::path(including).parent_path() / path;
      const std::filesystem::path normal = joined.lexically_normal();
      std::error_code             ec1, ec2;
      if (normal.empty() || normal == joined ||
          std::filesystem::weakly_canonical(joined, ec1) !=
            std::filesystem::weakly_canonical(normal, ec2) ||
          ec1 || ec2)
        return joined.string();
      return normal.string();
    }

    /**
     * Append @p file to @p out, following its 'include' lines. @p where is
     * "file:line" of the include line that names it (empty for the file of
     * the command line) and @p written its path as written there. Lines
     * are read as ParameterHandler reads them (trimmed, a trailing '\'
     * joins the next line, '#' starts a comment, "include " or "INCLUDE "
     * at the start); other lines are copied unchanged, so that
     * ParameterHandler reports their errors itself.
     */
    void
    expand(const std::string &file,
           const std::string &where,
           const std::string &written,
           ExpandedFile      &out)
    {
      const std::string at = where.empty() ? file : where;
      if (std::filesystem::is_directory(file))
        throw InputError(at, "'" + written + "' is a directory, not a parameter file");
      std::ifstream in(file);
      if (!in)
        throw InputError(at, where.empty() ? "cannot open the parameter file" :
                                             "cannot open the included file '" +
                                               written + "'" +
                                               (file == written ?
                                                  "" :
                                                  " (looked for " + file + ")"));
      std::error_code   ec;
      const std::string canonical =
        std::filesystem::weakly_canonical(file, ec).string();
      if (std::find(out.open_files.begin(), out.open_files.end(), canonical) !=
          out.open_files.end())
        throw InputError(at, "'" + written + "' includes itself (through " +
                               std::to_string(out.open_files.size()) + " file(s))");
      if (out.open_files.size() >= 32)
        throw InputError(at, "include files nested more than 32 deep");
      out.open_files.push_back(canonical);

      // The physical lines of the logical line being read.
      std::vector<std::pair<std::string, unsigned int>> pending;
      std::string                                      logical;
      bool                                             continued = false;
      int                                              depth     = 0;
      auto                                             flush     = [&]() {
        const std::string s = statement(logical);
        if (starts_with(s, "include ") || starts_with(s, "INCLUDE "))
          {
            const std::string name = Utilities::trim(s.substr(8));
            expand(include_path(file, name),
                   file + ":" + std::to_string(pending.front().second),
                   name,
                   out);
          }
        else
          {
            if (starts_with(s, "subsection ") || starts_with(s, "SUBSECTION "))
              ++depth;
            else if (s == "end" || s == "END")
              --depth;
            for (const auto &[text, number] : pending)
              {
                out.text += text + "\n";
                out.lines.push_back({file, number});
              }
          }
        pending.clear();
        logical.clear();
      };

      std::string line;
      for (unsigned int number = 1; std::getline(in, line); ++number)
        {
          pending.emplace_back(line, number);
          std::string trimmed = Utilities::trim(line);
          continued = !trimmed.empty() && trimmed.back() == '\\';
          if (continued)
            trimmed.pop_back();
          logical += trimmed;
          if (!continued)
            flush();
        }
      if (continued)
        {
          // ParameterHandler reads the last line of a file even if it ends
          // in '\'; an empty line keeps it from joining the next file's.
          const unsigned int last = pending.back().second;
          flush();
          out.text += "\n";
          out.lines.push_back({file, last});
        }
      if (!where.empty() && depth != 0 && out.unbalanced_file.empty())
        {
          out.unbalanced_file  = file;
          out.unbalanced_after = out.lines.size();
        }
      out.open_files.pop_back();
    }

    /**
     * If @p message starts as ParameterHandler's "Line <N> of file <NAME>"
     * (some of its messages lack the '>'), N and the rest of the message.
     */
    bool
    split_line_message(const std::string &message,
                       const std::string &name,
                       std::size_t       &number,
                       std::string       &rest)
    {
      const std::string head = "Line <";
      if (!starts_with(message, head))
        return false;
      std::size_t end = head.size();
      while (end < message.size() && std::isdigit(message[end]))
        ++end;
      if (end == head.size())
        return false;
      const std::string tail = message.substr(end);
      for (const std::string &sep : {"> of file <" + name + ">: ",
                                    "> of file <" + name + ": "})
        if (starts_with(tail, sep))
          {
            number = std::stoul(message.substr(head.size(), end - head.size()));
            rest   = tail.substr(sep.size());
            return true;
          }
      return false;
    }

    void
    print_usage(std::ostream &out)
    {
      out << "Usage: signorini FILE.prm\n"
             "       signorini --study FILE.prm   (the accuracy-versus-time "
             "study of its Study subsection)\n"
             "       signorini --check FILE.prm ...   (read and check the "
             "input only: no solve, nothing written)\n"
             "       signorini --restart DIR [FILE.prm]   (continue the run "
             "whose output directory is DIR\n"
             "                 from its newest checkpoint, on any number of "
             "MPI ranks; FILE.prm may\n"
             "                 extend End time or Number of cycles)\n"
             "       signorini --print-parameters   (every entry with its "
             "default, pattern and documentation)\n"
             "       signorini --help\n\n"
             "Solves the scene described by FILE.prm (see prm/ and doc/) and "
             "writes summary.json,\nused_parameters.prm, VTU/PVTU + .pvd and "
             "CSV files into its output directory.\n"
             "Run in parallel with: mpirun -np N signorini FILE.prm\n"
             "'include PATH' in a parameter file reads PATH relative to the "
             "folder of the file\nthat contains the line; other relative "
             "paths (Mesh > Gmsh file, Solver > Ipopt >\nOptions file) are "
             "relative to the folder of FILE.prm.\n"
             "Exit status: 0 converged (--check: valid input), 2 bad input, 3 solve failed (last "
             "converged step kept),\n4 a quantity is outside its "
             "requested tolerance, 1 internal error, 130 / 143 interrupted by\n"
             "SIGINT / SIGTERM (checkpoint of the last converged step written; "
             "a second signal exits at once).\n";
    }

    /// Build the scene (mesh, DoFs, every input check) without solving.
    template <int dim>
    void
    check_scene(ParameterHandler &prm, const std::string &file)
    {
      Simulator<dim> simulator(prm, file, /*quiet=*/true, MPI_COMM_WORLD);
    }

    template <int dim>
    Report
    run_scene(ParameterHandler  &prm,
              const std::string &file,
              const bool         quiet,
              const std::string &checkpoint = "")
    {
      Simulator<dim> simulator(prm, file, quiet, MPI_COMM_WORLD, checkpoint);
      return simulator.run(prm);
    }
  } // namespace

  void
  read_parameter_file(ParameterHandler &prm, const std::string &file)
  {
    std::string extension = std::filesystem::path(file).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](const unsigned char c) { return std::tolower(c); });
    if (extension != ".prm")
      {
        // ParameterHandler reads .xml and .json itself (they have no
        // 'include') and refuses other extensions.
        if (std::filesystem::is_directory(file))
          throw InputError(file, "'" + file + "' is a directory, not a parameter file");
        if (!std::ifstream(file))
          throw InputError(file, "cannot open the parameter file");
        try
          {
            prm.parse_input(file);
          }
        catch (const std::exception &e)
          {
            throw InputError(file, essential_message(e.what()));
          }
        return;
      }

    ExpandedFile expanded;
    expand(file, "", file, expanded);
    const InputError unbalanced(expanded.unbalanced_file,
                                "unequal numbers of 'subsection' and 'end' "
                                "lines: an included file must end every "
                                "subsection it enters, and only those");
    try
      {
        std::istringstream in(expanded.text);
        prm.parse_input(in, file, "", false);
      }
    catch (const std::exception &e)
      {
        const std::string message = essential_message(e.what());
        std::size_t       number  = 0;
        std::string       rest;
        const bool        has_line =
          split_line_message(message, file, number, rest) && number >= 1 &&
          number <= expanded.lines.size();
        // ParameterHandler, reading the included files one by one, would
        // have stopped at the end of an unbalanced one.
        if (!expanded.unbalanced_file.empty() &&
            (!has_line || number > expanded.unbalanced_after))
          throw unbalanced;
        if (has_line)
          {
            const SourceLine &source = expanded.lines[number - 1];
            throw InputError(source.file + ":" + std::to_string(source.line), rest);
          }
        throw InputError(file, message);
      }
    if (!expanded.unbalanced_file.empty())
      throw unbalanced;
  }

  namespace
  {
    /**
     * Run @p body for the parameter file @p file and turn its exceptions
     * into a message on rank 0 and an exit code: 2 for bad input, 1 for
     * anything else. An error that ends the run on some ranks only would
     * leave the others waiting in a collective operation: the failed rank
     * then prints its error and aborts the MPI job (driver/rank_agreement.h).
     */
    int
    guarded(const std::string &file, const bool root, const std::function<int()> &body)
    {
      int         code = internal_error;
      std::string message;
      try
        {
          return body();
        }
      catch (const InputError &e)
        {
          code    = input_error;
          message = std::string("signorini: error: ") + e.what();
        }
      catch (const std::bad_alloc &)
        {
          code    = input_error;
          message = "signorini: error: " + file +
                    ": out of memory: the scene needs more memory than "
                    "this machine has (reduce Mesh > Global refinements, "
                    "Local refinements or a body's Subdivisions)";
        }
      catch (const std::exception &e)
        {
          const std::string what = essential_message(e.what());
          // A number the pattern accepts but std::stod cannot hold (e.g. a
          // subnormal 1e-320, or beyond 1.8e308) is bad input, not a bug.
          if (what.find("Can't convert the parameter value") != std::string::npos)
            {
              code    = input_error;
              message = "signorini: error: " + file + ": " + what +
                        " (out of the range of a double: |x| must lie "
                        "between 2.2e-308 and 1.8e308, or be 0)";
            }
          else
            {
              code    = internal_error;
              message = "signorini: internal error: " + what;
            }
        }
      if (!RankAgreement::all_ranks_failed(RankAgreement::default_wait))
        {
          std::cerr << message << "\nsignorini: MPI rank "
                    << Utilities::MPI::this_mpi_process(MPI_COMM_WORLD)
                    << " failed alone (the other ranks did not within "
                    << RankAgreement::default_wait
                    << " s): aborting the run" << std::endl;
          MPI_Abort(MPI_COMM_WORLD, code);
        }
      if (root)
        std::cerr << message << std::endl;
      return code;
    }

    /// The result of a run on the screen: its quantities with their
    /// references and estimated errors, the target accuracy, the summary.
    void
    print_result(const Report &report)
    {
      std::cout << "\nResult (" << report.status << ", "
                << report.steps.size() << " load steps, "
                << report.iterations
                << (report.iteration_name == "ipopt"          ? " Ipopt" :
                    report.iteration_name == "interior_point" ? " interior point" :
                                                                " Newton")
                << " iterations):\n";
      for (const auto &q : report.quantities)
        {
          std::cout << "  " << q.name << " = " << std::setprecision(8)
                    << q.value;
          if (q.has_reference)
            std::cout << "   reference " << q.reference
                      << "   relative error " << std::setprecision(3)
                      << q.relative_error()
                      << (q.within_tolerance() ? "" : "   OUTSIDE TOLERANCE");
          if (q.has_estimate)
            {
              std::cout << "   estimated error " << std::setprecision(2)
                        << q.estimated_error;
              if (q.estimated_error > 0.)
                std::cout << " (relative " << q.estimated_relative_error()
                          << ", order " << q.observed_order << ")";
            }
          std::cout << "\n";
        }
      if (report.target_accuracy > 0.)
        {
          std::cout << "Target accuracy " << report.target_accuracy
                    << (report.target_met ? " met" : " NOT MET") << " after "
                    << report.last_cycle()
                    << " refinement cycles";
          if (!report.target_unmet.empty())
            {
              std::cout << "; above it:";
              for (const auto &name : report.target_unmet)
                std::cout << " " << name;
            }
          std::cout << "\n";
        }
      std::cout << "Summary: " << report.output_directory << "/summary.json"
                << std::endl;
    }

    /// signorini --check FILE...: each file on its own, so that every bad
    /// one is reported; the worst exit code.
    int
    check_files(const std::vector<std::string> &args, const bool root)
    {
      int worst = success;
      for (const std::string &file : args)
        {
          const int code = guarded(file, root, [&]() {
            ParameterHandler scene;
            declare_parameters(scene);
            read_parameter_file(scene, file);
            const unsigned int dim = scene.get_integer("Dimension");
            if (dim == 2)
              check_scene<2>(scene, file);
            else
              check_scene<3>(scene, file);
            if (root)
              std::cout << file << ": the input is valid (" << dim << "D)"
                        << std::endl;
            return int(success);
          });
          if (worst != internal_error && code != success)
            worst = code;
        }
      return worst;
    }
  } // namespace

  int
  run_program(int                                        argc,
              char                                     **argv,
              const bool                                 quiet,
              const std::function<void(const Report &)> &on_report)
  {
    // Open MPI settings that only save start-up time, unless the user
    // chose otherwise (driver/mpi_environment.h); summary.json lists them.
    MpiEnvironment::prepare();
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, numbers::invalid_unsigned_int);
    RankAgreement::initialize();
    const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    // deal.II prints exceptions to stderr when they are created in debug
    // mode; keep the user's screen to our own message.
    deal_II_exceptions::disable_abort_on_exception();

    ParameterHandler prm;
    declare_parameters(prm);

    std::vector<std::string> args(argv + 1, argv + argc);
    if (args.size() == 1 && (args[0] == "--help" || args[0] == "-h"))
      {
        if (root)
          print_usage(std::cout);
        return success;
      }
    if (args.size() == 1 && args[0] == "--print-parameters")
      {
        if (root)
          prm.print_parameters(std::cout, ParameterHandler::PRM);
        return success;
      }
    const bool study   = (args.size() == 2 && args[0] == "--study");
    const bool check   = (args.size() >= 2 && args[0] == "--check");
    const bool restart = ((args.size() == 2 || args.size() == 3) &&
                          args[0] == "--restart");
    if (study || check || restart)
      args.erase(args.begin());
    const bool names_files =
      std::none_of(args.begin(), args.end(), [](const std::string &a) {
        return a.empty() || a[0] == '-';
      });
    if ((args.size() != 1 && !check && !(restart && args.size() == 2)) ||
        !names_files)
      {
        if (root)
          {
            std::cerr << "signorini: expected exactly one parameter file "
                         "(--check: one or more)\n";
            print_usage(std::cerr);
          }
        return input_error;
      }

    if (check)
      return check_files(args, root);

    // The report on the screen and the exit code of a run.
    auto finish = [&](const Report &report) -> int {
      bool in_tolerance = true;
      for (const auto &q : report.quantities)
        in_tolerance &= q.within_tolerance();
      // A target accuracy that the cycles did not reach is a tolerance
      // the run missed.
      const bool target_missed =
        report.target_accuracy > 0. && !report.target_met &&
        report.status == "converged";
      in_tolerance &= !target_missed;

      if (root && !quiet)
        print_result(report);
      if (root && on_report)
        on_report(report);

      if (report.status == "interrupted")
        {
          if (root)
            std::cerr << "signorini: interrupted: " << report.reason << std::endl;
          return 128 + report.interrupt_signal;
        }
      if (report.status != "converged")
        {
          if (root)
            std::cerr << "signorini: the solve failed: " << report.reason
                      << std::endl;
          return solve_failed;
        }
      return in_tolerance ? success : out_of_tolerance;
    };

    // A run stops cleanly on SIGINT/SIGTERM from here on (a signal during
    // its setup stops it at its first load step, with a checkpoint at t = 0).
    if (!study)
      Interruption::install();

    if (restart)
      {
        const std::string directory = args[0];
        return guarded(directory, root, [&]() -> int {
          const std::string        folder = Checkpoint::newest(directory);
          // On any number of ranks (Simulator::restore()).
          const Checkpoint::Header header = Checkpoint::read_header(folder);
          std::string file;
          if (args.size() == 2)
            {
              file = args[1];
              read_parameter_file(prm, file);
            }
          else
            {
              // The checkpoint's own parameters, named as the original file
              // (relative paths in them are relative to its folder).
              file = header.parameter_file;
              std::istringstream in(header.parameters);
              prm.parse_input(in, file, "", false);
            }
          const auto changes = Checkpoint::incompatible_changes(header.parameters, prm);
          if (!changes.empty())
            {
              std::string list;
              for (const auto &c : changes)
                list += "\n  " + c;
              throw InputError(args.size() == 2 ? args[1] : "--restart",
                               "the checkpoint " + folder +
                                 " cannot continue with changed entries (only "
                                 "Load stepping > End time, Mesh refinement > "
                                 "Number of cycles, Output directory, Output and "
                                 "Checkpoint may change):" + list);
            }
          // The run's output directory holds checkpoints/checkpoint-N.
          prm.set("Output directory",
                  std::filesystem::path(folder).parent_path().parent_path().string());
          const Report report =
            (header.dimension == 2 ? run_scene<2>(prm, file, quiet, folder) :
                                     run_scene<3>(prm, file, quiet, folder));
          return finish(report);
        });
      }

    const std::string file = args[0];
    return guarded(file, root, [&]() -> int {
      read_parameter_file(prm, file);
      if (study)
        return Study::run(file, prm, MPI_COMM_WORLD);
      const unsigned int dim = prm.get_integer("Dimension");
      const Report       report =
        (dim == 2 ? run_scene<2>(prm, file, quiet) : run_scene<3>(prm, file, quiet));
      return finish(report);
    });
  }
} // namespace Signorini
