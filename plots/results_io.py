"""Reading the records of a `lumibench run` / `merge` result, from either of
the two files it writes: results.json (the document: context and records,
also .json.xz) or results.csv (one flat row per record, docs/experiments.md, "Results as a
table"; its unit-suffixed columns read back under the record keys, a partner's
equal_time_to being its equal-time label, not the canonical SPEC). Both give the same list of record dicts, shaped as in results.json:
`time_ms` a dict (median, min, max, reps, res, cv), `params` a dict, `ci95`
a dict of [lo, hi] by metric (seed-dependent methods), keys a record does
not have (empty CSV fields) absent, undefined metrics None. An equal-time
partner's result is read through equal_time(), whichever file and schema
version it came from; verdict() is the report's win / tie / loss rule.
Standard library only.
"""
import csv
import json
import lzma
import os
import sys

# CSV columns that hold text even when they look like a number.
TEXT = {"role", "series", "method", "spec", "scene", "luminaire", "precision", "device", "driver",
        "equal_time_label", "baseline", "baseline_spec", "verdict", "verdict_flip", "off_time", "luminaire_name",
        "unit"}
# Metric keys: an empty field is an undefined value (null in the JSON), kept as None.
METRICS = {"nmse", "nrmse", "relmse", "ueb", "leb", "mean_ref", "mean_test", "grad_nmse", "flip"}
# CSV columns named with their unit: the record key each stands for.
# The values are lux, or cd/m^2 on the specular scene's rows (ueb_cd_m2, ...;
# a column holds one unit, the other's column is empty on that row).
RENAMED = {"height_m": "height", "rotation_rad": "rotation", "ueb_lux": "ueb", "leb_lux": "leb",
           "mean_ref_lux": "mean_ref", "mean_test_lux": "mean_test", "ueb_cd_m2": "ueb", "leb_cd_m2": "leb",
           "mean_ref_cd_m2": "mean_ref", "mean_test_cd_m2": "mean_test"}


def _value(s):
    if s in ("True", "False", "true", "false"):
        return s in ("True", "true")
    for conv in (int, float):
        try:
            return conv(s)
        except ValueError:
            pass
    return s


def _key(col):
    """The record key of a CSV column (its unit suffix dropped)."""
    for suffix in ("_ci95_lo", "_ci95_hi"):
        if col.endswith(suffix):
            return _key(col[:-len(suffix)]) + suffix
    return RENAMED.get(col, col)


def _partner(r):
    """A partner row's equal-time keys as a schema 1 record has them: the
    matched method (equal_time_to: the label as the experiment wrote it, the
    CSV has no canonical SPEC), equal_time_n = N + extra and n = N."""
    if r.get("role") != "equal_time":
        return
    if "equal_time_label" in r:
        r["equal_time_to"] = r["equal_time_label"]
    if isinstance(r.get("n"), (int, float)):
        r["equal_time_n"] = r["n"]
        r["n"] = int(r["n"])
    # off_time holds the reason of a pair outside the tolerance, empty at equal time
    r["equal_time_ok"] = not r.get("off_time")
    r["equal_time_bracketed"] = "no integer N closer" in r.get("off_time", "")
    ratio, ms = r.get("equal_time_ratio"), (r.get("time_ms") or {}).get("median")
    if isinstance(ratio, (int, float)) and isinstance(ms, (int, float)) and ratio > 0:
        r["equal_time_method_ms"] = ms / ratio  # the CSV has the MC's paired median and the ratio


def _params(spec):
    """The parameters of a canonical SPEC ("name:key=value,...") as a dict."""
    _, _, rest = (spec or "").partition(":")
    return {k: _value(v) for k, v in (kv.split("=", 1) for kv in rest.split(",") if "=" in kv)}


