#pragma once
// Saving a file so that a save never destroys anything (the editor's scene
// files, EditorSceneFile.cpp). The text goes to a temporary file beside the
// target, `.NAME.saving-PID-N`, which is flushed to the disk and renamed over
// the target in one step; the folder is flushed too, so that the rename
// survives a power cut. A save replaces only a writable regular file: it
// refuses a read-only file, a folder, a FIFO, a device, a socket, and it
// writes through a symbolic link into the file the link names. A save killed
// mid-way (a signal, a crash) leaves its temporary file; the next save or
// open of the same file removes it once its process no longer runs.
// The platform's part (the new file, the replacement in one step, whether a
// process runs: POSIX or Windows) is in platform/SaveFiles.hpp.

#include <filesystem>
#include <string>

namespace stoa {

/// Replaces `file` with `text` as above. `what` names the content in
/// messages ("the scene"). Throws InputError(file, 0, "cannot save WHAT:
/// why") when it cannot or must not; `file` is then unchanged and no
/// temporary file is left.
void saveFileSafely(const std::filesystem::path& file, const std::string& text, const std::string& what);

/// Removes the temporary files `.NAME.saving-PID-N` beside `file` (beside its
/// target, for a symbolic link) whose process PID no longer runs. Never one
/// of a running process, whoever owns it. Best effort: never throws for a
/// file it cannot remove or a folder it cannot read.
void removeStaleSaves(const std::filesystem::path& file);

} // namespace stoa
