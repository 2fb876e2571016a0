#pragma once
// The submissions of a class, as the batch grader finds them in one folder:
//
//   submissions/alice/            a folder holding labs/ (or labs/ one folder down)
//   submissions/bob.zip           an archive of the same, unpacked with unzip
//   submissions/carol.tar.gz      the same with tar (.tgz too)
//
// The student's name is the entry's name without the archive extension. Each
// submission is staged (copied or unpacked) into the student's output folder
// before any student's code is built or run, and graded from that copy; its
// labs/ tree is found there: at the root, or inside the one top folder an
// archive tool made. The submission itself is only ever read, and a record of
// its files' hashes shows that grading did not change it.

#include <cstdint>
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

/// Copies the submission's files into `stageDir` (an archive is unpacked there,
/// by tar or unzip confined to that folder; a folder is copied, its symbolic
/// links as links, other special files left out) and returns the copy's labs/
/// folder. Nothing of the student's is ever built or run from the submission
/// itself. Throws InputError with the archive tool's message when unpacking
/// fails, or when a folder holds more than kMaxSubmissionBytes.
std::filesystem::path stageSubmission(const Submission& submission, const std::filesystem::path& stageDir);

/// The most a submission folder may hold (256 MiB, as for an unpacked archive).
constexpr std::uintmax_t kMaxSubmissionBytes = 256ull << 20;

/// One input file of a submission as it was read: its path (relative to the
/// submission; "" for an archive, which is one file), size and content hash.
struct InputFile {
    std::string path;
    std::uintmax_t size = 0;
    std::uint64_t hash = 0;
    bool operator==(const InputFile& other) const {
        return path == other.path && size == other.size && hash == other.hash;
    }
};

/// Every file of the submission (a folder's files, links as their target's
/// text; an archive: the archive), sorted by path, each with its hash.
std::vector<InputFile> recordInputs(const Submission& submission);

/// The paths that differ between two records of the same submission: changed,
/// gone or new ("(the archive)" for an archive). Empty when none.
std::vector<std::string> changedInputs(const std::vector<InputFile>& before, const std::vector<InputFile>& after);

/// The record as text, one file a line: "<hash, 16 hex digits>  <size>  <path>".
std::string inputsText(const std::vector<InputFile>& inputs);

/// The full path of `program` found on $PATH; empty when it is not there.
std::filesystem::path findOnPath(const std::string& program);

} // namespace stoa::grader
