#pragma once
// Where a lab program's files are. Not written by hand: stoa_add_lab()
// (framework/cmake/StoaLab.cmake) generates one small source per lab program that
// defines labBuildInfo(), so that a lab's app sources compile once for all its
// programs (solution, stubs, mistakes, ...). This header includes nothing, so that
// those generated sources compile in a blink.

namespace stoa {

struct LabBuildInfo {
    const char* name;          // "01_transforms"
    const char* track;         // "labs", "solutions" or "mistake:NAME"
    const char* labDirectory;  // labs/01_transforms (its cases.ini)
    const char* shaderPath;    // folders separated by '|'
    /// Where the lab's reference pictures are (<case>.png), for the window's
    /// comparison ('g'); "" when the build has none. The build decides
    /// (STOA_REFERENCES_DIR), so the framework never names the grader's folders.
    const char* referenceDirectory = "";
    /// A tool built on the lab's app (stoa-editor, stoa-crowds) names itself:
    /// in messages (nullptr: "labNN_name") and in the window's title (nullptr:
    /// "Stoa lab NN_name"). runLabOnCase() sets both.
    const char* programName = nullptr;
    const char* windowTitle = nullptr;
};

/// This program's build info (the generated definition).
LabBuildInfo labBuildInfo();

} // namespace stoa
