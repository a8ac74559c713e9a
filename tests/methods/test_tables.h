// test_tables.h -- two synthetic luminaires the specialisation tests share.
#pragma once

#include "photometry/load.h"

#include <cmath>

namespace lb::methods::test_tables {

// A rotational luminaire emitting only forward (cos^3 lobe): every rule fires.
inline photometry::Table frontLobe()
{
    return photometry::tabulate(
        [](double, double g) { return g < 90 ? 500 * std::pow(std::cos(g * M_PI / 180), 3) : 0.0; }, 2, 91);
}
// An asymmetric luminaire emitting into both hemispheres: only noHorizon.
inline photometry::Table asymmetric()
{
    return photometry::tabulate(
        [](double c, double g) { return 100 + 80 * std::cos(c * M_PI / 180) * std::sin(g * M_PI / 180) + g; }, 25, 37);
}

}  // namespace lb::methods::test_tables
