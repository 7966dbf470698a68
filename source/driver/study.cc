#include <signorini/input_error.h>
#include <signorini/output/json.h>
#include <signorini/driver/run.h>
#include <signorini/driver/simulator.h>
#include <signorini/driver/study.h>
#include <signorini/parameters/study_parameters.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <malloc.h>
#include <map>
#include <set>
#include <sstream>

#ifndef SIGNORINI_SOURCE_DIR
#  define SIGNORINI_SOURCE_DIR "."
#endif

namespace Signorini
{
  namespace Study
  {
    namespace
    {

      // Phases reported per row (TimerOutput sections of a run).
      const std::vector<std::string> phases = {"assembly",
                                               "contact",
                                               "linear solve",
                                               "line search",
                                               "sparsity pattern",
                                               "constraints",
                                               "refinement",
                                               "postprocessing",
                                               "output"};

      struct Variant
      {
        std::string              name;
        std::string              settings;
        std::string              series_entry;
        std::vector<std::string> series_values;
        std::string              key; // for error messages
      };

      struct Row
      {
        std::string                   variant;
        std::string                   run;   // series value
        int                           cycle = -1;
        std::string                   status;
        unsigned long long            cells = 0, dofs = 0;
        unsigned int                  contact_nodes = 0;
        unsigned int                  iterations    = 0;
        double                        wall          = 0.;
        double                        memory_mb     = 0.;
        std::map<std::string, double> timing;
        std::map<std::string, double> value, reference;
      };

      void
      set_entry(ParameterHandler  &prm,
                const std::string &path,
                const std::string &value,
                const std::string &key)
      {
        const auto parts = Utilities::split_string_list(path, '/');
        for (unsigned int i = 0; i + 1 < parts.size(); ++i)
          prm.enter_subsection(parts[i]);
        try
          {
            prm.set(parts.back(), value);
          }
        catch (const std::exception &e)
          {
            for (unsigned int i = 0; i + 1 < parts.size(); ++i)
              prm.leave_subsection();
            throw InputError(key, "cannot set '" + path + " = " + value +
                                    "': " + essential_message(e.what()));
          }
        for (unsigned int i = 0; i + 1 < parts.size(); ++i)
          prm.leave_subsection();
      }

      /// Apply "a/b/entry = value; ..." to @p prm.
      void
      apply(ParameterHandler &prm, const std::string &assignments, const std::string &key)
      {
        for (const auto &item : Utilities::split_string_list(assignments, ';'))
          {
            if (item.empty())
              continue;
            const auto eq = item.find('=');
            if (eq == std::string::npos)
              throw InputError(key, "'" + item + "' is not of the form "
                                    "Subsection/Entry = value");
            set_entry(prm,
                      Utilities::trim(item.substr(0, eq)),
                      Utilities::trim(item.substr(eq + 1)),
                      key);
          }
      }

      std::string
      file_name(std::string s)
      {
        for (auto &c : s)
          if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '.')
            c = '_';
        return s;
      }

      void
      reset_peak_memory()
      {
        // Linux: writing 5 to clear_refs resets VmHWM to the present
        // resident size, so that each run of the study reports its own
        // peak. The previous run's memory is freed but kept by malloc for
        // reuse (still resident): return it to the system first, or the
        // reset changes nothing (every row showed the largest run's peak).
        malloc_trim(0);
        std::ofstream("/proc/self/clear_refs") << "5";
      }

      template <int dim>
      Report
      run_scene(ParameterHandler &prm, const std::string &file, MPI_Comm comm)
      {
        Simulator<dim> simulator(prm, file, true, comm);
        return simulator.run(prm);
      }

      /// What the "Study" subsection asks for.
      struct Settings
      {
        std::vector<std::string> quantities, reported;
        std::string              reference_variant;
        double                   accuracy;
        bool                     write_fields;
        std::vector<Variant>     variants;
      };

      /// The converged solution of the discrete model, per quantity: its
      /// value, how it was found and, for an extrapolation, the observed
      /// order of convergence in h.
      struct ConvergedModel
      {
        std::map<std::string, double>      value;
        std::map<std::string, std::string> how;
        std::map<std::string, double>      order;
      };

