// Deliberately wrong: the isolate layer may not know about reports. This file
// must NOT compile (test grader.layers_refuse_wrong_way_includes).
#include "ChildProcess.hpp"
#include "Report.hpp"
