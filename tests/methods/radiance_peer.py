"""Irradiance of the normalized evaluation scene (docs/design.md section 2) computed by
Radiance (PyPI `pyradiance`, which bundles ies2rad, oconv and rtrace), the
lighting-simulation system the paper cites, as a peer of lumibench's `reference`.

    radiance_peer.py LUMIBENCH LUMINAIRE W L HEIGHT ROTATION RES EXTENT [rect|disk]

prints RES x RES values of E in lux, row by row (row 0 at the top, docs/design.md
section 2), one per line. Exit 3 when pyradiance is not installed.

The light: the luminaire's unfolded table (`lumibench luminaire dump`) written as a
full 0-360 IES table of absolute candela (ies2rad mirrors files whose horizontal
angles run 90-270, so it is never given one), turned into Radiance's `brightdata`
by ies2rad, on a W x L rectangle of our own: 16 x 16 polygons (Radiance splits one
source into at most 64 parts, too few near the light), multiplier 1 / (W L) as
ies2rad sets for its own opening. A disk (the ellipse inscribed in W x L): 16
equal-area rings of 128 sectors on the 128-gon scaled to the ellipse's area,
multiplier 4 / (pi W L). Near a large disk that is coarse: 0.6 m under a 1 m disk
of quadrant.ldt Radiance gives 768.3, 764.0, 762.9 lx with 8 x 64, 16 x 128 and
32 x 256 pieces (the reference: 762.3); finer pieces fail on small disks (32 x
256 on an 80 mm disk: 30 % off), so the test keeps to distances where 16 x 128
converges. ies2rad's frame is ours at R = pi (gamma = 0
along -z, C0 along +x, C90 along +y), so the scene is that light turned by pi - R
about x and lifted to the centre (0, 0, h + L/2).

The receiver: rtrace -I evaluates 1e-4 m along the normal, so the points are given
1e-4 m below the floor. Radiance's light is in W/sr/m^2 of 179 lm/W (ies2rad
divides candela by 179): E = 179 R for a white source.
"""
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile

SUB = 16  # polygons per side of the light
RINGS, SECTORS = 16, 128  # of a disk
WHITE_EFFICACY = 179.0


def radiance_bin():
    try:
        import pyradiance
    except ImportError:
        return None
    d = os.path.join(os.path.dirname(pyradiance.__file__), "bin")
    return d if os.path.exists(os.path.join(d, "rtrace")) else None


def read_tilt(path):
    """The TILT=INCLUDE block of an IES file as its lines (geometry, count, angles,
    factors), or None: Radiance applies it through ies2rad's tilt.cal, by the
    light's orientation in the scene (acos of its z axis's z after xform)."""
    if not path.lower().endswith(".ies"):
        return None
    with open(path, encoding="latin-1") as f:
        lines = f.read().splitlines()
    at = next((i for i, t in enumerate(lines) if t.strip().startswith("TILT=")), None)
    if at is None or lines[at].strip() != "TILT=INCLUDE":
        return None
    words = " ".join(lines[at + 1:]).split()
    n = int(words[1])
    return [words[0], str(n), " ".join(words[2:2 + n]), " ".join(words[2 + n:2 + 2 * n])]


def write_ies(table, path, w, l, tilt=None):
    """The unfolded table as an LM-63 file of absolute candela, every C plane, on a
    flat W x L rectangle (length W along C0, width L along C90), so that ies2rad
    writes the flat source's correction 1 / cos (a point would be a sphere); the
    file's TILT=INCLUDE block where it has one."""
    c, g, cd = table["c"], table["gamma"], table["cd"]
    nc, ng = len(c), len(g)
    assert len(cd) == nc * ng, "luminaire dump: cd is C-major, |C| x |gamma|"
    lines = ["IESNA:LM-63-2002", "[TEST] lumibench radiance peer"]
    lines += ["TILT=INCLUDE"] + tilt if tilt else ["TILT=NONE"]
    # lamps, lumens (-1: absolute), multiplier, |gamma|, |C|, type C, units m, w l h
    lines.append(f"1 -1 1 {ng} {nc} 1 2 {l!r} {w!r} 0")
    lines.append("1 1 0")
    lines.append(" ".join(repr(float(x)) for x in g))
    lines.append(" ".join(repr(float(x)) for x in c))
    for i in range(nc):
        lines.append(" ".join(repr(float(x)) for x in cd[i * ng:(i + 1) * ng]))
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def light_pieces(w, l, shape):
    """The light's polygons in its plane z = 0, counter-clockwise seen from below, and its area."""
    if shape == "rect":
        pieces = []
        for i in range(SUB):
            for j in range(SUB):
                x0, x1 = -w / 2 + w * i / SUB, -w / 2 + w * (i + 1) / SUB
                y0, y1 = -l / 2 + l * j / SUB, -l / 2 + l * (j + 1) / SUB
                pieces.append([(x0, y0), (x0, y1), (x1, y1), (x1, y0)])
        return pieces, w * l
    # the 128-gon with the ellipse's area: radius scaled by sqrt(2 pi / (K sin(2 pi / K)))
    k = SECTORS
    scale = math.sqrt(2 * math.pi / (k * math.sin(2 * math.pi / k)))
    def at(r, a):
        return (scale * r * w / 2 * math.cos(a), scale * r * l / 2 * math.sin(a))
    pieces = []
    for i in range(RINGS):
        r0, r1 = math.sqrt(i / RINGS), math.sqrt((i + 1) / RINGS)  # equal-area rings
        for j in range(k):
            a0, a1 = 2 * math.pi * j / k, 2 * math.pi * (j + 1) / k
            v = [at(r0, a0), at(r0, a1), at(r1, a1), at(r1, a0)] if i else [(0.0, 0.0), at(r1, a1), at(r1, a0)]
            pieces.append(v)
    return pieces, math.pi * w * l / 4


