#include <signorini/input_error.h>
#include <signorini/run.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <fstream>
#include <iomanip>
#include <iostream>

namespace Signorini
{
  namespace
  {
    void
    print_usage(std::ostream &out)
    {
      out << "Usage: signorini FILE.prm\n"
             "       signorini --print-parameters   (every entry with its "
             "default, pattern and documentation)\n"
             "       signorini --help\n\n"
             "Solves the scene described by FILE.prm (see prm/ and doc/) and "
             "writes summary.json,\nused_parameters.prm, VTU/PVTU + .pvd and "
             "CSV files into its output directory.\n"
             "Run in parallel with: mpirun -np N signorini FILE.prm\n"
             "Exit status: 0 converged, 2 bad input, 3 solve failed (last "
             "converged step kept),\n4 a quantity is outside its "
             "requested tolerance, 1 internal error.\n";
    }

    template <int dim>
    Report
    run_scene(ParameterHandler &prm, const std::string &file, const bool quiet)
    {
      Simulator<dim> simulator(prm, file, quiet, MPI_COMM_WORLD);
      return simulator.run(prm);
    }
  } // namespace

  int
  run_program(int                                        argc,
              char                                     **argv,
              const bool                                 quiet,
              const std::function<void(const Report &)> &on_report)
  {
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, numbers::invalid_unsigned_int);
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
    if (args.size() != 1 || args[0].empty() || args[0][0] == '-')
      {
        if (root)
          {
            std::cerr << "signorini: expected exactly one parameter file\n";
            print_usage(std::cerr);
          }
        return input_error;
      }
    const std::string file = args[0];

    try
      {
        {
          std::ifstream in(file);
          if (!in)
            throw InputError(file, "cannot open the parameter file");
        }
        try
          {
            prm.parse_input(file);
          }
        catch (const std::exception &e)
          {
            throw InputError(file, essential_message(e.what()));
          }

        const unsigned int dim = prm.get_integer("Dimension");
        const Report report =
          (dim == 2 ? run_scene<2>(prm, file, quiet) :
                      run_scene<3>(prm, file, quiet));

        bool in_tolerance = true;
        for (const auto &q : report.quantities)
          in_tolerance &= q.within_tolerance();

        if (root && !quiet)
          {
            std::cout << "\nResult (" << report.status << ", "
                      << report.steps.size() << " load steps, "
                      << report.newton_iterations
                      << (report.solver == "ipopt" ? " Ipopt" : " Newton")
                      << " iterations):\n";
            for (const auto &q : report.quantities)
              {
                std::cout << "  " << q.name << " = " << std::setprecision(8)
                          << q.value;
                if (q.has_reference)
                  std::cout << "   reference " << q.reference
                            << "   relative error " << std::setprecision(3)
                            << q.relative_error()
                            << (q.within_tolerance() ? "" :
                                                       "   OUTSIDE TOLERANCE");
                std::cout << "\n";
              }
            std::cout << "Summary: " << report.output_directory
                      << "/summary.json" << std::endl;
          }
        if (root && on_report)
          on_report(report);

        if (report.status != "converged")
          {
            if (root)
              std::cerr << "signorini: the solve failed: " << report.reason
                        << std::endl;
            return solve_failed;
          }
        return in_tolerance ? success : out_of_tolerance;
      }
    catch (const InputError &e)
      {
        if (root)
          std::cerr << "signorini: error: " << e.what() << std::endl;
        return input_error;
      }
    catch (const std::exception &e)
      {
        if (root)
          std::cerr << "signorini: internal error: "
                    << essential_message(e.what()) << std::endl;
        return internal_error;
      }
  }
} // namespace Signorini
