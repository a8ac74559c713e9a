#!/usr/bin/env bash
# Regenerates the suite's own luminaires (luminaires/*.ldt, *.ies) with
# `lumibench luminaire synth`. Run from the repository root after a build.
set -euo pipefail
bin=${LUMIBENCH:-build/lumibench}
out=luminaires
for kind in lambert spot downlight linear diffuse batwing sideways updown grazing pencil quadrant; do
  for ext in ldt ies; do "$bin" luminaire synth "$kind" --out "$out/$kind.$ext" >/dev/null; done
done
# Phong cos^n with n = 10 (flux 1000 lm like all the others).
for ext in ldt ies; do "$bin" luminaire synth phong --n 10 --out "$out/phong10.$ext" >/dev/null; done
ls "$out"