      /// A variant's first run (by wall time) within the accuracy.
      struct Reached
      {
        bool               found = false;
        unsigned long long dofs  = 0;
        double             wall  = 0.;
        std::string        run;
        int                cycle = -1;
      };

      /// The error of @p v relative to @p ref.
      double
      relative_error(const double v, const double ref)
      {
        return std::abs(v - ref) / std::abs(ref);
      }

      /// Read the "Study" subsection and check that it names variants,
      /// quantities and an existing reference variant.
      Settings
      read_settings(ParameterHandler &prm, const std::string &file)
      {
        Settings settings;
        prm.enter_subsection("Study");
        settings.quantities = Utilities::split_string_list(prm.get("Quantities"));
        settings.reported =
          Utilities::split_string_list(prm.get("Reported quantities"));
        settings.reference_variant = Utilities::trim(prm.get("Reference variant"));
        settings.accuracy          = prm.get_double("Accuracy");
        settings.write_fields      = prm.get_bool("Write fields");
        for (unsigned int v = 0; v < max_variants; ++v)
          {
            prm.enter_subsection("Variant " + std::to_string(v + 1));
            Variant variant;
            variant.name = Utilities::trim(prm.get("Name"));
            variant.key  = "Study > Variant " + std::to_string(v + 1);
            variant.settings      = prm.get("Settings");
            variant.series_entry  = Utilities::trim(prm.get("Series entry"));
            variant.series_values = Utilities::split_string_list(prm.get("Series values"));
            prm.leave_subsection();
            if (variant.name.empty())
              continue;
            if (!variant.series_entry.empty() && variant.series_values.empty())
              throw InputError(variant.key + " > Series values",
                               "the series entry '" + variant.series_entry +
                                 "' has no values");
            for (const auto &other : settings.variants)
              if (other.name == variant.name)
                throw InputError(variant.key + " > Name",
                                 "two variants are called '" + variant.name + "'");
            settings.variants.push_back(variant);
          }
        prm.leave_subsection();
        if (settings.variants.empty())
          throw InputError(file, "the study declares no variant (Study > Variant 1 > Name)");
        if (settings.quantities.empty())
          throw InputError("Study > Quantities", "names no quantity");
        if (std::none_of(settings.variants.begin(), settings.variants.end(),
                         [&](const Variant &v) {
                           return v.name == settings.reference_variant;
                         }))
          throw InputError("Study > Reference variant",
                           "'" + settings.reference_variant +
                             "' is not the Name of a variant");
        return settings;
      }

      /// Create the study's output directory (collective).
      void
      create_directory(const std::string &directory, const bool root, MPI_Comm comm)
      {
        // Rank 0 creates it; a failure is every rank's error.
        std::string error;
        if (root)
          {
            std::error_code ec;
            std::filesystem::create_directories(directory, ec);
            if (ec)
              error = ec.message();
          }
        error = Utilities::MPI::broadcast(comm, error, 0);
        if (!error.empty())
          throw InputError("Output directory",
                           "cannot create '" + directory + "': " + error);
      }

      /// Apply every variant's settings and series values to a fresh copy
      /// of the scene's parameters, so that a mistake in the last variant
      /// shows before the first run rather than hours later.
      void
      check_variants(const std::vector<Variant> &variants, const std::string &file)
      {
        for (const auto &variant : variants)
          {
            ParameterHandler check;
            ::Signorini::declare_parameters(check);
            read_parameter_file(check, file);
            apply(check, variant.settings, variant.key + " > Settings");
            if (!variant.series_entry.empty())
              for (const auto &value : variant.series_values)
                set_entry(check, variant.series_entry, value, variant.key + " > Series entry");
          }
      }

      /// The values of a variant's series; one empty value for a variant
      /// without a series entry (a single run).
      std::vector<std::string>
      series_of(const Variant &variant)
      {
        return variant.series_entry.empty() ? std::vector<std::string>{""} :
                                              variant.series_values;
      }