def light_scene(dist_rad, w, l, shape="rect"):
    """ies2rad's brightdata with our light: its polygons facing -z."""
    out = []
    for line in dist_rad.splitlines():
        if line.strip().startswith("'out_light' polygon") or line.strip().startswith("out_light polygon"):
            break
        out.append(line)
    text = "\n".join(out)
    # the brightdata's one real argument is ies2rad's 1 / area: ours instead
    head, sep, rest = text.partition("\n1 ")
    assert sep, "ies2rad output: expected the brightdata multiplier line '1 M'"
    rest_lines = rest.split("\n", 1)
    pieces, area = light_pieces(w, l, shape)
    text = head + f"\n1 {1.0 / area!r}\n" + (rest_lines[1] if len(rest_lines) > 1 else "")
    polys = []
    for i, v in enumerate(pieces):
        # counter-clockwise seen from below: the normal is -z (gamma < 90); a
        # Radiance polygon emits on its front side only, so a twin facing +z,
        # 1e-6 m above, emits gamma > 90 (each hides the other's back)
        down = " ".join(f"{x!r} {y!r} 0" for x, y in v)
        up = " ".join(f"{x!r} {y!r} 1e-6" for x, y in reversed(v))
        polys.append(f"out_light polygon p{i}\n0\n0\n{3 * len(v)} {down}")
        polys.append(f"out_light polygon q{i}\n0\n0\n{3 * len(v)} {up}")
    return text + "\n" + "\n".join(polys) + "\n"


def main(argv):
    if len(argv) not in (9, 10) or (len(argv) == 10 and argv[9] not in ("rect", "disk")):
        sys.stderr.write(__doc__)
        return 2
    binary, lum = argv[1], argv[2]
    shape = argv[9] if len(argv) == 10 else "rect"
    w, l, h, rot = (float(x) for x in argv[3:7])
    res, extent = int(argv[7]), float(argv[8])
    rbin = radiance_bin()
    if rbin is None:
        sys.stderr.write("pyradiance is not installed\n")
        return 3
    env = dict(os.environ, PATH=rbin + os.pathsep + os.environ.get("PATH", ""))
    env["RAYPATH"] = os.pathsep.join([".", os.path.join(os.path.dirname(rbin), "lib")])
    table = json.loads(subprocess.run([binary, "luminaire", "dump", lum], check=True, capture_output=True,
                                      text=True).stdout)
    tmp = tempfile.mkdtemp(prefix="lb-radiance-")
    try:
        write_ies(table, os.path.join(tmp, "lum.ies"), w, l, read_tilt(lum))
        subprocess.run(["ies2rad", "-dm", "-c", "1", "1", "1", "-o", "out", "lum.ies"], cwd=tmp, env=env,
                       check=True, capture_output=True)
        with open(os.path.join(tmp, "out.rad")) as f:
            scene = light_scene(f.read(), w, l, shape)
        with open(os.path.join(tmp, "light.rad"), "w") as f:
            f.write(scene)
        turn = math.degrees(math.pi - rot)
        placed = subprocess.run(["xform", "-rx", repr(turn), "-t", "0", "0", repr(h + l / 2), "light.rad"],
                                cwd=tmp, env=env, check=True, capture_output=True, text=True).stdout
        with open(os.path.join(tmp, "scene.rad"), "w") as f:
            f.write(placed)
        with open(os.path.join(tmp, "scene.oct"), "wb") as f:
            subprocess.run(["oconv", "scene.rad"], cwd=tmp, env=env, check=True, stdout=f)
        pts = []
        for r in range(res):
            y = extent / 2 - (r + 0.5) * extent / res
            for c in range(res):
                x = -extent / 2 + (c + 0.5) * extent / res
                pts.append(f"{x!r} {y!r} -1e-4 0 0 1")
        # -ab 0: direct only; -dj 0: no jitter; -ds 0.01: split sources down to 1 % of the
        # distance (up to Radiance's 64 parts); -dt 0 -dc 1: every source, fully tested
        rt = subprocess.run(["rtrace", "-h", "-I", "-ab", "0", "-dj", "0", "-ds", "0.01", "-dt", "0", "-dc", "1",
                             "-ov", "scene.oct"], cwd=tmp, env=env, check=True, capture_output=True, text=True,
                            input="\n".join(pts) + "\n")
        vals = [WHITE_EFFICACY * float(line.split()[0]) for line in rt.stdout.splitlines() if line.strip()]
        if len(vals) != res * res:
            sys.stderr.write(f"rtrace gave {len(vals)} values for {res * res} points\n")
            return 1
        sys.stdout.write("\n".join(repr(v) for v in vals) + "\n")
        return 0
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
