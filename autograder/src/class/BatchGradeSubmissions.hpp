#pragma once
// The submissions of a class, as the batch grader finds them in one folder:
//
//   submissions/alice/            a folder holding labs/ (or labs/ one folder down)
//   submissions/bob.zip           an archive of the same, unpacked with unzip
//   submissions/carol.tar.gz      the same with tar (.tgz too)
//
// The student's name is the entry's name without the archive extension. Each
// submission is staged into the student's output folder, where its labs/ tree
// is found: at the root, or inside the one top folder an archive tool made.

#include <filesystem>
#include <string>
#include <vector>

namespace stoa::grader {

enum class SubmissionKind { Folder, Zip, TarGz };

struct Submission {
    std::string student;             // "alice": the file name without .zip/.tar.gz/.tgz, made filename-safe
    std::filesystem::path source;    // the folder or archive
    SubmissionKind kind = SubmissionKind::Folder;
};

/// The submissions in `folder`, sorted by student. Hidden entries (".x") and other
/// files are skipped, each with a line in `skipped`. Throws InputError when
/// `folder` is not a folder or two entries give the same student name.
std::vector<Submission> findSubmissions(const std::filesystem::path& folder, std::vector<std::string>& skipped);

/// "alice" for "alice.tar.gz"; characters other than letters, digits, '.', '-'
/// and '_' become '_'.
std::string studentName(const std::filesystem::path& entry);

/// Where the labs/ tree of an unpacked submission is: <root>/labs, <root>/<top>/labs
/// when `root` holds one folder (macOS's __MACOSX and hidden entries ignored), or
/// `root` itself when it holds NN_name lab folders. Throws InputError saying where
/// it looked when there is none.
std::filesystem::path findLabsFolder(const std::filesystem::path& root);

/// Makes the submission's files available under `stageDir` (an archive is
/// unpacked there; a folder is used where it is) and returns its labs/ folder.
/// Throws InputError with the archive tool's message when unpacking fails.
std::filesystem::path stageSubmission(const Submission& submission, const std::filesystem::path& stageDir);

/// The full path of `program` found on $PATH; empty when it is not there.
std::filesystem::path findOnPath(const std::string& program);

} // namespace stoa::grader
