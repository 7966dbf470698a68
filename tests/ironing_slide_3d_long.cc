// tests/ironing_slide_3d on 2 MPI ranks (only a .mpirun=2 output): the same
// verdicts as on one rank. Long (about 2.5 min on 2 cores), so outside the
// default suite. The reactions at t = 1 and t = 2 agree with one rank to
// 1e-9; mid-slide the runs take mirror-image branches (doc/two_bodies.md).

#include "ironing_check.h"

int
main()
{
  IroningCheck::run_and_check("ironing_3d.prm", "6, 1, 6", "36, 1, 12", "z", 0.02, 0.08, 3e-2);
}
