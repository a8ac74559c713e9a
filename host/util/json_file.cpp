// json_file.cpp -- see json_file.h.
#include "util/json_file.h"

#include "util/check.h"
#include "util/error.h"
#include "util/fileio.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <filesystem>
#include "lb_build_config.h"

namespace lb::util {

using nlohmann::json;

namespace {

// A SAX pass over the text that checks what nlohmann's DOM parser accepts
// silently (a repeated key: the last wins) or recurses on (nesting), before
// the DOM is built.
class StrictJson : public nlohmann::json_sax<json> {
public:
    StrictJson(std::string name, int maxDepth) : name_(std::move(name)), maxDepth_(maxDepth) {}

    bool null() override { return true; }
    bool boolean(bool) override { return true; }
    bool number_integer(number_integer_t) override { return true; }
    bool number_unsigned(number_unsigned_t) override { return true; }
    bool number_float(number_float_t, const string_t&) override { return true; }
    bool string(string_t&) override { return true; }
    bool binary(binary_t&) override { return true; }
    bool start_object(std::size_t) override { return open(true); }
    bool start_array(std::size_t) override { return open(false); }
    bool end_object() override { return close(); }
    bool end_array() override { return close(); }
    bool key(string_t& k) override
    {
        if (!keys_.back().insert(k).second)
            throw InputError(fmt::format("{}: the key \"{}\" appears twice in one object (JSON leaves it to the "
                                         "reader which one counts; give it once)",
                                         name_, k));
        return true;
    }
    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& e) override
    {
        throw InputError(fmt::format("{}: not valid JSON: {}", name_, e.what()));
    }

private:
    bool open(bool object)
    {
        if (static_cast<int>(keys_.size()) >= maxDepth_)
            throw InputError(fmt::format("{}: JSON nested deeper than {} levels (objects and arrays inside each "
                                         "other); the suite's files need far fewer",
                                         name_, maxDepth_));
        keys_.emplace_back();  // an array's set stays empty: key() is never called inside it
        (void)object;
        return true;
    }
    bool close()
    {
        keys_.pop_back();
        return true;
    }

    std::string name_;
    int maxDepth_;
    std::vector<std::set<std::string>> keys_;  // per open object or array: the keys seen so far
};

}  // namespace

json parseJson(const std::string& text, const std::string& name, int maxDepth)
{
    StrictJson check(name, maxDepth);
    json::sax_parse(text, &check);
    try {
        return json::parse(text);
    } catch (const json::exception& e) {  // the strict pass refuses all of these first
        throw InputError(fmt::format("{}: not valid JSON: {}", name, e.what()));
    }
}

json readJson(const std::string& path, const std::string& what, size_t maxBytes, int maxDepth)
{
    return parseJson(readFile(path, what, maxBytes), path, maxDepth);
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
