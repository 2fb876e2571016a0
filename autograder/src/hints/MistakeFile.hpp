#pragma once
// The header of a planted mistake (solutions/NN_name/mistakes/NAME.mistake):
// `key: value` lines before the first line that starts with "--- ".
//
//   hint: the view matrix is transposed: the scene turns the wrong way
//   docs: labs/01_transforms.md#the-view-matrix
//   fails: orbit_front orbit_side
//   file: transforms.cpp
//   hint-ok: view_transposed         (optional, out-of-gallery test mistakes only)
//   --- find
//   ...
//
// The find/replace blocks after it are applied by the build (StoaLab.cmake);
// the grader only needs the header: which cases must fail, and the hint.

#include <filesystem>
#include <string>
#include <vector>

namespace stoa::grader {

struct MistakeFile {
    std::string name;                 // the file's stem: "view_transposed"
    std::string lab;                  // "01_transforms", from solutions/<lab>/mistakes/
    std::string hint;                 // required: what a student with this image should look at
    std::string docs;                 // optional: a docs page (and anchor)
    std::vector<std::string> fails;   // required, not empty: the cases this mistake must fail
    std::string file;                 // required: the student file the mistake changes
    std::string path;                 // where it was read from, for messages
    // A mistake kept outside the gallery (tests/data/out_of_gallery/, checked by
    // stoa-grade --check-hints): the gallery entries whose hint lists this
    // mistake's cause, so that naming them is right. Empty: any hint is wrong.
    std::vector<std::string> hintOk;
};

/// Parses the header. `fileName` is used for the name, messages and `path`.
/// Throws InputError with the line for a line that is not `key: value`, an
/// unknown or repeated key, and (line 0) a missing hint, fails or file.
MistakeFile parseMistakeHeader(const std::string& text, const std::string& fileName);

/// Reads and parses a .mistake file; `lab` is the name of the folder above mistakes/.
MistakeFile loadMistakeFile(const std::filesystem::path& path);

/// Every *.mistake file in `labSolutionsDir`/mistakes, sorted by name (none when
/// the folder does not exist).
std::vector<MistakeFile> loadMistakes(const std::filesystem::path& labSolutionsDir);

} // namespace stoa::grader