      /// Run the scene of @p file with the variant's settings and the
      /// series value @p value (empty: none), quietly and into its own
      /// folder, and print one line about it (collective).
      Report
      run_one(const std::string &file,
              const Variant     &variant,
              const std::string &value,
              const std::string &directory,
              const bool         write_fields,
              MPI_Comm           comm)
      {
        const bool       root = Utilities::MPI::this_mpi_process(comm) == 0;
        ParameterHandler run_prm;
        ::Signorini::declare_parameters(run_prm);
        read_parameter_file(run_prm, file);
        apply(run_prm, variant.settings, variant.key + " > Settings");
        if (!variant.series_entry.empty())
          set_entry(run_prm, variant.series_entry, value,
                    variant.key + " > Series entry");
        const std::string out =
          directory + "/" + file_name(variant.name) +
          (value.empty() ? std::string() : "-" + file_name(value));
        run_prm.set("Output directory", out);
        run_prm.enter_subsection("Output");
        run_prm.set("Verbosity", "quiet");
        if (!write_fields)
          run_prm.set("Format", "none");
        run_prm.leave_subsection();
        if (root)
          std::cout << "Study: " << variant.name
                    << (value.empty() ? "" : ", " + variant.series_entry +
                                               " = " + value)
                    << " ..." << std::flush;
        reset_peak_memory();
        Parameters::Global run_scene_parameters;
        run_scene_parameters.parse_parameters(run_prm, file);
        const unsigned int dim    = run_scene_parameters.dimension;
        const Report       report = dim == 2 ? run_scene<2>(run_prm, file, comm) :
                                         run_scene<3>(run_prm, file, comm);
        if (root)
          std::cout << " " << report.status << ", " << report.n_dofs
                    << " DoFs, " << std::setprecision(3)
                    << report.timing.at("total") << " s" << std::endl;
        return report;
      }

      /// Add the rows of one run to @p rows: one for the run, or one per
      /// refinement cycle.
      void
      add_rows(std::vector<Row>  &rows,
               const Variant     &variant,
               const std::string &value,
               const Report      &report)
      {
        auto make_row = [&](const std::vector<Quantity> &qs) {
          Row row;
          row.variant   = variant.name;
          row.run       = value;
          row.status    = report.status;
          row.memory_mb = report.peak_memory_mb;
          for (const auto &q : qs)
            {
              row.value[q.name] = q.value;
              if (q.has_reference)
                row.reference[q.name] = q.reference;
            }
          return row;
        };
        if (report.cycles.empty())
          {
            Row row           = make_row(report.quantities);
            row.cells         = report.n_cells;
            row.dofs          = report.n_dofs;
            row.contact_nodes = report.contact_nodes;
            row.iterations    = report.iterations;
            row.wall          = report.timing.at("total");
            row.timing        = report.timing;
            rows.push_back(row);
          }
        else
          {
            unsigned int iterations = 0;
            for (const auto &c : report.cycles)
              {
                Row row = make_row(c.quantities);
                iterations += c.iterations;
                row.cycle         = c.cycle;
                row.cells         = c.n_cells;
                row.dofs          = c.n_dofs;
                row.contact_nodes = c.contact_nodes;
                row.iterations    = iterations; // up to this cycle
                row.wall          = c.wall_seconds;
                row.timing        = c.timing;
                rows.push_back(row);
              }
          }
      }

      /// The converged solution of the discrete model from the reference
      /// variant's converged runs: Richardson extrapolation of the three
      /// finest where they converge monotonically, else the finest.
      ConvergedModel
      converged_model(const std::vector<Row> &rows,
                      const Settings         &settings,
                      const unsigned int      dimension)
      {
        std::vector<const Row *> finest;
        for (const auto &row : rows)
          if (row.variant == settings.reference_variant && row.status == "converged")
            finest.push_back(&row);
        std::sort(finest.begin(), finest.end(),
                  [](const Row *a, const Row *b) { return a->dofs < b->dofs; });
        ConvergedModel model;
        for (const auto &q : settings.quantities)
          {
            if (finest.empty() || finest.back()->value.count(q) == 0)
              throw SolveFailure("the reference variant '" + settings.reference_variant +
                                 "' has no converged run with quantity " + q);
            const double q3 = finest.back()->value.at(q);
            model.value[q]  = q3;
            model.how[q]    = "finest run";
            if (finest.size() >= 3)
              {
                const Row   &r1 = *finest[finest.size() - 3];
                const Row   &r2 = *finest[finest.size() - 2];
                const double q1 = r1.value.at(q), q2 = r2.value.at(q);
                const double d1 = q2 - q1, d2 = q3 - q2;
                if (d1 * d2 > 0. && std::abs(d2) < std::abs(d1))
                  {
                    const double ratio = d1 / d2;
                    model.value[q]     = q3 + d2 / (ratio - 1.);
                    model.how[q] = "Richardson extrapolation of the three finest runs";
                    // Rate in h ~ DoFs^(-1/dim): log(ratio) / log(h1/h2).
                    const double h_ratio =
                      std::pow(static_cast<double>(r2.dofs) / r1.dofs, 1. / dimension);
                    model.order[q] = std::log(ratio) / std::log(h_ratio);
                  }
              }
          }
        return model;
      }

