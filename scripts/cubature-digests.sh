#!/usr/bin/env bash
# Renders the cubature's straight-line forms (fan, Delaunay over corners + CP
# + barycentre, over every dynamic point, with static samples; 1 and 8 lanes,
# float and double, lut and exact lookup, clip, blends, options) and the
# general kernel on two scenes, and prints the sha256 of each EXR with the
# kernel form, its triangles and flips per pixel and its defines: the check
# that a kernel change leaves every image bit for bit as it was (diff two
# runs' outputs).
#
#   scripts/cubature-digests.sh [OUTDIR]      (default /tmp/lb-cubature-digests)
#
# LB=path picks the program (default build/lumibench); LUMIBENCH_KERNEL_DIR
# the kernel sources, so that one build renders two kernel trees (set
# POCL_CACHE_DIR apart for each). Needs jq.
set -euo pipefail
cd "$(dirname "$0")/.."
LB=${LB:-build/lumibench}
OUT=${1:-/tmp/lb-cubature-digests}
mkdir -p "$OUT"

DA="triangulation=delaunay,dynamic=cp+barycentre"
DALL="triangulation=delaunay,dynamic=cp+np+mrp+barycentre"
DST="triangulation=delaunay"
OPTS="weighting=dotout,normalize=formfactor,corner_inset=0.2,dyn_weight=1.5"
SPECS=(
    "cubature" "cubature:lanes=1" "cubature:lookup=exact" "cubature:weighting=sample,normalize=formfactor"
    "cubature:weighting=dotout,dynamic=none,blend_dist=2" "cubature:area=gauss3,horizon_eps=0.3"
    "cubature:$DA" "cubature:$DA,lanes=1,$OPTS" "cubature:$DA,area=gauss2,blend_dist=2,horizon_eps=0.3"
    "cubature:$DALL" "cubature:$DALL,lanes=1,horizon_eps=0.3" "cubature:$DALL,$OPTS,blend_dist=2"
    "cubature:$DST,static=1" "cubature:$DST,static=1,lanes=1,$OPTS" "cubature:$DST,static=3,blend_dist=2"
    "cubature:$DST,static=4,lanes=1" "cubature:specialize=none,$DALL"
)
DOUBLE_SPECS=("cubature:$DA" "cubature:$DALL,horizon_eps=0.3" "cubature:$DST,static=3")
# name luminaire height rotation (b: the horizon_eps=0.3 specs clip the vertical light along u)
SCENES=("a luminaires/grazing.ldt 0.1 3pi/4" "b luminaires/downlight.ldt 0.1 pi/2")

render() { # tag spec lum h rot precision
    "$LB" render --luminaire "$3" --method "$2" --height "$4" --rotation "$5" --res 61 --extent 4 \
        --precision "$6" --out "$OUT/$1.exr" --json >"$OUT/$1.json"
    printf '%s  %s  %s %s  %s\n' "$(sha256sum "$OUT/$1.exr" | cut -c1-16)" "$6" "$2" "${3##*/}:$4:$5" \
        "$(jq -r '[.stats.form, .stats.triangles_per_pixel, .stats.flips_per_pixel, .stats.defines] | map(tostring) | join(" ")' "$OUT/$1.json")"
}
n=0
for sc in "${SCENES[@]}"; do
    read -r name lum h rot <<<"$sc"
    for spec in "${SPECS[@]}"; do
        n=$((n + 1))
        render "$name-$n" "$spec" "$lum" "$h" "$rot" float
    done
    for spec in "${DOUBLE_SPECS[@]}"; do
        n=$((n + 1))
        render "$name-$n" "$spec" "$lum" "$h" "$rot" double
    done
done
