// Files on disk: reading one with its size checked before it is read
// into memory, and writing any text atomically (temporary file in the same
// folder, fsync, rename), so that an interrupted write never leaves half a
// file where a whole one was.
#include "io/job_io.h"

#include "io/job_messages.h"
#include "model/translate_noop.h"

#include <fmt/format.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <utility>

#include <fcntl.h>
#include <sys/file.h>
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

// "cannot write PATH: why", of every write that failed.
std::string cannotWrite(const std::string& path, int error)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "cannot write {}: {}"), path, systemError(error));
}

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
        // O_EXCL: a name that exists, a planted link included, is never opened.
        const int fd = ::open(tempPath.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
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
    if (text.size() > size) return refused(msg::io::fileUnreadable(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the file changed while it was read")));
    return {std::move(text), {}};
}

namespace {

// Writes `text` to a new exclusive temporary beside `target`, synced, with
// the permissions of the file it will replace; the temporary's path.
Result<std::string> writeTemporary(const std::filesystem::path& target, std::string_view text)
{
    std::string temp;
    const int fd = createTemporary(target, temp);
    if (fd < 0) return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "cannot create a file in {}: {}"), target.parent_path().string(), systemError(errno))};
    int error = 0;
    struct stat old {};
    const bool replacing = ::stat(target.c_str(), &old) == 0;
    if ((replacing && ::fchmod(fd, old.st_mode & 07777) != 0) || !writeAll(fd, text) || ::fsync(fd) != 0) error = errno;
    if (::close(fd) != 0 && error == 0) error = errno;
    if (error != 0) {
        ::unlink(temp.c_str());
        return Failure{cannotWrite(target.string(), error)};
    }
    return temp;
}

// Makes the renames in a folder durable.
void syncFolder(const std::filesystem::path& folder)
{
    const int dir = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dir < 0) return;
    ::fsync(dir);
    ::close(dir);
}

// Temporaries of `stem` in `folder` whose writer has died (".STEM.x.tmp-PID-N"),
// and the fixed-name partial PDF of older versions.
void removeStaleTemporaries(const std::filesystem::path& folder, const std::string& stem)
{
    std::error_code ec;
    std::filesystem::remove(folder / (stem + ".sheet.pdf.partial"), ec);
    const std::string prefix = "." + stem + ".";
    for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
        const std::string name = entry.path().filename().string();
        const auto tmp = name.rfind(".tmp-");
        if (!name.starts_with(prefix) || tmp == std::string::npos) continue;
        const std::string owner = name.substr(tmp + 5, name.find('-', tmp + 5) - (tmp + 5));
        if (owner.empty() || owner.find_first_not_of("0123456789") != std::string::npos) continue;
        const pid_t pid = static_cast<pid_t>(std::stol(owner));
        if (pid == ::getpid() || (::kill(pid, 0) != 0 && errno == ESRCH)) std::filesystem::remove(entry.path(), ec);
    }
}

// The journal of a set being switched in: ".STEM.set" in the folder, one
// line per step: "rename\tTEMP\tTARGET" or "remove\tPATH".
std::filesystem::path journalOf(const std::filesystem::path& folder, const std::string& stem)
{
    return folder / ("." + stem + ".set");
}

// Finishes the switch a killed process left: every temporary still there
// renamed over its target, every removal made, then the journal removed.
// Temporaries are whole and synced before a journal names them.
void rollForward(const std::filesystem::path& folder, const std::string& stem)
{
    const auto journal = journalOf(folder, stem);
    std::ifstream in(journal);
    if (!in) return;
    std::string line;
    bool complete = false;
    std::vector<std::pair<std::string, std::string>> steps;
    while (std::getline(in, line)) {
        if (line == "end") {
            complete = true;
            break;
        }
        const auto tab = line.find('\t');
        if (tab == std::string::npos) continue;
        steps.emplace_back(line.substr(0, tab), line.substr(tab + 1));
    }
    // A journal cut short was never in force: no rename had begun.
    if (complete) {
        for (const auto& [what, rest] : steps) {
            if (what == "rename") {
                const auto tab = rest.find('\t');
                if (tab == std::string::npos) continue;
                const std::string temp = rest.substr(0, tab), target = rest.substr(tab + 1);
                // Only names of this folder: a journal is never a way to write elsewhere.
                if (std::filesystem::path(temp).parent_path() != folder || std::filesystem::path(target).parent_path() != folder) continue;
                if (::access(temp.c_str(), F_OK) == 0) ::rename(temp.c_str(), target.c_str());
            } else if (what == "remove" && std::filesystem::path(rest).parent_path() == folder) {
                ::unlink(rest.c_str());
            }
        }
        syncFolder(folder);
    }
    ::unlink(journal.c_str());
    syncFolder(folder);
}

}  // namespace

Result<void> writeFileAtomically(const std::string& path, std::string_view text)
{
    const std::filesystem::path target = std::filesystem::absolute(path);
    auto temp = writeTemporary(target, text);
    if (!temp) return Failure{temp.error()};
    if (::rename(temp->c_str(), target.c_str()) != 0) {
        const int error = errno;
        ::unlink(temp->c_str());
        return Failure{cannotWrite(target.string(), error)};
    }
    syncFolder(target.parent_path());
    return {};
}

FileSet::FileSet(std::string folder, std::string stem, int lock)
    : folder_(std::move(folder)), stem_(std::move(stem)), lock_(lock)
{
}

