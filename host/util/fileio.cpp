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

// "a FIFO", "a directory", ... for messages.
std::string fileKind(const fs::file_status& st)
{
    switch (st.type()) {
    case fs::file_type::regular:
        return "a regular file";
    case fs::file_type::directory:
        return "a directory";
    case fs::file_type::fifo:
        return "a FIFO (named pipe)";
    case fs::file_type::character:
        return "a character device";
    case fs::file_type::block:
        return "a block device";
    case fs::file_type::socket:
        return "a socket";
    case fs::file_type::not_found:
        return "nothing (no such file)";
    default:
        return "not a regular file";
    }
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
    // O_NONBLOCK: opening a FIFO without a writer would block; fstat then
    // refuses everything but a regular file (FIFOs, devices such as
    // /dev/zero, sockets), so no read can wait forever.
    int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0) throw InputError(fmt::format("{}: cannot open {}: {}", path, what, std::strerror(errno)));
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        ::close(fd);
        std::error_code ec;
        throw InputError(fmt::format("{}: expected {}, got {}", path, what, fileKind(fs::status(path, ec))));
    }
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
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

// Where the bytes for `path` go: the path itself, a symbolic link there
// included (the rename replaces the link, not its target). An existing
// device, FIFO or socket is refused: opening a FIFO for writing blocks until
// a reader comes, and renaming a temporary over a device node would replace
// the node with a plain file.
std::string resolveTarget(const std::string& path)
{
    std::error_code ec;
    if (path.empty()) throw InputError("an output path is empty; expected a file path");
    fs::file_status st = fs::symlink_status(path, ec);
    if (!ec && fs::exists(st) && !fs::is_regular_file(st) && !fs::is_symlink(st))
        throw InputError(fmt::format("{}: expected a regular file path for an output, got {}", path, fileKind(st)));
    return path;
}

std::string linkMessage(const fs::path& p, const std::string& root)
{
    std::error_code ec;
    const fs::path to = fs::read_symlink(p, ec);
    return fmt::format("{}: a symbolic link (to {}) inside the output folder {}; expected a directory or file of "
                       "its own (lumibench writes no output through a link: remove it)",
                       p.string(), ec ? std::string("?") : to.string(), root);
}

}  // namespace

void writeFilesAtomic(const std::vector<std::pair<std::string, std::string>>& input)
{
    std::vector<std::pair<std::string, std::string>> files;
    for (const auto& [path, bytes] : input) files.push_back({resolveTarget(path), bytes});
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
}

void writeFileAtomic(const std::string& path, const std::string& bytes) { writeFilesAtomic({{path, bytes}}); }

namespace {

// Whether `name` is NAME.tmp.PID or NAME.tmp.PID.SEQ (older lumibench wrote
// the first) of a process that no longer runs.
bool staleTemporary(const std::string& name)
{
    auto k = name.rfind(".tmp.");
    if (k == std::string::npos || k == 0) return false;
    std::string rest = name.substr(k + 5);
    auto dot = rest.find('.');
    std::string pid = rest.substr(0, dot), seq = dot == std::string::npos ? "1" : rest.substr(dot + 1);
    auto digits = [](const std::string& s) {
        return !s.empty() && s.size() <= 10 && s.find_first_not_of("0123456789") == std::string::npos;
    };
    if (!digits(pid) || !digits(seq)) return false;
    long p = std::stol(pid);
    return p <= 0 || (::kill(static_cast<pid_t>(p), 0) != 0 && errno == ESRCH);
}

}  // namespace

size_t removeStaleTemporaries(const std::string& dir)
{
    size_t removed = 0;
    std::error_code ec;
    // Every level below: a killed run leaves them in images/SCENE/ too. Links
    // are not followed, so nothing outside `dir` is touched.
    for (fs::recursive_directory_iterator it(dir, fs::directory_options::none, ec), end; !ec && it != end;
         it.increment(ec)) {
        std::error_code sec;
        if (!it->is_regular_file(sec) || !staleTemporary(it->path().filename().string())) continue;
        if (fs::remove(it->path(), sec)) ++removed;
    }
    return removed;
}

void createDirsBelow(const std::string& root, const std::string& rel)
{
    std::error_code ec;
    fs::create_directories(root, ec);
    if (ec) throw Error(fmt::format("{}: cannot create the directory: {}", root, ec.message()));
    fs::path p = root;
    for (const auto& part : fs::path(rel)) {
        if (part.empty() || part == ".") continue;
        p /= part;
        const fs::file_status st = fs::symlink_status(p, ec);
        if (fs::is_symlink(st)) throw InputError(linkMessage(p, root));
        if (fs::is_directory(st)) continue;
        if (fs::exists(st))
            throw InputError(
                fmt::format("{}: expected a directory inside the output folder, got {}", p.string(), fileKind(st)));
        if (!fs::create_directory(p, ec) && ec)
            throw Error(fmt::format("{}: cannot create the directory: {}", p.string(), ec.message()));
    }
}

void refuseLinksBelow(const std::string& root, const std::string& rel, bool dirsOnly)
{
    std::error_code ec;
    fs::path p = root;
    for (const auto& part : fs::path(rel)) {
        p /= part;
        if (fs::is_symlink(fs::symlink_status(p, ec))) throw InputError(linkMessage(p, root));
    }
    if (!fs::is_directory(fs::symlink_status(p, ec))) return;
    for (fs::recursive_directory_iterator it(p, fs::directory_options::none, ec), end; !ec && it != end;
         it.increment(ec))
        if (it->is_symlink(ec) && (!dirsOnly || fs::is_directory(it->path(), ec)))
            throw InputError(linkMessage(it->path(), root));
}

void copyTreeAtomic(const std::string& from, const std::string& to)
{
    std::error_code ec;
    fs::recursive_directory_iterator it(from, fs::directory_options::none, ec), end;
    if (ec) throw Error(fmt::format("{}: cannot read the directory: {}", from, ec.message()));
    for (; it != end; it.increment(ec)) {
        if (ec) throw Error(fmt::format("{}: cannot read the directory: {}", from, ec.message()));
        std::error_code sec;
        if (it->is_symlink(sec) || !it->is_regular_file(sec)) continue;
        const fs::path rel = fs::relative(it->path(), from, sec);
        createDirsBelow(to, rel.parent_path().string());
        // Images are at most a few hundred MiB (16384^2 floats is 1 GiB: allow 4).
        writeFileAtomic((fs::path(to) / rel).string(),
                        readFile(it->path().string(), "a file to copy", size_t(4) << 30));
    }
}

void setTempOpenerForTesting(TempOpener o) { opener() = std::move(o); }

}  // namespace lb::util