def _record(row):
    r, time_ms = {}, {}
    params = json.loads(row["params"]) if row.get("params") else _params(row.get("spec"))
    for col, s in row.items():
        if col is None or col in ("series", "params") or col.startswith("param_"):
            continue
        key = _key(col)
        if s == "":
            if key in METRICS:
                r.setdefault(key, None)  # the same key's column in the other unit may hold it
            continue
        if key.endswith("_ci95_lo") or key.endswith("_ci95_hi"):
            pair = r.setdefault("ci95", {}).setdefault(key[:-len("_ci95_lo")], [None, None])
            pair[key.endswith("_hi")] = _value(s)
        elif key.startswith("time_ms_"):
            time_ms[key[len("time_ms_"):]] = _value(s)
        elif key == "n" and r.get("role") != "equal_time":
            continue  # MC's n outside a partner is its parameter, in params
        else:
            r[key] = s if key in TEXT else _value(s)
    r["time_ms"] = time_ms
    if r.get("role", "method") == "method" and row.get("series"):
        r["spec"] = row["series"]  # the SPEC as the experiment wrote it, as results.json's `spec`
    if "n" not in params and row.get("n") not in (None, "") and r.get("role") != "equal_time":
        params["n"] = _value(row["n"])  # a CSV without a params column: MC's n is its column
    _partner(r)
    r["params"] = params
    if r.get("baseline"):
        r["baseline"] = {"label": r["baseline"], "spec": r.pop("baseline_spec", "")}
    return r


def results_file(path):
    """A results directory's results.json (else its results.csv), or the file itself."""
    if os.path.isdir(path):
        for name in ("results.json", "results.csv"):
            if os.path.exists(os.path.join(path, name)):
                return os.path.join(path, name)
        raise OSError("{}: neither results.json nor results.csv".format(path))
    return path


def load_records(path):
    """The records of a results directory or file (.json, .json.xz or .csv).
    Raises OSError or ValueError when it cannot be read or is not a results file."""
    path = results_file(path)
    if path.endswith(".csv"):
        with open(path, newline="") as f:
            return [_record(row) for row in csv.DictReader(f)]
    if os.path.exists(path + ".journal"):
        sys.stderr.write("{0}: warning: {0}.journal holds records not yet folded in (a run in progress or "
                         "interrupted); `lumibench report DIR` folds them in\n".format(path))
    opener = lzma.open if path.endswith(".xz") else open
    with opener(path, "rt") as f:
        doc = json.load(f)
    recs = doc.get("records") if isinstance(doc, dict) else None
    if not isinstance(recs, list):
        raise ValueError("{}: no 'records' list (not a lumibench results file)".format(path))
    return recs


def load_context(path):
    """The run's context (device, commit, date, experiment_spec, ...) of a
    results directory or .json[.xz] file; {} for a CSV or where the file has none."""
    path = results_file(path)
    if path.endswith(".csv"):
        return {}
    opener = lzma.open if path.endswith(".xz") else open
    with opener(path, "rt") as f:
        doc = json.load(f)
    c = doc.get("context") if isinstance(doc, dict) else None
    return c if isinstance(c, dict) else {}


def pooled_nmse(recs):
    """NMSE of the records' images stitched side by side into one, as
    lumibench's report pools them (metrics::pooled, host/metrics/metrics.h):
    each record's SSE = nmse * P * mean_ref * mean_test (thesis Eq. 6.7 solved
    for the sum) with P its finite pixels (pixels - nonfinite; 1 for records
    without a pixel count), then
        NMSE = (sum SSE / sum P) / (mean_ref * mean_test)
    with the P-weighted means. NaN when either mean is not positive."""
    p = sr = st = sse = 0.0
    for r in recs:
        pi = float(r["pixels"] - r.get("nonfinite", 0)) if "pixels" in r else 1.0
        p += pi
        sr += pi * r["mean_ref"]
        st += pi * r["mean_test"]
        sse += r["nmse"] * pi * r["mean_ref"] * r["mean_test"]
    mr, mt = (sr / p, st / p) if p > 0 else (0.0, 0.0)
    return sse / p / (mr * mt) if mr > 0 and mt > 0 else float("nan")


def pooled(recs, key):
    """A metric of the records' images stitched into one, as metrics::pooled
    (host/metrics/metrics.h): nmse as pooled_nmse; grad_nmse the same over the
    neighbour pairs (each record's squared-difference sum grad_nmse *
    grad_pairs * mean_ref * mean_test, divided by the pairs and the pooled
    means); flip the pixel-weighted mean. NaN where a record lacks the metric
    or a pooled mean is not positive."""
    def num(r, k):
        v = r.get(k)
        return float(v) if isinstance(v, (int, float)) and v == v else float("nan")
    if key == "nmse":
        return pooled_nmse(recs) if all(num(r, "nmse") == num(r, "nmse") for r in recs) else float("nan")
    p = sr = st = acc = pairs = 0.0
    for r in recs:
        pi = float(r["pixels"] - r.get("nonfinite", 0)) if "pixels" in r else 1.0
        p += pi
        sr += pi * num(r, "mean_ref")
        st += pi * num(r, "mean_test")
        if key == "grad_nmse":
            gp = float(r.get("grad_pairs", pi))  # files without grad_pairs: the pixels
            acc += num(r, key) * gp * num(r, "mean_ref") * num(r, "mean_test")
            pairs += gp
        else:
            acc += num(r, key) * pi
    if p <= 0:
        return float("nan")
    if key != "grad_nmse":
        return acc / p
    mr, mt = sr / p, st / p
    return acc / pairs / (mr * mt) if mr > 0 and mt > 0 and pairs > 0 else float("nan")


