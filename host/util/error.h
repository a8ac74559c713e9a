// error.h -- the exceptions every layer throws and the CLI turns into exit codes.
#pragma once

#include <stdexcept>
#include <string>

namespace lb {

// Exit codes of build/lumibench (documented in --help):
//   1 internal or device error, 2 bad input (file, arguments).
enum ExitCode { kExitError = 1, kExitInput = 2 };

struct Error : std::runtime_error {
    int code;
    explicit Error(const std::string& msg, int c = kExitError) : std::runtime_error(msg), code(c) {}
};

// Bad user input: a malformed file, an unknown method, an out-of-range argument.
struct InputError : Error {
    explicit InputError(const std::string& msg) : Error(msg, kExitInput) {}
};

}  // namespace lb
