// plots/image_grid.py on the pictures `lumibench compare --png` writes (~1 s:
// one matplotlib start-up).
#include "metrics/image.h"
#include "metrics/png.h"
#include "testutil.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

namespace lb {
namespace {

namespace fs = std::filesystem;

// The Debian interpreter, which has python3-matplotlib (a python3 earlier on
// PATH, e.g. pyenv's, may not).
std::string python() { return fs::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3"; }

int sh(const std::string& cmd)
{
    int st = std::system(cmd.c_str());
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

// Writes DIR/r.exr, DIR/a.exr and `lumibench compare` of the two with --png
// DIR/row (plus `extra` flags); returns the prefix DIR/row.
std::string comparePictures(const fs::path& dir, const std::string& extra)
{
    Image r(16, 16), a(16, 16);
    for (size_t i = 0; i < r.px.size(); ++i) {
        r.px[i] = 1.0 + 0.1 * static_cast<double>(i % 16);
        a.px[i] = r.px[i] * (i % 3 == 0 ? 1.2 : 0.9);
    }
    writeExr((dir / "r.exr").string(), r);
    writeExr((dir / "a.exr").string(), a);
    const std::string prefix = (dir / "row").string();
    EXPECT_EQ(sh(test::binary() + " compare " + (dir / "r.exr").string() + " " + (dir / "a.exr").string() + " --png " +
                 prefix + extra),
              0);
    return prefix;
}

// Runs `body` in /usr/bin/python3 after a header that imports image_grid and
// sets d (DIR) and prefix; returns the exit status.
int imageGridScript(const fs::path& dir, const std::string& prefix, const std::string& body)
{
    std::ofstream((dir / "t.py").string())
        << "import sys\nsys.path.insert(0, '" << test::sourceDir()
        << "/plots')\nimport matplotlib\nmatplotlib.use('Agg')\n"
        << "import image_grid\nd, prefix = '" << dir.string() << "', '" << prefix << "'\n"
        << body;
    return sh(python() + " " + (dir / "t.py").string() + " > /dev/null");
}

TEST(Plots, ImageGridOfComparePictures)
{
    fs::path dir = fs::temp_directory_path() / ("lb_grid_" + std::to_string(getpid()));
    fs::create_directories(dir);
    const std::string prefix = comparePictures(dir, " --json > " + (dir / "row.json").string());
    const std::string script = test::sourceDir() + "/plots/image_grid.py";
    const std::string out = (dir / "grid.png").string();
    ASSERT_EQ(sh(python() + " " + script + " --out " + out + " 'test row=" + prefix + "' > /dev/null"), 0);
    auto g = readPng(out);  // a real PNG with room for a 1 x 3 grid
    EXPECT_GT(g.width, g.height);
    // A missing picture is a clear error, not a traceback.
    EXPECT_NE(sh(python() + " " + script + " --out " + out + " " + (dir / "nothing").string() + " 2> /dev/null"), 0);
    fs::remove_all(dir);
}

// The captions under the error pictures (NMSE, UEB, LEB, grad_nmse, FLIP)
// lie inside the figure at the size plots/experiment.py uses (2 inch
// pictures), with the widest numbers; and the check itself sees a caption
// that sticks out.
TEST(Plots, ImageGridCaptionsFitTheFigure)
{
    if (sh(python() + " -c 'import matplotlib' 2>/dev/null") != 0 && !test::deviceRequired())
        GTEST_SKIP() << python() << " has no matplotlib";
    fs::path dir = fs::temp_directory_path() / ("lb_grid_caption_" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string prefix = comparePictures(dir, " > /dev/null");
    // the widest values a caption shows
    FILE* j = std::fopen((prefix + ".json").c_str(), "w");
    ASSERT_NE(j, nullptr);
    std::fprintf(j, R"({"nmse": 1.23456e-05, "ueb": 12345.6, "leb": -12345.6, "grad_nmse": 1.23456e-05,
                        "flip": 0.123456, "nonfinite": 123456})");
    std::fclose(j);
    const std::string script = (dir / "t.py").string();
    FILE* f = std::fopen(script.c_str(), "w");
    ASSERT_NE(f, nullptr);
    std::fprintf(f, R"(import sys
sys.path.insert(0, %s)
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import image_grid
d, prefix = %s, %s
for size in (2.0, 2.6):
    fig = image_grid.main(["MCI=cubature N=12=" + prefix, "cubature=" + prefix, "--out", d + "/g.png",
                           "--size", str(size), "--dpi", "100"])
    for ax in fig.axes:
        if ax.xaxis.label.get_text():
            assert image_grid.inside(fig, ax.xaxis.label), (size, ax.xaxis.label.get_text())
# the check can fail: the one-line caption of before sticks out at 2 inch
fig = image_grid.main([prefix, "--out", d + "/g.png", "--size", "2.0", "--dpi", "100"])
ax = [a for a in fig.axes if a.xaxis.label.get_text()][0]
ax.set_xlabel("NMSE 1.23e-05  UEB +1.23e+04 lx  LEB -1.23e+04 lx", fontsize=8)
assert not image_grid.inside(fig, ax.xaxis.label), "inside() cannot fail"
)",
                 ("'" + test::sourceDir() + "/plots'").c_str(), ("'" + dir.string() + "'").c_str(),
                 ("'" + prefix + "'").c_str());
    std::fclose(f);
    EXPECT_EQ(sh(python() + " " + script + " > /dev/null"), 0);
    fs::remove_all(dir);
}

// Error pictures of several rows at one bound (compare --bound, as run and
// report draw a scene) get one colour bar beside the error column, in the
// pictures' colours, labelled in lux and in % of the reference mean; rows at
// different bounds get one bar each; a row without a bound none.
TEST(Plots, ImageGridHasALabelledColourBar)
{
    if (sh(python() + " -c 'import matplotlib' 2>/dev/null") != 0 && !test::deviceRequired())
        GTEST_SKIP() << python() << " has no matplotlib";
    fs::path dir = fs::temp_directory_path() / ("lb_grid_bar_" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    // the reference's mean is 1.75 lx: 0.5 lx is 28.6 %
    const std::string prefix = comparePictures(dir, " --bound 0.5 --json > " + (dir / "row.json").string());
    fs::copy_file(dir / "row.json", dir / "other.json");
    for (const char* s : {"_ref.png", "_test.png", "_err.png"}) fs::copy_file(prefix + s, (dir / "other").string() + s);
    EXPECT_EQ(imageGridScript(dir, prefix, R"(import json
def bars(fig):
    return [a for a in fig.axes if a.get_gid() == "colour_bar"]
def labels(fig):
    return [t.get_text() for a in bars(fig) for t in a.get_yticklabels()]
fig = image_grid.main(["a=" + prefix, "b=" + d + "/other", "--out", d + "/g.png", "--no-legend"])
assert len(bars(fig)) == 1, len(bars(fig))
got = labels(fig)
for want in ("+0.5 lx\n+28.6 %", "-0.5 lx\n-28.6 %", "0 lx\n0 %", "+0.25 lx\n+14.3 %"):
    assert want in got, (want, got)
# the bar's colours are the pictures' (host/metrics/tonemap.h colourBar)
from matplotlib.colors import to_hex
m = json.load(open(prefix + ".json"))
cmap = [c for c in bars(fig)[0].collections if c.cmap.name == "lumibench_error"][0].cmap
assert (to_hex(cmap(0.0)), to_hex(cmap(0.5)), to_hex(cmap(1.0))) == ("#0080ff", "#ffffff", "#d55e00"), cmap
assert m["colour_bar"][0] == "#0080ff" and m["colour_bar"][-1] == "#d55e00"
# other bound: one bar per row
j = dict(m, bound=1.0)
json.dump(j, open(d + "/other.json", "w"))
fig = image_grid.main(["a=" + prefix, "b=" + d + "/other", "--out", d + "/g.png", "--no-legend"])
assert len(bars(fig)) == 2, len(bars(fig))
assert "+1 lx\n+57.1 %" in labels(fig), labels(fig)
# no bound: no bar
j.pop("bound")
json.dump(j, open(d + "/other.json", "w"))
fig = image_grid.main(["b=" + d + "/other", "--out", d + "/g.png", "--no-legend"])
assert len(bars(fig)) == 0
)"),
              0);
    fs::remove_all(dir);
}

// Plot files are written atomically (plots/atomic.py): a savefig that fails
// half-way (here it writes some bytes and then raises ENOSPC) leaves the old
// figure and no temporary; a successful one leaves the PNG and no temporary.
TEST(Plots, FiguresAreWrittenAtomically)
{
    if (sh(python() + " -c 'import matplotlib' 2>/dev/null") != 0 && !test::deviceRequired())
        GTEST_SKIP() << python() << " has no matplotlib";
    fs::path dir = fs::temp_directory_path() / ("lb_atomic_plot_" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string script = (dir / "t.py").string();
    FILE* f = std::fopen(script.c_str(), "w");
    ASSERT_NE(f, nullptr);
    std::fprintf(f, R"(import errno, os, sys
sys.path.insert(0, %s)
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from atomic import save_figure
d = %s
target = os.path.join(d, "fig.png")
open(target, "w").write("old")
fig = plt.figure()
def broken(path, **kw):
    open(path, "wb").write(b"half a png")
    raise OSError(errno.ENOSPC, "No space left on device")
real = fig.savefig
fig.savefig = broken
try:
    save_figure(fig, target, dpi=50)
    sys.exit("no error")
except OSError:
    pass
assert open(target).read() == "old", "the old figure was replaced"
assert sorted(os.listdir(d)) == ["fig.png", "t.py"], os.listdir(d)
fig.savefig = real
save_figure(fig, target, dpi=50)
assert open(target, "rb").read(8) == b"\x89PNG\r\n\x1a\n", "not a PNG"
assert sorted(os.listdir(d)) == ["fig.png", "t.py"], os.listdir(d)
)",
                 ("'" + test::sourceDir() + "/plots'").c_str(), ("'" + dir.string() + "'").c_str());
    std::fclose(f);
    EXPECT_EQ(sh(python() + " " + script), 0);
    fs::remove_all(dir);
}

}  // namespace
}  // namespace lb
