#include "metrics/flip.h"

#include "metrics/metrics.h"
#include "util/error.h"
#include "util/fileio.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <limits>
#include <mutex>
#include "lb_build_config.h"

extern char** environ;

namespace lb::metrics {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// One answer may take a while for a large image (about 1 s at 512 x 512 on
// one core); a co-process silent for this long is treated as hung.
constexpr int kAnswerTimeoutMs = 600 * 1000;

// The co-process's folders are lumibench-flip-PID-XXXXXX in the temporary
// directory, removed when this process ends; one whose process was killed
// (kill -9 runs no destructor) is removed by the next lumibench that starts
// FLIP: those of PIDs that no longer run.
void removeStaleFolders(const fs::path& tmp)
{
    const std::string prefix = "lumibench-flip-";
    std::error_code ec;
    for (fs::directory_iterator it(tmp, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string n = it->path().filename().string();
        if (n.rfind(prefix, 0) != 0 || !it->is_directory(ec) || it->is_symlink(ec)) continue;
        const std::string pid = n.substr(prefix.size(), n.find('-', prefix.size()) - prefix.size());
        if (pid.empty() || pid.size() > 9 || pid.find_first_not_of("0123456789") != std::string::npos) continue;
        if (::kill(static_cast<pid_t>(std::stol(pid)), 0) == 0 || errno != ESRCH) continue;
        std::error_code rec;
        fs::remove_all(it->path(), rec);
    }
}

// The co-process and its temporary directory, started on first use.
class FlipServer {
public:
    ~FlipServer() { stop(false); }

    bool available(std::string* why)
    {
        std::lock_guard<std::mutex> lock(mu_);
        start();
        if (why) *why = fd_ >= 0 ? ready_ : reason_;
        return fd_ >= 0;
    }

    // The mean, from the co-process; one that died (or hung) is started
    // again once for this image, so that one image it could not survive does
    // not leave every later one without FLIP.
    double mean(const Image& R, const Image& A)
    {
        std::lock_guard<std::mutex> lock(mu_);
        for (int attempt = 0;; ++attempt) {
            start();
            if (fd_ < 0) return kNaN;
            const fs::path rp = dir_ / "reference.f32", tp = dir_ / "test.f32";
            try {
                util::writeFilesAtomic({{rp.string(), floats(R)}, {tp.string(), floats(A)}});
            } catch (const std::exception& e) {
                fail(fmt::format("cannot write the images for it: {}", e.what()));
                return kNaN;
            }
            json req = {{"reference", rp.string()}, {"test", tp.string()}, {"width", R.width}, {"height", R.height}};
            json ans;
            std::string err;
            if (sendAll(req.dump() + "\n", err) && readLine(ans, err)) return value(ans, R);
            if (attempt > 0) {
                fail(fmt::format("the FLIP co-process stopped answering twice ({})", err));
                return kNaN;
            }
            std::cerr << fmt::format("lumibench: warning: the FLIP co-process stopped answering ({}) at a {}x{} "
                                     "image; starting it again\n",
                                     err, R.width, R.height);
            stop(true);
            started_ = false;
        }
    }

private:
    static double value(const json& ans, const Image& R)
    {
        if (ans.contains("error")) {
            // This image only: say so every time (it is not the one-per-run "not available").
            std::cerr << fmt::format("lumibench: warning: FLIP of a {}x{} image failed: {}; flip is null\n", R.width,
                                     R.height, ans["error"].get<std::string>());
            return kNaN;
        }
        const json& v = ans.value("flip", json());
        return v.is_number() ? v.get<double>() : kNaN;
    }

    static std::string floats(const Image& img)
    {
        std::string bytes(img.px.size() * sizeof(float), '\0');
        for (size_t i = 0; i < img.px.size(); ++i) {
            float f = static_cast<float>(img.px[i]);  // little-endian hosts only, as the EXR path
            std::memcpy(&bytes[i * sizeof(float)], &f, sizeof f);
        }
        return bytes;
    }

    void start()
    {
        if (started_) return;
        started_ = true;
        const std::string py = flipPython();
        const std::string script = (fs::path(LB_SOURCE_DIR) / "host" / "metrics" / "flip_server.py").string();
        std::error_code ec;
        if (!fs::exists(py, ec)) {
            return fail(fmt::format("no Python at {} (run scripts/install-deps.sh, or set LUMIBENCH_FLIP_PYTHON "
                                    "to a Python with flip-evaluator)",
                                    py));
        }
        if (!fs::exists(script, ec)) return fail(fmt::format("the co-process script {} is missing", script));
        const fs::path tmp = fs::temp_directory_path(ec);
        removeStaleFolders(tmp);
        std::string tmpl = (tmp / fmt::format("lumibench-flip-{}-XXXXXX", ::getpid())).string();
        if (!mkdtemp(tmpl.data()))
            return fail(fmt::format("cannot make a temporary directory {}: {}", tmpl, std::strerror(errno)));
        dir_ = tmpl;

        int sv[2];
        if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sv) != 0)
            return fail(fmt::format("socketpair: {}", std::strerror(errno)));
        posix_spawn_file_actions_t fa;
        posix_spawn_file_actions_init(&fa);
        posix_spawn_file_actions_adddup2(&fa, sv[1], 0);  // dup2 clears close-on-exec on 0 and 1
        posix_spawn_file_actions_adddup2(&fa, sv[1], 1);
        std::vector<char*> argv = {const_cast<char*>(py.c_str()), const_cast<char*>(script.c_str()), nullptr};
        int rc = posix_spawn(&pid_, py.c_str(), &fa, nullptr, argv.data(), environ);
        posix_spawn_file_actions_destroy(&fa);
        close(sv[1]);
        if (rc != 0) {
            close(sv[0]);
            pid_ = -1;
            return fail(fmt::format("cannot start {}: {}", py, std::strerror(rc)));
        }
        fd_ = sv[0];
        json hello;
        std::string err;
        if (!readLine(hello, err)) return fail(fmt::format("{} {} did not start: {}", py, script, err));
        if (hello.contains("ready")) {
            ready_ = hello["ready"].get<std::string>();
            return;
        }
        fail(hello.contains("unavailable")
                 ? "flip-evaluator cannot be imported: " + hello["unavailable"].get<std::string>()
                 : "unexpected greeting " + hello.dump());
    }

