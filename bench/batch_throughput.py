#!/usr/bin/env python3
"""batch_throughput: `cadnurbs batch --jobs N` against FreeCAD's headless STEP -> VRML, on the same parts.

The parts: --parts N STEP models spread over the nine families of the part library (every k-th of the
sorted list, as library_sizes.py picks its FreeCAD sample), hard-linked (or copied) into OUT/in/<family>/
so that batch reads exactly those. Three runs, one after another on the same machine, each with the same
number of processes at a time (--jobs):

  batch    cadnurbs batch OUT/in -o OUT/batch --jobs N --inputs step --to x3dv (a fresh OUT/batch: nothing
           reused): the part read once, its .x3dv, and the record of what the conversion knew.
  convert  cadnurbs convert P.step -o P.x3dv, N processes at a time: the conversion alone.
  measure  with --with-measure: the batch again with --measure --deviation 0.01 (the report's record:
           every representation written and read back), for what the full comparison costs.
  freecad  freecadcmd bench/freecad_step_to_wrl.py per part (Part reads the STEP, MeshPart meshes it at
           LinearDeflection 0.01 mm, Mesh writes the .wrl), N processes at a time: what KiCad users run.

It prints, and writes to OUT/batch_throughput.md: parts per minute of each run (wall clock), the ratios,
failures, and the bytes of each side's files (raw and gzip'd at level 9) next to KiCad's shipped .wrl.

Run (not part of ctest; scripts/setup-bench.sh installs FreeCAD):
  bench/batch_throughput.py --cadnurbs build/converters/cadnurbs --parts 200 --jobs 2 --out /tmp/batch-bench
Standard library only (and library_sizes.py beside it).
"""
import argparse
import concurrent.futures
import json
import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from library_sizes import DEVIATION, FAMILIES, ROOT, freecad_sample, sizes  # noqa: E402


def link_or_copy(source, target):
    target.parent.mkdir(parents=True, exist_ok=True)
    try:
        os.link(source, target)
    except OSError:
        shutil.copyfile(source, target)


def run_parallel(jobs, work, items):
    """Runs work(item) for every item, `jobs` at a time; returns (wall seconds, results)."""
    t0 = time.perf_counter()
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        results = list(pool.map(work, items))
    return time.perf_counter() - t0, results


