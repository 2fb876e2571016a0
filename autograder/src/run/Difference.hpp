#pragma once
// Where a failed picture differs from the reference and how much, in words, for
// the report of a case that names no known mistake (and beside one that does).

#include <stoa/image/Image.hpp>
#include <stoa/image/ImageCompare.hpp>

#include <string>

namespace stoa::grader {

/// One line: "differs in 23% of the pixels, most of them in the top left
/// (41% of them) and the centre (30%); darker than the reference there".
/// A pixel differs when a channel is off by more than the tolerance (no shift
/// search: this says where to look, it does not grade). The picture is cut
/// into a 3 x 3 grid; the parts holding at least a fifth of the differing
/// pixels are named, largest first ("all over the picture" when none does, or
/// when six or more parts hold some). "" for images of different sizes.
std::string describeDifference(const Image& rendered, const Image& reference, const CompareOptions& options = {});

} // namespace stoa::grader
