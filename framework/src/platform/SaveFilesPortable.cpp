// SaveFiles where POSIX is missing: Windows. A new file is created with
// CreateFileW(CREATE_NEW) and flushed with FlushFileBuffers(); MoveFileExW
// with MOVEFILE_REPLACE_EXISTING | MOVEFILE_WRITE_THROUGH replaces the
// target in one step and returns only once the move is on the disk; whether
// a process runs is asked with OpenProcess() and GetExitCodeProcess(). The
// folder is read with std::filesystem.
#include <stoa/platform/SaveFiles.hpp>

#ifdef _WIN32

#ifndef NOMINMAX
#define NOMINMAX
#endif
#ifndef WIN32_LEAN_AND_MEAN
#define WIN32_LEAN_AND_MEAN
#endif
#include <windows.h>

namespace stoa::platform {

namespace fs = std::filesystem;

namespace {

std::error_code lastError() { return {static_cast<int>(::GetLastError()), std::system_category()}; }

/// Closes a Windows handle when it goes out of scope.
struct HandleCloser {
    HANDLE handle;
    ~HandleCloser() {
        if (handle != nullptr && handle != INVALID_HANDLE_VALUE) ::CloseHandle(handle);
    }
};

bool writeAll(HANDLE file, const std::string& text) {
    std::size_t written = 0;
    while (written < text.size()) {
        const std::size_t left = text.size() - written;
        const DWORD chunk = static_cast<DWORD>(left < (DWORD(1) << 30) ? left : (DWORD(1) << 30));
        DWORD done = 0;
        if (!::WriteFile(file, text.data() + written, chunk, &done, nullptr)) return false;
        written += done;
    }
    return ::FlushFileBuffers(file) != 0;
}

} // namespace

ProcessId currentProcessId() { return static_cast<ProcessId>(::GetCurrentProcessId()); }

bool processHasEnded(ProcessId pid) {
    if (pid <= 0 || pid > static_cast<ProcessId>(MAXDWORD)) return false;
    HandleCloser process{
        ::OpenProcess(PROCESS_QUERY_LIMITED_INFORMATION | SYNCHRONIZE, FALSE, static_cast<DWORD>(pid))};
    if (process.handle == nullptr) {
        // No such process; ERROR_ACCESS_DENIED is one that runs for someone else.
        return ::GetLastError() == ERROR_INVALID_PARAMETER;
    }
    DWORD code = 0;
    if (!::GetExitCodeProcess(process.handle, &code)) return false;
    if (code != STILL_ACTIVE) return true;
    // STILL_ACTIVE (259) may also be the code a process ended with: ask whether it is signalled.
    return ::WaitForSingleObject(process.handle, 0) == WAIT_OBJECT_0;
}

std::error_code writeNewFile(const fs::path& path, const std::string& text, const fs::path&) {
    // The permission bits need no copying: a file that may be replaced is writable, and so is the new one.
    HandleCloser file{
        ::CreateFileW(path.c_str(), GENERIC_WRITE, 0, nullptr, CREATE_NEW, FILE_ATTRIBUTE_NORMAL, nullptr)};
    if (file.handle == INVALID_HANDLE_VALUE) {
        const DWORD code = ::GetLastError();
        if (code == ERROR_FILE_EXISTS || code == ERROR_ALREADY_EXISTS) {
            return std::make_error_code(std::errc::file_exists);
        }
        return {static_cast<int>(code), std::system_category()};
    }
    std::error_code error;
    if (!writeAll(file.handle, text)) error = lastError();
    if (!::CloseHandle(file.handle) && !error) error = lastError();
    file.handle = nullptr;
    if (error) ::DeleteFileW(path.c_str());
    return error;
}

std::error_code replaceFile(const fs::path& from, const fs::path& to) {
    if (!::MoveFileExW(from.c_str(), to.c_str(), MOVEFILE_REPLACE_EXISTING | MOVEFILE_WRITE_THROUGH)) {
        return lastError();
    }
    return {};
}

void removeFile(const fs::path& file) { (void)::DeleteFileW(file.c_str()); }

void flushFolder(const fs::path&) {} // MOVEFILE_WRITE_THROUGH has flushed the move

void removeRegularFilesIf(const fs::path& folder, const std::function<bool(const std::string& name)>& isStale) {
    std::error_code error;
    for (fs::directory_iterator entry(folder, error), end; !error && entry != end; entry.increment(error)) {
        std::string name;
        try {
            name = entry->path().filename().string();
        } catch (const std::system_error&) {
            continue; // a name the narrow encoding cannot spell is no temporary file of ours
        }
        if (!isStale(name)) continue;
        std::error_code ignored;
        if (fs::is_regular_file(fs::symlink_status(entry->path(), ignored))) fs::remove(entry->path(), ignored);
    }
}

std::string describeWriteError(const std::error_code& error, const fs::path& folder) {
    if (error.category() == std::system_category()) {
        switch (error.value()) {
        case ERROR_FILE_NOT_FOUND:
        case ERROR_PATH_NOT_FOUND:
        case ERROR_INVALID_DRIVE: return "the folder " + folder.string() + " does not exist";
        case ERROR_ACCESS_DENIED:
        case ERROR_SHARING_VIOLATION:
            return "permission denied: cannot write in the folder " + folder.string() +
                   " (or the file is open in another program)";
        case ERROR_DISK_FULL:
        case ERROR_HANDLE_DISK_FULL: return "the disk is full";
        case ERROR_WRITE_PROTECT: return "the folder " + folder.string() + " is on a write-protected disk";
        case ERROR_DIRECTORY: return "this is a folder, not a file";
        default: break;
        }
    }
    return error.message();
}

} // namespace stoa::platform

#endif
