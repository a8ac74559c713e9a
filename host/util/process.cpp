// process.cpp -- see process.h.
#include "util/process.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>

extern char** environ;

namespace lb::util {

namespace {

// The child's standard output read to its end (EINTR retried).
void drain(int fd, std::string& out)
{
    std::array<char, 4096> buf;
    for (;;) {
        ssize_t n = read(fd, buf.data(), buf.size());
        if (n > 0) {
            out.append(buf.data(), static_cast<size_t>(n));
        } else if (n == 0 || errno != EINTR) {
            return;
        }
    }
}

int waitFor(pid_t pid)
{
    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) return -1;
    if (WIFEXITED(status)) return WEXITSTATUS(status);
    if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
    return -1;
}

}  // namespace

int runProcess(const std::vector<std::string>& argv, const ProcessOptions& opt, std::string* why)
{
    if (argv.empty() || argv[0].empty()) {
        if (why) *why = "no program given";
        return -1;
    }
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    int pipefd[2] = {-1, -1};
    if (opt.out && pipe2(pipefd, O_CLOEXEC) != 0) {
        if (why) *why = std::strerror(errno);
        return -1;
    }
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    if (opt.out) posix_spawn_file_actions_adddup2(&fa, pipefd[1], 1);  // dup2 clears close-on-exec
    if (opt.quietStderr) posix_spawn_file_actions_addopen(&fa, 2, "/dev/null", O_WRONLY, 0);
    if (!opt.stderrPath.empty())
        posix_spawn_file_actions_addopen(&fa, 2, opt.stderrPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (!opt.cwd.empty()) posix_spawn_file_actions_addchdir_np(&fa, opt.cwd.c_str());
    pid_t pid = -1;
    int rc = posix_spawnp(&pid, args[0], &fa, nullptr, args.data(), environ);
    posix_spawn_file_actions_destroy(&fa);
    if (opt.out) close(pipefd[1]);
    if (rc != 0) {
        if (opt.out) close(pipefd[0]);
        if (why) *why = std::strerror(rc);
        return -1;
    }
    if (opt.out) {
        drain(pipefd[0], *opt.out);
        close(pipefd[0]);
    }
    return waitFor(pid);
}

}  // namespace lb::util
