"""The suite's one figure style (docs/figures.md): the matplotlib style file
lumibench.mplstyle, the fixed colour and marker of every method family and
series, and the writer that puts each figure down as a 300-dpi PNG and a PDF
beside it.

    import style
    style.use()
    ax.plot(x, y, **style.plot_kw("cubature"))          # a point
    ax.plot(xs, ys, **style.plot_kw("MCI curve", line=True))
    style.save(fig, "out/nmse.png")                       # out/nmse.png + out/nmse.pdf

Colours are Okabe-Ito (Okabe and Ito 2008, safe under the three common colour
vision deficiencies) plus a neutral grey; colour and marker both encode the
family, and no two entries of the table share the pair. A variant of a family
(`cubature:triangulation=delaunay`) keeps the family's colour and gets a
marker from a hash of its spec; `MCI=<method>` (Monte Carlo at the time of
<method>) has <method>'s colour and marker, hollow, and a dashed line; a
family not in the table gets a colour (Paul Tol's muted scheme) and a marker
from a hash of its name. Hashes are CRC-32, so a series looks the same in
every figure, whatever else the figure shows. Standard library and matplotlib.
"""
import os
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
STYLE_FILE = os.path.join(HERE, "lumibench.mplstyle")

COLUMN_WIDTH = 3.4  # inches: one column of a two-column paper
TEXT_WIDTH = 7.0    # inches: the widest a figure is drawn (two columns)
MIN_FONT_PT = 8     # no text below this at the drawn size
DPI = 300           # the PNGs' resolution

# Okabe-Ito and a neutral grey.
OKABE_ITO = {"blue": "#0072B2", "orange": "#E69F00", "green": "#009E73", "vermillion": "#D55E00",
             "purple": "#CC79A7", "sky": "#56B4E9", "yellow": "#F0E442", "black": "#000000", "grey": "#999999"}
# Paul Tol's muted scheme, for families the table does not name.
TOL_MUTED = ["#CC6677", "#332288", "#DDCC77", "#117733", "#88CCEE", "#882255", "#44AA99", "#999933", "#AA4499"]

_C = OKABE_ITO
# family -> (colour, marker). Every pair is distinct (tests/plots checks it).
FAMILIES = {
    "cubature": (_C["blue"], "o"),
    "voronoi": (_C["green"], "D"),
    "robust": (_C["vermillion"], "s"),
    "structured": (_C["orange"], "^"),
    "point": (_C["grey"], "v"),
    "cp": (_C["purple"], "<"),
    "np": (_C["orange"], ">"),
    "mrp": (_C["green"], "p"),
    "mcpoints": (_C["purple"], "X"),
    "mc": (_C["black"], "P"),          # an MC method drawn as a point (not the curve)
    "reference": (_C["black"], "x"),
    "ltc": (_C["sky"], "o"),           # the specular scene's Cubature + LTC
    "vpl": (_C["vermillion"], "v"),
    "kmeans": (_C["orange"], "s"),
    "acrsm": (_C["green"], "o"),
}
# Variants of the committed experiments pinned to a marker (the family's
# colour), so that those drawn together never share one; other variants hash.
VARIANTS = {
    "cubature:triangulation=delaunay": "s",
    "cubature:triangulation=delaunay,dynamic=cp+barycentre": "D",
    "cubature:triangulation=delaunay,dynamic=cp+np+mrp+barycentre": "^",
    "cubature:dynamic=cp+barycentre": "v",
    "ltc:triangulation=delaunay": "v",
    "ltc:g_omega=exact": "X",
    "ltc:radiance=structured": "^",
    "ltc:radiance=cp": "<",
    "ltc:radiance=point": "s",
    "mc:n=8,sampling=vndf": ">",
    "mc:n=8,sampling=mis": "d",
}
CURVE = "MCI curve"  # Monte Carlo over N: a black line with dots
CURVE_STYLE = (_C["black"], ".")
PARTNER = "MCI="     # prefix of an equal-time partner's series
# One curve per Monte Carlo baseline ("curve:<label>"): colour and line style
# by the baseline's place in the run (set_baselines), dots at the points; the
# first is CURVE_STYLE's black. Dark colours that neither FAMILIES nor the
# hashed families (TOL_MUTED) use, with a marker no family gets ('.').
CURVE_PREFIX = "curve:"
CURVE_STYLES = [(_C["black"], "-"), ("#4B0082", "--"), ("#8C510A", "-."), ("#01665E", ":"),
                ("#B2182B", (0, (5, 1, 1, 1))), ("#5A5A5A", (0, (1, 1)))]
_baselines = []  # labels in the order of the run (set_baselines)
# Markers a variant or an unknown family may draw from.
MARKERS = ["o", "s", "D", "^", "v", "<", ">", "p", "h", "X", "P", "d", "8", "H"]


def set_baselines(labels):
    """The run's baseline labels, in order: the i-th gets CURVE_STYLES[i]
    (cycling), so that a baseline looks the same in every figure of a run."""
    _baselines[:] = list(labels)


def curve_series(label):
    return CURVE_PREFIX + label


def is_curve(series):
    return series == CURVE or series.startswith(CURVE_PREFIX)


def curve_style(series):
    """(colour, line style) of a baseline's curve."""
    if series == CURVE:
        return CURVE_STYLES[0]
    label = series[len(CURVE_PREFIX):]
    i = _baselines.index(label) if label in _baselines else len(_baselines) + _hash(label)
    return CURVE_STYLES[i % len(CURVE_STYLES)]


