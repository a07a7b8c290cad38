#!/usr/bin/env python3
"""conversion_times: seconds of `cadnurbs convert` per file and output kind, one process each, the kinds
of a file run one after another (A B C D, then the next file), so that they share the machine's state.

Inputs: every STEP/IGES/3DM file of ../shared/corpus (--corpus), or every STEP model of the nine part
library families under the KiCad cache (--library, the families of library_sizes.py). Kinds (--kinds):
  mesh  convert F --mesh -o F-mesh.wrl   (the certified mesh at convert's default D)
  cnb   convert F -o F.cnb
  x3dv  convert F -o F.x3dv                (NURBS with the viewer hints)
  wrl   convert F -o F.wrl                 (VRML97 NURBS)
Writes OUT/conversion_times.md (a row per file: seconds per kind, best of --repeat, and the ratios
x3dv/mesh and x3dv/cnb) and OUT/conversion_times.tsv; prints the totals and the largest ratios.

Run (not part of ctest):
  bench/conversion_times.py --cadnurbs build/converters/cadnurbs --corpus --out /tmp/times
  bench/conversion_times.py --cadnurbs build/converters/cadnurbs --library --kinds cnb,x3dv --out /tmp/lib
  (--first K --count N: files K .. K+N-1 only, to split the library over processes, one per core.)
Standard library only.
"""
import argparse
import subprocess
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from library_sizes import FAMILIES  # noqa: E402

CORPUS = Path(__file__).resolve().parent.parent.parent / "shared" / "corpus"
LIBRARY = Path.home() / ".cache" / "cadnurbs" / "kicad-packages3d-6.0.10-1"
KINDS = {"mesh": ("-mesh.wrl", ["--mesh"]), "cnb": (".cnb", []), "x3dv": (".x3dv", []), "wrl": (".wrl", [])}


def corpus_files():
    rows = [line.split("\t")[0] for line in (CORPUS / "MANIFEST.tsv").read_text().splitlines()[1:]]
    return [CORPUS / r for r in rows if r.lower().endswith((".step", ".stp", ".iges", ".igs", ".3dm"))]


def library_files():
    return [p for family in FAMILIES for p in sorted((LIBRARY / f"{family}.3dshapes").glob("*.step"))]


def timed(cadnurbs, source, output, extra, timeout):
    start = time.monotonic()
    try:
        done = subprocess.run([cadnurbs, "convert", str(source), "-o", str(output)] + extra,
                              capture_output=True, text=True, timeout=timeout)
        return time.monotonic() - start, done.returncode, done.stderr.strip().splitlines()[-1:]
    except subprocess.TimeoutExpired:
        return float("inf"), None, ["timeout"]
    finally:
        Path(output).unlink(missing_ok=True)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--cadnurbs", required=True)
    parser.add_argument("--out", required=True)
    which = parser.add_mutually_exclusive_group(required=True)
    which.add_argument("--corpus", action="store_true")
    which.add_argument("--library", action="store_true")
    parser.add_argument("--kinds", default="mesh,cnb,x3dv,wrl")
    parser.add_argument("--every", type=int, default=1, help="every k-th file only")
    parser.add_argument("--first", type=int, default=0, help="start at the file of this index (split a run over processes)")
    parser.add_argument("--count", type=int, default=None, help="at most this many files")
    parser.add_argument("--repeat", type=int, default=1)
    parser.add_argument("--timeout", type=float, default=120)
    args = parser.parse_args()
    kinds = args.kinds.split(",")
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    files = (corpus_files() if args.corpus else library_files())[:: args.every][args.first:]
    files = files[: args.count] if args.count is not None else files
    header = ["file"] + [k + " (s)" for k in kinds]
    ratios = [(a, b) for a, b in (("x3dv", "mesh"), ("x3dv", "cnb")) if a in kinds and b in kinds]
    header += [f"{a} / {b}" for a, b in ratios] + ["notes"]
    lines = ["| " + " | ".join(header) + " |", "|---|" + "---:|" * (len(header) - 2) + "---|"]
    tsv = ["\t".join(["file"] + kinds)]
    totals = {k: 0.0 for k in kinds}
    worst = {r: (0.0, "") for r in ratios}
    over = {r: 0 for r in ratios}
    for source in files:
        best, notes = {}, set()
        for _ in range(args.repeat):
            for kind in kinds:
                suffix, extra = KINDS[kind]
                seconds, status, message = timed(args.cadnurbs, source, out / (source.stem + suffix), extra, args.timeout)
                best[kind] = min(best.get(kind, float("inf")), seconds)
                if status != 0 and message:
                    notes.add(f"{kind}: {message[0][-90:]}")
        name = f"{source.parent.name}/{source.name}"
        cells = [f"{best[k]:.2f}" for k in kinds]
        for r in ratios:
            value = best[r[0]] / best[r[1]] if best[r[1]] > 0 else float("nan")
            cells.append(f"{value:.2f}")
            if value > worst[r][0]:
                worst[r] = (value, name)
            over[r] += value > 2.0
        for k in kinds:
            totals[k] += best[k]
        line = "| " + " | ".join([name] + cells + ["; ".join(sorted(notes))]) + " |"
        print(line, flush=True)
        lines.append(line)
        tsv.append("\t".join([name] + [f"{best[k]:.3f}" for k in kinds]))
    summary = [f"{len(files)} files; total seconds: " + ", ".join(f"{k} {totals[k]:.1f}" for k in kinds)]
    for a, b in ratios:
        summary.append(f"{a} / {b}: total {totals[a] / totals[b]:.2f}, largest {worst[(a, b)][0]:.2f} "
                       f"({worst[(a, b)][1]}), files over 2x: {over[(a, b)]}")
    lines += [""] + summary
    (out / "conversion_times.md").write_text("\n".join(lines) + "\n")
    (out / "conversion_times.tsv").write_text("\n".join(tsv) + "\n")
    print("\n".join(summary))


if __name__ == "__main__":
    main()
