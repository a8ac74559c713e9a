// json_file.cpp -- see json_file.h.
#include "util/json_file.h"

#include "util/check.h"
#include "util/error.h"
#include "util/fileio.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <filesystem>

namespace lb::util {

using nlohmann::json;

json readJson(const std::string& path, const std::string& what, size_t maxBytes)
{
    const std::string text = readFile(path, what, maxBytes);
    try {
        return json::parse(text);
    } catch (const json::parse_error& e) {
        throw InputError(fmt::format("{}: not valid JSON: {}", path, e.what()));
    }
}

json readJsonObject(const std::string& path, const std::string& what, size_t maxBytes)
{
    json j = readJson(path, what, maxBytes);
    if (!j.is_object()) throw InputError(fmt::format("{}: expected a JSON object", path));
    return j;
}

std::string resolveSourceDir(const std::string& dir)
{
    std::filesystem::path p(dir);
    if (p.is_absolute() || std::filesystem::exists(p)) return p.string();
    return (std::filesystem::path(LB_SOURCE_DIR) / p).string();
}

std::string JsonKeys::name(const std::string& key) const { return fmt::format("{}: key \"{}{}\"", path, prefix, key); }

void JsonKeys::fail(const std::string& key, const std::string& what) const
{
    throw InputError(fmt::format("{}: {}", name(key), what));
}

void JsonKeys::onlyKnown(const std::set<std::string>& known) const
{
    for (auto it = j.begin(); it != j.end(); ++it)
        if (!known.count(it.key())) fail(it.key(), fmt::format("unknown key (known: {})", fmt::join(known, ", ")));
}

const json& JsonKeys::at(const std::string& key) const
{
    if (!j.contains(key)) fail(key, "missing");
    return j.at(key);
}

double JsonKeys::number(const std::string& key, double lo, double hi) const
{
    const json& v = at(key);
    if (!v.is_number()) fail(key, fmt::format("expected a number, found {}", v.dump()));
    return checkRange(name(key), v.get<double>(), lo, hi);
}

long JsonKeys::integer(const std::string& key, long lo, long hi) const
{
    const json& v = at(key);
    if (!v.is_number_integer()) fail(key, fmt::format("expected an integer, found {}", v.dump()));
    return checkRange(name(key), v.get<long>(), lo, hi);
}

std::string JsonKeys::string(const std::string& key) const
{
    const json& v = at(key);
    if (!v.is_string()) fail(key, fmt::format("expected a string, found {}", v.dump()));
    return v.get<std::string>();
}

bool JsonKeys::boolean(const std::string& key) const
{
    const json& v = at(key);
    if (!v.is_boolean()) fail(key, "expected true or false");
    return v.get<bool>();
}

std::vector<std::string> JsonKeys::strings(const std::string& key, bool nonEmpty) const
{
    const json& v = at(key);
    std::vector<std::string> out;
    if (!v.is_array()) fail(key, fmt::format("expected a list of strings like [\"a\", \"b\"], found {}", v.dump()));
    for (const auto& x : v) {
        if (!x.is_string()) fail(key, fmt::format("expected a list of strings, found element {}", x.dump()));
        out.push_back(x.get<std::string>());
    }
    if (nonEmpty && out.empty()) fail(key, "expected a non-empty list");
    return out;
}

std::vector<long> JsonKeys::integers(const std::string& key, long lo, long hi) const
{
    const json& v = at(key);
    if (!v.is_array()) fail(key, fmt::format("expected a list of integers, found {}", v.dump()));
    std::vector<long> out;
    for (const auto& x : v) {
        if (!x.is_number_integer() || x.get<long>() < lo || x.get<long>() > hi)
            fail(key, fmt::format("expected integers in [{}, {}], found element {}", lo, hi, x.dump()));
        out.push_back(x.get<long>());
    }
    return out;
}

std::vector<double> JsonKeys::numbers(const std::string& key, double lo, double hi, const std::string& unit) const
{
    const json& v = at(key);
    if (!v.is_array() || v.empty()) fail(key, "expected a non-empty list of numbers");
    std::vector<double> out;
    for (const auto& x : v) {
        if (!x.is_number()) fail(key, fmt::format("expected numbers, found element {}", x.dump()));
        out.push_back(checkRange(name(key), x.get<double>(), lo, hi, unit));
    }
    return out;
}

std::vector<double> JsonKeys::angles(const std::string& key, std::vector<std::string>& texts) const
{
    const json& v = at(key);
    if (!v.is_array() || v.empty()) fail(key, "expected a non-empty list");
    std::vector<double> out;
    for (const auto& x : v) {
        if (!x.is_string() && !x.is_number())
            fail(key, fmt::format("expected radians or an expression like 3pi/4, found {}", x.dump()));
        std::string text = x.is_string() ? x.get<std::string>() : x.dump();
        out.push_back(parseAngle(name(key), text));
        texts.push_back(text);
    }
    return out;
}

}  // namespace lb::util
