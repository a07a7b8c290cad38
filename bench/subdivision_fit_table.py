#!/usr/bin/env python3
"""The Loop fit against quadric decimation on issue 11's nine parts (capping-90 and every corpus STL):
`cadnurbs fit-loop IN -o CONTROL.obj --control-vertices 200 [--connectivity]` on each part, one after the
other. Prints a markdown table: input triangles, control vertices, RMS and max two-sided distance of
the fitted limit surface and of the quadric decimation with as many vertices, their ratios (the issue
asks RMS <= 0.5 and max <= 1), which of fit_best_start's starts was kept, whether the last refit
(refit_watching_spans) was kept, and the CPU and wall seconds of each run.

usage: bench/subdivision_fit_table.py [--connectivity] [--cadnurbs BINARY] [--held-out OCCT_MESHER] [PART...]
(default binary: build/converters/cadnurbs, copied first since the build folder's may be relinked
meanwhile; default parts: the nine). Run at nice 0. With --connectivity a part takes some 15-20 plain
fits (the tray: 17 minutes of CPU), so give it the parts you want.

--held-out OCCT_MESHER: instead, the parts like issue 38 item 6's held-out meshes, made in a temporary
folder (nothing kept): a scanned vessel (a vase profile revolved, open rim, closed base, 0.04 mm noise)
and corpus STEP parts meshed by OpenCASCADE's BRepMesh at 1e-3 of their diagonal (OCCT_MESHER is
bench/occt_mesh_to_stl.cpp compiled; its header gives the command).
"""
import argparse
import math
import random
import struct
import os
import re
import resource
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CORPUS = os.path.join(os.path.dirname(ROOT), "shared", "corpus", "stl")
PARTS = [os.path.join(ROOT, "samples", "capping-90.stl")] + sorted(
    os.path.join(CORPUS, name) for name in os.listdir(CORPUS) if name.lower().endswith(".stl"))


HELD_OUT_STEP = ["screw.step", "io1-cm-214.stp", "dm1-id-214.stp", "base_interface_AP203.STEP", "io1-tu-203.stp",
                 "goteborg.step", "as1_pe_203.stp", "as1-tu-203.stp"]


def vessel_stl(path, seed=1, around=96, up=64, noise=0.04):
    """A scanned-vessel-like binary STL: a vase profile (height 120 mm) revolved, open at the rim, closed by
    a base of rings; every vertex moved by Gaussian noise of `noise` mm. Returns the triangle count."""
    rnd = random.Random(seed)
    height = 120.0

    def radius(z):
        t = z / height
        return 22 + 14 * math.sin(math.pi * t * 1.1) - 9 * math.exp(-((t - 0.85) / 0.08) ** 2)

    rows = []
    for j in range(up + 1):
        z = height * j / up
        row = []
        for i in range(around):
            a = 2 * math.pi * (i + 0.5 * (j % 2)) / around
            r = radius(z) + rnd.gauss(0, noise)
            row.append((r * math.cos(a), r * math.sin(a), z + rnd.gauss(0, noise)))
        rows.append(row)
    triangles = []
    for j in range(up):
        for i in range(around):
            a, b = rows[j][i], rows[j][(i + 1) % around]
            c, d = rows[j + 1][i], rows[j + 1][(i + 1) % around]
            triangles += [(a, b, c), (b, d, c)] if j % 2 == 0 else [(a, d, c), (a, b, d)]
    rings = [rows[0]]
    for k in range(1, 8):
        s = 1 - k / 8
        rings.append([(p[0] * s + rnd.gauss(0, noise), p[1] * s + rnd.gauss(0, noise), rnd.gauss(0, noise)) for p in rows[0]])
    for k in range(len(rings) - 1):
        for i in range(around):
            a, b = rings[k][i], rings[k][(i + 1) % around]
            c, d = rings[k + 1][i], rings[k + 1][(i + 1) % around]
            triangles += [(a, c, b), (b, c, d)]
    for i in range(around):
        triangles.append((rings[-1][i], (0.0, 0.0, 0.0), rings[-1][(i + 1) % around]))
    with open(path, "wb") as f:
        f.write(b"vessel".ljust(80, b" ") + struct.pack("<I", len(triangles)))
        for t in triangles:
            f.write(struct.pack("<3f", 0, 0, 0) + b"".join(struct.pack("<3f", *p) for p in t) + b"\0\0")
    return len(triangles)