def _method_of(series):
    """'MCI=cubature [strong]' -> 'cubature': a partner's method (the
    baseline's label in brackets where a run has several)."""
    s = series[len(PARTNER):] if series.startswith(PARTNER) else series
    if s.endswith("]") and " [" in s:
        s = s[:s.rindex(" [")]
    return s


def use():
    """Applies lumibench.mplstyle to matplotlib's rcParams."""
    import matplotlib.pyplot as plt
    plt.style.use(STYLE_FILE)


def _hash(s):
    return zlib.crc32(s.encode("utf-8"))


def family(series):
    """'MCI=cubature:x=1' -> 'cubature'; 'voronoi' -> 'voronoi'; 'MCI curve' -> 'MCI curve'."""
    if is_curve(series):
        return series
    return _method_of(series).split(":")[0]


def colour_marker(series):
    """The (hex colour, marker) of a series, from the table or a hash."""
    if is_curve(series):
        return curve_style(series)[0], CURVE_STYLE[1]
    s = _method_of(series)
    fam = family(s)
    if fam in FAMILIES:
        colour, marker = FAMILIES[fam]
        if s in VARIANTS:
            return colour, VARIANTS[s]
        if s != fam:  # a variant: the family's colour, a marker no entry of that colour has
            taken = {mk for c, mk in list(FAMILIES.values()) + [CURVE_STYLE] if c == colour}
            pool = [m for m in MARKERS if m not in taken]
            marker = pool[_hash(s) % len(pool)]
        return colour, marker
    h = _hash(fam)
    return TOL_MUTED[h % len(TOL_MUTED)], MARKERS[(h // len(TOL_MUTED)) % len(MARKERS)]


def is_partner(series):
    return series.startswith(PARTNER)


def plot_kw(series, line=False, label=None, ms=None):
    """ax.plot keyword arguments for a series: its colour and marker, hollow
    and dashed for an equal-time partner, a line only where `line` (or for the
    MCI curve). The artist's gid is 'series:<series>' (tests/plots reads it)."""
    colour, marker = colour_marker(series)
    hollow = is_partner(series)
    kw = {"color": colour, "marker": marker, "markeredgecolor": colour,
          "markerfacecolor": "none" if hollow else colour,
          "linestyle": ("--" if hollow else "-") if line else "none",
          "gid": "series:" + series, "label": series if label is None else label}
    if is_curve(series):
        kw["linestyle"] = curve_style(series)[1]
    if hollow:
        kw["markeredgewidth"] = 1.2
    if ms is not None:
        kw["markersize"] = ms
    elif is_curve(series):
        kw["markersize"] = 4
    return kw


def series_of(r):
    """What a plot groups a record by: its `series` where the file has one,
    else 'MCI curve' (the MCI curve), 'MCI=<label>' (an equal-time partner),
    or the method's spec."""
    if r.get("series"):
        return r["series"]
    if r.get("role") == "mci_curve":
        return CURVE
    if r.get("equal_time_to") or r.get("role") == "equal_time":
        et = (r.get("equal_time") or {}) if isinstance(r.get("equal_time"), dict) else {}
        return PARTNER + (et.get("label") or r.get("equal_time_label") or r.get("equal_time_to") or "?")
    return r.get("spec") or r.get("method", "?")


def order(series):
    """A sort key: methods by name, each partner right after its method, the curve last."""
    if is_curve(series):
        return ("~", _baselines.index(series[len(CURVE_PREFIX):]) if series[len(CURVE_PREFIX):] in _baselines
                else len(_baselines), series)
    s = _method_of(series)
    return (s, int(is_partner(series)), series)


# Called as hook(fig, [paths]) by save(); tests/plots sets it to inspect the figures.
on_save = None


def save(fig, path, dpi=None):
    """Writes `fig` as PNG (at `dpi`, default 300) and PDF beside it, both
    atomically (atomic.py), with a tight bounding box (nothing clipped).
    `path` may end in .png, .pdf or .svg; the PNG and the PDF are always
    written. Returns the paths written."""
    from atomic import save_figure
    stem, ext = os.path.splitext(os.fspath(path))
    paths = [stem + ".png", stem + ".pdf"]
    if ext.lower() == ".svg":
        paths.append(stem + ".svg")
    # the tight box measured once (a draw), for both files
    fig.canvas.draw()
    box = fig.get_tightbbox(fig.canvas.get_renderer()).padded(0.03)
    for p in paths:
        save_figure(fig, p, dpi=dpi or DPI, bbox_inches=box)
    if on_save is not None:
        on_save(fig, paths)
    return paths


def wrap(label, width=28):
    """A long legend label broken at its commas into lines of about `width`
    characters (specs such as cubature:triangulation=delaunay,dynamic=...)."""
    if len(label) <= width:
        return label
    lines, cur = [], ""
    for part in label.split(","):
        piece = part if not cur else "," + part
        if cur and len(cur) + len(piece) > width:
            lines.append(cur + ",")
            cur = part
        else:
            cur += piece
    lines.append(cur)
    return "\n".join(lines)


def legend_columns(labels, width_in):
    """How many legend columns of these labels fit `width_in` inches at 8 pt
    (about 0.065 in per character, 0.45 in for the handle and the gap)."""
    longest = max([max(len(s) for s in lb.split("\n")) for lb in labels] + [1])
    return max(1, min(len(labels), int(width_in // (0.065 * longest + 0.45))))
