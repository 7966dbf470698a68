#pragma once

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <limits>

namespace Signorini
{
  using VectorType = dealii::TrilinosWrappers::MPI::Vector;
  using MatrixType = dealii::TrilinosWrappers::SparseMatrix;

  /**
   * What one evaluation of an objective returns besides the vectors:
   * the value and its parts, whether the state is admissible (every
   * quadrature point has J > 0 and finite values), the smallest J, and a
   * force scale sqrt(sum over cells of |f_int,K|^2 + |f_ext,K|^2) that
   * makes residual tolerances relative and unit-free.
   */
  struct Evaluation
  {
    double value         = 0.;
    double strain_energy = 0.;
    double external_work = 0.;
    double min_J         = std::numeric_limits<double>::max();
    double force_scale   = 0.;
    bool   admissible    = true;
  };
} // namespace Signorini
