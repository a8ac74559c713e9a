"""Error against run time, with every Monte Carlo baseline's curve (plots/experiment.py draws them).

- One curve per baseline (results_io.baselines: each MC spec of the run, by
  its label): the baseline over N, sorted by N and drawn at the times as
  measured, its 95 % band over seeds shaded where the records have one, N
  beside its points. A point whose measured time is not above that of a
  smaller N (a filter's fixed cost, or a floor, makes N = 1 and 2 cost the
  same; the rest is timing noise) is ringed, so the line's step back in time
  reads as a measurement, not as a faster N.
- Every method as a point (filled, its family's colour and marker) with its
  interval: the metric's 95 % interval over seeds (vertical) and the timed
  runs' min .. max (horizontal). Equal-time partners hollow, per scene only.
- Per scene (metric_time: a panel per height and rotation, one figure per
  luminaire), and pooled (pooled_time: the geometric mean over scenes of the
  metric, its bounds and the times, one panel for all scenes and one per
  luminaire). A pooled curve point is the mean over the scenes where the
  error at that N is defined (N* where some lack it), a pooled method is
  drawn where every scene has it.
- The caption under the legend names the device, the timing resolution (the
  pixels each launch was timed at), the timed runs and the seeds.
"""
import collections
import math
import os
import textwrap

import matplotlib.pyplot as plt

import style
from results_io import (baseline_of, equal_time, interval, is_curve, is_partner, mc_spec, without_per_record,
                        written_spec)


def finite(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)


def value(r, key):
    """The metric of a record, None where it is null, missing or not positive."""
    v = r.get(key)
    return v if finite(v) and v > 0 else None


def median_ms(r):
    t = (r.get("time_ms") or {}).get("median")
    return t if finite(t) and t > 0 else None


def bounds(r, key):
    """(lo, hi) of a record's metric: its 95 % interval over seeds, else the
    value twice. A lower bound at or below zero (a Student-t interval of a
    few noisy draws) is drawn at a hundredth of the value: a log axis has no
    zero."""
    v = value(r, key)
    lo, hi = interval(r, key)
    lo = lo if finite(lo) else v
    hi = hi if finite(hi) else v
    return (lo if lo > 0 else v / 100), hi


def time_range(r):
    t = r.get("time_ms") or {}
    m = median_ms(r)
    lo, hi = t.get("min"), t.get("max")
    return (lo if finite(lo) and lo > 0 else m), (hi if finite(hi) and hi > 0 else m)


def curve_of(r, known):
    """The baseline label whose curve a record belongs to: a curve point, or a
    method record that is the same MC at some N (the runner keeps one cell
    where a method equals a curve point); None otherwise."""
    if is_curve(r):
        return baseline_of(r, known)[0]
    if r.get("role", "method") == "method" and r.get("method") == "mc" and not is_partner(r):
        spec = mc_spec(r.get("params"), "mc")
        return next((label for s, label in known.items() if without_per_record(s) == spec), None)
    return None


def series(r, known):
    """The legend series of a record that is drawn as a point: its method's
    spec, or MCI=<method> for a partner (with [label] where the run has
    several baselines)."""
    if not is_partner(r):
        return written_spec(r)
    s = style.PARTNER + ((equal_time(r) or {}).get("label") or "?")
    if len(known) > 1:
        s += " [{}]".format(baseline_of(r, known)[0])
    return s


# A point: (time, value, value lo, value hi, time lo, time hi); a curve point has its N in front.
def curves(cell, key, known):
    """{label: [(n, t, v, lo, hi, tlo, thi), ...] sorted by N} of the records of one scene."""
    out = collections.defaultdict(dict)
    for r in cell:
        label = curve_of(r, known)
        if label is None or not value(r, key) or not median_ms(r):
            continue
        n = (r.get("params") or {}).get("n", r.get("n"))
        if finite(n):
            out[label][n] = (n, median_ms(r), value(r, key)) + bounds(r, key) + time_range(r)
    return {label: [pts[n] for n in sorted(pts)] for label, pts in out.items()}


