#include <signorini/contact/anderson.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>

namespace Signorini
{
  namespace Contact
  {
    std::vector<double>
    AndersonMixing::next(const std::vector<double> &x, const std::vector<double> &g,
                         const double floor)
    {
      const std::size_t   n = x.size();
      std::vector<double> f(n);
      for (std::size_t i = 0; i < n; ++i)
        f[i] = g[i] - x[i];
      if (has_last && last_f.size() == n && depth > 0)
        {
          // dg_j = g_j+1 - g_j = (f_j+1 - f_j) + (x_j+1 - x_j).
          std::vector<double> d_f(n), d_g(n);
          for (std::size_t i = 0; i < n; ++i)
            {
              d_f[i] = f[i] - last_f[i];
              d_g[i] = d_f[i] + x[i] - last_x[i];
            }
          df.push_back(d_f);
          dx.push_back(d_g);
          if (df.size() > depth)
            {
              df.pop_front();
              dx.pop_front();
            }
        }
      else
        clear();
      last_x   = x;
      last_f   = f;
      has_last = true;
      std::vector<double> result(g);
      const unsigned int  m = df.size();
      if (m > 0)
        {
          // The normal equations of the least-squares problem, summed over
          // the ranks, with a relative Tikhonov shift against dependent
          // columns.
          std::vector<double> sums(m * m + m, 0.);
          for (unsigned int a = 0; a < m; ++a)
            {
              for (unsigned int b = 0; b < m; ++b)
                for (std::size_t i = 0; i < n; ++i)
                  sums[a * m + b] += df[a][i] * df[b][i];
              for (std::size_t i = 0; i < n; ++i)
                sums[m * m + a] += df[a][i] * f[i];
            }
          dealii::Utilities::MPI::sum(sums, comm, sums);
          dealii::FullMatrix<double> A(m, m);
          dealii::Vector<double>     rhs(m), gamma(m);
          double                     trace = 0.;
          for (unsigned int a = 0; a < m; ++a)
            trace += sums[a * m + a];
          for (unsigned int a = 0; a < m; ++a)
            {
              for (unsigned int b = 0; b < m; ++b)
                A(a, b) = sums[a * m + b];
              A(a, a) += 1e-12 * trace + 1e-300;
              rhs(a) = sums[m * m + a];
            }
          A.gauss_jordan();
          A.vmult(gamma, rhs);
          for (unsigned int a = 0; a < m; ++a)
            for (std::size_t i = 0; i < n; ++i)
              result[i] -= gamma(a) * dx[a][i];
        }
      for (double &r : result)
        r = std::max(r, floor);
      return result;
    }
  } // namespace Contact
} // namespace Signorini
