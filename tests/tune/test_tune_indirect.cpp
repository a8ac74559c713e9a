// lumibench tune on the indirect scene: the tuner drives the indirect
// families' tunables (here the VPLs' 1/r^2 clamp) like the direct ones.
#include "testutil.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace lb {
namespace {

namespace fs = std::filesystem;

// 64 VPLs under the default clamp (0.1 m) leave the floor blotchy: near a VPL
// 1/r^2 is large. A longer clamp trades that variance for bias; on these
// scenes the search finds ~0.44 m and train NMSE 0.225 -> 0.098, validation
// 0.062 -> 0.051 (PoCL, res 16). The test asks for half of that gain on train
// (a clamp that does not reach the kernel leaves every evaluation equal) and
// for any gain on the held-out luminaire and rotation.
TEST(TuneIndirect, VplClampImprovesTrainAndValidation)
{
    LB_REQUIRE_RUNTIME(rt);
    const fs::path dir = fs::temp_directory_path() / ("lb_tune_indirect_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    nlohmann::json e = {{"name", "tune-indirect-test"},
                        {"scene", "indirect"},
                        {"albedo", 0.5},
                        {"method", "vpl:n=64"},
                        {"params", {"clamp"}},
                        {"reference", "reference:dir_cell=0.25,dir_tol=1e-4"},
                        {"luminaire_dir", test::sourceDir() + "/luminaires"},
                        {"res", 16},
                        {"precision", "float"},
                        {"train", {{"luminaires", {"lambert.ldt"}}, {"heights", {1.1}}, {"rotations", {"3pi/4"}}}},
                        {"validation", {{"luminaires", {"batwing.ldt"}}, {"heights", {1.1}}, {"rotations", {"pi/2"}}}},
                        {"algorithm", "LN_SBPLX"},
                        {"maxeval", 12},
                        {"seed", 1}};
    std::ofstream(dir / "e.json") << e.dump();
    auto r =
        test::runCli("tune " + (dir / "e.json").string() + " --out " + (dir / "out").string() + " --quiet --no-plot");
    ASSERT_EQ(r.code, 0) << r.err;
    nlohmann::json doc;
    std::ifstream(dir / "out" / "tune.json") >> doc;
    fs::remove_all(dir);
    const double d = doc["default"]["train_nmse"], t = doc["tuned"]["train_nmse"];
    EXPECT_LT(t, 0.75 * d) << doc["tuned"].dump();
    EXPECT_LT(doc["tuned"]["validation_nmse"].get<double>(), doc["default"]["validation_nmse"].get<double>());
    EXPECT_GT(doc["tuned"]["params"]["clamp"].get<double>(), 0.1);  // longer than the default
    EXPECT_EQ(doc["tuned"]["nonfinite"].get<long>(), 0);
}

}  // namespace
}  // namespace lb
