#pragma once

#include <signorini/parameters/checkpoint_parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace Signorini
{
  using namespace dealii;

  // When checkpoints are written: parameters/checkpoint_parameters.h.

  namespace Checkpoint
  {
    /// Version of the checkpoint format (state files and their order).
    constexpr unsigned int format_version = 9; // 2: contact area and moment in the step record; 3: estimated errors of the quantities; 4: linear solves in the step record; 5: refined_back; 6: AMG builds in the step record; 7: the state on nodes and cells as fields attached to the mesh (any number of ranks); 8: friction in the step record; 9: the per-pair values in the step record

    /// What every state file starts with; read before anything is built.
    struct Header
    {
      unsigned int format     = format_version;
      unsigned int dimension  = 0;
      unsigned int n_ranks    = 0;
      unsigned int sequence   = 0; // the NNNNNN of the folder
      std::string  parameter_file; // as the original run named it
      std::string  parameters;     // the used parameters (ShortPRM text)
      /// The mesh is the one the parameters build (no refinement cycle
      /// yet): the restarted run builds it the same way. On as many ranks,
      /// that gives the same cells in the same order, hence the same DoF
      /// numbering and the same round-off, and the vectors are restored
      /// entry by entry from each rank's state file; on another number of
      /// ranks the vectors are copied cell by cell (by CellId) from the
      /// checkpoint's mesh, loaded beside the built one. Otherwise the mesh
      /// is loaded from the checkpoint (p4est, on any number of ranks) and
      /// the vectors are transferred cell by cell with it.
      bool mesh_as_built = true;
      /// With 'Estimate from a coarser mesh' the mesh counts as built
      /// throughout: the restarted run coarsens it again, and, if this
      /// flag is set, refines it back (the same history, hence the same
      /// numbering).
      bool refined_back = false;
      /// The fields of the parts' MeshState (nodal forces, multipliers) on
      /// DoFs and on cells, attached to the mesh after the solution and
      /// the pattern state.
      unsigned int n_dof_fields  = 0;
      unsigned int n_cell_fields = 0;

      template <class Archive>
      void
      serialize(Archive &ar, const unsigned int)
      {
        ar &format &dimension &n_ranks &sequence &parameter_file &parameters;
        // An older format's header reads as far as it goes, so that
        // read_header() can name its format.
        ar &mesh_as_built;
        if (format >= 5)
          ar &refined_back;
        if (format >= 7)
          ar &n_dof_fields &n_cell_fields;
      }
    };

    /// DIR/checkpoints.
    std::string
    root(const std::string &output_directory);

    /// The folder of checkpoint @p sequence in @p output_directory.
    std::string
    folder(const std::string &output_directory, const unsigned int sequence);

    /// This rank's state file in @p checkpoint_folder.
    std::string
    state_file(const std::string &checkpoint_folder, const unsigned int rank);

    /// The mesh file (p4est) in @p checkpoint_folder.
    std::string
    mesh_file(const std::string &checkpoint_folder);

    /// The complete checkpoints in @p output_directory, oldest first.
    std::vector<std::string>
    list(const std::string &output_directory);

    /**
     * The newest complete checkpoint of the run in @p directory, which is
     * the run's output directory or one checkpoint folder. Throws
     * InputError (naming --restart) if there is none.
     */
    std::string
    newest(const std::string &directory);

    /// Read the header of @p checkpoint_folder's first state file;
    /// InputError if it is missing or not a checkpoint of this version.
    Header
    read_header(const std::string &checkpoint_folder);

    /**
     * The entries of @p restarted that differ from those of the text
     * @p saved (ShortPRM, as in Header::parameters) and that a restart
     * cannot honour: every entry except Load stepping > End time, Mesh
     * refinement > Number of cycles, Output directory and the Output and
     * Checkpoint subsections. Each as "Section > Entry: 'old' -> 'new'".
     */
    std::vector<std::string>
    incompatible_changes(const std::string &saved, const ParameterHandler &restarted);
  } // namespace Checkpoint
} // namespace Signorini
