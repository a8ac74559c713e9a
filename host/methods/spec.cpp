#include "methods/spec.h"

#include "methods/registry.h"
#include "util/error.h"

#include <fmt/format.h>

#include <cstdlib>

namespace lb::methods {

namespace {
const Param& paramOf(const Family& f, const std::string& key)
{
    for (auto& p : f.params)
        if (p.name == key) return p;
    std::vector<std::string> names;
    for (auto& p : f.params) names.push_back(p.name);
    throw InputError(fmt::format("method {}: unknown parameter '{}'; valid: {}", f.name, key,
                                 names.empty() ? std::string("(none)") : fmt::format("{}", fmt::join(names, ", "))));
}
}  // namespace

MethodSpec parseSpec(const std::string& text, SceneKind kind)
{
    MethodSpec s;
    size_t colon = text.find(':');
    s.name = text.substr(0, colon);
    s.kind = kind;
    const Family& f = family(s.name, kind);
    for (auto& p : f.params) s.values[p.name] = p.def;
    std::string rest = colon == std::string::npos ? std::string() : text.substr(colon + 1);
    size_t b = 0;
    while (!rest.empty()) {
        size_t e = rest.find(',', b);
        std::string kv = rest.substr(b, e == std::string::npos ? std::string::npos : e - b);
        size_t eq = kv.find('=');
        if (eq == std::string::npos || eq == 0)
            throw InputError(fmt::format("method spec '{}': expected key=value, got '{}'", text, kv));
        std::string key = kv.substr(0, eq), value = kv.substr(eq + 1);
        const Param& p = paramOf(f, key);
        if (s.given.count(key)) throw InputError(fmt::format("method spec '{}': {} given twice", text, key));
        s.values[key] = p.canonical(f.name, value);
        s.given.insert(key);
        if (e == std::string::npos) break;
        b = e + 1;
    }
    if (f.validate) f.validate(s);
    return s;
}

double MethodSpec::num(const std::string& key) const { return std::strtod(str(key).c_str(), nullptr); }
long MethodSpec::integer(const std::string& key) const { return std::strtol(str(key).c_str(), nullptr, 10); }

const std::string& MethodSpec::str(const std::string& key) const
{
    auto it = values.find(key);
    if (it == values.end()) throw Error(fmt::format("method {} has no parameter {}", name, key));
    return it->second;
}

std::vector<std::string> MethodSpec::list(const std::string& key) const
{
    std::vector<std::string> items;
    const std::string& v = str(key);
    size_t b = 0;
    while (true) {
        size_t e = v.find('+', b);
        items.push_back(v.substr(b, e == std::string::npos ? std::string::npos : e - b));
        if (e == std::string::npos) break;
        b = e + 1;
    }
    return items;
}

std::string MethodSpec::canonical() const
{
    std::string out = name;
    char sep = ':';
    for (auto& [k, v] : values) {  // std::map: sorted keys
        out += sep + k + "=" + v;
        sep = ',';
    }
    return out;
}

nlohmann::json MethodSpec::paramsJson() const
{
    nlohmann::json j = nlohmann::json::object();
    const Family& f = family(name, kind);
    for (auto& p : f.params) {
        const std::string& v = str(p.name);
        if (p.kind == Kind::Int)
            j[p.name] = integer(p.name);
        else if (p.kind == Kind::Real)
            j[p.name] = num(p.name);
        else
            j[p.name] = v;
    }
    return j;
}

}  // namespace lb::methods
