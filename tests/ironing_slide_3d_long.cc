// tests/ironing_slide_3d on 2 MPI ranks (only a .mpirun=2 output): the same
// verdicts and reactions as on one rank. Kept outside the default suite
// (about 25 s on 2 cores since the transport predictor; 2.5 min before).
// The iteration count is not printed: 656 here against 657 on one rank,
// the first sliding steps (before the bulge in front of the die has
// formed) still take 50 to 63 iterations, where round-off decides
// (doc/two_bodies.md).

#include "ironing_check.h"

int
main()
{
  IroningCheck::run_and_check("ironing_3d.prm", "8, 1, 8", "48, 1, 16", "z", 0.02, 0.08, 3e-2);
}
