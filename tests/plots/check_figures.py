"""Renders every plot kind of plots/ from the small committed results in
tests/plots/data and checks what a paper needs of a figure:

- a PNG and a PDF beside it, the PNG at 300 dpi or more and at most the text
  width (style.TEXT_WIDTH, plus the saved box's padding) wide;
- no visible text below style.MIN_FONT_PT at that size;
- every artist of a series (gid 'series:<name>') in the colour and marker of
  style.py's table, hollow for an equal-time partner, filled otherwise;
- legends outside every axes (not over the data);
- the per-height figure shows the pooled NMSE of the rotations, not their mean;
- N beside the points of the MCI curve.

The checker itself is shown to fail on a figure that breaks each rule.

    /usr/bin/python3 tests/plots/check_figures.py PLOTS_DIR DATA_DIR WORK_DIR

Exits 1 with the list of failures, 0 when all hold.
"""
import json
import os
import shutil
import subprocess
import sys

PLOTS, DATA, WORK = sys.argv[1:4]
sys.path.insert(0, PLOTS)
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.colors import to_hex  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
from matplotlib.text import Text  # noqa: E402
from PIL import Image  # noqa: E402

import style  # noqa: E402

saved = []  # (kind, figure, paths)
kind = None
style.on_save = lambda fig, paths: saved.append((kind, fig, paths))


def file_problems(paths):
    out = []
    png = [p for p in paths if p.endswith(".png")]
    pdf = [p for p in paths if p.endswith(".pdf")]
    if not png or not pdf:
        out.append(f"not both a PNG and a PDF: {paths}")
    for p in pdf:
        if not os.path.exists(p) or open(p, "rb").read(5) != b"%PDF-":
            out.append(f"{p}: no PDF")
    for p in png:
        if not os.path.exists(p):
            out.append(f"{p}: missing")
            continue
        im = Image.open(p)
        dpi = im.info.get("dpi", (0, 0))[0]
        # PIL reads the pHYs chunk's pixels per metre back as 299.9994 for 300
        if dpi < style.DPI - 0.5:
            out.append(f"{p}: {dpi:.0f} dpi, below {style.DPI}")
        # the saved box adds 0.03 in of padding each side
        if dpi > 0 and im.size[0] / dpi > style.TEXT_WIDTH + 0.1:
            out.append(f"{p}: {im.size[0] / dpi:.2f} in wide, wider than the text width {style.TEXT_WIDTH} in")
    return out


def font_problems(fig):
    out = []
    for t in fig.findobj(Text):
        if t.get_visible() and t.get_text().strip() and t.get_fontsize() < style.MIN_FONT_PT - 1e-9:
            out.append(f"text {t.get_text()[:30]!r} at {t.get_fontsize():.1f} pt")
    return out


def colour_problems(fig):
    """(problems, number of series artists checked)"""
    out, n = [], 0
    for line in fig.findobj(Line2D):
        gid = line.get_gid() or ""
        if not gid.startswith("series:"):
            continue
        n += 1
        name = gid[len("series:"):]
        colour, marker = style.colour_marker(name)
        if to_hex(line.get_color()) != to_hex(colour) or to_hex(line.get_markeredgecolor()) != to_hex(colour):
            out.append(f"{name}: colour {to_hex(line.get_color())}, the table says {colour}")
        if line.get_marker() != marker:
            out.append(f"{name}: marker {line.get_marker()!r}, the table says {marker!r}")
        face = line.get_markerfacecolor()
        hollow = isinstance(face, str) and face == "none"
        if hollow != style.is_partner(name):
            out.append(f"{name}: {'hollow' if hollow else 'filled'} marker")
    return out, n


def legend_problems(fig):
    out = []
    fig.canvas.draw()
    r = fig.canvas.get_renderer()
    legends = list(fig.legends) + [ax.get_legend() for ax in fig.axes if ax.get_legend()]
    for lg in legends:
        lb = lg.get_window_extent(r)
        for ax in fig.axes:
            if ax.get_visible() and lb.overlaps(ax.get_window_extent(r)):
                out.append("a legend lies over the data of an axes")
    return out


def problems(fig, paths):
    c, _ = colour_problems(fig)
    return file_problems(paths) + font_problems(fig) + c + legend_problems(fig)


