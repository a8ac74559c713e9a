"""What the mc-baselines scripts share: build/lumibench's render and compare
(argument lists, no shell), atomic JSON files, HEIGHT:ROTATION scene lists."""
import json
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BIN = os.path.join(ROOT, "build", "lumibench")
ZUMTOBEL = os.path.join(ROOT, "..", "shared", "luminaires", "zumtobel")


def render(lum, h, rot, spec, res, out, reps=1):
    """Renders spec into the EXR file out; returns lumibench's JSON record (time_ms, ...)."""
    cmd = [BIN, "render", "--luminaire", lum, "--method", spec, "--height", str(h), "--rotation", rot,
           "--res", str(res), "--reps", str(reps), "--out", out, "--json"]
    r = subprocess.run(cmd, check=True, capture_output=True, text=True)
    return json.loads(r.stdout)


def nmse(ref, test):
    r = subprocess.run([BIN, "compare", ref, test, "--json"], check=True, capture_output=True, text=True)
    return json.loads(r.stdout)["nmse"]


def write_json(path, doc):
    """Writes doc to path atomically (a temporary file in the same directory, renamed)."""
    tmp = f"{path}.tmp{os.getpid()}"
    with open(tmp, "w") as f:
        json.dump(doc, f, indent=1)
        f.flush()
        os.fsync(f.fileno())
    os.replace(tmp, path)


def parse_scenes(text, prog):
    """'0.1:3pi/4,1.1:pi/2' -> [(0.1, '3pi/4'), (1.1, 'pi/2')]; exits with status 2 on bad input."""
    scenes = []
    for item in text.split(","):
        h, _, rot = item.partition(":")
        try:
            scenes.append((float(h), rot))
        except ValueError:
            scenes = None
        if scenes is None or not rot:
            print(f"{prog}: --scenes: '{item}' is not HEIGHT:ROTATION (e.g. 0.1:3pi/4)", file=sys.stderr)
            sys.exit(2)
    return scenes
