// tests/ironing_slide_3d on 2 MPI ranks (only a .mpirun=2 output): the same
// verdicts and reactions as on one rank. Kept outside the default suite
// (about 25 s on 2 cores since the transport predictor; 2.5 min before).
// That includes the total of Newton iterations (416), which an earlier
// version of the transport predictor missed by one (656 against 657): its
// tangent step after the carried state could climb in the first sliding
// steps (doc/two_bodies.md).

#include "ironing_check.h"

int
main()
{
  IroningCheck::run_and_check("ironing_3d.prm", "8, 1, 8", "48, 1, 16", "z", 0.02, 0.08, 3e-2, true);
}
