// check.h -- the one range check for command-line flags and experiment keys,
// and strict parsing of numbers and angles given as text. Every complaint
// names the flag or key (`name`, e.g. "--height" or "smoke.json: key \"reps\""),
// the accepted range and what was given, as an lb::InputError (exit code 2).
#pragma once

#include <string>
#include <type_traits>

namespace lb::util {

// `v` if it is finite and in [lo, hi]; else InputError
// "NAME: expected a number in [lo, hi] UNIT, got V" (nan and inf included).
double checkRange(const std::string& name, double v, double lo, double hi, const std::string& unit = "");
// The same for integers ("expected an integer in [lo, hi]").
long checkIntRange(const std::string& name, long v, long lo, long hi, const std::string& unit);
template <class I, std::enable_if_t<std::is_integral_v<I>, int> = 0>
I checkRange(const std::string& name, I v, I lo, I hi, const std::string& unit = "")
{
    return static_cast<I>(
        checkIntRange(name, static_cast<long>(v), static_cast<long>(lo), static_cast<long>(hi), unit));
}

// A finite decimal number (the whole text); InputError naming `name` otherwise.
double parseReal(const std::string& name, const std::string& text);

// Rotations are angles in [0, 2 pi] radians (docs/design.md section 2 sweeps pi/2 .. pi).
constexpr double kTwoPi = 6.28318530717958647692;

// An angle in radians in [0, 2 pi]: a plain number, or [C][*]pi[/D] with
// C and D unsigned decimal numbers, D > 0 (pi, 3pi/4, 3*pi/4, pi/2, 0.75pi).
// Anything else (pi/-2, -pi, pi/0, 1/2) is an InputError naming `name`.
double parseAngle(const std::string& name, const std::string& text);

// `name` (a file name) unchanged if it is valid UTF-8; else InputError
// "NAME: WHAT's name is not valid UTF-8 (byte 0xNN at offset K); expected a
// UTF-8 name: rename the file", the name written with \xNN for each byte that
// is not printable ASCII. The records, the report and every JSON output hold
// names as text: a name they cannot hold is refused where it is first read.
const std::string& requireUtf8(const std::string& name, const std::string& what);

}  // namespace lb::util