def points(cell, key, known, partners=True):
    """{series: (t, v, lo, hi, tlo, thi)} of the records drawn as points."""
    out = {}
    for r in cell:
        if curve_of(r, known) is not None or not value(r, key) or not median_ms(r):
            continue
        if is_partner(r) and not partners:
            continue
        if not is_partner(r) and r.get("role", "method") != "method":
            continue
        out[series(r, known)] = (median_ms(r), value(r, key)) + bounds(r, key) + time_range(r)
    return out


def non_monotone(pts):
    """Indices of curve points whose time is not above that of every smaller N."""
    out, top = [], 0.0
    for i, p in enumerate(pts):
        if i and p[1] <= top:
            out.append(i)
        top = max(top, p[1])
    return out


def draw_curve(ax, label, pts, all_n=True, fewer=()):
    """A baseline's curve: the band, the line through its points in N order,
    N beside them (every other one where more than six would crowd the panel;
    the last always; the first and the last only where not all_n) and a ring
    round each point whose time steps back."""
    s = style.curve_series(label)
    colour = style.colour_marker(s)[0]
    ts, vs = [p[1] for p in pts], [p[2] for p in pts]
    if any(p[3] < p[4] for p in pts):
        ax.fill_between(ts, [p[3] for p in pts], [p[4] for p in pts], color=colour, alpha=0.15, lw=0,
                        gid="band:" + label)
    ax.plot(ts, vs, **style.plot_kw(s))
    back = non_monotone(pts)
    if back:
        ax.plot([ts[i] for i in back], [vs[i] for i in back], linestyle="none", marker="o", markersize=7,
                markerfacecolor="none", markeredgecolor=colour, markeredgewidth=0.8, gid="time-steps-back")
    step = (2 if len(pts) > 6 else 1) if all_n else max(1, len(pts) - 1)
    for i, p in enumerate(pts):
        last = i == len(pts) - 1
        if i % step == 0 or last:
            # the last one below-left of its point: inside the panel, not under the next one
            ax.annotate(_n_text(p[0]) + ("*" if p[0] in fewer else ""), (p[1], p[2]), xytext=(-2, -3) if last else (2, 2),
                        textcoords="offset points", ha="right" if last else "left", va="top" if last else "bottom",
                        fontsize=style.MIN_FONT_PT, color=colour, gid="curve-label")


def _n_text(n):
    return str(int(n)) if float(n).is_integer() else "{:.3g}".format(n)


def draw_point(ax, s, p):
    """A method (or partner) at (t, v) with its intervals as thin lines in its colour."""
    t, v, lo, hi, tlo, thi = p
    colour = style.colour_marker(s)[0]
    if lo < hi:
        ax.vlines(t, lo, hi, colors=colour, lw=0.8, gid="interval:" + s)
    if tlo < thi:
        ax.hlines(v, tlo, thi, colors=colour, lw=0.8, gid="interval:" + s)
    ax.plot(t, v, **style.plot_kw(s))


def draw_panel(ax, curve_map, point_map, fewer=None):
    # N beside every other point of the first curve; of the others, the ends (else they crowd)
    for k, (label, pts) in enumerate(sorted(curve_map.items(), key=lambda kv: style.order(style.curve_series(kv[0])))):
        draw_curve(ax, label, pts, all_n=k == 0, fewer=(fewer or {}).get(label, ()))
    for s in sorted(point_map, key=style.order):
        draw_point(ax, s, point_map[s])
    ax.set_xscale("log")
    ax.set_yscale("log")
    # no minor ticks: on log axes over many decades they were most of the drawing time
    ax.minorticks_off()