def held_out_parts(folder, mesher):
    """The vessel and the STEP parts meshed by OpenCASCADE, written into folder; returns their paths."""
    parts = [os.path.join(folder, "vessel.stl")]
    vessel_stl(parts[0])
    step = os.path.join(os.path.dirname(ROOT), "shared", "corpus", "step")
    for name in HELD_OUT_STEP:
        parts.append(os.path.join(folder, os.path.splitext(name)[0] + "_occt.stl"))
        subprocess.run([mesher, os.path.join(step, name), parts[-1], "1e-3"], check=True)
    return parts


def fit(binary, part, folder, connectivity):
    """One fit-loop run; returns its figures and times."""
    args = [binary, "fit-loop", part, "-o", os.path.join(folder, "control.obj"), "--control-vertices", "200"]
    if connectivity:
        args.append("--connectivity")
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    out = subprocess.run(args, capture_output=True, text=True, check=True).stdout
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    number = r"([-+0-9.e]+)"
    triangles = re.search(r": (\d+) triangles, \d+ welded vertices", out)
    control = re.search(r"control mesh: (\d+) vertices", out)
    limit = re.search(r"limit surface .* RMS " + number + r" \S+, max " + number, out)
    qem = re.search(r"quadric decimation .* RMS " + number + r" \S+, max " + number, out)
    start = re.search(r"^start kept: (\w+)", out, re.M)
    last = re.search(r"^last refit .*; (kept|not kept)", out, re.M)
    return {
        "triangles": int(triangles.group(1)), "control": int(control.group(1)),
        "rms": float(limit.group(1)), "max": float(limit.group(2)),
        "qem_rms": float(qem.group(1)), "qem_max": float(qem.group(2)),
        "start": {"features": "features kept", "plain": "plain, tagged", "guarded": "guarded, balanced"}[start.group(1)] if start else "",
        "last_refit": last.group(1) if last else "",
        "wall": wall, "cpu": (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime),
    }


def main():
    parser = argparse.ArgumentParser(description="fit-loop against quadric decimation, as a markdown table")
    parser.add_argument("--connectivity", action="store_true", help="run fit-loop with --connectivity")
    parser.add_argument("--cadnurbs", default=os.path.join(ROOT, "build", "converters", "cadnurbs"))
    parser.add_argument("--held-out", metavar="OCCT_MESHER", help="fit the held-out-like parts instead")
    parser.add_argument("parts", nargs="*", default=PARTS)
    options = parser.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        if options.held_out:
            options.parts = held_out_parts(folder, options.held_out)
        binary = os.path.join(folder, "cadnurbs")
        shutil.copy2(options.cadnurbs, binary)
        print("| part | input triangles | control vertices | fit RMS | fit max | QEM RMS | QEM max "
              "| RMS ratio | max ratio | passes | start kept | last refit | CPU s (wall s) |")
        print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
        for part in options.parts:
            f = fit(binary, part, folder, options.connectivity)
            rms_ratio, max_ratio = f["rms"] / f["qem_rms"], f["max"] / f["qem_max"]
            print(f"| {os.path.basename(part)} | {f['triangles']} | {f['control']} | {f['rms']:.4g} | {f['max']:.4g} "
                  f"| {f['qem_rms']:.4g} | {f['qem_max']:.4g} | {rms_ratio:.3f} | {max_ratio:.3f} "
                  f"| {'yes' if rms_ratio <= 0.5 and max_ratio <= 1 else 'no'} | {f['start']} | {f['last_refit']} | {f['cpu']:.0f} ({f['wall']:.0f}) |",
                  flush=True)


if __name__ == "__main__":
    main()
