#!/usr/bin/env python3
"""The Loop fit against quadric decimation on issue 11's nine parts (capping-90 and every corpus STL):
`cadnurbs fit-loop IN -o CONTROL.obj --control-vertices 200 [--connectivity]` on each part, one after the
other. Prints a markdown table: input triangles, control vertices, RMS and max two-sided distance of
the fitted limit surface and of the quadric decimation with as many vertices, their ratios (the issue
asks RMS <= 0.5 and max <= 1), which of fit_best_start's starts was kept, whether the last refit
(refit_watching_spans) was kept, and the CPU and wall seconds of each run.

usage: bench/subdivision_fit_table.py [--connectivity] [--cadnurbs BINARY] [PART...]
(default binary: build/converters/cadnurbs, copied first since the build folder's may be relinked
meanwhile; default parts: the nine). Run at nice 0. With --connectivity a part takes some 15-20 plain
fits (the tray: 17 minutes of CPU), so give it the parts you want.
"""
import argparse
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
    parser.add_argument("parts", nargs="*", default=PARTS)
    options = parser.parse_args()
    with tempfile.TemporaryDirectory() as folder:
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
