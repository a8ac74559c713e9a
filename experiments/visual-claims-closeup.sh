#!/usr/bin/env bash
# visual-claims-closeup.sh -- the close-up image grid of docs/studies/visual-claims.md (the
# thesis' Fig. 6.11): ARCOS at h = 0.1, R = 3pi/4, the 2 m x 2 m square below the
# light, for the reference, SCT, voronoi, Delaunay with extra points, MCI-24, MCI-40
# and MCI at the time of SCT. One tone-mapping scale k for every row (that of the
# reference's mean), one error bound (the largest |error| of SCT) for every error
# picture, so that rows compare by eye.
#
#   experiments/visual-claims-closeup.sh N_EQ [OUT.png] [WORKDIR]
#
# N_EQ: MC's sample count at SCT's time (the `n` of the MCI-eq record of ARCOS,
# h 0.1, 3pi/4 in the run of experiments/visual-claims.json). Defaults:
# docs/figures/visual-claims-arcos.png, /tmp/lb-visual-closeup. Needs
# build/lumibench, jq and /usr/bin/python3 with matplotlib; the reference is
# cached ($LUMIBENCH_CACHE), so a rerun takes seconds.
set -euo pipefail
cd "$(dirname "$0")/.."
LB=${LB:-build/lumibench}
N_EQ=${1:?usage: visual-claims-closeup.sh N_EQ [OUT.png] [WORKDIR]}
[[ $N_EQ =~ ^[1-9][0-9]*$ ]] || { echo "visual-claims-closeup.sh: N_EQ must be a positive integer, got '$N_EQ'" >&2; exit 2; }
PNG=${2:-docs/figures/visual-claims-arcos.png}
W=${3:-/tmp/lb-visual-closeup}
LUM=../shared/luminaires/zumtobel/ARCOS3_60712332.LDT
[[ -f $LUM ]] || { echo "visual-claims-closeup.sh: $LUM not found (../shared beside the checkout)" >&2; exit 2; }
mkdir -p "$W"
SCENE=(--luminaire "$LUM" --height 0.1 --rotation 3pi/4 --extent 2 --res 256 --reps 1)

ROWS=(
    "SCT|cubature"
    "voronoi|voronoi"
    "Delaunay+|cubature:triangulation=delaunay,dynamic=cp+np+mrp+barycentre"
    "MCI-24|mc:n=24"
    "MCI-40|mc:n=40"
    "MCI-$N_EQ (SCT's time)|mc:n=$N_EQ"
)
"$LB" render "${SCENE[@]}" --method reference:tol=1e-4 --out "$W/reference.exr" >&2
for row in "${ROWS[@]}"; do
    spec=${row#*|}
    "$LB" render "${SCENE[@]}" --method "$spec" --out "$W/${spec//[:=,+]/_}.exr" >&2
done
# One scale for every picture: k = 1 / mean(reference); one error bound: SCT's largest |error|.
first="$W/cubature.exr"
j=$("$LB" compare "$W/reference.exr" "$first" --json)
K=$(jq -r '1 / .mean_ref' <<<"$j")
B=$(jq -r '[.ueb, -.leb] | max' <<<"$j")
args=()
for row in "${ROWS[@]}"; do
    label=${row%%|*}
    spec=${row#*|}
    p="$W/${spec//[:=,+]/_}"
    "$LB" compare "$W/reference.exr" "$p.exr" --json --k "$K" --bound "$B" --png "$p" > "$p.json"
    args+=("$label=$p")
done
/usr/bin/python3 plots/image_grid.py --out "$PNG" \
    --title "ARCOS, h 0.1, R 3pi/4: the 2 m x 2 m below the light (256 x 256)" "${args[@]}"
echo "$PNG" >&2