# The keys of a partner's equal-time result (results.h, EqualTime).
EQUAL_TIME_KEYS = ("label", "n", "ratio", "ok", "bracketed", "method_ms", "method_cv", "partner_ms", "partner_cv",
                   "cell_ms", "tolerance")


def equal_time(r):
    """The equal-time result of a partner record as a dict of EQUAL_TIME_KEYS
    (None where unknown), from results.json (schema 2: "equal_time": {...};
    schema 1: flat equal_time_* keys, equal_time_target_ms the method's time)
    or results.csv (equal_time_<key> columns). None for a record that is no
    equal-time partner. The one place the plots read these fields."""
    if r.get("role") != "equal_time" and "equal_time_to" not in r and "equal_time" not in r:
        return None
    et = r.get("equal_time")
    if isinstance(et, dict):
        out = {k: et.get(k) for k in EQUAL_TIME_KEYS}
    else:
        out = {k: r.get("equal_time_" + k) for k in EQUAL_TIME_KEYS}
        if out["method_ms"] is None:
            out["method_ms"] = r.get("equal_time_target_ms")
        if out["partner_ms"] is None:
            out["partner_ms"] = (r.get("time_ms") or {}).get("median")
        for k in ("ok", "bracketed"):  # as lumibench reads a schema 1 record (results.cpp)
            if out[k] is None:
                out[k] = False
    if out["n"] is None:
        out["n"] = r.get("n")
    if out["label"] is None:
        out["label"] = r.get("equal_time_to")
    return out


def matched(r):
    """The method an equal-time partner was timed against, as (name, params):
    from its equal-time label (the SPEC as the experiment wrote it, e.g.
    "ltc") or, where a record has none (schema 1), the canonical SPEC in
    equal_time_to ("ltc:g_omega=estimate,..."); None for a record that is no
    partner. Whichever file it came from (results.json or results.csv, whose
    equal_time_to is the label): compare params against the family's
    defaults, not the strings."""
    et = equal_time(r)
    spec = (et or {}).get("label") or r.get("equal_time_to")
    if not et or not isinstance(spec, str):
        return None
    name, _, rest = spec.partition(":")
    return name, dict(kv.split("=", 1) for kv in rest.split(",") if "=" in kv)


def interval(r, metric="nmse"):
    """[lo, hi] of a metric: its 95 % interval over seeds where the record has
    one, else [value, value] (None where undefined)."""
    ci = (r.get("ci95") or {}).get(metric)
    if ci and ci[0] is not None and ci[1] is not None:
        return list(ci)
    v = r.get(metric)
    return [v, v]


def verdict(method, partner, metric="nmse"):
    """The equal-time verdict of `method` against its MC partner (results.h
    results::verdict): "win" where the method's interval lies below the
    partner's, "loss" where above, "tie" where they overlap, "n/a" where a
    value is undefined. Lower is better (NMSE and the other error metrics)."""
    m, p = interval(method, metric), interval(partner, metric)
    if any(v is None or v != v for v in m + p):
        return "n/a"
    if m[1] < p[0]:
        return "win"
    if m[0] > p[1]:
        return "loss"
    return "tie"


# MC parameters that vary within one baseline: its sample count, the seed of a
# draw, and the fraction of tiles an equal-time partner gives N + 1 samples.
PER_RECORD_PARAMS = ("n", "seed", "extra")


def _param_text(v):
    if isinstance(v, float) and v.is_integer() and abs(v) < 1e15:
        return str(int(v))
    return str(v)


