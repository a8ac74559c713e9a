// The scripts that read equal-time partners (plots/specular.py,
// robust_table.py, visual_claims.py) give the same tables from results.csv as
// from results.json, though the CSV names a partner's method by its label as
// the experiment wrote it and the JSON by its canonical SPEC.
#include "experiments/results.h"
#include "testutil.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace lb {
namespace {

namespace fs = std::filesystem;

// DIR/results.json unpacked from a committed .json.xz, and its results.csv.
bool unpack(const std::string& xz, const fs::path& dir)
{
    fs::create_directories(dir);
    int code = -1;
    test::shellOutput("xz -dc '" + xz + "' > '" + (dir / "results.json").string() + "'", &code);
    if (code != 0) return false;
    results::saveCsv((dir / "results.json").string(), results::load((dir / "results.json").string()));
    return true;
}

std::string run(const std::string& script, const fs::path& file)
{
    int code = -1;
    std::string out = test::shellOutput(
        "/usr/bin/python3 " + test::sourceDir() + "/plots/" + script + " '" + file.string() + "' 2>&1", &code);
    EXPECT_EQ(code, 0) << script << " " << file << "\n" << out;
    return out;
}

TEST(Plots, PartnerScriptsReadTheCsvAsTheJson)
{
    fs::path dir = fs::temp_directory_path() / ("lb_partner_csv_" + std::to_string(getpid()));
    fs::remove_all(dir);
    const std::string res = test::sourceDir() + "/experiments/results/";
    if (!unpack(res + "specular/reduced/results.json.xz", dir / "specular")) GTEST_SKIP() << "no xz";
    // A label with a default written out ("ltc:radiance=cubature" is `ltc`):
    // the JSON's canonical SPEC and the CSV's label name the same method.
    const fs::path sj = dir / "specular" / "results.json";
    nlohmann::json doc = nlohmann::json::parse(std::ifstream(sj));
    for (auto& r : doc["records"])
        if (r.contains("equal_time")) r["equal_time"]["label"] = "ltc:radiance=cubature";
    std::ofstream(sj) << doc.dump();
    results::saveCsv(sj.string(), results::load(sj.string()));
    const std::string fromJson = run("specular.py", sj);
    EXPECT_NE(fromJson.find("MCI=ltc"), std::string::npos) << fromJson;
    EXPECT_EQ(fromJson.find("MCI=ltc:"), std::string::npos) << fromJson;
    EXPECT_EQ(run("specular.py", dir / "specular" / "results.csv"), fromJson);

    for (const auto& [name, script] : {std::pair<std::string, std::string>{"robust-pocl-xeon", "robust_table.py"},
                                       {"visual-claims-pocl-xeon", "visual_claims.py"}}) {
        ASSERT_TRUE(unpack(res + name + ".json.xz", dir / name));
        const std::string j = run(script, dir / name / "results.json");
        EXPECT_NE(j.find("|"), std::string::npos) << j;  // a table
        EXPECT_EQ(run(script, dir / name / "results.csv"), j) << script;
    }
    fs::remove_all(dir);
}

}  // namespace
}  // namespace lb
