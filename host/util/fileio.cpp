#include "util/fileio.h"

#include "util/error.h"

#include <fmt/format.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace lb::util {

namespace fs = std::filesystem;

namespace {

TempOpener& opener()
{
    static TempOpener o;
    return o;
}

int openTemp(const std::string& tmp)
{
    if (opener()) return opener()(tmp);
    return ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
}

std::string tempPathFor(const std::string& path)
{
    static std::atomic<unsigned> seq{0};
    return fmt::format("{}.tmp.{}.{}", path, ::getpid(), seq++);
}

// Writes all of `bytes` to `fd`, then fsync and close; false with errno set on
// the first failure (the descriptor is closed either way).
bool writeAllAndClose(int fd, const std::string& bytes)
{
    const char* p = bytes.data();
    size_t left = bytes.size();
    while (left > 0) {
        ssize_t n = ::write(fd, p, left);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            if (n == 0) errno = EIO;
            int e = errno;
            ::close(fd);
            errno = e;
            return false;
        }
        p += n;
        left -= static_cast<size_t>(n);
    }
    // fsync reports delayed write errors (e.g. ENOSPC on a network file
    // system) and puts the data on disk before the rename makes it visible.
    if (::fsync(fd) != 0 && errno != EINVAL && errno != EROFS) {  // EINVAL: a special file without fsync
        int e = errno;
        ::close(fd);
        errno = e;
        return false;
    }
    return ::close(fd) == 0;
}

void syncDirectory(const std::string& path)
{
    fs::path dir = fs::path(path).parent_path();
    int fd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd >= 0) {
        ::fsync(fd);  // the rename itself on disk; best effort
        ::close(fd);
    }
}

}  // namespace

std::string readFile(const std::string& path, const std::string& what, size_t maxBytes)
{
    std::error_code ec;
    if (fs::is_directory(path, ec)) throw InputError(fmt::format("{}: expected {}, got a directory", path, what));
    int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) throw InputError(fmt::format("{}: cannot open {}: {}", path, what, std::strerror(errno)));
    std::string out;
    char buf[65536];
    for (;;) {
        ssize_t n = ::read(fd, buf, sizeof buf);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            int e = errno;
            ::close(fd);
            throw InputError(fmt::format("{}: cannot read {}: {}", path, what, std::strerror(e)));
        }
        if (n == 0) break;
        if (out.size() + static_cast<size_t>(n) > maxBytes) {  // stop at the limit: /dev/zero never ends
            ::close(fd);
            throw InputError(fmt::format("{}: expected {} of at most {} bytes, got more", path, what, maxBytes));
        }
        out.append(buf, static_cast<size_t>(n));
    }
    ::close(fd);
    return out;
}

namespace {

// Where the bytes for `path` go: a symbolic link is followed (its target is
// replaced, the link stays); an existing device, FIFO or socket (--out
// /dev/null, a pipe) is written in place, since renaming a temporary over it
// would replace the device node with a plain file.
struct Target {
    std::string path;
    bool special = false;
};

Target resolveTarget(const std::string& path)
{
    std::error_code ec;
    Target t{path, false};
    if (fs::is_symlink(fs::symlink_status(path, ec))) {
        fs::path real = fs::weakly_canonical(path, ec);
        if (!ec) t.path = real.string();
    }
    fs::file_status st = fs::status(t.path, ec);
    t.special = !ec && fs::exists(st) && !fs::is_regular_file(st) && !fs::is_directory(st);
    return t;
}

void writeInPlace(const std::string& path, const std::string& bytes)
{
    int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd < 0) throw Error(fmt::format("{}: cannot write: {}", path, std::strerror(errno)));
    if (!writeAllAndClose(fd, bytes))
        throw Error(fmt::format("{}: cannot write {} bytes: {}", path, bytes.size(), std::strerror(errno)));
}

}  // namespace

void writeFilesAtomic(const std::vector<std::pair<std::string, std::string>>& input)
{
    std::vector<std::pair<std::string, std::string>> files;
    std::vector<std::pair<std::string, const std::string*>> special;
    for (const auto& [path, bytes] : input) {
        Target t = resolveTarget(path);
        if (t.special)
            special.push_back({t.path, &bytes});
        else
            files.push_back({t.path, bytes});
    }
    std::vector<std::string> temps;
    auto removeTemps = [&] {
        for (const auto& t : temps) ::unlink(t.c_str());
    };
    for (const auto& [path, bytes] : files) {
        std::string tmp = tempPathFor(path);
        int fd = openTemp(tmp);
        if (fd < 0) {
            int e = errno;
            removeTemps();
            throw Error(fmt::format("{}: cannot write: {}", path, std::strerror(e)));
        }
        temps.push_back(tmp);
        if (!writeAllAndClose(fd, bytes)) {
            int e = errno;
            removeTemps();
            throw Error(
                fmt::format("{}: cannot write {} bytes: {} (nothing written)", path, bytes.size(), std::strerror(e)));
        }
    }
    for (size_t i = 0; i < files.size(); ++i)
        if (::rename(temps[i].c_str(), files[i].first.c_str()) != 0) {
            int e = errno;
            for (size_t k = i; k < temps.size(); ++k) ::unlink(temps[k].c_str());
            throw Error(
                fmt::format("{}: cannot write: rename from {} failed: {}", files[i].first, temps[i], std::strerror(e)));
        }
    for (const auto& f : files) syncDirectory(f.first);
    for (const auto& [path, bytes] : special) writeInPlace(path, *bytes);
}

void writeFileAtomic(const std::string& path, const std::string& bytes) { writeFilesAtomic({{path, bytes}}); }

size_t removeStaleTemporaries(const std::string& dir)
{
    size_t removed = 0;
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        // NAME.tmp.PID or NAME.tmp.PID.SEQ (older lumibench wrote the first)
        auto k = name.rfind(".tmp.");
        if (k == std::string::npos || k == 0) continue;
        std::string rest = name.substr(k + 5);
        auto dot = rest.find('.');
        std::string pid = rest.substr(0, dot), seq = dot == std::string::npos ? "1" : rest.substr(dot + 1);
        auto digits = [](const std::string& s) {
            return !s.empty() && s.size() <= 10 && s.find_first_not_of("0123456789") == std::string::npos;
        };
        if (!digits(pid) || !digits(seq)) continue;
        long p = std::stol(pid);
        if (p <= 0 || (::kill(static_cast<pid_t>(p), 0) != 0 && errno == ESRCH)) {
            std::error_code rec;
            if (fs::remove(it->path(), rec)) ++removed;
        }
    }
    return removed;
}

void setTempOpenerForTesting(TempOpener o) { opener() = std::move(o); }

}  // namespace lb::util
