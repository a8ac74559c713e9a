#include "methods/param.h"

#include "util/check.h"
#include "util/error.h"

#include <fmt/format.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace lb::methods {

Param Param::real(std::string n, double d, double lo, double hi, Scale s, std::string m, bool tune)
{
    Param p;
    p.name = std::move(n);
    p.kind = Kind::Real;
    p.def = fmt::format("{}", d);
    p.lo = lo;
    p.hi = hi;
    p.scale = s;
    p.meaning = std::move(m);
    p.tunable = tune;
    return p;
}

Param Param::integer(std::string n, long d, long lo, long hi, Scale s, std::string m, bool tune)
{
    Param p = real(std::move(n), static_cast<double>(d), static_cast<double>(lo), static_cast<double>(hi), s,
                   std::move(m), tune);
    p.kind = Kind::Int;
    p.def = fmt::format("{}", d);
    return p;
}

Param Param::choice(std::string n, std::string d, std::vector<std::string> c, std::string m)
{
    Param p;
    p.name = std::move(n);
    p.kind = Kind::Choice;
    p.def = std::move(d);
    p.choices = std::move(c);
    p.meaning = std::move(m);
    return p;
}

Param Param::list(std::string n, std::string d, std::vector<std::string> c, std::string m)
{
    Param p = choice(std::move(n), std::move(d), std::move(c), std::move(m));
    p.kind = Kind::List;
    return p;
}

Param Param::text(std::string n, std::string d, std::string m)
{
    Param p = choice(std::move(n), std::move(d), {}, std::move(m));
    p.kind = Kind::Text;
    return p;
}

std::string Param::allowed() const
{
    switch (kind) {
    case Kind::Real:
        return fmt::format("a number in [{}, {}]", lo, hi);
    case Kind::Int:
        return fmt::format("an integer in [{}, {}]", lo, hi);
    case Kind::Choice:
        return fmt::format("one of {}", fmt::join(choices, "|"));
    case Kind::List:
        return fmt::format("a '+'-joined list of {}", fmt::join(choices, "|"));
    case Kind::Text:
        return "a non-empty text without ',' (e.g. a file path)";
    }
    return "";
}

std::string Param::canonical(const std::string& method, const std::string& value) const
{
    auto bad = [&] {
        throw InputError(fmt::format("method {}: bad value '{}' for {}: expected {}", method, value, name, allowed()));
    };
    if (kind == Kind::Real || kind == Kind::Int) {
        // Decimal only, the whole value (no 0x10, no empty value, no nan).
        double v = 0;
        try {
            v = util::parseReal(name, value);
        } catch (const InputError&) {
            bad();
        }
        if (v < lo || v > hi) bad();
        if (kind == Kind::Int) {
            if (v != std::floor(v)) bad();
            return fmt::format("{}", static_cast<long>(v));
        }
        return fmt::format("{}", v);
    }
    if (kind == Kind::Text) {
        if (value.empty()) bad();  // ',' cannot reach here: it separates the SPEC's pairs
        return value;
    }
    auto isChoice = [&](const std::string& s) {
        for (auto& c : choices)
            if (c == s) return true;
        return false;
    };
    if (kind == Kind::Choice) {
        if (!isChoice(value)) bad();
        return value;
    }
    // List: '+'-joined, each a choice, no repeats.
    std::vector<std::string> items;
    size_t b = 0;
    while (true) {
        size_t e = value.find('+', b);
        std::string it = value.substr(b, e == std::string::npos ? std::string::npos : e - b);
        if (!isChoice(it)) bad();
        for (auto& x : items)
            if (x == it) bad();
        items.push_back(it);
        if (e == std::string::npos) break;
        b = e + 1;
    }
    return fmt::format("{}", fmt::join(items, "+"));
}

}  // namespace lb::methods
