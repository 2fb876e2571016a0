#pragma once
// Where the grader finds things: the labs (folders labs/NN_name/ with a
// cases.ini), their programs in the bin folder, the reference images, and the
// planted-mistake programs.
//
//   labs/01_transforms/cases.ini                         the manifest (public cases)
//   <bin>/lab01_transforms                               the lab's program ("lab" + folder name)
//   <bin>/mistakes/01_transforms.MISTAKE/lab01_transforms   one program per planted mistake
//   autograder/references/01_transforms/CASE.png         the reference images
//   solutions/01_transforms/hidden_cases.ini             hidden cases (only where solutions/ exists)
//   solutions/01_transforms/references/CASE.png          their references (not in the student release)

#include <filesystem>
#include <string>
#include <vector>

namespace stoa::grader {

struct LabEntry {
    std::string lab;                       // the folder name, "01_transforms"
    std::filesystem::path manifestPath;    // labs/01_transforms/cases.ini
};

/// Every labs/NN_*/ folder of `sourceDir` that has a cases.ini, sorted by name.
std::vector<LabEntry> findLabs(const std::filesystem::path& sourceDir);

/// The labs named by `requested` ("01_transforms", "01", "1" or "transforms"), in
/// lab order without repeats; all of `labs` when `requested` is empty. Throws
/// UsageError naming the unknown lab and listing the labs.
std::vector<LabEntry> selectLabs(const std::vector<LabEntry>& labs, const std::vector<std::string>& requested);

/// "lab01_transforms" for "01_transforms".
std::string programName(const std::string& lab);

/// <binDir>/lab01_transforms
std::filesystem::path labProgram(const std::filesystem::path& binDir, const std::string& lab);

/// <binDir>/<folder>/01_transforms.MISTAKE/lab01_transforms: "mistakes" for the
/// planted ones, "out-of-gallery" for the test mistakes of stoa-grade --check-hints.
std::filesystem::path mistakeProgram(const std::filesystem::path& binDir, const std::string& lab,
                                     const std::string& mistake, const std::string& folder = "mistakes");

/// <sourceDir>/autograder/references/<lab>: the public cases' references (and their render times).
std::filesystem::path referenceFolder(const std::filesystem::path& sourceDir, const std::string& lab);

/// <sourceDir>/solutions/<lab>/references: the hidden cases' references.
std::filesystem::path hiddenReferenceFolder(const std::filesystem::path& sourceDir, const std::string& lab);

/// <sourceDir>/autograder/references/<lab>/<caseName>.png
std::filesystem::path referenceImagePath(const std::filesystem::path& sourceDir, const std::string& lab,
                                         const std::string& caseName);

/// <sourceDir>/solutions/<lab>/hidden_cases.ini: the lab's hidden cases, in the
/// manifest format; they ship with the solutions, so never to students.
std::filesystem::path hiddenManifestPath(const std::filesystem::path& sourceDir, const std::string& lab);

/// <sourceDir>/solutions/<lab>/references/<caseName>.png: a hidden case's reference.
std::filesystem::path hiddenReferenceImagePath(const std::filesystem::path& sourceDir, const std::string& lab,
                                               const std::string& caseName);

/// <binDir>/cascade/lab01_transforms: the lab's student code with the earlier labs'
/// solutions linked in (built where solutions exist; see StoaLab.cmake).
std::filesystem::path cascadeProgram(const std::filesystem::path& binDir, const std::string& lab);

/// True when `path` is a regular file this user may execute.
bool isExecutable(const std::filesystem::path& path);

/// The folder of the running program (from /proc/self/exe); empty when unknown.
std::filesystem::path executableDir();

} // namespace stoa::grader
