// The cubature method's parameters: parsing, defines, errors.
#include "math/kmath.h"
#include "methods/cubature_options.h"
#include "methods/straight.h"
#include "util/error.h"

#include <gtest/gtest.h>

namespace lb::methods {
namespace {

TEST(CubatureOptions, DefaultsAreThePapersMethod)
{
    auto o = CubatureOptions::parse({});
    EXPECT_EQ(o.defines(), "-DLB_CUB_TRI=0 -DLB_CUB_WEIGHT=1 -DLB_CUB_NORMALIZE=0 -DLB_CUB_DYNAMIC=1");
    EXPECT_EQ(dynamicSetName(o.dynamic), "cp");
    EXPECT_EQ(o.lanes, "auto");
    EXPECT_DOUBLE_EQ(o.tunables.plane_eps, 1e-3);
    EXPECT_DOUBLE_EQ(o.tunables.horizon_eps, 0.0);
}

TEST(CubatureOptions, ParsesEveryOption)
{
    auto o = CubatureOptions::parse({{"triangulation", "delaunay"},
                                     {"weighting", "dotout"},
                                     {"normalize", "formfactor"},
                                     {"dynamic", "cp+mrp+barycentre"},
                                     {"plane_eps", "0.01"},
                                     {"horizon_eps", "0.1"}});
    EXPECT_EQ(o.defines(), "-DLB_CUB_TRI=1 -DLB_CUB_WEIGHT=2 -DLB_CUB_NORMALIZE=1 -DLB_CUB_DYNAMIC=13");
    EXPECT_EQ(o.dynamic, LB_CUB_CP | LB_CUB_MRP | LB_CUB_BARY);  // the header's bits
    EXPECT_DOUBLE_EQ(o.tunables.plane_eps, 0.01);
    EXPECT_DOUBLE_EQ(o.tunables.horizon_eps, 0.1);
    EXPECT_EQ(dynamicSetName(o.dynamic), "cp+mrp+barycentre");
    EXPECT_EQ(parseDynamicSet("none"), 0);
    EXPECT_EQ(dynamicSetName(15), "cp+np+mrp+barycentre");
}

TEST(CubatureOptions, BadValuesAreInputErrors)
{
    for (auto kv : std::vector<std::map<std::string, std::string>>{{{"triangulation", "voronoi"}},
                                                                   {{"weighting", "Average"}},
                                                                   {{"normalize", "yes"}},
                                                                   {{"dynamic", "cp+foo"}},
                                                                   {{"dynamic", ""}},
                                                                   {{"dynamic", "cp+none"}},
                                                                   {{"dynamic", "bary"}},
                                                                   {{"plane_eps", "-1"}},
                                                                   {{"horizon_eps", "0.1x"}},
                                                                   {{"horizon_eps", "nan"}},
                                                                   {{"flips", "3"}}})
        EXPECT_THROW(CubatureOptions::parse(kv), InputError) << kv.begin()->first;
}

// CubatureOptions holds the table's defaults (cubatureParams), no copy of them.
TEST(CubatureOptions, DefaultsAreTheTables)
{
    CubatureOptions o;
    for (const auto& p : cubatureParams()) {
        CubatureOptions q = CubatureOptions::parse({{p.name, p.def}});
        EXPECT_EQ(q.defines(), o.defines()) << p.name;
    }
    EXPECT_DOUBLE_EQ(o.tunables.area_q, kDefaultAreaQ);
    EXPECT_DOUBLE_EQ(o.tunables.area_sin, kDefaultAreaSin);
    EXPECT_DOUBLE_EQ(o.tunables.blend_dist, 1e6);
    EXPECT_TRUE(o.lut && o.specialize);
    EXPECT_EQ(o.area, 0);
    EXPECT_EQ(CubatureOptions::parse({{"area", "gauss3"}}).area, 3);
    EXPECT_EQ(CubatureOptions::parse({{"lanes", "8"}}).lanes, "8");
}

// The kernel's real arguments (LB_CUB_TUNABLES) are the table's Real
// parameters, in table order, and a SPEC value reaches the field of that name.
TEST(CubatureOptions, KernelTunablesAreTheRealParameters)
{
    std::vector<std::string> reals;
    for (const auto& p : cubatureParams())
        if (p.kind == Kind::Real) reals.push_back(p.name);
    EXPECT_EQ(cubatureTunableNames(), reals);
    EXPECT_EQ(cubatureTunableNames().size(), sizeof(lb::f64::lb_cub_tunables) / sizeof(double));
    auto o = CubatureOptions::parse({{"corner_inset", "0.25"}, {"dyn_weight", "3"}, {"area_sin", "0.75"}});
    EXPECT_EQ(o.tunables.corner_inset, 0.25);
    EXPECT_EQ(o.tunables.dyn_weight, 3.0);
    EXPECT_EQ(o.tunables.area_sin, 0.75);
    EXPECT_EQ(o.tunables.plane_eps, 1e-3);
}

// The one lanes rule of every family with lane forms: auto = 8 on CPU devices, 1 elsewhere.
TEST(CubatureOptions, LanesAutoIsEightOnCpusOnly)
{
    EXPECT_EQ(lanesFor("auto", "CPU"), 8);
    EXPECT_EQ(lanesFor("auto", "GPU"), 1);
    EXPECT_EQ(lanesFor("1", "CPU"), 1);
    EXPECT_EQ(lanesFor("8", "GPU"), 8);
}

}  // namespace
}  // namespace lb::methods