      /// Per variant (every one, reached or not): the first converged row
      /// (by wall time) within the accuracy for every quantity.
      std::map<std::string, Reached>
      first_within_accuracy(const std::vector<Row> &rows,
                            const Settings         &settings,
                            const ConvergedModel   &model)
      {
        std::map<std::string, Reached> reached;
        for (const auto &variant : settings.variants)
          reached[variant.name] = Reached();
        for (const auto &row : rows)
          {
            if (row.status != "converged")
              continue;
            bool ok = true;
            for (const auto &q : settings.quantities)
              ok &= row.value.count(q) > 0 &&
                    relative_error(row.value.at(q), model.value.at(q)) <=
                      settings.accuracy;
            auto &r = reached[row.variant];
            if (ok && (!r.found || row.wall < r.wall))
              r = {true, row.dofs, row.wall, row.run, row.cycle};
          }
        return reached;
      }

      /// study.csv: one line per run or cycle, with its phases' times and
      /// its quantities' errors.
      void
      write_csv(const std::string      &file,
                const std::vector<Row> &rows,
                const Settings         &settings,
                const ConvergedModel   &model)
      {
        std::ofstream csv(file);
        csv << "variant,run,cycle,status,cells,dofs,contact_nodes,iterations,"
               "wall_time,peak_memory_mb";
        for (const auto &p : phases)
          csv << ",time_" << file_name(p);
        for (const auto &q : settings.quantities)
          csv << "," << q << "," << q << "_error_analytic," << q
              << "_error_converged";
        for (const auto &q : settings.reported)
          csv << "," << q;
        csv << "\n" << std::setprecision(10);
        for (const auto &row : rows)
          {
            // Names may hold commas: quoted, as CSV readers expect.
            csv << '"' << row.variant << "\",\"" << row.run << "\"," << row.cycle << ","
                << row.status << "," << row.cells << "," << row.dofs << ","
                << row.contact_nodes << "," << row.iterations << "," << row.wall
                << "," << row.memory_mb;
            for (const auto &p : phases)
              csv << "," << (row.timing.count(p) ? row.timing.at(p) : 0.);
            for (const auto &q : settings.quantities)
              {
                if (row.value.count(q) == 0)
                  {
                    csv << ",,,";
                    continue;
                  }
                csv << "," << row.value.at(q) << ",";
                if (row.reference.count(q))
                  csv << relative_error(row.value.at(q), row.reference.at(q));
                csv << "," << relative_error(row.value.at(q), model.value.at(q));
              }
            for (const auto &q : settings.reported)
              {
                csv << ",";
                if (row.value.count(q) && std::isfinite(row.value.at(q)))
                  csv << row.value.at(q);
              }
            csv << "\n";
          }
      }

