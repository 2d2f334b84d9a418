// Files on disk: reading one with its size checked before it is read
// into memory, and writing any text atomically (temporary file in the same
// folder, fsync, rename), so that an interrupted write never leaves half a
// file where a whole one was.
#include "io/job_io.h"

#include "io/job_messages.h"

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace taiwa {

namespace {

Diagnostic fileProblem(std::string message) { return {Severity::Error, std::nullopt, "", "", std::move(message)}; }

io::TextReadResult refused(std::string message)
{
    io::TextReadResult r;
    r.diagnostics.push_back(fileProblem(std::move(message)));
    return r;
}

std::string systemError(int error) { return std::generic_category().message(error); }

// Writes all of `text` to `fd`, retrying short writes; false with errno set on failure.
bool writeAll(int fd, std::string_view text)
{
    while (!text.empty()) {
        const ssize_t n = ::write(fd, text.data(), text.size());
        if (n < 0) {
            if (errno == EINTR) continue;
            return false;
        }
        text.remove_prefix(static_cast<std::size_t>(n));
    }
    return true;
}

// Creates a new temporary file beside `target`; its path in `tempPath`.
int createTemporary(const std::filesystem::path& target, std::string& tempPath)
{
    static std::atomic<unsigned> counter{0};  // exports and autosave write from several threads
    for (int attempt = 0; attempt < 100; ++attempt) {
        const std::string name = "." + target.filename().string() + ".tmp-" + std::to_string(::getpid()) + "-"
                                 + std::to_string(++counter);
        tempPath = (target.parent_path() / name).string();
        const int fd = ::open(tempPath.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0 || errno != EEXIST) return fd;
    }
    errno = EEXIST;
    return -1;
}

}  // namespace

io::TextReadResult io::readTextFile(const std::string& path, std::size_t maxBytes)
{
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (ec) return refused(msg::io::fileCannotOpen(ec.message()));
    // status() reports a missing file as a type, not as an error.
    if (status.type() == std::filesystem::file_type::not_found)
        return refused(msg::io::fileCannotOpen(std::make_error_code(std::errc::no_such_file_or_directory).message()));
    if (std::filesystem::is_directory(status)) return refused(msg::io::fileCannotOpen(systemError(EISDIR)));
    // Devices and pipes could be endless: only regular files are read.
    if (!std::filesystem::is_regular_file(status)) return refused(msg::io::notAFile());
    const auto size = std::filesystem::file_size(path, ec);
    if (ec) return refused(msg::io::fileCannotOpen(ec.message()));
    if (size > maxBytes) return refused(msg::io::fileTooLarge(size, maxBytes));

    std::ifstream in(path, std::ios::binary);
    if (!in) return refused(msg::io::fileCannotOpen(systemError(errno)));
    // One byte more than its size: a file that grew since is noticed.
    std::string text(static_cast<std::size_t>(size) + 1, '\0');
    in.read(text.data(), static_cast<std::streamsize>(text.size()));
    if (in.bad()) return refused(msg::io::fileUnreadable(systemError(errno)));
    text.resize(static_cast<std::size_t>(in.gcount()));
    if (text.size() > size) return refused(msg::io::fileUnreadable("the file changed while it was read"));
    return {std::move(text), {}};
}

std::optional<std::string> writeFileAtomically(const std::string& path, std::string_view text)
{
    const std::filesystem::path target = std::filesystem::absolute(path);
    std::string temp;
    const int fd = createTemporary(target, temp);
    if (fd < 0) return "cannot create a file in " + target.parent_path().string() + ": " + systemError(errno);

    // Keep the permissions of the file being replaced.
    int error = 0;
    struct stat old {};
    const bool replacing = ::stat(target.c_str(), &old) == 0;
    if ((replacing && ::fchmod(fd, old.st_mode & 07777) != 0) || !writeAll(fd, text) || ::fsync(fd) != 0) error = errno;
    if (::close(fd) != 0 && error == 0) error = errno;
    if (error == 0 && ::rename(temp.c_str(), target.c_str()) != 0) error = errno;
    if (error == 0) {
        // Make the rename itself durable.
        const int dir = ::open(target.parent_path().c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
        if (dir >= 0) {
            ::fsync(dir);
            ::close(dir);
        }
        return std::nullopt;
    }
    ::unlink(temp.c_str());
    return "cannot write " + target.string() + ": " + systemError(error);
}

}  // namespace taiwa