def legend_labels(names, known, curve_ns):
    """The legend's text of each series: a curve by its label, its spec where
    that says more, and its N; a partner as <baseline>=<method>."""
    specs = {label: short_spec(spec, known) for spec, label in known.items()}
    out = []
    for n in names:
        if style.is_curve(n):
            label = n[len(style.CURVE_PREFIX):]
            spec = specs.get(label, "")
            text = "{} over N{}{}".format(label, " = " + curve_ns[label] if curve_ns.get(label) else "",
                                          " ({})".format(spec) if spec and spec != label else "")
            out.append(style.wrap(text, 40))
        elif style.is_partner(n):
            # "<baseline>=<method>": that baseline at the method's time, as the report names it
            body = n[len(style.PARTNER):]
            label = next(iter(specs), "MC")
            if body.endswith("]") and " [" in body:
                body, label = body[:body.rindex(" [")], body[body.rindex(" [") + 2:-1]
            out.append(style.wrap("{}={}".format(label, body)))
        else:
            out.append(style.wrap(n))
    return out


# Parameters that say which Monte Carlo a baseline is; the legend always names them.
SAMPLER_KEYS = ("domain", "sequence", "pattern", "denoise", "paper")


def short_spec(spec, known):
    """A baseline's spec for a legend: its sampler's parameters, and the others
    where they differ between the run's baselines (the full specs are in the
    records and the report)."""
    parse = lambda s: dict(kv.split("=", 1) for kv in s.partition(":")[2].split(",") if "=" in kv)  # noqa: E731
    mine, all_ = parse(spec), [parse(s) for s in known]
    keep = [k for k in sorted(mine) if k in SAMPLER_KEYS or len({p.get(k) for p in all_}) > 1]
    return spec.partition(":")[0] + (":" + ",".join("{}={}".format(k, mine[k]) for k in keep) if keep else "")


def figure_legend(fig, width_in, known, curve_ns, marks_back):
    """One legend for every panel, below them (outside the data): the methods,
    each followed by its equal-time partners (one entry for all of them where
    the run has several baselines), then the baselines' curves."""
    handles = {}
    for ax in fig.axes:
        for hd, lb in zip(*ax.get_legend_handles_labels()):
            if not lb.startswith("_"):
                handles.setdefault(lb, hd)
    names = sorted(handles, key=style.order)
    partners = len(known) > 1 and any(style.is_partner(n) for n in names)
    if partners:  # one entry for them all, not one per method and baseline
        names = [n for n in names if not style.is_partner(n)]
    labels = legend_labels(names, known, curve_ns)
    hs = [handles[n] for n in names]
    if partners:
        hs.append(plt.Line2D([], [], linestyle="none", marker="o", markerfacecolor="none", markeredgecolor="0.3",
                             markeredgewidth=1.2))
        labels.append("hollow: a baseline at a method's time\n(the method's colour and marker)")
    if marks_back:
        hs.append(plt.Line2D([], [], linestyle="none", marker="o", markersize=7, markerfacecolor="none",
                             markeredgecolor="0.3", markeredgewidth=0.8))
        labels.append("time not above a smaller N's")
    ncol = style.legend_columns(labels, width_in)
    return fig.legend(hs, labels, loc="upper center", bbox_to_anchor=(0.5, 0.0), ncol=ncol)


def caption_text(records, pooled_note=""):
    """The device(s), the timing resolution, the timed runs and the seeds of the records."""
    devices = sorted({r.get("device") for r in records if r.get("device")})
    res = sorted({(r.get("time_ms") or {}).get("res") for r in records} - {None})
    reps = sorted({(r.get("time_ms") or {}).get("reps") for r in records} - {None})
    seeds = sorted({r.get("seeds") for r in records if r.get("seeds")})
    text = "Device: {}. Timing resolution {} pixels per launch (OpenCL profiling events, median of {} runs; " \
        "horizontal bars: min .. max).".format(
            "; ".join(devices) or "not recorded", " / ".join("{0} x {0}".format(k) for k in res) or "the image's",
            "/".join(str(k) for k in reps) or "?")
    if seeds:
        text += " Bands and vertical bars: 95 % interval over {} seeds.".format("/".join(str(k) for k in seeds))
    return text + (" " + pooled_note if pooled_note else "")


