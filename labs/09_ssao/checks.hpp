#pragma once
// Lab 09's property checks (the cases with a `check` key in cases.ini), for what
// the pictures cannot show. See docs/labs/09_ssao.md, "Checks".

#include <stoa/lab/PropertyCheck.hpp>

namespace lab09 {

/// kernel_in_order: ssaoKernel() draws its numbers in the order the docs give
/// (x, y, z, then the length, sample by sample), so that every machine and
/// every compiler makes the same kernel from the same seed (docs: "The sample kernel").
stoa::CheckResult checkKernelInOrder();

} // namespace lab09
