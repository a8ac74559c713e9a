// Peer check of the reference against Radiance (rtrace -I -ab 0 through PyPI's
// pyradiance, tests/methods/radiance_peer.py): the irradiance of the normalized
// scene, point by point, for the nine ../shared/luminaires/ieslibrary files on the
// 1 x 1 light, the one rectangular opening among them at its declared size, and
// the suite's own quadrant luminaire (C0 / C90 / C180 / C270 all differ, so a
// turned or mirrored frame cannot pass). Both sides integrate the area form of
// docs/design.md section 1 with the same intensity table, so they must agree to the
// accuracy of the two integrations. Skips when pyradiance is not in .venv.
#include "metrics/image.h"
#include "testutil.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

namespace lb {
namespace {

namespace fs = std::filesystem;

struct PeerCase {
    std::string file;
    double w, l, height;
    std::string rotation;  // as the CLI takes it
    double rotationRad;
    std::string shape = "rect";
};

constexpr int kRes = 8;  // 64 points over the 5 m square, 0.625 m apart
constexpr double kExtent = 5.0;

std::string venvPython() { return test::sourceDir() + "/.venv/bin/python"; }

bool havePyradiance()
{
    int code = -1;
    test::shellOutput("'" + venvPython() + "' -c 'import pyradiance' 2>/dev/null", &code);
    return code == 0;
}

// sqrt(mean((ours - radiance)^2)) / mean(radiance) over the image; prints both images' worst pixel.
double relativeRms(const PeerCase& pc, const fs::path& dir)
{
    const fs::path exr = dir / "ref.exr";
    std::ostringstream args;
    args << "render --luminaire '" << pc.file << "' --method reference:tol=1e-6 --height " << pc.height
         << " --rotation " << pc.rotation << " --size " << pc.w << "x" << pc.l << " --res " << kRes << " --extent "
         << kExtent << " --shape " << pc.shape << " --out '" << exr.string() << "' --reps 1 --no-cache";
    test::CliResult r = test::runCli(args.str());
    EXPECT_EQ(r.code, 0) << r.err;
    if (r.code != 0) return INFINITY;
    Image ours = readExr(exr.string());

    std::ostringstream cmd;
    cmd.precision(17);
    cmd << "'" << venvPython() << "' '" << test::sourceDir() << "/tests/methods/radiance_peer.py' '" << test::binary()
        << "' '" << pc.file << "' " << pc.w << " " << pc.l << " " << pc.height << " " << pc.rotationRad << " " << kRes
        << " " << kExtent << " " << pc.shape;
    int code = -1;
    std::istringstream out(test::shellOutput(cmd.str(), &code));
    EXPECT_EQ(code, 0) << cmd.str();
    std::vector<double> rad;
    for (double v; out >> v;) rad.push_back(v);
    EXPECT_EQ(rad.size(), ours.px.size());
    if (rad.size() != ours.px.size()) return INFINITY;

    double se = 0, mean = 0, worst = 0;
    size_t at = 0;
    for (size_t i = 0; i < rad.size(); ++i) {
        double d = ours.px[i] - rad[i];
        se += d * d;
        mean += rad[i];
        if (std::abs(d) > worst) worst = std::abs(d), at = i;
    }
    mean /= double(rad.size());
    double rrms = std::sqrt(se / double(rad.size())) / mean;
    std::printf("%s %s %gx%g h %g R %s: relative RMS %.3g (worst pixel %zu: %.6g against Radiance's %.6g lx)\n",
                fs::path(pc.file).filename().c_str(), pc.shape.c_str(), pc.w, pc.l, pc.height, pc.rotation.c_str(),
                rrms, at, ours.px[at], rad[at]);
    return rrms;
}

TEST(RadiancePeer, ReferenceAgreesWithRtraceOnRectangles)
{
    LB_REQUIRE_RUNTIME(rt);
    if (!fs::exists(venvPython()) || !havePyradiance())
        GTEST_SKIP() << "pyradiance is not installed in .venv (scripts/install-deps.sh could not reach PyPI)";
    const double pi = M_PI;
    std::vector<PeerCase> cases;
    const std::string quadrant = test::sourceDir() + "/luminaires/quadrant.ldt";
    cases.push_back({quadrant, 1, 1, 1.1, "3pi/4", 3 * pi / 4});
    cases.push_back({quadrant, 1, 1, 0.1, "pi/2", pi / 2});
    cases.push_back({quadrant, 1, 1, 0.1, "pi", pi});
    const std::string shared = test::sharedDir();
    if (!shared.empty()) {
        std::vector<std::string> ies;
        for (auto& e : fs::directory_iterator(shared + "/luminaires/ieslibrary"))
            if (e.path().extension() == ".ies") ies.push_back(e.path().string());
        std::sort(ies.begin(), ies.end());
        EXPECT_EQ(ies.size(), 9u);
        for (const auto& f : ies) cases.push_back({f, 1, 1, 1.1, "3pi/4", 3 * pi / 4});
        // the one rectangle among them, at its declared opening: length 0.27 m along C0 (W), width 0.24 m (L)
        const std::string rect = shared + "/luminaires/ieslibrary/02a7562c650498ebb301153dbbf59207.ies";
        cases.push_back({rect, 0.27, 0.24, 0.1, "pi", pi});
        cases.push_back({rect, 0.27, 0.24, 0.1, "5pi/8", 5 * pi / 8});
    }
    const fs::path dir = test::freshDir("radiance-peer");
    for (const PeerCase& pc : cases) {
        // 1e-3: measured 1.3e-5 .. 4.2e-4 on these cases (the larger where a beam edge
        // falls between Radiance's source parts); a wrong frame costs far more: while
        // this test was written, a point source without the flat 1 / cos gave 0.05 .. 5,
        // a one-sided light (no gamma > 90) 0.05 .. 0.44.
        EXPECT_LT(relativeRms(pc, dir), 1e-3) << pc.file << " h " << pc.height << " R " << pc.rotation;
    }
    fs::remove_all(dir);
    if (shared.empty()) GTEST_SKIP() << "../shared is not present: checked the suite's own luminaire only";
}

TEST(RadiancePeer, ReferenceAgreesWithRtraceOnDisks)
{
    // The round openings at their declared diameters (docs/studies/as-declared.md) and a
    // 1 m disk of the suite's quadrant luminaire, near (h 0.1) and mid-range,
    // facing down and tilted; Radiance's disk is 2048 polygons of the 128-gon
    // scaled to the disk's area (radiance_peer.py).
    LB_REQUIRE_RUNTIME(rt);
    if (!fs::exists(venvPython()) || !havePyradiance())
        GTEST_SKIP() << "pyradiance is not installed in .venv (scripts/install-deps.sh could not reach PyPI)";
    const double pi = M_PI;
    const std::string quadrant = test::sourceDir() + "/luminaires/quadrant.ldt";
    std::vector<PeerCase> cases = {{quadrant, 1, 1, 1.1, "pi", pi, "disk"},
                                   {quadrant, 1, 1, 1.1, "3pi/4", 3 * pi / 4, "disk"},
                                   {quadrant, 1, 0.5, 0.1, "5pi/8", 5 * pi / 8, "disk"}};
    const std::string shared = test::sharedDir();
    if (!shared.empty())
        for (const char* stem : {"007cfb11e343e2f42e3b476be4ab684e", "00c6ce79e1d2cdf3a1fb491aaaa47ae0"}) {
            const std::string f = shared + "/luminaires/ieslibrary/" + stem + ".ies";
            const double d = std::string(stem).rfind("007", 0) == 0 ? 0.08 : 0.15;  // declared diameters
            cases.push_back({f, d, d, 0.1, "pi", pi, "disk"});
            cases.push_back({f, d, d, 0.1, "pi/2", pi / 2, "disk"});
        }
    const fs::path dir = test::freshDir("radiance-peer-disk");
    for (const PeerCase& pc : cases) {
        // 2e-3: measured 5e-5 .. 1.4e-3; the largest where Radiance's pieces are
        // coarsest against the distance (the 150 mm disk 0.1 m above the floor; its
        // error falls 4x per refinement towards the reference, radiance_peer.py)
        EXPECT_LT(relativeRms(pc, dir), 2e-3) << pc.file << " h " << pc.height << " R " << pc.rotation;
    }
    fs::remove_all(dir);
}

// An IES file with TILT=INCLUDE (the suite's quadrant luminaire with factors
// 1, 0.9, 0.8 at lamp tilts 0, 45, 90 degrees): Radiance applies the table
// through ies2rad's tilt.cal by the light's orientation in the scene, lumibench
// by the scene's rotation (photometry::tiltedFor). The factor moves every
// value by up to 20 %, far beyond the peer's agreement.
TEST(RadiancePeer, TiltIncludeIsAppliedAsRadianceAppliesIt)
{
    LB_REQUIRE_RUNTIME(rt);
    if (!fs::exists(venvPython()) || !havePyradiance())
        GTEST_SKIP() << "pyradiance is not installed in .venv (scripts/install-deps.sh could not reach PyPI)";
    const fs::path dir = test::freshDir("radiance-peer-tilt");
    std::ifstream in(test::sourceDir() + "/luminaires/quadrant.ies");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const size_t at = text.find("TILT=NONE");
    ASSERT_NE(at, std::string::npos);
    text.replace(at, 9, "TILT=INCLUDE\n1\n3\n0 45 90\n1 0.9 0.8");
    const std::string file = (dir / "tilted.ies").string();
    std::ofstream(file) << text;
    const double pi = M_PI;
    for (const PeerCase& pc : std::vector<PeerCase>{{file, 1, 1, 1.1, "pi", pi},
                                                    {file, 1, 1, 1.1, "3pi/4", 3 * pi / 4},
                                                    {file, 1, 1, 1.1, "5pi/8", 5 * pi / 8},
                                                    {file, 1, 1, 0.1, "pi/2", pi / 2}}) {
        // 1e-3, as for the untilted files above; the factor 0.9 alone is 0.1
        EXPECT_LT(relativeRms(pc, dir), 1e-3) << "h " << pc.height << " R " << pc.rotation;
    }
    fs::remove_all(dir);
}

}  // namespace
}  // namespace lb
