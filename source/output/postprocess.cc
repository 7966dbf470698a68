#include <signorini/archive_io.h>
#include <signorini/first_error.h>
#include <signorini/input_error.h>
#include <signorini/output/atomic_file.h>
#include <signorini/output/postprocess.h>

#include <deal.II/base/multithread_info.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <hdf5.h>

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace Signorini
{
  namespace
  {
    /**
     * J, Cauchy stress sigma = P F^T / J (sigma_zz separately in plane
     * strain), von Mises stress and the mean pressure -tr(sigma)/3, from
     * the displacement gradient and the cell's material.
     */
    template <int dim>
    class StressOutput : public DataPostprocessor<dim>
    {
    public:
      explicit StressOutput(
        const std::map<types::material_id, const Material::Interface *> &materials)
        : materials(materials)
      {}

      std::vector<std::string>
      get_names() const override
      {
        std::vector<std::string> names = {"J"};
        for (unsigned int i = 0; i < dim * dim; ++i)
          names.emplace_back("cauchy_stress");
        if (dim == 2)
          names.emplace_back("sigma_zz");
        names.emplace_back("von_mises");
        names.emplace_back("pressure");
        return names;
      }

      std::vector<DataComponentInterpretation::DataComponentInterpretation>
      get_data_component_interpretation() const override
      {
        std::vector<DataComponentInterpretation::DataComponentInterpretation>
          interpretation(1, DataComponentInterpretation::component_is_scalar);
        for (unsigned int i = 0; i < dim * dim; ++i)
          interpretation.push_back(
            DataComponentInterpretation::component_is_part_of_tensor);
        for (unsigned int i = 0; i < (dim == 2 ? 3u : 2u); ++i)
          interpretation.push_back(
            DataComponentInterpretation::component_is_scalar);
        return interpretation;
      }

      UpdateFlags
      get_needed_update_flags() const override
      {
        return update_gradients;
      }

      void
      evaluate_vector_field(const DataPostprocessorInputs::Vector<dim> &inputs,
                            std::vector<Vector<double>> &computed) const override
      {
        const auto cell = inputs.template get_cell<dim>();
        const Material::Interface &material =
          *materials.at(cell->material_id());
        for (unsigned int q = 0; q < computed.size(); ++q)
          {
            Tensor<2, dim> F = unit_symmetric_tensor<dim>();
            for (unsigned int i = 0; i < dim; ++i)
              F[i] += inputs.solution_gradients[q][i];
            const Tensor<2, 3> sigma = Material::cauchy_stress(material, F);
            unsigned int       k     = 0;
            computed[q][k++]         = determinant(F);
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = 0; j < dim; ++j)
                computed[q][k++] = sigma[i][j];
            if (dim == 2)
              computed[q][k++] = sigma[2][2];
            const double p = trace(sigma) / 3.;
            Tensor<2, 3> s = sigma;
            for (unsigned int i = 0; i < 3; ++i)
              s[i][i] -= p;
            computed[q][k++] = std::sqrt(1.5 * scalar_product(s, s));
            computed[q][k++] = -p;
          }
      }

    private:
      const std::map<types::material_id, const Material::Interface *> &materials;
    };

    /**
     * A DataOut whose patches, once built, can be taken away with the
     * names and vector/tensor ranges that describe them: what
     * DataOutBase::write_vtu needs, without the DoFHandler and the vectors
     * the patches were built from.
     */
    template <int dim>
    class DetachableDataOut : public DataOut<dim>
    {
    public:
      using Ranges = std::vector<
        std::tuple<unsigned int,
                   unsigned int,
                   std::string,
                   DataComponentInterpretation::DataComponentInterpretation>>;

      struct Frame
      {
        std::vector<DataOutBase::Patch<dim, dim>> patches;
        std::vector<std::string>                  names;
        Ranges                                    ranges;
      };

      std::vector<std::string>
      names() const
      {
        return this->get_dataset_names();
      }

      Ranges
      ranges() const
      {
        return this->get_nonscalar_data_ranges();
      }

      Frame
      detach()
      {
        Frame frame;
        frame.names  = names();
        frame.ranges = ranges();
        frame.patches.swap(this->patches);
        return frame;
      }
    };

    /**
     * Patches at the cells' vertices where the mapping is linear (the
     * vertices are then the mapped points, and DataOut need not evaluate
     * the mapping at them); through the mapping where it curves the cells.
     */
    template <int dim>
    typename DataOut<dim>::CurvedCellRegion
    curved_region(const Mapping<dim> &mapping)
    {
      const auto *q = dynamic_cast<const MappingQ<dim> *>(&mapping);
      return (q != nullptr && q->get_degree() == 1) ?
               DataOut<dim>::no_curved_cells :
               DataOut<dim>::curved_inner_cells;
    }
  } // namespace

  void
  PostprocessParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Postprocess");
    {
      prm.enter_subsection("Mean boundary displacement");
      prm.declare_entry("Boundary id",
                        "-1",
                        Patterns::Integer(-1, 255),
                        "Report the mean displacement component over this "
                        "boundary (area-weighted, reference configuration); "
                        "-1: not reported.");
      prm.declare_entry("Component",
                        "y",
                        Patterns::Selection("x|y|z"),
                        "Displacement component.");
      prm.declare_entry("Name",
                        "mean_displacement",
                        Patterns::Anything(),
                        "Name of the quantity in summary.json.");
      prm.declare_entry("Reference value",
                        "",
                        Patterns::Anything(),
                        "Reference value [length] (empty: none); summary.json "
                        "then carries the relative error.");
      prm.declare_entry("Relative tolerance",
                        "0",
                        Patterns::Double(0.),
                        "If > 0 and a reference is given, a run whose "
                        "relative error exceeds it is reported as outside "
                        "tolerance (and the test driver fails).");
      prm.leave_subsection();

      prm.declare_entry("Reaction boundaries",
                        "",
                        Patterns::List(Patterns::Integer(0, 255)),
                        "Report the reaction force (force of the supports on "
                        "the body, summed over the boundary's degrees of "
                        "freedom) on these Dirichlet boundary ids, per load "
                        "step in reactions.csv and at the end in "
                        "summary.json.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Output");
    {
      prm.declare_entry("Format",
                        "vtu",
                        Patterns::Selection("vtu|hdf5|none"),
                        "vtu: a .pvtu per step with a solution.pvd series for "
                        "ParaView, and one .vtu piece per rank (per thread "
                        "of a rank with at least 2000 cells a thread: the "
                        "pieces are compressed side by side). hdf5: one .h5 per "
                        "step and a solution.xdmf series. none: no fields "
                        "(summary.json and CSV are always written).");
      prm.declare_entry("Compression",
                        "best speed",
                        Patterns::Selection("best speed|best compression|none"),
                        "zlib compression of the VTU fields. best speed: "
                        "files a few percent larger than with best "
                        "compression (3.5% on prm/hertz_peer.prm), written "
                        "about 9 times faster (doc/performance.md). none: "
                        "no compression, 3 times larger files.");
      prm.declare_entry("Interval",
                        "1",
                        Patterns::Integer(1),
                        "Write fields every this many load steps (the last "
                        "step is always written).");
      prm.declare_entry("Verbosity",
                        "normal",
                        Patterns::Selection("quiet|normal|verbose"),
                        "quiet: errors only. normal: one line per load step "
                        "and per Newton iteration, with line-search and "
                        "Hessian-regularisation notes. verbose: also the "
                        "timing table at the end.");
    }
    prm.leave_subsection();
  }

  void
  PostprocessParameters::parse_parameters(ParameterHandler &prm,
                                          const unsigned int dim)
  {
    prm.enter_subsection("Postprocess");
    {
      prm.enter_subsection("Mean boundary displacement");
      mean_displacement_boundary = prm.get_integer("Boundary id");
      const std::string comp     = prm.get("Component");
      mean_displacement_component = (comp == "x" ? 0 : comp == "y" ? 1 : 2);
      if (mean_displacement_component >= dim)
        throw InputError("Postprocess > Mean boundary displacement > Component",
                         "z does not exist in 2D");
      mean_displacement_name = prm.get("Name");
      const std::string ref  = prm.get("Reference value");
      if (!ref.empty())
        {
          try
            {
              reference = Utilities::string_to_double(ref);
            }
          catch (...)
            {
              throw InputError(
                "Postprocess > Mean boundary displacement > Reference value",
                "'" + ref + "' is not a number");
            }
          has_reference = true;
        }
      tolerance = prm.get_double("Relative tolerance");
      prm.leave_subsection();

      for (const auto &s :
           Utilities::split_string_list(prm.get("Reaction boundaries")))
        reaction_boundaries.push_back(Utilities::string_to_int(s));
    }
    prm.leave_subsection();

    prm.enter_subsection("Output");
    format                  = prm.get("Format");
    {
      const std::string c = prm.get("Compression");
      compression = c == "best speed" ? DataOutBase::VtkFlags::best_speed :
                    c == "none"       ? DataOutBase::VtkFlags::no_compression :
                                        DataOutBase::VtkFlags::best_compression;
    }
    interval                = prm.get_integer("Interval");
    const std::string level = prm.get("Verbosity");
    verbosity = level == "quiet"   ? Verbosity::quiet :
                level == "verbose" ? Verbosity::verbose :
                                     Verbosity::normal;
    prm.leave_subsection();
  }

  template <int dim>
  Postprocessor<dim>::Postprocessor(
    const PostprocessParameters                                     &p,
    const DoFHandler<dim>                                           &dof_handler,
    const Mapping<dim>                                              &mapping,
    const std::map<types::material_id, const Material::Interface *> &materials,
    const EnergyFunctional<dim>                                     &energy,
    const AffineConstraints<double>                                 &hanging_constraints,
    const std::set<types::boundary_id>                              &mesh_ids,
    const std::string                                               &output_directory)
    : dof_handler(dof_handler)
    , mapping(mapping)
    , materials(materials)
    , energy(energy)
    , hanging_constraints(hanging_constraints)
    , output_directory(output_directory)
    , parameters(p)
  {
    if (parameters.mean_displacement_boundary >= 0 &&
        mesh_ids.count(parameters.mean_displacement_boundary) == 0)
      throw InputError("Postprocess > Mean boundary displacement > Boundary id",
                       "boundary id " +
                         std::to_string(parameters.mean_displacement_boundary) +
                         " does not exist in the mesh");
    for (const int id : p.reaction_boundaries)
      {
        if (mesh_ids.count(id) == 0)
          throw InputError("Postprocess > Reaction boundaries",
                           "boundary id " + std::to_string(id) +
                             " does not exist in the mesh");
        reaction_boundaries.push_back(id);
      }
  }

  template <int dim>
  std::vector<Quantity>
  Postprocessor<dim>::compute_quantities(const VectorType &u, const double time)
  {
    std::vector<Quantity> quantities;
    const MPI_Comm        comm = dof_handler.get_communicator();

    if (parameters.mean_displacement_boundary >= 0)
      {
        FEFaceValues<dim> fe_face(mapping,
                                  dof_handler.get_fe(),
                                  QGauss<dim - 1>(dof_handler.get_fe().degree + 1),
                                  update_values | update_JxW_values);
        const FEValuesExtractors::Scalar component(parameters.mean_displacement_component);
        std::vector<double>              values(fe_face.n_quadrature_points);
        double                           integral = 0., area = 0.;
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            for (const auto f : cell->face_indices())
              if (cell->face(f)->at_boundary() &&
                  cell->face(f)->boundary_id() ==
                    static_cast<types::boundary_id>(parameters.mean_displacement_boundary))
                {
                  fe_face.reinit(cell, f);
                  fe_face[component].get_function_values(u, values);
                  for (unsigned int q = 0; q < values.size(); ++q)
                    {
                      integral += values[q] * fe_face.JxW(q);
                      area += fe_face.JxW(q);
                    }
                }
        integral = Utilities::MPI::sum(integral, comm);
        area     = Utilities::MPI::sum(area, comm);
        Quantity q;
        q.name          = parameters.mean_displacement_name;
        q.value         = integral / area;
        q.has_reference = parameters.has_reference;
        q.reference     = parameters.reference;
        q.tolerance     = parameters.tolerance;
        q.estimable     = true;
        quantities.push_back(q);
      }

    // The energy of the bodies at this state, with the residual when the
    // reactions need it: reaction = f_int - f_ext at the boundary's
    // degrees of freedom, i.e. minus the unconstrained residual (hanging
    // nodes condensed).
    VectorType residual;
    if (!reaction_boundaries.empty())
      residual.reinit(dof_handler.locally_owned_dofs(), comm);
    const Evaluation evaluation =
      energy.evaluate(u, time, hanging_constraints,
                      reaction_boundaries.empty() ? nullptr : &residual, nullptr);
    if (!reaction_boundaries.empty())
      {
        std::vector<double> sums;
        for (const auto id : reaction_boundaries)
          {
            for (unsigned int c = 0; c < dim; ++c)
              {
                ComponentMask mask(dim, false);
                mask.set(c, true);
                IndexSet dofs =
                  DoFTools::extract_boundary_dofs(dof_handler, mask, {id});
                dofs       = dofs & dof_handler.locally_owned_dofs();
                double sum = 0.;
                for (const auto i : dofs)
                  sum -= residual[i];
                sums.push_back(Utilities::MPI::sum(sum, comm));
                Quantity q;
                q.name = std::string("reaction_") + "xyz"[c] + "_boundary_" +
                         std::to_string(id);
                q.value     = sums.back();
                q.estimable = true;
                quantities.push_back(q);
              }
            // Each component's error is judged against the boundary's
            // whole reaction.
            double norm = 0.;
            for (unsigned int c = 0; c < dim; ++c)
              norm += sums[sums.size() - 1 - c] * sums[sums.size() - 1 - c];
            for (unsigned int c = 0; c < dim; ++c)
              quantities[quantities.size() - 1 - c].scale = std::sqrt(norm);
          }
        if (Utilities::MPI::this_mpi_process(comm) == 0)
          {
            std::ofstream csv(output_directory + "/reactions.csv",
                              reactions_header_written ? std::ios::app :
                                                         std::ios::trunc);
            if (!reactions_header_written)
              {
                csv << "time";
                for (const auto id : reaction_boundaries)
                  for (unsigned int c = 0; c < dim; ++c)
                    csv << ",R" << "xyz"[c] << "_" << id;
                csv << "\n";
                reactions_header_written = true;
              }
            csv << std::setprecision(12) << time;
            for (const double s : sums)
              csv << "," << s;
            csv << "\n";
          }
      }
    // The total potential energy of the modelled part: the strain energy
    // minus the work of the dead loads, without the contact terms (a
    // penalty's or a barrier's energy is not the bodies').
    Quantity potential;
    potential.name      = "potential_energy";
    potential.value     = evaluation.value;
    potential.estimable = true;
    quantities.push_back(potential);
    return quantities;
  }

  template <int dim>
  void
  Postprocessor<dim>::add_displacement_fields(const VectorType             &u,
                                              const DataPostprocessor<dim> &stress,
                                              DataOut<dim> &data_out) const
  {
    data_out.attach_dof_handler(dof_handler);
    std::vector<DataComponentInterpretation::DataComponentInterpretation>
      interpretation(dim, DataComponentInterpretation::component_is_part_of_vector);
    data_out.add_data_vector(u,
                             std::vector<std::string>(dim, "displacement"),
                             DataOut<dim>::type_dof_data,
                             interpretation);
    data_out.add_data_vector(u, stress);
  }

  template <int dim>
  void
  Postprocessor<dim>::write_output(const VectorType  &u,
                                   const double       time,
                                   const unsigned int step,
                                   const bool         last_step,
                                   const std::string &series)
  {
    if (parameters.format == "none" || (step % parameters.interval != 0 && !last_step))
      return;
    flush();
    const MPI_Comm comm = dof_handler.get_communicator();

    // What the patches are built from. DataOut copies every vector it is
    // given into its own ghosted vector when it is attached (deal.II 9.4's
    // DataEntry; collective), so the solver may change u, and the contact
    // model its fields, once this function returns. The postprocessor it
    // points to lives as long as the DataOut; the mesh, the DoFs and the
    // mapping change only after a flush() (refinement).
    struct Sources
    {
      explicit Sources(
        const std::map<types::material_id, const Material::Interface *> &materials)
        : stress(materials)
      {}
      StressOutput<dim>      stress;
      DetachableDataOut<dim> data_out;
    };
    auto sources = std::make_shared<Sources>(materials);
    DetachableDataOut<dim> &data_out = sources->data_out;
    add_displacement_fields(u, sources->stress, data_out);

    const auto &tria = dof_handler.get_triangulation();
    Vector<float> material_id(tria.n_active_cells()), rank(tria.n_active_cells());
    unsigned int  n_owned_cells = 0;
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          ++n_owned_cells;
          material_id[cell->active_cell_index()] = cell->material_id();
          rank[cell->active_cell_index()]        = cell->subdomain_id();
        }
    data_out.add_data_vector(material_id, "material_id");
    data_out.add_data_vector(rank, "mpi_rank");
    if (extra_fields)
      extra_fields(data_out); // collective (ghosted contact fields)
    const unsigned int degree = dof_handler.get_fe().degree;
    const auto         region = curved_region(mapping);

    if (parameters.format == "vtu")
      {
        // Names as DataOutInterface::write_vtu_with_pvtu_record gives them,
        // series_SSSS.P.vtu and series_SSSS.pvtu, with P counting the pieces
        // of every rank in turn: zlib compresses on one core, so a rank with
        // several threads (and at least 2000 cells for each) splits its
        // patches into that many pieces, compressed and written side by
        // side. The same count on every rank; 1 gives one piece per rank.
        const unsigned int n_ranks   = Utilities::MPI::n_mpi_processes(comm);
        const unsigned int this_rank = Utilities::MPI::this_mpi_process(comm);
        const unsigned int per_rank  = Utilities::MPI::min(
          std::max(1u, std::min(MultithreadInfo::n_threads(), n_owned_cells / 2000)),
          comm);
        const unsigned int n_pieces = n_ranks * per_rank;
        const unsigned int n_digits = Utilities::needed_digits(n_pieces - 1);
        const std::string  stem = series + "_" + Utilities::int_to_string(step, 4);
        std::vector<std::string> pieces;
        for (unsigned int p = 0; p < n_pieces; ++p)
          pieces.push_back(stem + "." + Utilities::int_to_string(p, n_digits) +
                           ".vtu");

        DataOutBase::VtkFlags flags;
        flags.compression_level = parameters.compression;
        pending            = std::make_unique<PendingFrame>();
        pending->series    = series;
        pending->pvtu_name = stem + ".pvtu";
        if (Utilities::MPI::this_mpi_process(comm) == 0)
          {
            // The names and ranges come from the attached data, not from
            // the patches.
            std::ostringstream pvtu;
            DataOutBase::write_pvtu_record(pvtu, pieces, data_out.names(),
                                           data_out.ranges(), flags);
            pending->pvtu_text = pvtu.str();
          }
        pvd_records[series].emplace_back(time, pending->pvtu_name);

        // Building the patches (the stress at every vertex), compressing
        // them (zlib) and writing this rank's pieces, on threads, from
        // DataOut's copies: no MPI there, and the mesh is only read. The
        // sources are released by flush() on this thread.
        std::vector<std::string> paths;
        for (unsigned int k = 0; k < per_rank; ++k)
          paths.push_back(output_directory + "/" + pieces[this_rank * per_rank + k]);
        Sources *const job = sources.get();
        pending->sources   = sources;
        const Mapping<dim> &map = mapping;
        pending->written = std::async(std::launch::async,
                                      [job, &map, degree, region, flags, paths]() {
          job->data_out.build_patches(map, degree, region);
          auto frame = job->data_out.detach();
          // Piece k: the k-th of the contiguous ranges of patches.
          std::vector<std::vector<DataOutBase::Patch<dim, dim>>> parts(paths.size());
          const std::size_t n = frame.patches.size();
          for (std::size_t k = 0; k < parts.size(); ++k)
            parts[k].assign(
              std::make_move_iterator(frame.patches.begin() + n * k / parts.size()),
              std::make_move_iterator(frame.patches.begin() +
                                      n * (k + 1) / parts.size()));
          const auto write_piece = [&parts, &frame, &flags, &paths](const unsigned int k) {
            AtomicFile file(paths[k]);
            try
              {
                DataOutBase::write_vtu(parts[k], frame.names, frame.ranges,
                                       flags, file.stream());
              }
            catch (const ExcIO &)
              {
                // deal.II's message says only that some I/O failed.
                throw std::runtime_error(write_failure(paths[k]));
              }
            std::string reason;
            if (!file.commit(&reason)) // the reason names the file
              throw std::runtime_error(reason);
          };
          std::vector<std::future<void>> others;
          for (unsigned int k = 1; k < paths.size(); ++k)
            others.push_back(std::async(std::launch::async, write_piece, k));
          std::exception_ptr failure;
          try
            {
              write_piece(0);
            }
          catch (...)
            {
              failure = std::current_exception();
            }
          for (auto &other : others)
            try
              {
                other.get();
              }
            catch (...)
              {
                if (!failure)
                  failure = std::current_exception();
              }
          if (failure)
            std::rethrow_exception(failure);
        });
      }
    else
      {
        data_out.build_patches(mapping, degree, region);
        DataOutBase::DataOutFilter filter(
          DataOutBase::DataOutFilterFlags(false, true));
        data_out.write_filtered_data(filter);
        const std::string h5 =
          series + "-" + Utilities::int_to_string(step, 4) + ".h5";
        // deal.II reports a failed HDF5 or XDMF write (a full disk) as an
        // I/O assertion that names neither the file nor the cause: a failed
        // output with the file's name instead, on every rank.
        std::string error, file = output_directory + "/" + h5;
        try
          {
            errno = 0;
            data_out.write_hdf5_parallel(filter, file, comm);
            xdmf_entries[series].push_back(
              data_out.create_xdmf_entry(filter, h5, time, comm));
            file = output_directory + "/" + series + ".xdmf";
            errno = 0;
            data_out.write_xdmf_file(xdmf_entries[series], file, comm);
          }
        catch (const std::exception &)
          {
            error = write_failure(file);
          }
        error = first_error(comm, error);
        if (!error.empty())
          {
            // A half-written .h5 goes: it is in no series, and on a full
            // disk its space is what summary.json needs to say why. deal.II
            // leaves the file open when it throws; H5close() closes every
            // HDF5 identifier (the library starts again if called again).
            H5close();
            if (Utilities::MPI::this_mpi_process(comm) == 0 &&
                file == output_directory + "/" + h5)
              {
                std::error_code ec;
                std::filesystem::remove(file, ec);
              }
            throw OutputFailure("field output: " + error);
          }
      }
  }

  template <int dim>
  void
  Postprocessor<dim>::flush()
  {
    if (!pending)
      return;
    const std::unique_ptr<PendingFrame> frame = std::move(pending);
    const MPI_Comm                      comm  = dof_handler.get_communicator();
    std::string                         error;
    try
      {
        frame->written.get();
      }
    catch (const std::exception &e)
      {
        error = e.what();
      }
    // Every rank learns of a failed file, and throws with it.
    error = first_error(comm, error);
    if (!error.empty())
      throw OutputFailure("field output: " + error);
    // The records, once every piece is complete (rank 0; its failure is
    // every rank's).
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::string reason;
        AtomicFile  pvtu(output_directory + "/" + frame->pvtu_name);
        pvtu.stream() << frame->pvtu_text;
        if (!pvtu.commit(&reason))
          error = "cannot write " + frame->pvtu_name + ": " + reason;
        else
          {
            // Into a string first: deal.II throws if the stream it writes
            // to has failed, which would leave the other ranks waiting in
            // the broadcast below.
            std::ostringstream text;
            DataOutBase::write_pvd_record(text, pvd_records[frame->series]);
            AtomicFile pvd(output_directory + "/" + frame->series + ".pvd");
            pvd.stream() << text.str();
            if (!pvd.commit(&reason))
              error = "cannot write " + frame->series + ".pvd: " + reason;
          }
      }
    error = Utilities::MPI::broadcast(comm, error, 0);
    if (!error.empty())
      throw OutputFailure("field output: " + error);
  }

  template <int dim>
  Postprocessor<dim>::~Postprocessor()
  {
    if (pending && pending->written.valid())
      pending->written.wait();
  }

  template <int dim>
  std::string
  Postprocessor<dim>::write_snapshot(const VectorType &u, const std::string &name)
  {
    if (parameters.format == "none")
      return "";
    flush();
    const StressOutput<dim> stress(materials);
    DataOut<dim>            data_out;
    add_displacement_fields(u, stress, data_out);
    data_out.build_patches(mapping, dof_handler.get_fe().degree,
                           curved_region(mapping));
    DataOutBase::VtkFlags flags;
    flags.compression_level = parameters.compression;
    data_out.set_flags(flags);
    return data_out.write_vtu_with_pvtu_record(output_directory + "/", name, 0,
                                               dof_handler.get_communicator(), 4);
  }

  template <int dim>
  void
  Postprocessor<dim>::save_state(OutputArchive &archive) const
  {
    archive << pvd_records << xdmf_entries << reactions_header_written;
  }

  template <int dim>
  void
  Postprocessor<dim>::load_state(InputArchive &archive)
  {
    archive >> pvd_records >> xdmf_entries >> reactions_header_written;
  }

  template class Postprocessor<2>;
  template class Postprocessor<3>;
} // namespace Signorini
