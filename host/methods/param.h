// param.h -- the parameters of every method, declared once.
//
// Each method family declares its parameters (name, default, bounds, scale,
// meaning) where it registers itself (host/methods/family_*.cpp); the CLI's
// SPEC parser, the result files and the tuner all read this one table through
// tunables() (methods/registry.h) / MethodSpec::family().params.
#pragma once

#include <string>
#include <vector>

namespace lb::methods {

enum class Kind { Real, Int, Choice, List, Text };
enum class Scale { Linear, Log };

struct Param {
    std::string name;
    Kind kind = Kind::Real;
    std::string def;  // default, as it would be written in a SPEC
    double lo = 0, hi = 0;  // bounds of Real / Int values (inclusive)
    Scale scale = Scale::Linear;  // how a tuner should search [lo, hi]
    std::vector<std::string> choices;  // Choice: one of them; List: '+'-joined subset
    std::string meaning;
    bool tunable = false;  // continuous knob a tuner may search (Real/Int)

    static Param real(std::string n, double d, double lo, double hi, Scale s, std::string m, bool tune = true);
    static Param integer(std::string n, long d, long lo, long hi, Scale s, std::string m, bool tune = false);
    static Param choice(std::string n, std::string d, std::vector<std::string> c, std::string m);
    static Param list(std::string n, std::string d, std::vector<std::string> c, std::string m);
    // Free text (a file path): non-empty, without ',' (the SPEC's separator).
    static Param text(std::string n, std::string d, std::string m);

    // Checks a value and returns its canonical text; throws InputError naming
    // the method, the key, what was given and what is allowed.
    std::string canonical(const std::string& method, const std::string& value) const;
    std::string allowed() const;  // "real in [0, 1]", "one of fan|delaunay", ...
};

}  // namespace lb::methods
