#include "SafeSave.hpp"

#include <stoa/core/InputError.hpp>

#include <stoa/platform/SaveFiles.hpp>

#include <atomic>
#include <charconv>
#include <optional>

namespace stoa {

namespace fs = std::filesystem;

namespace {

constexpr int kMaxLinks = 40;   // links followed before a chain counts as a loop (Linux's own limit)

/// `file` with the symbolic links at its end followed, each relative to the
/// link's own folder; nullopt for a loop (more than kMaxLinks links). The
/// result may not exist (a link to a file not yet written).
std::optional<fs::path> followLinks(const fs::path& file) {
    fs::path path = file;
    for (int hop = 0; hop <= kMaxLinks; ++hop) {
        std::error_code error;
        if (!fs::is_symlink(fs::symlink_status(path, error)) || error) return path;
        const fs::path target = fs::read_symlink(path, error);
        if (error) return path;
        path = target.is_absolute() ? target : path.parent_path() / target;
    }
    return std::nullopt;
}

/// Why a save must not replace what is at `target` (`subject` names it in
/// the message); empty for a writable regular file or nothing at all. Read
/// without following a link and without opening anything, so a FIFO cannot block.
std::string whyNotReplace(const fs::path& target, const std::string& subject) {
    std::error_code error;
    const fs::file_status status = fs::symlink_status(target, error);
    if (error || status.type() == fs::file_type::not_found) return ""; // a missing folder is reported when writing
    const char* kind = nullptr;
    switch (status.type()) {
    case fs::file_type::regular: {
        // The write bits, not access(): root may write anything, but a file
        // someone made read-only is still not to be replaced.
        const fs::perms write = fs::perms::owner_write | fs::perms::group_write | fs::perms::others_write;
        if ((status.permissions() & write) != fs::perms::none) return "";
        return subject + " is read-only (make it writable, or save under another name)";
    }
    case fs::file_type::directory: kind = "a folder"; break;
    case fs::file_type::fifo: kind = "a FIFO (a named pipe)"; break;
    case fs::file_type::character: kind = "a character device"; break;
    case fs::file_type::block: kind = "a block device"; break;
    case fs::file_type::socket: kind = "a socket"; break;
    default: kind = "something other than a file"; break;
    }
    return subject + " is " + kind + ", not a regular file; a save replaces only a regular file";
}

/// The PID in `entry` when it reads `prefix` PID "-" N (N a counter); 0 when not.
platform::ProcessId savingPid(const std::string& entry, const std::string& prefix) {
    if (entry.size() <= prefix.size() || entry.compare(0, prefix.size(), prefix) != 0) return 0;
    const char* const last = entry.data() + entry.size();
    const char* const first = entry.data() + prefix.size();
    platform::ProcessId pid = 0;
    const auto [dash, pidError] = std::from_chars(first, last, pid);
    if (pidError != std::errc() || pid <= 0 || dash == last || *dash != '-') return 0;
    unsigned long long counter = 0;
    const auto [end, counterError] = std::from_chars(dash + 1, last, counter);
    if (counterError != std::errc() || end != last) return 0;
    return pid;
}

/// Removes `.NAME.saving-PID-N` in `folder` when process PID no longer runs
/// (never one of a running process, whoever owns it).
void removeStaleTemporaries(const fs::path& folder, const std::string& name) {
    const std::string prefix = "." + name + ".saving-";
    const platform::ProcessId self = platform::currentProcessId();
    platform::removeRegularFilesIf(folder, [&](const std::string& entry) {
        const platform::ProcessId pid = savingPid(entry, prefix);
        return pid != 0 && pid != self && platform::processHasEnded(pid);
    });
}

/// Writes `text` to a new temporary file for `target` in `folder`, named in
/// `temporary`; the error when none could be written (then none is left).
std::error_code writeTemporary(const fs::path& folder, const fs::path& target, const std::string& text,
                               fs::path& temporary) {
    static std::atomic<unsigned> counter{0};
    std::error_code error = std::make_error_code(std::errc::file_exists);
    for (int attempt = 0; attempt < 100 && error == std::errc::file_exists; ++attempt) {
        temporary = folder / ("." + target.filename().string() + ".saving-" +
                              std::to_string(platform::currentProcessId()) + "-" + std::to_string(counter++));
        error = platform::writeNewFile(temporary, text, target);
    }
    return error;
}

} // namespace

void saveFileSafely(const fs::path& file, const std::string& text, const std::string& what) {
    const std::string name = file.string();
    const auto refuse = [&](const std::string& why) { throw InputError(name, 0, "cannot save " + what + ": " + why); };
    if (name.empty()) refuse("no file was named (the path is empty)");
    // Through a symbolic link into the file it names: the link stays a link.
    const std::optional<fs::path> followed = followLinks(file);
    if (!followed) {
        refuse("it is a symbolic link loop (following the links never reaches a file); remove a link or save under "
               "another name");
    }
    const fs::path& target = *followed;
    const std::string subject = target == file ? "it" : "the link's target " + target.string();
    if (const std::string why = whyNotReplace(target, subject); !why.empty()) refuse(why);

    // Same folder as the target, so same file system: the replacement is one step.
    const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
    removeStaleTemporaries(folder, target.filename().string());
    fs::path temporary;
    // Written and flushed to the disk; a file saved over an existing one keeps its permissions.
    std::error_code error = writeTemporary(folder, target, text, temporary);
    if (error) refuse(platform::describeWriteError(error, folder));
    // Checked again just before the replacement: what was swapped in meanwhile is not replaced either.
    const std::string why = whyNotReplace(target, subject);
    if (why.empty()) error = platform::replaceFile(temporary, target);
    if (error || !why.empty()) {
        platform::removeFile(temporary);
        refuse(why.empty() ? platform::describeWriteError(error, folder) : why);
    }
    platform::flushFolder(folder);
}

void removeStaleSaves(const fs::path& file) {
    const std::optional<fs::path> target = followLinks(file);
    if (!target || target->filename().empty()) return;
    const fs::path folder = target->has_parent_path() ? target->parent_path() : fs::path(".");
    removeStaleTemporaries(folder, target->filename().string());
}

} // namespace stoa