def add_caption(fig, legend, text, width_in):
    """The caption under the legend, wrapped to the figure's width."""
    dpi = fig.dpi
    fig.set_dpi(style.DPI)  # measured at the saved file's dpi, where the text runs a little longer
    try:
        box = legend.get_window_extent(fig.canvas.get_renderer())
        y = (box.y0 - 0.08 * fig.dpi) / fig.bbox.height
    finally:
        fig.set_dpi(dpi)
    chars = max(30, int((width_in - 0.1) / 0.062))
    # the empty last line: room below the text, whose extent at the saved dpi may exceed the one measured
    fig.text(0.5, y, "\n".join(textwrap.wrap(text, chars)) + "\n ", ha="center", va="top",
             fontsize=style.MIN_FONT_PT, gid="caption")


def curve_ns(records, known):
    """{label: 'lo..hi'} of the N on each baseline's curve."""
    ns = collections.defaultdict(set)
    for r in records:
        label = curve_of(r, known)
        n = (r.get("params") or {}).get("n")
        if label is not None and finite(n):
            ns[label].add(n)
    return {k: "{}..{}".format(_n_text(min(v)), _n_text(max(v))) for k, v in ns.items()}


def safe(s):
    return "".join(c if c.isalnum() or c in ".-" else "_" for c in str(s))


def stem(lum):
    return os.path.splitext(os.path.basename(lum))[0]


def lum_name(r):
    """The luminaire as its file names it (the record's luminaire_name), else the file's stem."""
    return r.get("luminaire_name") or stem(r["luminaire"])


def rot_label(rad):
    return "R={:.0f}°".format(math.degrees(rad))


def metric_time(records, out, dpi, key, name, known):
    """One figure per luminaire and precision; a panel per (height, rotation)."""
    by = collections.defaultdict(list)
    for r in records:
        by[(r["luminaire"], r["precision"])].append(r)
    files = []
    for (lum, prec), rs in sorted(by.items()):
        heights = sorted({r["height"] for r in rs})
        rots = sorted({r["rotation"] for r in rs})
        # at most the text width: 0.75 in for the y labels, panels of at most 1.8 in
        pw = min(1.8, (style.TEXT_WIDTH - 0.8) / len(rots))
        W, H = 0.75 + pw * len(rots) + 0.05, 0.45 + 0.42 + 0.85 * pw * len(heights)
        fig, axes = plt.subplots(len(heights), len(rots), figsize=(W, H), squeeze=False, sharex=True, sharey=True)
        back = False
        for i, h in enumerate(heights):
            for j, rot in enumerate(rots):
                ax = axes[i][j]
                cell = [r for r in rs if r["height"] == h and r["rotation"] == rot]
                cm = curves(cell, key, known)
                back |= any(non_monotone(p) for p in cm.values())
                draw_panel(ax, cm, points(cell, key, known))
                if i == 0:
                    ax.set_title(rot_label(rot))
                if j == 0:
                    ax.set_ylabel("h={} m\n{}".format(h, name))
                if i == len(heights) - 1:
                    ax.set_xlabel("time (ms)")
        fig.suptitle("{} ({}): {} against kernel time".format(lum_name(rs[0]), prec, name))
        # Fixed margins in inches instead of tight_layout, which took 70 % of
        # the plotting time (it measures every tick label of every panel);
        # the saved file's bounding box takes in the legend below.
        fig.subplots_adjust(left=0.75 / W, right=1 - 0.05 / W, top=1 - 0.45 / H, bottom=0.42 / H,
                            wspace=0.06, hspace=0.08)
        legend = figure_legend(fig, W, known, curve_ns(rs, known), back)
        add_caption(fig, legend, caption_text(rs), W)
        path = os.path.join(out, "{}_time_{}_{}.png".format(key, safe(stem(lum)), prec))
        files += style.save(fig, path, dpi=dpi)
        plt.close(fig)
    return files


def geomean(xs):
    return math.exp(sum(math.log(x) for x in xs) / len(xs))