failures = []


def expect(cond, what):
    if not cond:
        failures.append(what)


def run_kind(name, fn):
    global kind
    kind = name
    before = len(saved)
    try:
        fn()
    except SystemExit as e:
        if e.code not in (0, None):
            failures.append(f"{name}: exited {e.code}")
    figs = saved[before:]
    expect(figs, f"{name}: no figure saved through style.save")
    for _, fig, paths in figs:
        for p in problems(fig, paths):
            failures.append(f"{name} {os.path.basename(paths[0])}: {p}")
    return figs


def main_with_argv(module, argv):
    def call():
        old = sys.argv
        sys.argv = [module + ".py"] + argv
        try:
            mod = __import__(module)
            r = mod.main(sys.argv) if module in ("indirect_flicker",) else mod.main()
            if r not in (0, None):
                raise SystemExit(r)
        finally:
            sys.argv = old
    return call


os.makedirs(WORK, exist_ok=True)
exp_dir = os.path.join(WORK, "exp")
os.makedirs(exp_dir, exist_ok=True)
shutil.copy(os.path.join(DATA, "results.json"), exp_dir)

# 1. experiment.py: NMSE against time per luminaire, NMSE per luminaire per height
import experiment  # noqa: E402
figs = run_kind("experiment", lambda: experiment.main([exp_dir]))
names = sorted(os.path.basename(p[0]) for _, _, p in figs)
expect(names == ["nmse_all_time_float.png", "nmse_by_luminaire_time_float.png", "nmse_h0.1_float.png",
                 "nmse_h1.1_float.png", "nmse_time_ARCOS3_60712332_float.png", "nmse_time_PANOS_60813872_float.png"],
       f"experiment: figures {names}")
for _, fig, paths in figs:
    base = os.path.basename(paths[0])
    _, n = colour_problems(fig)
    # pooled figures have no partners (each scene's lies on its curve)
    want = 5 if base.startswith(("nmse_all", "nmse_by")) else 7
    expect(n >= want, f"{base}: {n} series artists (cubature, its variant, voronoi, point, partners, curve)")
    if "_time_" in base:
        labels = {t.get_text() for t in fig.findobj(Text) if t.get_gid() == "curve-label"}
        expect({"1", "64"} <= labels, f"{base}: N labels on the MCI curve {sorted(labels)}")

# The per-height figure: ARCOS, h 0.1, cubature is the pooled NMSE of its two rotations.
from results_io import load_records, pooled  # noqa: E402
recs = [r for r in load_records(os.path.join(DATA, "results.json"))
        if r["luminaire"].startswith("ARCOS") and r["height"] == 0.1 and r.get("spec") == "cubature"
        and r["role"] == "method"]
want = pooled(recs, "nmse")
mean = sum(r["nmse"] for r in recs) / len(recs)
# the data must tell the two apart, else the check below could not fail
expect(len(recs) == 2 and abs(mean / want - 1) > 0.1, f"pooled {want} and mean {mean} of the test data are alike")
fig = next(f for _, f, p in figs if os.path.basename(p[0]) == "nmse_h0.1_float.png")
line = next(ln for ln in fig.findobj(Line2D) if ln.get_gid() == "series:cubature")
ys = list(line.get_ydata())
expect(len(ys) == 2 and abs(ys[0] / want - 1) < 1e-9,  # the same arithmetic: only rounding apart
       f"nmse_h0.1: cubature on ARCOS at {ys[:1]}, pooled {want}, mean {mean}")

# Eight luminaires (the test's two, copied under other names) at one height:
# the widest per-height figure still fits the text width with its legend.
many = [dict(r, luminaire=f"L{k}_{r['luminaire']}") for k in range(4)
        for r in load_records(os.path.join(DATA, "results.json")) if r["height"] == 0.1]
wide_dir = os.path.join(WORK, "wide")
os.makedirs(wide_dir, exist_ok=True)
run_kind("experiment (8 luminaires)", lambda: experiment.metric_per_height(many, wide_dir, style.DPI, "nmse", "NMSE"))

