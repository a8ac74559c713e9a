// process.h -- running a child program without a shell.
//
// The program and its arguments travel as an argument vector to posix_spawn:
// no string is ever parsed by a shell, so a directory named
// "x'$(touch PWNED)'y" or "it's results" is one argument like any other.
#pragma once

#include <string>
#include <vector>

namespace lb::util {

struct ProcessOptions {
    std::string* out = nullptr;  // when set, receives the child's standard output
    bool quietStderr = false;  // the child's standard error to /dev/null
    std::string stderrPath;  // when set, the child's standard error goes to this file (created or truncated)
    std::string cwd;  // when set, the child's working directory
};

// Runs argv[0] (a path; a bare name is looked up on PATH) with argv[1..] and
// waits for it. Returns its exit status, 128 + N when signal N ended it, and
// -1 when it could not be started (`why` then says why, if given).
int runProcess(const std::vector<std::string>& argv, const ProcessOptions& opt = {}, std::string* why = nullptr);

}  // namespace lb::util
