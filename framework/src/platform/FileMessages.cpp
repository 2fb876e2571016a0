#include "FileMessages.hpp"

namespace stoa::platform {

std::string describeFileType(std::filesystem::file_type type) {
    using std::filesystem::file_type;
    switch (type) {
    case file_type::directory: return "a folder";
    case file_type::fifo: return "a FIFO (named pipe), which could block reading forever";
    case file_type::character: return "a character device (such as /dev/zero), which could be read without end";
    case file_type::block: return "a block device";
    case file_type::socket: return "a socket";
    default: return "not a regular file";
    }
}

std::string describeOpenError(const std::error_code& error) {
    // Compared with portable conditions: errno values on POSIX, the
    // platform's codes (as std::filesystem reports them) elsewhere.
    if (error == std::errc::no_such_file_or_directory) return "the file does not exist";
    if (error == std::errc::not_a_directory) return "the file does not exist (a part of its path is not a folder)";
    if (error == std::errc::too_many_symbolic_link_levels) {
        return "the path is a loop of symbolic links (too many levels of symbolic links)";
    }
    if (error == std::errc::filename_too_long) {
        return "the file name is too long for the system (a part of the path has over 255 bytes, "
               "or the whole path is too long)";
    }
    if (error == std::errc::permission_denied) return "permission denied: the file cannot be read";
    return "the file cannot be opened: " + error.message();
}

} // namespace stoa::platform