# Two Monte Carlo baselines (the test's curve and partners again as a second,
# labelled baseline at half the error, with a 95 % band over seeds, and N = 2
# timed below N = 1 on one scene as a filter's fixed cost makes it): every
# figure of error against time draws both curves, each band, the ring where
# the time steps back, and the device and timing resolution in the caption.
import error_time  # noqa: E402
from results_io import baselines  # noqa: E402
two = load_records(os.path.join(DATA, "results.json"))
second = []
for r in two:
    if r["role"] in ("mci_curve", "equal_time"):
        c = json.loads(json.dumps(r))
        c["params"]["domain"] = "solid"
        c["baseline"] = {"label": "strong", "spec": "mc:domain=solid"}
        c["nmse"] = r["nmse"] / 2
        c["seeds"] = 8
        c["ci95"] = {"nmse": [r["nmse"] / 3, r["nmse"] / 1.5]}
        c["time_ms"] = dict(r["time_ms"], res=128)
        second.append(c)
first_scene = second[0]["scene"]
t1 = next(c["time_ms"]["median"] for c in second if c["scene"] == first_scene and c["params"]["n"] == 1
          and c["role"] == "mci_curve")
for c in second:
    if c["scene"] == first_scene and c["role"] == "mci_curve" and c["params"]["n"] == 2:
        c["time_ms"]["median"] = t1 * 0.95
    if c["scene"] == second[-1]["scene"] != first_scene and c["role"] == "mci_curve" and c["params"]["n"] == 1:
        c["nmse"] = None  # undefined (a black image): the pooled N = 1 is over the other scenes, marked 1*
two += second
known = baselines(two)
expect(list(known.values()) == ["MC", "strong"], f"baselines {known}")
style.set_baselines(known.values())
two_dir = os.path.join(WORK, "two")
os.makedirs(two_dir, exist_ok=True)
figs = run_kind("error_time (two baselines)", lambda: (
    error_time.metric_time(two, two_dir, style.DPI, "nmse", "NMSE", known),
    error_time.pooled_time(two, two_dir, style.DPI, "nmse", "NMSE", known, per_luminaire=False),
    error_time.pooled_time(two, two_dir, style.DPI, "nmse", "NMSE", known)))
expect(len(figs) == 4, f"error_time: {len(figs)} figures of two baselines, not 4")
for _, fig, paths in figs:
    base = os.path.basename(paths[0])
    gids = {a.get_gid() for a in fig.findobj() if a.get_gid()}
    for want in ("series:curve:MC", "series:curve:strong", "band:strong"):
        expect(want in gids, f"{base}: no {want}")
    expect("band:MC" not in gids, f"{base}: a band where the baseline has no seeds")
    if base.startswith("nmse_time_ARCOS"):
        rings = [a for a in fig.findobj(Line2D) if a.get_gid() == "time-steps-back"]
        expect(any(abs(x / (t1 * 0.95) - 1) < 1e-9 for a in rings for x in a.get_xdata()),
               f"{base}: no ring on the second baseline where its N = 2 is timed below N = 1")
    if base.startswith("nmse_all"):
        ns = {t.get_text() for t in fig.findobj(Text) if t.get_gid() == "curve-label"}
        expect("1*" in ns, f"{base}: N = 1 of the second baseline not marked as over fewer scenes: {sorted(ns)}")
    cap = " ".join(" ".join(t.get_text().split()) for t in fig.findobj(Text) if t.get_gid() == "caption")
    for want in ("Xeon", "128 x 128", "over 8 seeds"):
        expect(want in cap, f"{base}: the caption lacks {want!r}: {cap!r}")
    legend = " ".join(t.get_text() for lg in fig.legends for t in lg.get_texts())
    expect("strong over N" in legend and "mc:domain=solid" in legend, f"{base}: legend {legend!r}")

# 2. specular.py --fig
run_kind("specular", main_with_argv("specular", [os.path.join(DATA, "specular.json"),
                                                  "--md", os.path.join(WORK, "spec.md"),
                                                  "--fig", os.path.join(WORK, "specular.png")]))
# 3. indirect_flicker.py on a committed sequence
seq = os.path.join(PLOTS, "..", "experiments", "results", "indirect", "sequence-rotate-ARCOS3_60712332.json")
with open(os.devnull, "w") as null:
    stdout, sys.stdout = sys.stdout, null
    try:
        run_kind("indirect_flicker", main_with_argv("indirect_flicker", [os.path.join(WORK, "flicker.png"), seq]))
    finally:
        sys.stdout = stdout
