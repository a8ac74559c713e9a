#include "experiments/run_lock.h"

#include "util/error.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace lb::experiments {

using nlohmann::json;

namespace {

// open(2) of a file of the output folder, never through a link.
int openHere(const std::string& path)
{
    int fd = ::open(path.c_str(), O_CREAT | O_RDWR | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd >= 0) return fd;
    if (errno == ELOOP)
        throw InputError(fmt::format("{}: a symbolic link; expected a regular file (lumibench writes no output "
                                     "through a link: remove it)",
                                     path));
    throw Error(fmt::format("{}: cannot open: {}", path, std::strerror(errno)));
}

void lockOrThrow(int fd, int op, const std::string& path)
{
    while (::flock(fd, op) != 0) {
        if (errno == EINTR) continue;
        const int e = errno;
        ::close(fd);
        throw Error(fmt::format("{}: cannot lock: {}", path, std::strerror(e)));
    }
}

std::string readAll(int fd)
{
    std::string s;
    char buf[4096];
    for (off_t off = 0;;) {
        ssize_t n = ::pread(fd, buf, sizeof buf, off);
        if (n <= 0) break;
        s.append(buf, size_t(n));
        off += n;
    }
    return s;
}

}  // namespace

RunLock::RunLock(const std::string& resultsPath, const std::string& identity, const std::string& name,
                 const std::string& file)
{
    const std::string guardPath = resultsPath + ".lock", path = resultsPath + ".run";
    const int guard = openHere(guardPath);
    lockOrThrow(guard, LOCK_EX, guardPath);
    struct Close {
        int fd;
        ~Close() { ::close(fd); }
    } closeGuard{guard};
    fd_ = openHere(path);
    const json mine = {{"identity", identity}, {"experiment", name}, {"file", file}, {"pid", ::getpid()}};
    if (::flock(fd_, LOCK_EX | LOCK_NB) == 0) {  // no run holds it: ours from now on
        const std::string text = mine.dump() + '\n';
        if (::ftruncate(fd_, 0) != 0 || ::pwrite(fd_, text.data(), text.size(), 0) != ssize_t(text.size())) {
            const int e = errno;
            ::close(fd_);
            throw Error(fmt::format("{}: cannot write: {}", path, std::strerror(e)));
        }
        lockOrThrow(fd_, LOCK_SH, path);  // (under the guard: no other run tests in between)
        return;
    }
    json other = json::object();
    try {
        other = json::parse(readAll(fd_));
    } catch (const json::exception&) {
    }
    if (other.is_object() && other.value("identity", std::string()) == identity) {
        lockOrThrow(fd_, LOCK_SH, path);  // a shard of the same experiment: join
        return;
    }
    ::close(fd_);
    fd_ = -1;
    const auto field = [&](const char* k) {
        return other.is_object() && other.contains(k)
            ? (other[k].is_string() ? other[k].get<std::string>() : other[k].dump())
            : std::string("?");
    };
    throw InputError(fmt::format("{}: another run is writing into this folder (experiment '{}' from {}, pid {}); "
                                 "expected one experiment per output folder at a time (this one: '{}' from {}): "
                                 "wait for it to end, or give another --out",
                                 path, field("experiment"), field("file"), field("pid"), name, file));
}

RunLock::~RunLock()
{
    if (fd_ >= 0) ::close(fd_);  // closing drops the lock
}

}  // namespace lb::experiments
