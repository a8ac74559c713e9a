#!/usr/bin/env bash
# cubature-variants.sh -- the table of docs/studies/cubature-variants.md: every cubature variant and
# voronoi against the reference, next to MC at equal time (DESIGN section 6),
# for ARCOS, PERLUCE, INTRO at h = 0.1 and 1.1, R = 3pi/4.
#
#   experiments/cubature-variants.sh [RES] [OUTDIR]     (defaults 128, /tmp/lb-cubature-variants)
#
# The reference is float with tol=1e-4 (relative per pixel: an NMSE floor of
# ~1e-8, far below every variant's): at 256^2 and the default 1e-5 in double
# it takes ~9 min per scene for the kinked ARCOS table on the 2-core PoCL CPU.
#
# Needs build/lumibench, jq and /usr/bin/python3 (numpy-free). Prints a
# markdown table on stdout, progress on stderr; images and JSON under OUTDIR.
# Luminaires from ../shared/luminaires/zumtobel, else the suite's own
# spot / diffuse / sideways.
set -euo pipefail
cd "$(dirname "$0")/.."
LB=${LB:-build/lumibench}   # the program (override: LB=path)
RES=${1:-128}
OUT=${2:-/tmp/lb-cubature-variants}
ROT=3pi/4
MC_FIT="2 8 32 128"   # MC sample counts of the t(N) fit
mkdir -p "$OUT"

Z=../shared/luminaires/zumtobel
if [[ -d $Z ]]; then
    LUMS=("ARCOS=$Z/ARCOS3_60712332.LDT" "PERLUCE=$Z/PERLUCE_42182932.LDT" "INTRO=$Z/INTRO_60714483.LDT")
else
    LUMS=("spot=luminaires/spot.ldt" "diffuse=luminaires/diffuse.ldt" "sideways=luminaires/sideways.ldt")
fi

VARIANTS=(
    "fan+cp (default)|cubature"
    "delaunay+cp|cubature:triangulation=delaunay"
    "weighting=sample|cubature:weighting=sample"
    "weighting=average|cubature:weighting=average"
    "weighting=dotout|cubature:weighting=dotout"
    "formfactor|cubature:normalize=formfactor"
    "delaunay cp+bary|cubature:triangulation=delaunay,dynamic=cp+barycentre"
    "delaunay cp+np+mrp+bary|cubature:triangulation=delaunay,dynamic=cp+np+mrp+barycentre"
    "voronoi|voronoi"
)

# render NAME SPEC LUM H -> OUT/NAME.exr and OUT/NAME.json (render --json)
render() {
    "$LB" render --luminaire "$3" --method "$2" --height "$4" --rotation "$ROT" --res "$RES" \
        --out "$OUT/$1.exr" --json "${@:5}" >"$OUT/$1.json"
}
# nmse REF TEST
nmse() { "$LB" compare "$OUT/$1.exr" "$OUT/$2.exr" --json | jq -r .nmse; }
ms() { jq -r .time_ms.median "$OUT/$1.json"; }

ROWS="$OUT/rows.tsv"
: >"$ROWS"
for lum in "${LUMS[@]}"; do
    lname=${lum%%=*}
    lfile=${lum#*=}
    for h in 0.1 1.1; do
        tag="$lname-h$h"
        echo "$tag: reference" >&2
        render "$tag-ref" reference:tol=1e-4 "$lfile" "$h"
        # MC t(N): least-squares line through the fit points.
        fit=""
        for n in $MC_FIT; do
            render "$tag-mc$n" "mc:n=$n" "$lfile" "$h"
            fit="$fit $n:$(ms "$tag-mc$n")"
        done
        for v in "${VARIANTS[@]}"; do
            vname=${v%%|*}
            spec=${v#*|}
            key="$tag-$(echo "$vname" | tr -c 'a-zA-Z0-9\n' '_')"
            echo "$tag: $vname" >&2
            render "$key" "$spec" "$lfile" "$h"
            t=$(ms "$key")
            e=$(nmse "$tag-ref" "$key")
            tri=$(jq -r '.stats.triangles_per_pixel // "-"' "$OUT/$key.json")
            flp=$(jq -r '.stats.flips_per_pixel // "-"' "$OUT/$key.json")
            # N_eq from the line, at least 1; then verify by rendering MC there.
            neq=$(/usr/bin/python3 -c "
import sys
pts=[tuple(map(float,p.split(':'))) for p in '$fit'.split()]
n=len(pts); sx=sum(p[0] for p in pts); sy=sum(p[1] for p in pts)
sxx=sum(p[0]**2 for p in pts); sxy=sum(p[0]*p[1] for p in pts)
b=(n*sxy-sx*sy)/(n*sxx-sx*sx); a=(sy-b*sx)/n
print(max(1, round(($t-a)/b)))")
            render "$key-mceq" "mc:n=$neq" "$lfile" "$h"
            printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$lname" "$h" "$vname" "$t" "$e" "$tri" "$flp" \
                "$neq" "$(ms "$key-mceq")" "$(nmse "$tag-ref" "$key-mceq")" >>"$ROWS"
        done
        echo "$tag: MC fit$fit" >>"$OUT/mcfit.txt"
    done
done

dev=$(jq -r .device "$OUT/$(ls "$OUT" | grep -m1 'ref.json$')")
echo "Device: $dev; res ${RES}x${RES}, R = 3pi/4, float, reference tol 1e-4; median of 5 device-event times; $(date -u +%Y-%m-%d)."
echo
/usr/bin/python3 - "$ROWS" <<'PY'
import sys
print("| luminaire | h | variant | time_ms | NMSE | tri/px | flips/px | N_eq | MC time_ms | NMSE MC@N_eq |")
print("|---|---|---|---|---|---|---|---|---|---|")
def f(x, fmt):
    try: return fmt.format(float(x))
    except ValueError: return x
for line in open(sys.argv[1]):
    l, h, v, t, e, tri, fl, n, tm, em = line.rstrip("\n").split("\t")
    print(f"| {l} | {h} | {v} | {f(t,'{:.2f}')} | {f(e,'{:.3e}')} | {f(tri,'{:.2f}')} | {f(fl,'{:.3f}')} | {n} | {f(tm,'{:.2f}')} | {f(em,'{:.3e}')} |")
PY