def mc_spec(params, method="mc"):
    """The canonical SPEC of an MC record's baseline: its method and every
    parameter but n, seed and extra, sorted by name ("mc:domain=solid,...")."""
    rest = ",".join("{}={}".format(k, _param_text(v)) for k, v in sorted((params or {}).items())
                    if k not in PER_RECORD_PARAMS)
    return method + (":" + rest if rest else "")


def without_per_record(spec):
    """A baseline's SPEC without the parameters that vary within it (n, seed,
    extra), its parameters sorted by name: one spelling of one baseline."""
    name, _, rest = (spec or "").partition(":")
    kept = [kv for kv in rest.split(",") if kv and kv.split("=", 1)[0] not in PER_RECORD_PARAMS]
    return name + (":" + ",".join(sorted(kept, key=lambda kv: kv.split("=", 1)[0])) if kept else "")


def _explicit_baseline(r):
    """(label, spec) as a record names its baseline, or (None, None): a
    "baseline" object {label, spec} or string, or flat baseline_label /
    baseline_spec keys (results.csv); the spec without_per_record."""
    b = r.get("baseline")
    if isinstance(b, dict):
        label, spec = b.get("label"), b.get("spec")
    else:
        label, spec = (b if isinstance(b, str) and b else r.get("baseline_label")), r.get("baseline_spec")
    return label or None, (without_per_record(spec) if spec else None)


def is_curve(r):
    return r.get("role") == "mci_curve"


def is_partner(r):
    return r.get("role") == "equal_time" or "equal_time_to" in r


def baselines(records, context=None):
    """The Monte Carlo baselines of a run, in the order first met, as an
    ordered dict {canonical spec: label}: from the records' own baseline
    fields where they have them, else from their parameters (every parameter
    but n, seed and extra). An unlabelled baseline is named by the
    experiment's `mc` (a string) or "MC" where it is the only one unlabelled,
    else by the parameters that tell them apart ("domain=solid,sequence=sobol")."""
    found, labels, specs_of = {}, {}, {}
    for r in records:
        if not (is_curve(r) or is_partner(r)):
            continue
        label, spec = _explicit_baseline(r)
        spec = spec or mc_spec(r.get("params"), r.get("method", "mc"))
        if label and specs_of.setdefault(label, spec) != spec:
            spec = specs_of[label]  # one label, one baseline: its first spelling
        found.setdefault(spec, None)
        if label and not labels.get(spec):
            labels[spec] = label
    unnamed = [s for s in found if not labels.get(s)]
    if unnamed:
        written = ((context or {}).get("experiment_spec") or {}).get("mc")
        if len(unnamed) == 1:
            labels[unnamed[0]] = written if isinstance(written, str) and written else "MC"
        else:
            parts = {s: dict(kv.split("=", 1) for kv in s.partition(":")[2].split(",") if "=" in kv) for s in found}
            keys = sorted({k for p in parts.values() for k in p if len({q.get(k) for q in parts.values()}) > 1})
            for s in unnamed:
                labels[s] = ",".join("{}={}".format(k, parts[s][k]) for k in keys if k in parts[s]) or s
    return {s: labels[s] for s in found}


def baseline_of(r, known):
    """(label, spec) of a curve point or equal-time partner, `known` being
    baselines(records); None for any other record."""
    if not (is_curve(r) or is_partner(r)):
        return None
    label, spec = _explicit_baseline(r)
    spec = spec or mc_spec(r.get("params"), r.get("method", "mc"))
    if label:
        spec = next((s for s, lb in known.items() if lb == label), spec)
    return label or known.get(spec, spec), spec


def pair_verdict(method, partner, metric="nmse"):
    """The equal-time verdict of a method against one partner: the partner
    record's own `verdict` where the run wrote one (a string, or one per
    metric), else "off-time" where the pair's
    times differ by more than its tolerance (equal_time ok false), else
    verdict()."""
    v = partner.get("verdict")
    if isinstance(v, dict):
        v = v.get(metric)
    if isinstance(v, str) and v:
        return v
    et = equal_time(partner) or {}
    if et.get("ok") is False:
        return "off-time"
    return verdict(method, partner, metric)


def written_spec(r):
    """A method record's SPEC as the experiment wrote it (what a partner's
    equal-time label names): results.csv's `series` where its `spec` is the
    canonical one, else `spec`."""
    if r.get("role", "method") == "method" and isinstance(r.get("series"), str) and r["series"]:
        return r["series"]
    return r.get("spec") or r.get("method")