    // Not available from now on: one warning, the co-process stopped.
    void fail(const std::string& why)
    {
        reason_ = why;
        std::cerr << fmt::format("lumibench: warning: FLIP is not available: {}; flip is null in this run's output\n",
                                 why);
        stop(true);
    }

    bool sendAll(const std::string& s, std::string& err)
    {
        size_t off = 0;
        while (off < s.size()) {
            ssize_t n = send(fd_, s.data() + off, s.size() - off, MSG_NOSIGNAL);  // no SIGPIPE when it died
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) {
                err = std::strerror(errno);
                return false;
            }
            off += static_cast<size_t>(n);
        }
        return true;
    }

    // One JSON line from the co-process.
    bool readLine(json& out, std::string& err)
    {
        size_t nl;
        while ((nl = buf_.find('\n')) == std::string::npos) {
            pollfd p{fd_, POLLIN, 0};
            int r = poll(&p, 1, kAnswerTimeoutMs);
            if (r < 0 && errno == EINTR) continue;
            if (r == 0) {
                err = fmt::format("no answer in {} s", kAnswerTimeoutMs / 1000);
                return false;
            }
            char chunk[4096];
            ssize_t n = r > 0 ? recv(fd_, chunk, sizeof chunk, 0) : -1;
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) {
                err = n == 0 ? "it exited (its messages are above)" : std::strerror(errno);
                return false;
            }
            buf_.append(chunk, static_cast<size_t>(n));
        }
        std::string line = buf_.substr(0, nl);
        buf_.erase(0, nl + 1);
        try {
            out = json::parse(line);
        } catch (const json::parse_error&) {
            err = "not a JSON line: " + line.substr(0, 200);
            return false;
        }
        if (!out.is_object()) {
            err = "not a JSON object: " + line.substr(0, 200);
            return false;
        }
        return true;
    }

    // Closing its input ends it; `force` (given up on it, maybe hung) kills it first.
    void stop(bool force)
    {
        if (fd_ >= 0) close(fd_);
        fd_ = -1;
        if (pid_ > 0) {
            if (force) kill(pid_, SIGKILL);
            int st = 0;
            while (waitpid(pid_, &st, 0) < 0 && errno == EINTR) {}
        }
        pid_ = -1;
        std::error_code ec;
        if (!dir_.empty()) fs::remove_all(dir_, ec);
        dir_.clear();
    }

    std::mutex mu_;
    bool started_ = false;
    int fd_ = -1;
    pid_t pid_ = -1;
    fs::path dir_;
    std::string buf_, ready_, reason_;
};

FlipServer& server()
{
    static FlipServer s;
    return s;
}

}  // namespace

std::string flipPython()
{
    if (const char* env = std::getenv("LUMIBENCH_FLIP_PYTHON"); env && *env) return env;
    return (fs::path(LB_SOURCE_DIR) / ".venv" / "bin" / "python").string();
}

bool flipAvailable(std::string* why) { return server().available(why); }

double flip(const Image& reference, const Image& test)
{
    checkComparable(reference, test);
    return server().mean(reference, test);
}

}  // namespace lb::metrics
