#pragma once
// stoa-grade's command line.
//
//   stoa-grade [--lab NN_name|NN]... [--case NAME]... [--bin-dir DIR] [--backend osmesa|egl]
//              [--json FILE] [--html FILE] [--junit FILE] [--timeout SECONDS] [--jobs N] [--work-dir DIR]
//              [--expect pass|not-attempted]
//   stoa-grade --update-references [--lab ...] [--case ...]
//   stoa-grade --check-mistakes [--lab ...]
//   stoa-grade --check-hints DIR [--lab ...]
//   stoa-grade --determinism [--lab ...] [--case ...]
//   stoa-grade --write-heatmap-legend FILE
//   stoa-grade --help
//
// Options take their value as the next argument or after '=' (--jobs=4).

#include "GradeOptions.hpp"

#include <string>
#include <vector>

namespace stoa::grader {

/// Parses the arguments after the program name. Throws UsageError naming the
/// argument and the valid choices.
Options parseCommandLine(const std::vector<std::string>& arguments);

/// The --help text.
std::string usageText();

} // namespace stoa::grader
