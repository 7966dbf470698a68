#pragma once

#include <signorini/contact/model.h>
#include <signorini/output/report.h>
#include <signorini/scene/refinement.h>
#include <signorini/solvers/step_solver.h>

namespace Signorini
{
  /**
   * Write summary.json and (with refinement cycles) refinement_cycles.csv
   * into the report's output directory (rank 0 writes; each file is
   * renamed into place once complete). The run's own record comes from
   * @p report; the contact model, the step solver and the
   * incompressibility constraints each write their own entries.
   */
  template <int dim>
  void
  write_summary(const Report               &report,
                const RefinementParameters &refinement,
                const Contact::Model<dim>  *contact,
                const StepSolver<dim>      &solver,
                const unsigned int          incompressibility_constraints,
                MPI_Comm                    comm);

  /**
   * load_steps.csv, one row per converged load step (and refinement
   * cycle), appended and flushed as each step converges so that an
   * interrupted run keeps the rows of its converged steps.
   */
  class LoadStepTable
  {
  public:
    /// The file in @p output_directory; only @p writer (rank 0) writes.
    /// With @p friction, the rows end with the friction columns.
    /// With @p part_columns (Contact::Model::part_columns()), the rows
    /// end with those quantities (Report::Step::part_values).
    LoadStepTable(const std::string              &output_directory,
                  const bool                      writer,
                  const bool                      friction     = false,
                  const std::vector<std::string> &part_columns = {});

    /// Start the file anew with its header (a new run).
    void
    start(const std::string &iteration_name, const unsigned int dim);

    /// Append the row of step number @p index (from 1).
    void
    append(const unsigned int   index,
           const Report::Step &step,
           const unsigned int   dim);

    const std::string &
    path() const
    {
      return file;
    }

  private:
    std::string              file;
    bool                     writer;
    bool                     friction;
    std::vector<std::string> part_columns;
  };

  /**
   * progress.json: where a running run is (status, load time and step,
   * refinement cycle, elapsed and estimated remaining wall time),
   * replaced after every converged step (rank 0 writes), for scripts and
   * dashboards.
   */
  void
  write_progress(const std::string &output_directory,
                 const std::string &status,
                 const double       time,
                 const double       end_time,
                 const unsigned int step,
                 const unsigned int cycle,
                 const double       elapsed_seconds,
                 const double       remaining_seconds);
} // namespace Signorini
