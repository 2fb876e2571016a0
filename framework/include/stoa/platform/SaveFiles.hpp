#pragma once
// The platform's part of saving a file safely (editor/SafeSave.hpp): creating
// a new file and flushing it to the disk, replacing one file by another in one
// step, and telling whether the process that left a temporary file still runs.
// POSIX: open(O_EXCL), fsync(), rename(), kill(pid, 0). Windows: CreateFileW
// (CREATE_NEW), FlushFileBuffers(), MoveFileExW (MOVEFILE_REPLACE_EXISTING |
// MOVEFILE_WRITE_THROUGH), OpenProcess() and GetExitCodeProcess().

#include <filesystem>
#include <functional>
#include <string>
#include <system_error>

namespace stoa::platform {

using ProcessId = long long;

/// This process's id.
ProcessId currentProcessId();

/// Whether process `pid` is known to have ended: false while it runs, also
/// when it belongs to another user, and when the platform cannot tell.
bool processHasEnded(ProcessId pid);

/// Creates the file `path` only when nothing has that name, writes all of
/// `text` to it, flushes it to the disk and closes it. A new file gets the
/// permission bits of `permissionsOf` when that file exists (POSIX). Returns
/// no error on success; std::errc::file_exists when the name was taken
/// (nothing was written); any other error leaves no file at `path`.
std::error_code writeNewFile(const std::filesystem::path& path, const std::string& text,
                             const std::filesystem::path& permissionsOf);

/// Puts the file `from` in the place of `to` in one step: `to`, if it
/// exists, is replaced; never a moment without a file at `to`. Both are in
/// the same folder.
std::error_code replaceFile(const std::filesystem::path& from, const std::filesystem::path& to);

/// Removes `file`, best effort.
void removeFile(const std::filesystem::path& file);

/// Flushes the folder's entries to the disk, so that a replaceFile() in it
/// survives a power cut (POSIX; MOVEFILE_WRITE_THROUGH does it on Windows).
void flushFolder(const std::filesystem::path& folder);

/// Removes each regular file (not a link, not a folder) in `folder` whose
/// name `isStale` accepts. Best effort: never throws for a file it cannot
/// remove or a folder it cannot read.
void removeRegularFilesIf(const std::filesystem::path& folder,
                          const std::function<bool(const std::string& name)>& isStale);

/// Words for a failed write in `folder` ("the disk is full"), for messages.
std::string describeWriteError(const std::error_code& error, const std::filesystem::path& folder);

} // namespace stoa::platform
