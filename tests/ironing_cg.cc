// Shallow ironing (prm/ironing.prm) on the coarse mesh of tests/ironing_slide
// with CG + AMG instead of the direct solver, the whole path, with the checks
// of ironing_check.h and the same tolerances. Until 2026-11-27 this stopped in
// its first load step, before the die touches: the die's answer is a rigid
// motion, its energy (E = 6.9e9) is pure round-off (about 1e-7), and the
// Newton iterations followed CG directions solved only to the forcing term,
// whose decrease the energy cannot resolve, until the line search gave up
// after 30 backtracks. Now the energy reports its round-off (eps times the
// shear modulus times the volume), the line search judges such steps by the
// gradient norm, and a direction in the round-off regime is solved again to
// the fixed tolerance, so that the increment test can end the step. Measured
// on this mesh: 80 load steps without a cut, the reactions at t = 1, 1.5 and
// 2 the same to 4 digits as the direct solver's (tests/ironing_slide). The
// .mpirun=2 variant expects the same lines (the Newton iterations are not
// printed: CG's directions depend on ML's aggregates, hence on the ranks).

#include "ironing_check.h"

int
main()
{
  const std::string cg = "subsection Solver\n  subsection Linear solver\n"
                         "    set Type = cg-amg\n  end\nend\n";
  IroningCheck::run_and_check("ironing.prm", "4, 4", "24, 8", "y", 0.01, 0.02, 3e-2, false, cg);
}
