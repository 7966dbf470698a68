#pragma once

#include <deal.II/base/mpi.h>

#include <deque>
#include <vector>

namespace Signorini
{
  namespace Contact
  {
    /**
     * Anderson acceleration (type II, Walker & Ni 2011) of a fixed-point
     * iteration x = G(x) whose vector is distributed over MPI ranks (each
     * rank holds its own entries). Given the input x_k of an evaluation and
     * its output g_k = G(x_k), next() returns
     *
     *   x_k+1 = g_k - sum_j gamma_j (g_j+1 - g_j),
     *
     * with gamma minimising |f_k - sum_j gamma_j (f_j+1 - f_j)|, f = g - x,
     * over the last @p depth differences, and every entry clipped at @p floor
     * (normal forces stay >= 0). The friction loop uses it for the lagged
     * normal forces, whose plain iteration converges linearly, slowly where
     * the normal and the tangential problems are coupled.
     */
    class AndersonMixing
    {
    public:
      AndersonMixing(const unsigned int depth, const MPI_Comm comm)
        : depth(depth)
        , comm(comm)
      {}

      /// Forget the history (a new load step).
      void
      clear()
      {
        dx.clear();
        df.clear();
        last_x.clear();
        last_f.clear();
        has_last = false;
      }

      std::vector<double>
      next(const std::vector<double> &x, const std::vector<double> &g, const double floor = 0.);

    private:
      unsigned int                    depth;
      MPI_Comm                        comm;
      std::deque<std::vector<double>> dx, df; // differences of g and of f
      std::vector<double>             last_x, last_f;
      // A last iterate exists (not last_f's size: a rank without points
      // has empty vectors, and every rank must take the same branch into
      // the collective sum of next()).
      bool                            has_last = false;
    };
  } // namespace Contact
} // namespace Signorini
