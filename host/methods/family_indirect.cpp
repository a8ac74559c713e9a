// The indirect scene (docs/design.md section 9): the converged reference
// (kernels/indirect_reference.cl) and the RSM methods vpl, kmeans and acrsm
// (kernels/indirect.cl), all multi-pass families (Plan::prePasses).
#include "methods/registry.h"

#include "math/indirect_math.h"
#include "util/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace lb::methods {

namespace {

constexpr int kTex = LB_IND_TEX;  // reals per texel / centre / light (kernels/common/indirect.h)
constexpr int kPart = 16;  // reals per cluster partial sum

// ---- reference ----

// The E_dir node grid of common/indirect.h for cells of about `cell` metres.
struct NodeGrid {
    std::vector<cl_int> grid;  // (gs, gt, first node) per surface
    std::vector<cl_int> cells;  // first cell per surface, then the count
    int nodes = 0;
};

NodeGrid nodeGrid(double cell)
{
    NodeGrid g;
    int node = 0, c = 0;
    for (int k = 0; k < LB_ROOM_NSURF; ++k) {
        glm::dvec3 o, a, b, n;
        f64::lb_room_surface(k, &o, &a, &b, &n);
        int gs = std::max(1, static_cast<int>(std::ceil(glm::length(a) / cell - 1e-9)));
        int gt = std::max(1, static_cast<int>(std::ceil(glm::length(b) / cell - 1e-9)));
        g.grid.insert(g.grid.end(), {gs, gt, node});
        g.cells.push_back(c);
        node += 16 * gs * gt;
        c += gs * gt;
    }
    g.cells.push_back(c);
    g.nodes = node;
    return g;
}

cl::Buffer intBuffer(LaunchContext& c, const std::vector<cl_int>& v)
{
    cl::Buffer b(c.rt.context(), CL_MEM_READ_WRITE | CL_MEM_COPY_HOST_PTR,
                 std::max<size_t>(v.size(), 1) * sizeof(cl_int), const_cast<cl_int*>(v.data()));
    c.buffers.push_back(b);
    return b;
}

// The E_dir passes' buffers and kernels (edir_nodes, edir_delta), and the
// render kernel's edir, grid, delta.
void bindEdir(LaunchContext& c, const NodeGrid& g, double dirTol, int dirSplits)
{
    c.stats["edir_nodes"] = g.nodes;
    c.named["grid"] = intBuffer(c, g.grid);
    c.named["cells"] = intBuffer(c, g.cells);
    c.named["edir"] = c.outputReals(g.nodes);
    c.named["centre"] = c.outputReals(g.cells.back());
    c.named["edir_err"] = c.outputReals(g.nodes);
    c.named["delta"] = c.outputReals(LB_ROOM_NSURF);
    c.arg("edir", c.named["edir"]);
    c.arg("grid", c.named["grid"]);
    c.arg("delta", c.named["delta"]);
    c.bind(c.pass("edir_nodes"), c.named["P"], c.named["lum"], c.named["grid"], c.named["cells"], cl_int(g.nodes),
           c.named["edir"], c.named["centre"], c.named["edir_err"], LaunchContext::Real{dirTol}, cl_int(dirSplits));
    c.bind(c.pass("edir_delta"), c.named["grid"], c.named["cells"], c.named["edir"], c.named["centre"],
           c.named["edir_err"], c.named["delta"]);
    c.stats["edir_points"] = g.nodes + g.cells.back();
}

// The reference's statistics, and the reflected flux rho int E_dir dA over
// walls and ceiling by the nodes' Gauss rule.
void finishIndirectReference(LaunchContext& c, const NodeGrid& g)
{
    finishReference(c);
    auto e = c.readReals(c.named.at("edir"), g.nodes);
    auto delta = c.readReals(c.named.at("delta"), LB_ROOM_NSURF);
    double flux = 0;
    for (int k = 0; k < LB_ROOM_NSURF; ++k) {
        glm::dvec3 o, a, b, nn;
        f64::lb_room_surface(k, &o, &a, &b, &nn);
        int gs = g.grid[3 * k], gt = g.grid[3 * k + 1], base = g.grid[3 * k + 2];
        double cellArea = glm::length(a) / gs * glm::length(b) / gt;
        for (int it = 0; it < 4 * gt; ++it)
            for (int is = 0; is < 4 * gs; ++is)
                flux += cellArea * f64::lb_gl4_w(it % 4) * f64::lb_gl4_w(is % 4) * e[base + it * 4 * gs + is];
    }
    c.stats["reflected_flux_lm"] = c.scene.albedo * flux;
    c.stats["edir_interp_delta"] = delta;
}

void registerIndirectReference(Registry& r)
{
    Family f;
    f.name = "reference";
    f.scenes = {SceneKind::Indirect};
    f.summary = "converged one-bounce indirect light: E_dir on walls and ceiling by the adaptive area cubature, the "
                "bounce by adaptive cubature over the five surfaces, with an error estimate";
    f.file = "indirect_reference.cl";
    f.params = {
        Param::real("tol", 1e-4, 1e-8, 1e-1, Scale::Log, "target relative error of the bounce per pixel", false),
        Param::integer("max_splits", 128, 0, 160, Scale::Linear, "bounce cell splits per pixel at most"),
        Param::real("dir_tol", 1e-5, 1e-9, 1e-1, Scale::Log, "target relative error of E_dir per wall node", false),
        Param::integer("dir_splits", 128, 0, 128, Scale::Linear, "E_dir cell splits per wall node at most"),
        Param::real("dir_cell", 0.125, 0.01, 1.0, Scale::Log,
                    "side (m) of the cells of the E_dir node grid (4 x 4 Gauss nodes each)", false),
    };
    f.expensive = true;
    f.bandRows = 16;
    f.args = {"edir", "grid", "delta", "errout", "splits_out", "rel_tol", "max_splits"};
    f.plan = [](const MethodSpec& s, const Scene& scene, const photometry::Table&, const ocl::DeviceInfo&, Precision) {
        Plan p;
        p.args = {PlanArg::device("edir"), PlanArg::device("grid"), PlanArg::device("delta")};
        referenceArgs(p, s, scene);
        const NodeGrid g = nodeGrid(s.num("dir_cell"));
        p.bind = [g, dirTol = s.num("dir_tol"), dirSplits = s.integer("dir_splits")](LaunchContext& c) {
            bindEdir(c, g, dirTol, static_cast<int>(dirSplits));
        };
        p.finish = [g](LaunchContext& c) { finishIndirectReference(c, g); };
        p.prePasses = [](LaunchContext& c) {
            std::vector<StageEvent> ev;
            const size_t n = c.stats["edir_points"].get<size_t>();
            ev.push_back({"edir", c.rt.launch1D(c.pass("edir_nodes"), n, 64)});
            ev.push_back({"edir", c.rt.launch1D(c.pass("edir_delta"), LB_ROOM_NSURF, 1)});
            return ev;
        };
        return p;
    };
    r.add(f);
}

// ---- the RSM methods ----

bool powerOfTwo(long n) { return n > 0 && (n & (n - 1)) == 0; }

int rsmSide(const LaunchContext& c) { return static_cast<int>(c.spec.integer("rsm")); }  // texels per side
int clusterCount(const LaunchContext& c) { return static_cast<int>(c.spec.integer("k")); }  // kmeans, acrsm

std::vector<Param> rsmParams()
{
    return {
        Param::integer("rsm", 256, 16, 2048, Scale::Log,
                       "RSM texels per side over the room's unfolded net (a power of two)"),
        Param::choice("direct", "cubature", {"point", "cubature", "reference"},
                      "direct light of each RSM texel: point light at the centroid, the cubature (fan around CP), "
                      "or the adaptive reference"),
        Param::real("dir_tol", 1e-3, 1e-7, 1e-1, Scale::Log, "direct=reference: its target relative error", false),
    };
}

void checkRsm(const MethodSpec& s)
{
    if (!powerOfTwo(s.integer("rsm")))
        throw InputError(fmt::format("method {}: rsm={} is not a power of two (the pyramid and the net need one)",
                                     s.name, s.integer("rsm")));
}

std::string rsmDefines(const MethodSpec& s)
{
    const std::string& d = s.str("direct");
    return fmt::format("-DLB_RSM_DIRECT={}", d == "point" ? 0 : (d == "cubature" ? 1 : 2));
}

// The RSM buffer and its pass kernel, bound.
void setupRsm(LaunchContext& c)
{
    const int T = rsmSide(c);
    c.named["tex"] = c.outputReals(static_cast<size_t>(kTex) * T * T);
    // 128: direct=reference's split budget; 1e-3: the cubature's default plane shift
    c.bind(c.pass("rsm"), c.named["P"], c.named["lum"], c.named["tex"], cl_int(T),
           LaunchContext::Real{c.spec.num("dir_tol")}, cl_int(128), LaunchContext::Real{1e-3});
}

cl::Event launchRsm(LaunchContext& c)
{
    const int T = rsmSide(c);
    return c.rt.launch2D(c.pass("rsm"), T, T, 8, 8);
}

// Stats every RSM method reports: the RSM's reflected flux and, for the
// clusterings, the flux of lit texels no cluster took.
void finishRsm(LaunchContext& c)
{
    const int T = rsmSide(c);
    auto tex = c.readReals(c.named.at("tex"), static_cast<size_t>(kTex) * T * T);
    double flux = 0;
    for (int i = 0; i < T * T; ++i) flux += tex[kTex * i + LB_IND_FLUX];
    c.stats["rsm_flux_lm"] = flux;
    if (c.named.count("label")) {
        std::vector<cl_int> label(static_cast<size_t>(T) * T);
        c.rt.queue().enqueueReadBuffer(c.named.at("label"), CL_TRUE, 0, label.size() * sizeof(cl_int), label.data());
        double lost = 0;
        for (int i = 0; i < T * T; ++i)
            if (label[i] < 0) lost += tex[kTex * i + LB_IND_FLUX];
        c.stats["unmapped_flux_fraction"] = flux > 0 ? lost / flux : 0.0;
    }
    if (c.named.count("lights")) {
        const int n = c.stats.value("lights", 0);
        auto l = c.readReals(c.named.at("lights"), static_cast<size_t>(kTex) * n);
        double lf = 0;
        int active = 0;
        for (int i = 0; i < n; ++i) {
            lf += l[kTex * i + LB_IND_FLUX];
            if (l[kTex * i + LB_IND_FLUX] > 0) ++active;
        }
        c.stats["lights_flux_lm"] = lf;
        c.stats["lights_active"] = active;
    }
}

// The passes that draw n texels by flux (row_sums, sample) into the lights
// buffer `lights` (their indices into "pick").
void setupSampling(LaunchContext& c, int n, const std::string& lights)
{
    const int T = rsmSide(c);
    c.named["rowsum"] = c.outputReals(T);
    c.named["pick"] = c.outputInts(n);
    c.bind(c.pass("row_sums"), c.named["tex"], cl_int(T), c.named["rowsum"]);
    c.bind(c.pass("sample"), c.named["tex"], cl_int(T), c.named["rowsum"], cl_int(n), c.named[lights], c.named["pick"]);
}

void launchSampling(LaunchContext& c, int n, std::vector<StageEvent>& ev)
{
    const int T = rsmSide(c);
    ev.push_back({"cluster", c.rt.launch1D(c.pass("row_sums"), T, 64)});
    ev.push_back({"cluster", c.rt.launch1D(c.pass("sample"), n, 64)});
}

// The RSM methods' plan: the direct light's define, the render kernel's
// arguments (the lights the passes fill, kTex reals each; their count; the
// squared clamp distance), the passes' binder (`bind`) and finishRsm.
Plan rsmPlan(const MethodSpec& s, int nlights, double clamp, std::function<void(LaunchContext&)> bind,
             Plan::Passes passes)
{
    Plan p;
    p.defines = rsmDefines(s);
    p.args = {PlanArg::outputReals("lights", static_cast<size_t>(kTex) * nlights), PlanArg::integer("nlights", nlights),
              PlanArg::real("clamp2", clamp * clamp)};
    p.bind = [nlights, bind = std::move(bind)](LaunchContext& c) {
        c.stats["lights"] = nlights;
        bind(c);
    };
    p.finish = finishRsm;
    p.prePasses = std::move(passes);
    return p;
}

// A family's plan hook from its number of lights and clamp distance, the
// binder of its passes and the passes.
PlanHook rsmHook(std::function<int(const MethodSpec&)> nlights, std::function<double(const MethodSpec&)> clamp,
                 std::function<void(LaunchContext&)> bind, Plan::Passes passes)
{
    return [=](const MethodSpec& s, const Scene&, const photometry::Table&, const ocl::DeviceInfo&, Precision) {
        return rsmPlan(s, nlights(s), clamp(s), bind, passes);
    };
}

int lightsOfN(const MethodSpec& s) { return static_cast<int>(s.integer("n")); }
int lightsOfK(const MethodSpec& s) { return static_cast<int>(s.integer("k")); }

// vpl, and the same family as the indirect scene's "mc": the equal-time
// partner the runner fits (VPL count N at the time of a method).
void registerVpl(Registry& r, const std::string& name)
{
    Family f;
    f.name = name;
    f.scenes = {SceneKind::Indirect};
    f.summary = name == "vpl" ? "N virtual point lights importance-sampled from the RSM by flux (Dachsbacher and "
                                "Stamminger 2005)"
                              : "indirect scene: the equal-time partner, N VPLs from the RSM (as vpl)";
    f.file = "indirect.cl";
    f.params = rsmParams();
    f.params.push_back(Param::integer("n", 256, 1, 1 << 16, Scale::Log, "number of VPLs", true));
    f.params.push_back(
        Param::real("clamp", 0.1, 0.0, 1.0, Scale::Linear, "distance (m) below which 1/r^2 is clamped (0: none)"));
    f.validate = checkRsm;
    f.args = {"lights", "nlights", "clamp2"};
    const Plan::Passes passes = [](LaunchContext& c) {
        std::vector<StageEvent> ev;
        ev.push_back({"rsm", launchRsm(c)});
        launchSampling(c, static_cast<int>(c.spec.integer("n")), ev);
        return ev;
    };
    f.plan = rsmHook(
        lightsOfN, [](const MethodSpec& s) { return s.num("clamp"); },
        [](LaunchContext& c) {
            setupRsm(c);
            setupSampling(c, lightsOfN(c.spec), "lights");
        },
        passes);
    if (name == "vpl") f.benchSpecs = {"vpl:n=64", "vpl:n=1024", "vpl:direct=point"};
    r.add(f);
}

// kmeans and acrsm share the Lloyd sums and the VAL evaluation.
std::vector<Param> clusterParams(long k, long iters)
{
    auto p = rsmParams();
    p.push_back(Param::integer("k", k, 1, 1024, Scale::Log, "number of clusters (virtual area lights)", true));
    p.push_back(
        Param::integer("iters", iters, 1, 64, Scale::Linear, "Lloyd iterations (mapping + averaging) per frame"));
    p.push_back(Param::real("wx", 1.0, 0.0, 10.0, Scale::Linear, "weight of the normalized distance (seed Eq. 4.4)"));
    p.push_back(Param::real("wn", 1.0, 0.0, 10.0, Scale::Linear, "weight of the normal difference 1 - |n_c . n|"));
    p.push_back(Param::real("wb", 0.2, 0.0, 10.0, Scale::Linear,
                            "weight of the radiosity difference |B_c - B| / (B_c + B) (the seed's importance)"));
    p.push_back(Param::choice("area", "sum", {"sum", "radius"},
                              "VAL area: the members' area, or pi r^2 of the farthest member (the seed's 4.7)"));
    return p;
}

void setupClusters(LaunchContext& c)
{
    const int T = rsmSide(c), K = clusterCount(c);
    setupRsm(c);
    c.named["centres"] = c.outputReals(static_cast<size_t>(kTex) * K);
    c.named["label"] = c.outputInts(static_cast<size_t>(T) * T);
    c.named["partial"] = c.outputReals(static_cast<size_t>(kPart) * K * T);
    // acrsm's state, zero (frame 0 seeds every cluster; kmeans never writes it)
    c.named["state"] = c.outputReals(static_cast<size_t>(kTex) * K);
    std::vector<double> zero(static_cast<size_t>(kTex) * K, 0.0);
    std::vector<float> zf(zero.size(), 0.0f);
    c.rt.queue().enqueueWriteBuffer(
        c.named["state"], CL_TRUE, 0, c.dbl() ? zero.size() * sizeof(double) : zf.size() * sizeof(float),
        c.dbl() ? static_cast<const void*>(zero.data()) : static_cast<const void*>(zf.data()));
    c.bind(c.pass("km_partial"), c.named["tex"], cl_int(T), c.named["label"], cl_int(K), c.named["centres"],
           c.named["partial"]);
    c.bind(c.pass("km_reduce"), c.named["partial"], cl_int(T), cl_int(K), c.named["centres"], c.named["lights"],
           c.named["state"], cl_int(c.spec.name == "acrsm" ? 1 : 0), cl_int(c.spec.str("area") == "sum" ? 0 : 1));
}

void lloydSums(LaunchContext& c, std::vector<StageEvent>& ev)
{
    const int T = rsmSide(c), K = clusterCount(c);
    ev.push_back({"cluster", c.rt.launch2D(c.pass("km_partial"), K, T, 8, 8)});
    ev.push_back({"cluster", c.rt.launch1D(c.pass("km_reduce"), K, 64)});
}

void registerKmeans(Registry& r)
{
    Family f;
    f.name = "kmeans";
    f.scenes = {SceneKind::Indirect};
    f.summary = "K k-means clusters of RSM texels (position, normal, radiosity), restarted every frame from K texels "
                "sampled by flux, Lloyd iterations on the device; each a disk VAL (point-to-disk form factor)";
    f.file = "indirect.cl";
    f.params = clusterParams(64, 4);
    f.validate = checkRsm;
    f.args = {"lights", "nlights", "clamp2"};
    const Plan::Passes passes = [](LaunchContext& c) {
        const int T = rsmSide(c), K = clusterCount(c);
        std::vector<StageEvent> ev;
        ev.push_back({"rsm", launchRsm(c)});
        launchSampling(c, K, ev);
        ev.push_back({"cluster", c.rt.launch1D(c.pass("centres_from"), K, 64)});
        for (long i = 0; i < c.spec.integer("iters"); ++i) {
            ev.push_back({"cluster", c.rt.launch2D(c.pass("km_assign"), T, T, 8, 8)});
            lloydSums(c, ev);
        }
        return ev;
    };
    f.plan = rsmHook(
        lightsOfK, [](const MethodSpec&) { return 0.0; },
        [](LaunchContext& c) {
            const int T = rsmSide(c), K = clusterCount(c);
            using Real = LaunchContext::Real;
            setupClusters(c);
            c.named["seedlights"] = c.outputReals(static_cast<size_t>(kTex) * K);
            setupSampling(c, K, "seedlights");
            c.bind(c.pass("centres_from"), c.named["tex"], c.named["pick"], cl_int(K), c.named["centres"]);
            c.bind(c.pass("km_assign"), c.named["tex"], cl_int(T), c.named["centres"], cl_int(K),
                   Real{c.spec.num("wx")}, Real{c.spec.num("wn")}, Real{c.spec.num("wb")}, c.named["label"]);
        },
        passes);
    f.benchSpecs = {"kmeans:k=16", "kmeans:k=256"};
    r.add(f);
}

void checkAcrsm(const MethodSpec& s)
{
    checkRsm(s);
    long levels = 0;
    while ((1L << levels) < s.integer("rsm")) ++levels;
    if (s.integer("warp_stop") >= levels)
        throw InputError(
            fmt::format("method acrsm: warp_stop={} must be below log2(rsm) = {}", s.integer("warp_stop"), levels));
    if (s.integer("k") > 1024) throw InputError("method acrsm: k at most 1024");
}

// The importance pyramid over the RSM of side T: its buffer, the levels'
// offsets in it, and the passes that build it (pyr_base, one pyr_down per
// level); returns the number of levels.
int setupPyramid(LaunchContext& c, int T)
{
    int levels = 0;
    while ((1 << levels) < T) ++levels;
    std::vector<cl_int> off(levels + 1);
    int at = 0;
    for (int m = 0; m <= levels; ++m) {
        off[m] = at;
        at += (T >> m) * (T >> m);
    }
    c.named["pyr"] = c.outputReals(at);
    c.named["off"] = intBuffer(c, off);
    c.bind(c.pass("pyr_base"), c.named["tex"], cl_int(T), c.named["pyr"]);
    for (int m = 0; m < levels; ++m) {
        // one kernel object per level: the arguments differ
        cl::Kernel& pd =
            c.passKernels.emplace(fmt::format("pyr_down{}", m), c.rt.kernel(c.family.file, "pyr_down", c.options))
                .first->second;
        c.bind(pd, c.named["pyr"], cl_int(off[m]), cl_int(T >> m), cl_int(off[m + 1]));
    }
    return levels;
}

void acrsmBind(LaunchContext& c)
{
    const int T = rsmSide(c), K = clusterCount(c);
    setupClusters(c);
    const int levels = setupPyramid(c, T);
    c.stats["levels"] = levels;
    using Real = LaunchContext::Real;
    const Real window{c.spec.num("window") * T};
    // the frame (argument 5 of ac_evaluate, 9 of ac_seed) is set per launch
    c.bind(c.pass("ac_evaluate"), cl_int(K), cl_int(T), c.named["state"], c.named["centres"], c.named["lights"],
           cl_int(0), window, Real{c.spec.num("eps_m")}, Real{c.spec.num("eps_s")});
    c.bind(c.pass("ac_seed"), c.named["tex"], cl_int(T), c.named["pyr"], c.named["off"], cl_int(levels),
           static_cast<cl_int>(c.spec.integer("warp_stop")), cl_int(K), c.named["state"], c.named["centres"],
           cl_int(0));
    c.bind(c.pass("ac_map"), c.named["tex"], cl_int(T), c.named["centres"], c.named["state"], cl_int(K), window,
           Real{c.spec.num("wx")}, Real{c.spec.num("wn")}, Real{c.spec.num("wb")}, c.named["label"]);
}

// One frame: the RSM, its pyramid, the clusters evaluated (merge, split)
// from the last frame, seeded, and refined by the mapping and Lloyd's sums.
std::vector<StageEvent> acrsmPasses(LaunchContext& c)
{
    const int T = rsmSide(c), K = clusterCount(c);
    const int levels = c.stats["levels"].get<int>();
    std::vector<StageEvent> ev;
    ev.push_back({"rsm", launchRsm(c)});
    ev.push_back({"cluster", c.rt.launch2D(c.pass("pyr_base"), T, T, 8, 8)});
    for (int m = 0; m < levels; ++m) {
        const int n = std::max(1, (T >> m) / 2);
        ev.push_back(
            {"cluster",
             c.rt.launch2D(c.passKernels.at(fmt::format("pyr_down{}", m)), n, n, std::min(8, n), std::min(8, n))});
    }
    if (c.frame > 0) {
        cl::Kernel& e = c.pass("ac_evaluate");
        e.setArg(5, cl_int(c.frame));
        ev.push_back({"cluster", c.rt.launch1D(e, 1, 1)});
    }
    cl::Kernel& sd = c.pass("ac_seed");
    sd.setArg(9, cl_int(c.frame));
    ev.push_back({"cluster", c.rt.launch1D(sd, K, 64)});
    for (long i = 0; i < c.spec.integer("iters"); ++i) {
        ev.push_back({"cluster", c.rt.launch2D(c.pass("ac_map"), T, T, 8, 8)});
        lloydSums(c, ev);
    }
    ++c.frame;
    return ev;
}

void registerAcrsm(Registry& r)
{
    Family f;
    f.name = "acrsm";
    f.scenes = {SceneKind::Indirect};
    f.summary = "adaptively clustered RSM (the ACRSM seed): clusters kept from frame to frame, Halton seeds warped by "
                "the importance pyramid, windowed mapping, averaging, merge and split; disk VALs";
    f.file = "indirect.cl";
    f.params = clusterParams(64, 1);
    f.params.push_back(Param::real("window", 0.25, 0.01, 1.0, Scale::Linear,
                                   "side of a cluster's mapping window, as a fraction of the RSM's side (seed 5.2: "
                                   "64-256 texels at 512)"));
    f.params.push_back(Param::integer("warp_stop", 0, 0, 11, Scale::Linear,
                                      "finest pyramid level the warping descends to (0: the texels)"));
    f.params.push_back(Param::real("eps_m", 0.4, 0.0, 1.0, Scale::Linear, "merge threshold (seed Eq. 4.8: 0.35-0.5)"));
    f.params.push_back(Param::real("eps_s", 0.15, 0.0, 1.0, Scale::Linear, "split threshold (seed Eq. 4.8: 0.1-0.2)"));
    f.params.push_back(Param::integer("settle", 8, 1, 1000, Scale::Linear,
                                      "frames of a static scene before render() reads the image (its steady state)"));
    f.validate = checkAcrsm;
    f.args = {"lights", "nlights", "clamp2"};
    f.settleFrames = [](const MethodSpec& s) { return static_cast<int>(s.integer("settle")); };
    f.plan = rsmHook(
        lightsOfK, [](const MethodSpec&) { return 0.0; }, acrsmBind, acrsmPasses);
    f.benchSpecs = {"acrsm:k=16", "acrsm:k=256"};
    r.add(f);
}

}  // namespace

void registerIndirect(Registry& r)
{
    registerIndirectReference(r);
    registerVpl(r, "vpl");
    registerVpl(r, "mc");
    registerKmeans(r);
    registerAcrsm(r);
}

}  // namespace lb::methods
