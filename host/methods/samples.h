// samples.h -- the fixed point sets of MC integration (thesis 6.5), made on the
// host, deterministic for a given (pattern, n, seed): 2n values (s, t) in
// [0, 1)^2, s along the light's u, t along v.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace lb::methods {

// pattern: "poisson" (best-candidate Poisson-disk, Mitchell 1991, 10 candidates
// per point, distances on the unit torus so that every point is uniform
// over seeds), "halton" (bases 2, 3; seed != 0 adds a Cranley-Patterson shift),
// "stratified" (one jittered point per cell of n equal-area cells in
// floor(sqrt(n)) rows), "random" (independent uniform points).
std::vector<double> samplePoints(const std::string& pattern, int n, std::uint64_t seed);

// The points (s, t) mapped in place onto the disk inscribed in [0, 1]^2
// (kernels/common/mc_sample.h lb_mc_concentric): a disk light's area samples.
void mapToDisk(std::vector<double>& st);

// The radical inverse of i in base b (Halton coordinate).
double radicalInverse(std::uint64_t i, unsigned base);

}  // namespace lb::methods