FileSet::FileSet(FileSet&& o) noexcept
    : folder_(std::move(o.folder_)), stem_(std::move(o.stem_)), lock_(std::exchange(o.lock_, -1)),
      staged_(std::move(o.staged_))
{
    o.staged_.clear();
}

FileSet::~FileSet()
{
    for (const auto& s : staged_) ::unlink(s.temp.c_str());
    if (lock_ >= 0) ::close(lock_);  // releases the flock
}

Result<FileSet> FileSet::open(const std::string& folder, const std::string& stem)
{
    const std::filesystem::path dir = std::filesystem::absolute(folder);
    auto lockPath = lockPathFor(dir.string(), stem);
    if (!lockPath) return Failure{lockPath.error()};
    const int fd = ::open(lockPath->c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0600);
    if (fd < 0) return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "cannot create the lock file {}: {}"), *lockPath, systemError(errno))};
    while (::flock(fd, LOCK_EX) != 0) {
        if (errno == EINTR) continue;
        const int error = errno;
        ::close(fd);
        return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "cannot lock {}: {}"), *lockPath, systemError(error))};
    }
    rollForward(dir, stem);
    removeStaleTemporaries(dir, stem);
    // The empty lock file an earlier version left in the folder.
    struct stat old {};
    const std::string oldLock = (dir / ("." + stem + ".lock")).string();
    if (::lstat(oldLock.c_str(), &old) == 0 && S_ISREG(old.st_mode) && old.st_size == 0) ::unlink(oldLock.c_str());
    return FileSet(dir.string(), stem, fd);
}

Result<std::string> FileSet::lockPathFor(const std::string& folder, const std::string& stem)
{
    // The user's runtime folder, else a folder of the user's own in the temporary one.
    std::error_code ec;
    const char* runtime = std::getenv("XDG_RUNTIME_DIR");
    std::filesystem::path locks = runtime && *runtime && std::filesystem::is_directory(runtime, ec)
                                      ? std::filesystem::path(runtime) / "taiwa-locks"
                                      : std::filesystem::temp_directory_path(ec) / ("taiwa-locks-" + std::to_string(::getuid()));
    if (::mkdir(locks.c_str(), 0700) != 0 && errno != EEXIST)
        return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "cannot create the lock file {}: {}"), locks.string(), systemError(errno))};
    // Keyed by the folder's canonical path (a link or "a/../b" is the same
    // folder) and the stem: FNV-1a, 64 bits.
    const std::string key = std::filesystem::weakly_canonical(std::filesystem::absolute(folder), ec).string() + '\n' + stem;
    std::uint64_t h = 14695981039346656037ull;
    for (const unsigned char c : key) h = (h ^ c) * 1099511628211ull;
    return (locks / fmt::format("export-{:016x}.lock", h)).string();
}

Result<void> FileSet::add(const std::string& name, std::string_view bytes)
{
    const std::filesystem::path target = std::filesystem::path(folder_) / name;
    auto temp = writeTemporary(target, bytes);
    if (!temp) return Failure{temp.error()};
    staged_.push_back({target.string(), std::move(*temp)});
    return {};
}

void FileSet::remove(const std::string& name)
{
    const std::filesystem::path target = std::filesystem::path(folder_) / name;
    std::error_code ec;
    if (std::filesystem::symlink_status(target, ec).type() != std::filesystem::file_type::not_found)
        removals_.push_back(target.string());
}

Result<std::vector<std::string>> FileSet::commit(const std::function<void(std::size_t)>& between)
{
    // The journal, whole and synced before the first rename: a kill from
    // here on is finished by the next open().
    std::string journal;
    for (const auto& s : staged_) journal += "rename\t" + s.temp + "\t" + s.target + "\n";
    for (const auto& r : removals_) journal += "remove\t" + r + "\n";
    journal += "end\n";
    const auto journalPath = journalOf(folder_, stem_);
    if (auto written = writeFileAtomically(journalPath.string(), journal); !written) return Failure{written.error()};

    // The old files are kept under a second name until every new one is in place.
    std::vector<std::string> backups(staged_.size());
    for (std::size_t i = 0; i < staged_.size(); ++i) {
        const std::string backup = staged_[i].temp + ".old";
        if (::link(staged_[i].target.c_str(), backup.c_str()) == 0) backups[i] = backup;
    }
    const auto dropBackups = [&] {
        for (const auto& b : backups)
            if (!b.empty()) ::unlink(b.c_str());
    };
    std::vector<std::string> written;
    for (std::size_t i = 0; i < staged_.size(); ++i) {
        if (::rename(staged_[i].temp.c_str(), staged_[i].target.c_str()) == 0) {
            written.push_back(staged_[i].target);
            if (between) between(written.size());
            continue;
        }
        const int error = errno;
        // Put back what was there: the old set stays whole.
        for (std::size_t k = 0; k < i; ++k) {
            if (!backups[k].empty()) ::rename(backups[k].c_str(), staged_[k].target.c_str());
            else ::unlink(staged_[k].target.c_str());
            backups[k].clear();
        }
        dropBackups();
        ::unlink(journalPath.c_str());
        syncFolder(folder_);
        return Failure{cannotWrite(staged_[i].target, error)};
    }
    for (const auto& r : removals_) ::unlink(r.c_str());
    staged_.clear();
    removals_.clear();
    dropBackups();
    syncFolder(folder_);
    ::unlink(journalPath.c_str());
    syncFolder(folder_);
    return written;
}

}  // namespace taiwa