def pool(cells, key, known):
    """The geometric mean over scenes (cells: one list of records per scene)
    of each baseline's curve and of each method every scene has: (curves,
    points, fewer) as curves() and points() give them, `fewer` {label: the N
    that some scenes lack (an undefined error: a black image at N = 1), whose
    mean is over the others}."""
    per = [(curves(c, key, known), points(c, key, known, partners=False)) for c in cells]
    if not per:
        return {}, {}, {}
    mean = lambda rows: tuple(geomean(col) for col in zip(*rows))  # noqa: E731
    cm, fewer = {}, {}
    for label in set().union(*(set(c) for c, _ in per)):
        by_n = collections.defaultdict(list)
        for c, _ in per:
            for p in c.get(label, []):
                by_n[p[0]].append(p[1:])
        cm[label] = [(n,) + mean(by_n[n]) for n in sorted(by_n)]
        fewer[label] = {n for n in by_n if len(by_n[n]) < len(per)}
    pm = {s: mean([p[s] for _, p in per]) for s in set.intersection(*(set(p) for _, p in per))}
    return cm, pm, fewer


def scenes(records):
    """{scene key: its records} (luminaire, height, rotation and the rest of the scene)."""
    out = collections.OrderedDict()
    for r in records:
        k = r.get("scene") or (r["luminaire"], r["height"], r["rotation"], r.get("res"))
        out.setdefault(k, []).append(r)
    return out


def pooled_time(records, out, dpi, key, name, known, per_luminaire=True, path=None):
    """One panel over every scene (the geometric mean), and with
    per_luminaire a figure with a panel per luminaire: one figure each per
    precision. Returns the paths written."""
    files = []
    for prec in sorted({r["precision"] for r in records}):
        rs = [r for r in records if r["precision"] == prec]
        groups = [("all {} scenes".format(len(scenes(rs))), rs)]
        kind = "all"
        if per_luminaire:
            kind = "by_luminaire"
            groups = [(lum_name(v[0]), v) for _, v in sorted(_by(rs, "luminaire").items())]
        files += _pooled_figure(groups, rs, key, name, known, prec,
                                path or os.path.join(out, "{}_{}_time_{}.png".format(key, kind, prec)), dpi)
    return files


def _by(records, k):
    out = collections.defaultdict(list)
    for r in records:
        out[r[k]].append(r)
    return out


def _pooled_figure(groups, rs, key, name, known, prec, path, dpi):
    cols = min(len(groups), 3)
    rows = -(-len(groups) // cols)
    pw = min(2.6 if cols == 1 else 2.1, (style.TEXT_WIDTH - 0.8) / cols)
    W, H = 0.75 + pw * cols + 0.05, 0.5 + 0.42 + 0.8 * pw * rows
    fig, axes = plt.subplots(rows, cols, figsize=(W, H), squeeze=False, sharex=True, sharey=True)
    back = partial = False
    for k, (title, recs) in enumerate(groups):
        ax = axes[k // cols][k % cols]
        cm, pm, fewer = pool(list(scenes(recs).values()), key, known)
        back |= any(non_monotone(p) for p in cm.values())
        partial |= any(fewer.values())
        draw_panel(ax, cm, pm, fewer)
        ax.set_title(textwrap.shorten(title, int(pw / 0.065)), fontsize=style.MIN_FONT_PT)
        if k % cols == 0:
            ax.set_ylabel("{} (geometric mean)".format(name))
        if k // cols == rows - 1 or k + cols >= len(groups):
            ax.set_xlabel("time (ms, geometric mean)")
            ax.xaxis.set_tick_params(labelbottom=True)
    for k in range(len(groups), rows * cols):
        axes[k // cols][k % cols].set_visible(False)
    fig.suptitle("{} against kernel time, geometric mean over scenes ({})".format(name, prec))
    fig.subplots_adjust(left=0.75 / W, right=1 - 0.05 / W, top=1 - 0.5 / H, bottom=0.42 / H, wspace=0.08,
                        hspace=0.35)
    legend = figure_legend(fig, W, known, curve_ns(rs, known), back)
    note = "Geometric means over the panel's scenes{}.".format(
        "; N* over the scenes where the error is defined (some lack it)" if partial else "")
    add_caption(fig, legend, caption_text(rs, note), W)
    files = style.save(fig, path, dpi=dpi)
    plt.close(fig)
    return files
