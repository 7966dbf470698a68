#pragma once

#include <signorini/output/quantity.h>

#include <signorini/output/postprocess_parameters.h>

#include <signorini/archive.h>

#include <signorini/problem/energy_functional.h>
#include <signorini/material/interface.h>
#include <signorini/types.h>

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>

#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <functional>
#include <future>
#include <memory>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace Signorini
{
  using namespace dealii;

  /**
   * Everything a run reports about a converged state: the quantities of
   * interest of the "Postprocess" subsection (mean boundary displacement
   * with an optional reference value and tolerance, reaction forces on
   * boundary ids), and the graphical output of the "Output" subsection
   * (VTU/PVTU with a .pvd series, or HDF5/XDMF): displacement, J, Cauchy
   * stress (with sigma_zz in plane strain), von Mises stress, material
   * id and MPI rank. CSV files: reactions.csv (one row per load step).
   */
  template <int dim>
  class Postprocessor
  {
  public:
    /// Checks the boundary ids of @p parameters against the mesh's.
    Postprocessor(const PostprocessParameters                               &parameters,
                  const DoFHandler<dim>                                     &dof_handler,
                  const Mapping<dim>                                        &mapping,
                  const std::map<types::material_id, const Material::Interface *> &materials,
                  const EnergyFunctional<dim>                               &energy,
                  const AffineConstraints<double>                           &hanging_constraints,
                  const std::set<types::boundary_id>                        &mesh_boundary_ids,
                  const std::string                                         &output_directory);

    /// Quantities of interest at the ghosted state @p u, load time @p time.
    std::vector<Quantity>
    compute_quantities(const VectorType &u, const double time);

    /**
     * Write the graphical output of load step @p step if it is due, as
     * part of the series @p series (its files are series-NNNN.*, indexed
     * by @p time in series.pvd or series.xdmf).
     */
    void
    write_output(const VectorType  &u,
                 const double       time,
                 const unsigned int step,
                 const bool         last_step,
                 const std::string &series = "solution");

    /**
     * Write the state @p u outside the solution series, as
     * NAME_0000.pvtu (+ .vtu): used for the last iterate of a failed
     * solve, which must not be presented as a result. Returns the name of
     * the record written, or "" (Format = none).
     */
    std::string
    write_snapshot(const VectorType &u, const std::string &name);

    /**
     * Finish the VTU frame that is being written in the background: wait
     * for this rank's file, check on every rank that all were written
     * (collective), then add the frame to its .pvtu and .pvd records (rank
     * 0). A frame is only named in a record once all its files are
     * complete. write_output and write_snapshot call it first; the driver
     * calls it before a checkpoint and at the end of a run. Throws, on
     * every rank, if a file could not be written.
     */
    void
    flush();

    /// Waits for a frame still being written (without recording it).
    ~Postprocessor();

    /// Called before the patches are built, to add further fields.
    std::function<void(DataOut<dim> &)> extra_fields;

    /// Save and load the series written so far (their .pvd / .xdmf
    /// records) for checkpoints.
    void
    save_state(OutputArchive &archive) const;
    void
    load_state(InputArchive &archive);

    PostprocessParameters::Verbosity
    verbosity() const
    {
      return parameters.verbosity;
    }

  private:
    /// Attach the DoFHandler and add the displacement and @p stress fields.
    void
    add_displacement_fields(const VectorType             &u,
                            const DataPostprocessor<dim> &stress,
                            DataOut<dim>                 &data_out) const;

    const DoFHandler<dim>                                           &dof_handler;
    const Mapping<dim>                                              &mapping;
    const std::map<types::material_id, const Material::Interface *> &materials;
    const EnergyFunctional<dim>                                     &energy;
    const AffineConstraints<double>                                 &hanging_constraints;
    std::string                                                      output_directory;

    const PostprocessParameters     parameters;
    std::vector<types::boundary_id> reaction_boundaries; // checked ids
    std::map<std::string, std::vector<std::pair<double, std::string>>> pvd_records;
    std::map<std::string, std::vector<XDMFEntry>>                      xdmf_entries;
    bool                                        reactions_header_written = false;

    /**
     * The VTU frame being built and written by a background thread while
     * the next load step is solved: this rank's file, what its patches are
     * built from (the DataOut, which holds its own copies of the vectors,
     * and its postprocessor; released by flush() on the calling thread), and on
     * rank 0 the .pvtu text and the series to commit once every rank's
     * file is complete.
     */
    struct PendingFrame
    {
      std::future<void>     written;
      std::shared_ptr<void> sources;
      std::string           series;
      std::string           pvtu_name;
      std::string           pvtu_text;
    };
    std::unique_ptr<PendingFrame> pending;
  };
} // namespace Signorini
