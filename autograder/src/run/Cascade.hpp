#pragma once
// Cascades: lab N builds on the labs before it, so a mistake in lab 02 would
// also fail lab 05's pictures. Where solutions exist, a lab that uses earlier
// labs has a second program, <bin>/cascade/labNN_name: the student's code for
// lab N with the earlier labs' solutions linked in (framework/cmake/StoaLab.cmake).
// The grader renders every case of such a lab with both programs and the lab
// gets the higher of the two scores, so each lab is graded on its own work.
// Both runs are reported; the cases of the run that does not count are kept
// with `counted = false` and add nothing to the totals.

#include "GradeResult.hpp"

#include <vector>

namespace stoa::grader {

/// For every lab with cascade results in `results`: sums the points of its own
/// run and of its cascade run and marks the results of the run with fewer points
/// (the cascade run on a tie) as not counted. Labs without a cascade run are left as they are.
void applyCascadePolicy(std::vector<GradeResult>& results);

} // namespace stoa::grader
