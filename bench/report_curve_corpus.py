#!/usr/bin/env python3
"""Issue 39's curve check: `cadnurbs report FILE --curve` on each file, then, at every D the report measured,
.cnb against Draco and meshoptimizer (each the smaller of its raw and gzip'd bytes, as the report delivers).

    report_curve_corpus.py CADNURBS OUT_DIR [--timeout SECONDS] FILE...

Writes OUT_DIR/<file name>.md (the report) and prints one tab-separated line per file and D:

    file  D  cnb  draco  meshopt  cnb_below_both

("-" where a codec has no figure at that D; "no mesh figure", not counted, where neither has), then a
summary: files done, files that timed out or failed, the (file, D) points where .cnb is below both, and
where it is not.
"""
import os
import subprocess
import sys


def curve_rows(markdown):
    """(representation, D, delivered bytes) from the report's storage-against-accuracy table."""
    rows, inside = [], False
    for line in markdown.splitlines():
        if line.startswith("| representation | D | bytes | gzip'd | floats |"):
            inside = True
            continue
        if inside:
            if not line.startswith("|"):
                if rows:
                    break
                continue
            cells = [c.strip() for c in line.strip("|").split("|")]
            if cells[0].startswith("---"):
                continue
            rows.append((cells[0], float(cells[1]), min(int(cells[2]), int(cells[3]))))
    return rows


def main(argv):
    if len(argv) < 4:
        sys.exit(__doc__)
    cadnurbs, out_dir, rest = argv[1], argv[2], argv[3:]
    timeout = 1200
    if rest and rest[0] == "--timeout":
        timeout, rest = int(rest[1]), rest[2:]
    os.makedirs(out_dir, exist_ok=True)
    done, failed, below, not_below = 0, [], 0, []
    for path in rest:
        name = os.path.basename(path)  # with its extension: goteborg.step and goteborg.iges both
        out = os.path.join(out_dir, name + ".md")
        try:
            run = subprocess.run([cadnurbs, "report", path, "--curve", "-o", out], capture_output=True, text=True,
                                 timeout=timeout)
        except subprocess.TimeoutExpired:
            failed.append(f"{name}: over {timeout} s")
            continue
        if run.returncode != 0:
            failed.append(f"{name}: exit {run.returncode}: {run.stderr.strip().splitlines()[-1:]}")
            continue
        done += 1
        by_d = {}
        for key, d, size in curve_rows(open(out).read()):
            by_d.setdefault(d, {})[key] = size
        for d in sorted(by_d, reverse=True):
            sizes = by_d[d]
            if "cnb" not in sizes:
                continue
            meshes = [sizes[k] for k in ("draco", "meshopt") if k in sizes]
            cells = [str(sizes.get(k, "-")) for k in ("cnb", "draco", "meshopt")]
            if not meshes:  # the report made no mesh file at this D
                print("\t".join([name, f"{d:g}"] + cells + ["no mesh figure"]), flush=True)
                continue
            ok = all(sizes["cnb"] < m for m in meshes)
            print("\t".join([name, f"{d:g}"] + cells + ["yes" if ok else "no"]), flush=True)
            if ok:
                below += 1
            else:
                not_below.append(f"{name} at D = {d:g}")
    print(f"\n{done} files reported, {len(failed)} not: " + "; ".join(failed))
    print(f".cnb below both mesh codecs at {below} of {below + len(not_below)} (file, D) points"
          + ("; not at: " + ", ".join(not_below) if not_below else ""))


if __name__ == "__main__":
    main(sys.argv)
