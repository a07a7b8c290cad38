#!/usr/bin/env python3
"""convert --simplify D on the corpus's STEP/IGES files and on parts of the part library (issue 15).

For every file: D = 0.001 x the bounding-box diagonal (as `cadnurbs info` prints it); the file is
converted to .x3dv twice, plainly and with --simplify D, and the table gets control points before and
after (from the --simplify summary line), the .x3dv bytes of both, the certified deviation against D, and
the open edges of the mesh at D (the compact form sewn and meshed, before and after) as watertightness.

usage: bench/simplify_table.py [--cadnurbs build/converters/cadnurbs] [--corpus ../shared/corpus]
                               [--library /tmp/kicad-step] [--per-family 2] [--extra 2]
                               [--skip-above BYTES] [--out DIR] [--only FILE ...]
Standard library only. Run it nice'd: nice -n 19 python3 bench/simplify_table.py
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import time

SUMMARY = re.compile(
    r"simplified within (?P<d>\S+) \S+ \(faces moved by at most (?P<move>\S+), (?P<attempts>\d+) attempts?(?:; \d+ repeated parts placed as copies first)?\): "
    r"(?P<knots>\d+) knots removed .*?control points (?P<before>\d+) -> (?P<after>\d+), certified deviation "
    r"(?P<dev>\S+) .*?meshed at \S+: (?P<open_before>\d+) open edges \((?P<len_before>\S+) \S+\) before, "
    r"(?P<open_after>\d+) open edges \((?P<len_after>\S+) \S+\) after, (?P<unshared>\d+) unshared")
BOX = re.compile(r"bounding box \(control points and vertices\):\s+(\S+)\s+(\S+)\s+(\S+)\s+to\s+(\S+)\s+(\S+)\s+(\S+)")


def corpus_files(corpus, skip_above):
    listed, skipped = [], []
    with open(os.path.join(corpus, "MANIFEST.tsv")) as manifest:
        next(manifest)
        for line in manifest:
            path, size = line.split("\t")[:2]
            if not re.search(r"\.(stp|step|igs|iges)$", path, re.I):
                continue
            (skipped if int(size) > skip_above else listed).append(os.path.join(corpus, path))
    return listed, skipped


def library_parts(library, per_family, extra):
    """Evenly spaced parts of each family (sorted by name), per_family each; `extra` families one more."""
    parts = []
    if not os.path.isdir(library):
        return parts
    families = sorted(d for d in os.listdir(library) if os.path.isdir(os.path.join(library, d)))
    for k, family in enumerate(families):
        names = sorted(n for n in os.listdir(os.path.join(library, family)) if re.search(r"\.(stp|step)$", n, re.I))
        want = min(len(names), per_family + (1 if k < extra else 0))
        for q in range(want):
            parts.append(os.path.join(library, family, names[(2 * q + 1) * len(names) // (2 * want)]))
    return parts


def run(command):
    started = time.time()
    done = subprocess.run(command, capture_output=True, text=True)
    return done, time.time() - started


def measure(cadnurbs, path, out_dir):
    row = {"file": os.path.relpath(path, os.path.dirname(os.path.dirname(path)))}
    info, _ = run([cadnurbs, "info", path])
    box = BOX.search(info.stdout)
    if info.returncode != 0 or not box:
        row["error"] = (info.stderr.strip().splitlines() or ["info failed"])[-1]
        return row
    lo, hi = [float(x) for x in box.groups()[:3]], [float(x) for x in box.groups()[3:]]
    d = 1e-3 * sum((b - a) ** 2 for a, b in zip(lo, hi)) ** 0.5
    base = os.path.join(out_dir, os.path.basename(path))
    plain, _ = run([cadnurbs, "convert", path, "-o", base + ".x3dv"])
    if plain.returncode != 0:
        row["error"] = (plain.stderr.strip().splitlines() or ["convert failed"])[-1]
        return row
    simple, seconds = run([cadnurbs, "convert", path, "-o", base + ".simplified.x3dv", "--simplify", "%.6g" % d])
    row["seconds"] = seconds
    found = SUMMARY.search(simple.stdout)
    if not found:
        row["error"] = (simple.stderr.strip().splitlines() or ["no summary"])[-1]
        return row
    row.update({k: found.group(k) for k in found.groupdict()})
    row["D"] = d
    row["ok"] = simple.returncode == 0
    if not row["ok"]:
        row["error"] = simple.stderr.strip().splitlines()[-1]
    row["bytes_before"] = os.path.getsize(base + ".x3dv")
    row["bytes_after"] = os.path.getsize(base + ".simplified.x3dv") if row["ok"] else None
    for name in (base + ".x3dv", base + ".simplified.x3dv"):
        if os.path.exists(name):
            os.remove(name)
    return row


def watertight(row):
    if int(row["open_before"]) == 0:
        return "yes" if int(row["open_after"]) == 0 else "NO"
    same = row["open_after"] == row["open_before"] and row["len_after"] == row["len_before"]
    return "open as input (%s edges%s)" % (row["open_before"], "" if same else ", now " + row["open_after"])


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser()
    parser.add_argument("--cadnurbs", default=os.path.join(here, "..", "build", "converters", "cadnurbs"))
    parser.add_argument("--corpus", default=os.path.join(here, "..", "..", "shared", "corpus"))
    parser.add_argument("--library", default="/tmp/kicad-step")
    parser.add_argument("--per-family", type=int, default=2)
    parser.add_argument("--extra", type=int, default=2)
    parser.add_argument("--skip-above", type=int, default=1_000_000, help="corpus files larger than this are left out")
    parser.add_argument("--out", default="/tmp/simplify_table")
    parser.add_argument("--only", nargs="+", help="these files instead of the corpus and the library")
    a = parser.parse_args()
    os.makedirs(a.out, exist_ok=True)
    # A copy of the binary: the build folder's may be relinked by a build while the table runs.
    # (A binary being linked is not executable yet: wait for the link to end.)
    for _ in range(60):
        if os.access(a.cadnurbs, os.X_OK):
            break
        time.sleep(5)
    cadnurbs = os.path.join(a.out, "cadnurbs")
    shutil.copy2(a.cadnurbs, cadnurbs)
    if a.only:
        files, skipped = a.only, []
    else:
        files, skipped = corpus_files(a.corpus, a.skip_above)
        files += library_parts(a.library, a.per_family, a.extra)
    print("| file | D | control points | .x3dv bytes | certified deviation | moved at most | watertight (mesh at D) | s |")
    print("|---|---|---|---|---|---|---|---|")
    for path in files:
        row = measure(cadnurbs, path, a.out)
        if "knots" not in row:
            print("| %s | | | | | | failed: %s | |" % (row["file"], row["error"]), flush=True)
            continue
        saved = "%s -> %s" % (row["before"], row["after"])
        size = "%d -> %s" % (row["bytes_before"], row["bytes_after"] if row["ok"] else "(none: " + row["error"] + ")")
        print("| %s | %.3g | %s | %s | %s%s | %s (%s attempt%s) | %s | %.1f |" % (
            row["file"], row["D"], saved, size, row["dev"], "" if float(row["dev"]) <= row["D"] else " > D",
            row["move"], row["attempts"], "" if row["attempts"] == "1" else "s", watertight(row), row["seconds"]), flush=True)
    if skipped:
        print("\nleft out (over %d bytes): %s" % (a.skip_above, ", ".join(os.path.relpath(p, a.corpus) for p in skipped)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
