// json_file.h -- reading the suite's JSON input files (experiments, tune
// files, results): the file read and parsed with errors naming it, and the
// keys of an object read with errors naming the file and the key,
//     smoke.json: key "reps": expected an integer, found "5"
// as an lb::InputError (exit code 2).
#pragma once

#include <nlohmann/json.hpp>

#include <cstddef>
#include <set>
#include <string>
#include <vector>

namespace lb::util {

// How deep the suite's JSON may nest: objects and arrays inside each other.
// Input files need a handful of levels; results files carry an experiment
// file inside a record's context, hence twice as many there.
constexpr int kMaxJsonDepth = 64;

// `text` parsed as JSON, strictly: nesting deeper than maxDepth, a key
// repeated in one object, a number too large for a double (1e400) and
// anything not JSON are refused with an lb::InputError naming `name` (a file,
// or a file and line) and the position. Every JSON the suite reads goes
// through here.
nlohmann::json parseJson(const std::string& text, const std::string& name, int maxDepth = kMaxJsonDepth);

// The JSON document of a file of at most maxBytes ("PATH: not valid JSON: ..."
// otherwise); `what` names the file's kind for readFile's complaints.
nlohmann::json readJson(const std::string& path, const std::string& what, size_t maxBytes,
                        int maxDepth = kMaxJsonDepth);
// The same for a file that must hold an object ("PATH: expected a JSON object").
nlohmann::json readJsonObject(const std::string& path, const std::string& what, size_t maxBytes);

// A directory named in an input file: as given when absolute or present,
// else relative to the source tree (LB_SOURCE_DIR), so that experiments run
// from any working directory.
std::string resolveSourceDir(const std::string& dir);

// The keys of a JSON object read from file `path`; every complaint names
// the file and the key (prefix + key for a nested object: "train.heights").
struct JsonKeys {
    std::string path;
    const nlohmann::json& j;
    std::string prefix = "";

    // "PATH: key \"KEY\"", the name range checks report.
    std::string name(const std::string& key) const;
    [[noreturn]] void fail(const std::string& key, const std::string& what) const;
    // Fails on the first key not in `known`, listing them.
    void onlyKnown(const std::set<std::string>& known) const;
    bool has(const std::string& key) const { return j.contains(key); }
    const nlohmann::json& at(const std::string& key) const;  // fails when missing
    double number(const std::string& key, double lo, double hi) const;
    long integer(const std::string& key, long lo, long hi) const;
    std::string string(const std::string& key) const;
    bool boolean(const std::string& key) const;
    // A list of strings. A bare string is an error (a typo for a list of one
    // would otherwise pass silently).
    std::vector<std::string> strings(const std::string& key, bool nonEmpty = true) const;
    std::vector<long> integers(const std::string& key, long lo, long hi) const;
    // A non-empty list of numbers, each in [lo, hi] `unit`.
    std::vector<double> numbers(const std::string& key, double lo, double hi, const std::string& unit) const;
    // A non-empty list of angles in radians: numbers or expressions like
    // 3pi/4 (parseAngle); `texts` gets each as written.
    std::vector<double> angles(const std::string& key, std::vector<std::string>& texts) const;
};

}  // namespace lb::util