# 4. tune.py, 5. polar.py
run_kind("tune", main_with_argv("tune", [os.path.join(DATA, "tune.json"), os.path.join(WORK, "tune.png")]))
run_kind("polar", main_with_argv("polar", [os.path.join(DATA, "polar.json"), "-o", os.path.join(WORK, "polar.png")]))
# 6. image_grid.py on made-up picture triples
import numpy as np  # noqa: E402
import image_grid  # noqa: E402
pic = os.path.join(WORK, "row")
for suffix in ("_ref.png", "_test.png", "_err.png"):
    plt.imsave(pic + suffix, np.random.default_rng(1).random((16, 16, 3)))
with open(pic + ".json", "w") as f:
    json.dump({"nmse": 0.0123, "ueb": 12.5, "leb": -3.25}, f)
with open(os.devnull, "w") as null:
    stdout, sys.stdout = sys.stdout, null
    try:
        run_kind("image_grid", lambda: image_grid.main(["cubature=" + pic, "--out", os.path.join(WORK, "grid.png"),
                                                        "--size", "2.0"]))
    finally:
        sys.stdout = stdout

# A scene label that reads as an option (a luminaire named -h.ldt) is the grid's title, not a flag.
grid = experiment.one_grid(("-h_h0.1_rpi-2_float", ["cubature=" + pic], os.path.join(WORK, "grid-h.png"), 100))
expect(os.path.exists(grid[0]), "image grid of a scene named -h...: no figure")

# The table: no two entries share a (colour, marker) pair.
pairs = {}
for name in list(style.FAMILIES) + list(style.VARIANTS) + [style.CURVE]:
    cm = style.colour_marker(name)
    expect(cm not in pairs, f"{name} and {pairs.get(cm)} share {cm}")
    pairs[cm] = name
# A baseline's curve after the first (black, as the MCI curve) has a colour no
# family has, fixed or hashed, so that it is not read as a method's.
taken = {c.lower() for c, _ in style.FAMILIES.values()} | {c.lower() for c in style.TOL_MUTED}
for colour, _ in style.CURVE_STYLES[1:]:
    expect(colour.lower() not in taken, f"curve colour {colour} is a method family's")
# A partner has its method's colour and marker; an unknown family the same in
# every process (CRC-32, not Python's salted hash()).
expect(style.colour_marker("MCI=voronoi") == style.colour_marker("voronoi"), "MCI=voronoi not voronoi's colour")
probe = ("import sys; sys.path.insert(0, {!r}); import style; "
         "print(style.colour_marker('someday-method:x=1'))").format(PLOTS)
seen = {subprocess.run([sys.executable, "-c", probe], env=dict(os.environ, PYTHONHASHSEED=s), check=True,
                       capture_output=True, text=True).stdout for s in ("1", "2")}
expect(len(seen) == 1, f"an unknown family's style depends on the process: {seen}")

# The checks can fail: a figure breaking every rule is caught by each.
kind = "broken"
bad = plt.figure(figsize=(8, 3))
ax = bad.add_subplot()
ax.plot([1, 2], [1, 2], "s", color="#ff0000", gid="series:cubature", label="cubature")
ax.plot([1, 2], [2, 1], "o", color=style.colour_marker("voronoi")[0], mfc="none", gid="series:voronoi")
ax.set_title("small", fontsize=6)
ax.legend(loc="center")
bad_png = os.path.join(WORK, "bad.png")
with matplotlib.rc_context({"savefig.bbox": "standard"}):  # the full 8 in (the style crops to the content)
    bad.savefig(bad_png, dpi=100)
found = problems(bad, [bad_png])
for what in ("not both a PNG and a PDF", "dpi, below", "wider than the text width", "at 6.0 pt", "cubature: colour",
             "cubature: marker", "voronoi: hollow", "legend lies over"):
    expect(any(what in p for p in found), f"the checker misses '{what}' in {found}")

if failures:
    print("\n".join(failures))
    sys.exit(1)
print(f"check_figures: {len(saved)} figures of {len({k for k, _, _ in saved})} kinds pass")