      /// The content of study.json.
      Json
      study_json(const std::string                    &file,
                 const Settings                       &settings,
                 const ConvergedModel                 &model,
                 const std::map<std::string, Reached> &reached)
      {
        Json j = Json::object();
        j["parameter file"]    = file;
        j["reference variant"] = settings.reference_variant;
        j["accuracy"]          = settings.accuracy;
        if (!settings.reported.empty())
          {
            Json list = Json::array();
            for (const auto &q : settings.reported)
              list.push_back(Json(q));
            j["reported quantities"] = list;
          }
        Json &c = j["converged model"];
        for (const auto &q : settings.quantities)
          {
            Json o      = Json::object();
            o["value"]  = model.value.at(q);
            o["method"] = model.how.at(q);
            if (model.order.count(q))
              o["observed order in h"] = model.order.at(q);
            c[q] = o;
          }
        Json &r = j["first run within the accuracy"];
        for (const auto &variant : settings.variants)
          {
            Json        o = Json::object();
            const auto &x = reached.at(variant.name);
            o["reached"]  = x.found;
            if (x.found)
              {
                o["dofs"]          = x.dofs;
                o["wall time [s]"] = x.wall;
                if (!x.run.empty())
                  o["run"] = x.run;
                if (x.cycle >= 0)
                  o["cycle"] = x.cycle;
              }
            r[variant.name] = o;
          }
        return j;
      }

      /// Print the converged model and each variant's first run within
      /// the accuracy.
      void
      print_results(const Settings                       &settings,
                    const ConvergedModel                 &model,
                    const std::map<std::string, Reached> &reached)
      {
        std::cout << "\nConverged model (" << settings.reference_variant << "):";
        for (const auto &q : settings.quantities)
          std::cout << " " << q << " = " << std::setprecision(8) << model.value.at(q)
                    << " (" << model.how.at(q) << ")";
        std::cout << "\nFirst run within " << settings.accuracy
                  << " of it for every quantity:\n";
        for (const auto &variant : settings.variants)
          {
            const auto &x = reached.at(variant.name);
            std::cout << "  " << std::left << std::setw(28) << variant.name;
            if (x.found)
              std::cout << x.dofs << " DoFs, " << std::setprecision(3) << x.wall
                        << " s";
            else
              std::cout << "not reached";
            std::cout << "\n";
          }
      }

      /// Draw the study's plots with scripts/plot_study.py, or say how to
      /// get them where matplotlib is missing.
      void
      plot(const std::string &directory)
      {
        const std::string script =
          std::string(SIGNORINI_SOURCE_DIR) + "/scripts/plot_study.py";
        // Debian's interpreter has Debian's python3-matplotlib.
        const std::string python =
          std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
        if (std::filesystem::exists(script) &&
            std::system((python + " -c 'import matplotlib' > /dev/null 2>&1").c_str()) == 0)
          {
            const std::string command = python + " " + script + " " + directory;
            if (std::system(command.c_str()) != 0)
              std::cerr << "signorini: the plots failed: " << command << std::endl;
          }
        else
          std::cout << "Plots: python3-matplotlib is not installed (apt-get "
                       "install python3-matplotlib), then run python3 "
                    << script << " " << directory << std::endl;
      }
    } // namespace

    int
    run(const std::string &file, ParameterHandler &prm, MPI_Comm comm)
    {
      const bool     root     = Utilities::MPI::this_mpi_process(comm) == 0;
      const Settings settings = read_settings(prm, file);

      Parameters::Global scene;
      scene.parse_parameters(prm, file);
      const std::string directory = scene.output_directory + "/study";
      create_directory(directory, root, comm);
      // Check every variant's settings before the first run.
      check_variants(settings.variants, file);

      std::vector<Row> rows;
      bool             all_converged = true;
      for (const auto &variant : settings.variants)
        for (const auto &value : series_of(variant))
          {
            const Report report =
              run_one(file, variant, value, directory, settings.write_fields, comm);
            all_converged &= (report.status == "converged");
            add_rows(rows, variant, value, report);
          }

      const ConvergedModel model = converged_model(rows, settings, scene.dimension);
      const auto           reached = first_within_accuracy(rows, settings, model);
      if (root)
        {
          // Closed before the plot script reads it.
          write_csv(directory + "/study.csv", rows, settings, model);
          print_results(settings, model, reached);
          {
            std::ofstream json(directory + "/study.json");
            study_json(file, settings, model, reached).write(json);
            json << "\n";
          }
          std::cout << "Study: " << directory << "/study.csv, study.json" << std::endl;
          plot(directory);
        }
      return all_converged ? 0 : 3;
    }
  } // namespace Study
} // namespace Signorini
