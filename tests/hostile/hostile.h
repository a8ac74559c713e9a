// hostile.h -- what the hostile suites share: build/lumibench run through an
// argument vector (no shell) under `timeout`, so that the strings reach the
// program exactly as written and a read that blocks fails the test instead of
// hanging it; fresh folders, the smallest experiment.
#pragma once

#include "testutil.h"
#include "util/process.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <vector>

namespace lb::hostile {

namespace fs = std::filesystem;
using nlohmann::json;

struct CliRun {
    int code = -1;
    std::string out, err;
};

// build/lumibench `args` in directory `cwd`, killed after `seconds`
// (exit 124: it blocked); `env` adds NAME=VALUE pairs to its environment.
inline CliRun lumibench(const fs::path& cwd, const std::vector<std::string>& args, int seconds = 120,
                        const std::vector<std::string>& env = {})
{
    static int seq = 0;
    std::vector<std::string> argv = {"timeout", "-k", "5", std::to_string(seconds), test::binary()};
    if (!env.empty()) {
        argv.insert(argv.begin(), env.begin(), env.end());
        argv.insert(argv.begin(), "env");
    }
    argv.insert(argv.end(), args.begin(), args.end());
    CliRun r;
    util::ProcessOptions o;
    o.out = &r.out;
    o.cwd = cwd.string();
    // stderr beside cwd, not in it: the tests look for files that appear there
    const fs::path err = cwd.parent_path() / fmt::format("{}.stderr.{}", cwd.filename().string(), seq++);
    o.stderrPath = err.string();
    r.code = util::runProcess(argv, o);
    std::ifstream f(err);
    r.err.assign(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
    fs::remove(err);
    return r;
}

inline std::string what(const std::vector<std::string>& args)
{
    std::string s;
    for (const auto& a : args) s += " [" + a + "]";
    return s;
}

// Every path below `d`, relative to it (links not followed).
inline std::set<std::string> tree(const fs::path& d)
{
    std::set<std::string> out;
    for (const auto& e : fs::recursive_directory_iterator(d)) out.insert(fs::relative(e.path(), d).string());
    return out;
}

inline fs::path tmpDir(const std::string& name)
{
    fs::path d = test::freshDir("hostile-" + name) / "work";
    fs::create_directories(d);
    return d;
}

inline void writeText(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

inline std::string slurp(const fs::path& p)
{
    std::ifstream in(p, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

inline fs::path luminaire(const std::string& name) { return fs::path(test::sourceDir()) / "luminaires" / name; }
inline fs::path lambert() { return luminaire("lambert.ldt"); }

// The smallest experiment: one luminaire, one scene, point and mc; with an
// equal-time partner when `equalTime`.
inline json tinyExperiment(const fs::path& lumDir, const std::vector<std::string>& luminaires, bool equalTime = false)
{
    json j = {{"name", "tiny"},
              {"luminaire_dir", lumDir.string()},
              {"luminaires", luminaires},
              {"heights", {1.0}},
              {"rotations", {"pi"}},
              {"methods", {"point"}},
              {"reference", "reference:tol=1e-3"},
              {"res", 4},
              {"time_res", 8},
              {"reps", 5},
              {"save_images", true}};
    if (equalTime) {
        j["equal_time"] = {"point"};
        j["mci_curve"] = {1, 2};
    }
    return j;
}

}  // namespace lb::hostile