def totals(paths):
    raw = gz = 0
    for p in paths:
        a, b = sizes(p)
        raw, gz = raw + a, gz + b
    return raw, gz


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cadnurbs", type=Path, default=ROOT / "build" / "converters" / "cadnurbs")
    ap.add_argument("--library", type=Path, default=None, help="the kicad-packages3d folder (default: fetched)")
    ap.add_argument("--out", type=Path, default=ROOT / "build" / "bench-batch")
    ap.add_argument("--parts", type=int, default=200)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--freecadcmd", default="freecadcmd")
    ap.add_argument("--timeout", type=float, default=600, help="seconds per part")
    ap.add_argument("--with-measure", action="store_true", help="also time batch --measure")
    args = ap.parse_args()
    cadnurbs = args.cadnurbs.resolve()
    if args.library is None:
        args.library = Path(subprocess.run([str(ROOT / "scripts" / "fetch-part-library.sh")], check=True,
                                           capture_output=True, text=True).stdout.strip())
    if shutil.which(args.freecadcmd) is None:
        sys.exit(f"batch_throughput: no {args.freecadcmd} (scripts/setup-bench.sh installs it)")
    out = args.out.resolve()
    if out.exists():
        shutil.rmtree(out)
    all_parts = [(f, s) for f in FAMILIES for s in sorted((args.library / (f + ".3dshapes")).glob("*.step"))]
    parts = freecad_sample(all_parts, args.parts)
    inputs = []
    for family, step in parts:
        target = out / "in" / family / step.name
        link_or_copy(step, target)
        inputs.append((family, step, target))

    # 1. cadnurbs batch.
    t0 = time.perf_counter()
    batch = subprocess.run([str(cadnurbs), "batch", str(out / "in"), "-o", str(out / "batch"), "--jobs", str(args.jobs),
                            "--inputs", "step", "--to", "x3dv", "--timeout", str(args.timeout)],
                           capture_output=True, text=True)
    batch_seconds = time.perf_counter() - t0
    measure_seconds = measure_failed = None
    if args.with_measure:
        t0 = time.perf_counter()
        subprocess.run([str(cadnurbs), "batch", str(out / "in"), "-o", str(out / "measure"), "--jobs", str(args.jobs),
                        "--inputs", "step", "--to", "x3dv", "--measure", "--deviation", str(DEVIATION),
                        "--timeout", str(args.timeout)], capture_output=True, text=True)
        measure_seconds = time.perf_counter() - t0
        measured = json.loads((out / "measure" / "report.json").read_text())
        measure_failed = sum(1 for p in measured["parts"] if p.get("status") != "ok")
    report = json.loads((out / "batch" / "report.json").read_text())
    batch_failed = sum(1 for p in report["parts"] if p.get("status") != "ok")

    # 2. cadnurbs convert alone.
    def convert(item):
        family, _, step = item
        target = out / "convert" / family / (step.stem + ".x3dv")
        target.parent.mkdir(parents=True, exist_ok=True)
        try:
            r = subprocess.run([str(cadnurbs), "convert", str(step), "-o", str(target)], capture_output=True,
                               timeout=args.timeout)
            return r.returncode == 0
        except subprocess.TimeoutExpired:
            return False
    convert_seconds, convert_ok = run_parallel(args.jobs, convert, inputs)

    # 3. FreeCAD, headless.
    def freecad(item):
        family, _, step = item
        folder = out / "freecad" / family
        folder.mkdir(parents=True, exist_ok=True)
        wrl, rep = folder / (step.stem + ".wrl"), folder / (step.stem + ".json")
        env = dict(os.environ, CADNURBS_FC_IN=str(step), CADNURBS_FC_OUT=str(wrl),
                   CADNURBS_FC_DEVIATION=str(DEVIATION), CADNURBS_FC_REPORT=str(rep))
        try:
            subprocess.run([args.freecadcmd, str(ROOT / "bench" / "freecad_step_to_wrl.py")], capture_output=True,
                           timeout=args.timeout, env=env, cwd=str(folder))
        except subprocess.TimeoutExpired:
            return False
        return rep.exists() and json.loads(rep.read_text()).get("ok", False) and wrl.exists()
    freecad_seconds, freecad_ok = run_parallel(args.jobs, freecad, inputs)

    n = len(inputs)
    ours_x3dv = [out / "batch" / f / (s.name + ".x3dv") for f, _, s in inputs]
    fc_wrl = [out / "freecad" / f / (s.stem + ".wrl") for f, _, s in inputs]
    kicad = [orig.with_suffix(".wrl") for _, orig, _ in inputs]
    both = [i for i in range(n) if ours_x3dv[i].exists() and fc_wrl[i].exists() and kicad[i].exists()]
    pick = lambda paths: [paths[i] for i in both]  # noqa: E731
    rate = lambda seconds: 60 * n / seconds  # noqa: E731
    lines = [
        f"# batch throughput, {n} parts of {len(all_parts)} (every k-th over the nine families), --jobs {args.jobs}",
        "",
        "| run | wall s | parts/min | failed | speed against FreeCAD (its wall s / this run's) |",
        "|---|---:|---:|---:|---:|",
        f"| cadnurbs batch --to x3dv (record + .x3dv) | {batch_seconds:.1f} | {rate(batch_seconds):.1f} | "
        f"{batch_failed} | {freecad_seconds / batch_seconds:.2f} |",
    ] + ([f"| cadnurbs batch --to x3dv --measure | {measure_seconds:.1f} | {rate(measure_seconds):.1f} | "
          f"{measure_failed} | {freecad_seconds / measure_seconds:.2f} |"] if measure_seconds else []) + [
        f"| cadnurbs convert to .x3dv only | {convert_seconds:.1f} | {rate(convert_seconds):.1f} | "
        f"{convert_ok.count(False)} | {freecad_seconds / convert_seconds:.2f} |",
        f"| FreeCAD {DEVIATION} mm mesh .wrl | {freecad_seconds:.1f} | {rate(freecad_seconds):.1f} | "
        f"{freecad_ok.count(False)} | 1.00 |",
        "",
        f"batch / convert (wall, same --jobs): {batch_seconds / convert_seconds:.2f}",
        "",
        f"Bytes over the {len(both)} parts every side converted (raw / gzip'd at level 9):",
        "",
        "| files | raw | gzip'd | raw / KiCad | gzip'd / KiCad gzip'd |",
        "|---|---:|---:|---:|---:|",
    ]
    kicad_raw, kicad_gz = totals(pick(kicad))
    for label, paths in (("ours .x3dv (NURBS, compact)", pick(ours_x3dv)),
                         (f"FreeCAD .wrl (mesh, {DEVIATION} mm)", pick(fc_wrl)), ("KiCad's shipped .wrl", pick(kicad))):
        raw, gz = totals(paths)
        lines.append(f"| {label} | {raw:,} | {gz:,} | {raw / kicad_raw:.3f} | {gz / kicad_gz:.3f} |")
    text = "\n".join(lines) + "\n"
    (out / "batch_throughput.md").write_text(text)
    print(text)
    if batch.returncode not in (0, 3):
        print(f"batch_throughput: batch exited {batch.returncode}: {batch.stderr[-500:]}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
