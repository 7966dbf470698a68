// Code_Aster's SSNV128, prm/ssnv128.prm (issue 50): the GRECO plate on
// the rigid plane with Coulomb friction mu = 1. Its u_x at the contact
// nodes A-E (x = 0, 1.25, 5, 7.5, 11.25 mm on y = 0; the x - X column of
// contact_profile.csv) within 5% of the issue's references 2.86, 2.72,
// 2.28, 1.98, 1.50 (x 1e-5 m) and of Code_Aster's own results 2.8649,
// 2.7269, 2.2924, 1.9929, 1.5608. Measured: 2.8492, 2.7112, 2.2772,
// 1.9760, 1.5401, i.e. -0.38%, -0.33%, -0.12%, -0.20%, +2.7% from the
// former and -0.55%, -0.58%, -0.67%, -0.85%, -1.32% from the latter. The
// contact force balances the top load (1e-6). Only verdicts are printed.

#include "run_output.h"

#include <cmath>
#include <fstream>
#include <iostream>

int
main()
{
  using RunOutput::verdict;
  std::ofstream out("output");
  out << "exit code 0: " << verdict(RunOutput::run_scene("run", "ssnv128.prm", "") == 0)
      << "\n";
  const auto   nodes     = RunOutput::read_csv("run/contact_profile.csv");
  const char  *names     = "ABCDE";
  const double x[5]      = {0., 0.00125, 0.005, 0.0075, 0.01125};
  const double issue[5]      = {2.86e-5, 2.72e-5, 2.28e-5, 1.98e-5, 1.50e-5};
  const double code_aster[5] = {2.8649e-5, 2.7269e-5, 2.2924e-5, 1.9929e-5, 1.5608e-5};
  for (unsigned int i = 0; i < 5; ++i)
    {
      double ux    = std::nan("");
      for (const auto &n : nodes)
        if (std::abs(n.at("Xx") - x[i]) < 1e-9 && std::abs(n.at("Xy")) < 1e-9)
          ux = n.at("x") - n.at("Xx");
      const double error   = (ux - issue[i]) / issue[i];
      const double error_2 = (ux - code_aster[i]) / code_aster[i];
      std::cerr << names[i] << ": u_x " << ux << " relative errors " << error << ", "
                << error_2 << "\n";
      out << names[i] << ": u_x within 5% of the reference and of Code_Aster's result: "
          << verdict(std::abs(error) <= 0.05 && std::abs(error_2) <= 0.05) << "\n";
    }
  // Vertical balance: 5e7 Pa x 0.04 m on the top against the contact.
  const double fy = RunOutput::summary_quantity("run/summary.json", "contact_force_y");
  out << "contact force balances the top load (1e-6): "
      << verdict(std::abs(fy - 5e7 * 0.04) <= 1e-6 * 5e7 * 0.04) << "\n";
}
