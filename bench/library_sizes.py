#!/usr/bin/env python3
"""library_sizes: the sizes of cadnurbs' output against the meshes KiCad ships, on a real part library.

What it measures. For every STEP model of the chosen families of Debian's kicad-packages3d (KiCad's 3D
library, fetched by scripts/fetch-part-library.sh; each part NAME.step comes with NAME.wrl, the mesh
VRML97 that KiCad ships, made with FreeCAD/StepUp, 0.1-inch units), in sorted order, it runs one
`cadnurbs convert` process per output, each with a timeout:

  x3dv    convert P.step -o P.x3dv                          (the main output, timed: seconds per part)
  x3dvz   convert P.step -o P.x3dvz                         (gzip'd X3D)
  wrl     convert P.step -o P.wrl                           (VRML97 + the shared cadnurbs-nurbs-protos.wrl,
                                                             counted once, not per part)
  exact   convert P.step --exact-nurbs -o P-exact.x3dv
  mesh    convert P.step --mesh --deviation 0.01 -o P-mesh.wrl   (our mesh, D = 0.01 mm)

and records each file's size as written and gzip'd (level 9, in Python, over the bytes written; a file
that is gzip'd already counts as written), the faces and fallen-back faces from convert's line
"IN: N faces: A as trimmed NURBS, B fell back to a mesh", and each failure (exit status, the last line
of stderr, or the timeout). An option or extension the binary does not know ("unknown option",
"unknown output format") makes that column "n/a", not a failure; it is probed once on the smallest
part, and a column the binary refuses there is not run on the others. KiCad's P.wrl is measured the
same way (raw and gzip'd).

Then, in the same run, FreeCAD side by side on --freecad N parts (every k-th part of the sorted list,
so spread over the families): FreeCAD's headless STEP -> mesh VRML (bench/freecad_step_to_wrl.py run
by freecadcmd: Part reads the STEP, MeshPart.meshFromShape(LinearDeflection=0.01 mm) meshes it, Mesh
writes the .wrl), one part at a time, next to our own x3dv and mesh conversions of the same part run
again one at a time, so that the times compare: whole process for both, and FreeCAD's time after
importing its modules separately.

It writes a Markdown report (a table per family and a total row, then the parts whose .x3dv is larger
than KiCad's .wrl, the largest files, and the FreeCAD comparison) to stdout and OUT/library_sizes.md,
and per-part CSVs OUT/library_sizes.csv and OUT/freecad.csv. Ratios are ratios of totals (over the
parts where both sides exist), never means of ratios.

Resumable: each finished part is appended to OUT/library_sizes.jsonl (OUT/freecad.jsonl for the
FreeCAD side) under a key made of the part's path, size and time, the binary's size and time and the
settings; a rerun skips the parts already measured with the same binary. --fresh ignores that.

Run (not part of ctest):

  scripts/setup-bench.sh                 # freecad, python3, gzip (beyond scripts/setup.sh)
  scripts/fetch-part-library.sh          # once: the library, cached outside the repository
  cmake -S . -B build -DCMAKE_BUILD_TYPE=RelWithDebInfo && cmake --build build --target cadnurbs
  bench/library_sizes.py                 # all nine families, FreeCAD on 20 parts
  bench/library_sizes.py --limit 3 --freecad 2    # a quick look

Standard library only.
"""

import argparse
import concurrent.futures
import csv
import datetime
import gzip
import hashlib
import json
import os
import re
import shutil
import statistics
import subprocess
import sys
import threading
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
FAMILIES = [
    "Connector_PinHeader_2.54mm", "Package_DIP", "Package_DFN_QFN", "Package_QFP", "Package_BGA",
    "Resistor_THT", "Inductor_THT", "LED_THT", "Connector_Phoenix_MC",
]
DEVIATION = 0.01  # mm, our mesh and FreeCAD's
PROTOS = "cadnurbs-nurbs-protos.wrl"


class Kind:
    def __init__(self, name, suffix, extra, probe, gzipped=False):
        self.name, self.suffix, self.extra, self.probe, self.gzipped = name, suffix, extra, probe, gzipped


KINDS = [
    Kind("x3dv", ".x3dv", [], probe=False),
    Kind("x3dvz", ".x3dvz", [], probe=True, gzipped=True),
    Kind("wrl", ".wrl", [], probe=False),
    Kind("exact", "-exact.x3dv", ["--exact-nurbs"], probe=True),
    Kind("mesh", "-mesh.wrl", ["--mesh", "--deviation", str(DEVIATION)], probe=False),
]
KIND = {k.name: k for k in KINDS}

NA_PATTERNS = ("unknown option", "unknown output format")


# ---------------------------------------------------------------------------------------------------
# Measuring


def sizes(path, already_gzipped=False):
    """(bytes as written, bytes gzip'd at level 9); a gzip'd file counts as written."""
    data = Path(path).read_bytes()
    if already_gzipped:
        return len(data), len(data)
    return len(data), len(gzip.compress(data, compresslevel=9, mtime=0))


def last_line(text):
    lines = [l.strip() for l in text.splitlines() if l.strip()]
    return lines[-1][:300] if lines else ""


def parse_faces(stdout):
    """Faces and fallen-back faces from "IN: N faces: A as trimmed NURBS, B fell back to a mesh"."""
    for line in stdout.splitlines():
        if "fell back" not in line:
            continue
        faces = re.search(r"(\d+)\s+faces\b", line)
        fallbacks = re.search(r"(\d+)\s+(?:faces?\s+)?fell back", line)
        if faces and fallbacks:
            return int(faces.group(1)), int(fallbacks.group(1))
    return None, None


def parse_fallback_reasons(stderr):
    """convert's "... face K (TYPE) written as a mesh: REASON" lines, as "TYPE: REASON xN; ..."."""
    counts = {}
    for line in stderr.splitlines():
        m = re.search(r"\(([^()]*)\)\s+written as a mesh:\s*(.*)", line)
        if m:
            reason = f"{m.group(1)}: {re.sub(r'[0-9]+', 'N', m.group(2).strip())}"[:200]
            counts[reason] = counts.get(reason, 0) + 1
    return "; ".join(f"{k} x{n}" for k, n in sorted(counts.items(), key=lambda kv: -kv[1]))


def parse_triangles(stdout):
    m = re.search(r"\((\d+)\s+triangles", stdout)
    return int(m.group(1)) if m else None


def convert(cadnurbs, step, out, kind, timeout):
    """One `cadnurbs convert` process. Returns a dict: status ok / n/a / fail / timeout, and so on."""
    cmd = [str(cadnurbs), "convert", str(step), *kind.extra, "-o", str(out)]
    if out.exists():
        out.unlink()
    t0 = time.perf_counter()
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return {"status": "timeout", "seconds": time.perf_counter() - t0, "error": f"timeout after {timeout} s"}
    seconds = time.perf_counter() - t0
    r = {"seconds": seconds, "stdout": p.stdout, "stderr": p.stderr}
    if p.returncode != 0:
        err = last_line(p.stderr)
        if any(s in err for s in NA_PATTERNS):
            r.update(status="n/a", error=err)
        else:
            r.update(status="fail", error=f"exit {p.returncode}: {err}")
        return r
    if not out.exists():
        r.update(status="fail", error="exit 0 but no output file")
        return r
    r["bytes"], r["gz"] = sizes(out, kind.gzipped)
    r["status"] = "ok"
    return r


def fingerprint(path):
    st = Path(path).stat()
    return f"{Path(path).resolve()}:{st.st_size}:{st.st_mtime_ns}"


def part_key(step, binary_fp, kinds_run, timeout):
    text = "|".join([fingerprint(step), binary_fp, ",".join(kinds_run), str(DEVIATION), str(timeout)])
    return hashlib.sha1(text.encode()).hexdigest()


def measure_part(args, family, step, kinds_run):
    """Every conversion of one part, one after the other. Returns the part's record."""
    out_dir = args.out / family
    out_dir.mkdir(parents=True, exist_ok=True)
    stem = step.stem
    rec = {"family": family, "part": stem, "step_bytes": step.stat().st_size}
    kicad = step.with_suffix(".wrl")
    if kicad.exists():
        rec["kicad"], rec["kicad_gz"] = sizes(kicad)
    for kind in KINDS:
        if kind.name not in kinds_run:
            rec[kind.name + "_status"] = "n/a"
            continue
        r = convert(args.cadnurbs, step, out_dir / (stem + kind.suffix), kind, args.timeout)
        rec[kind.name + "_status"] = r["status"]
        rec[kind.name + "_seconds"] = round(r["seconds"], 4)
        if r["status"] == "ok":
            rec[kind.name] = r["bytes"]
            rec[kind.name + "_gz"] = r["gz"]
        if "error" in r:
            rec[kind.name + "_error"] = r["error"]
        if kind.name == "x3dv" and r["status"] == "ok":
            rec["faces"], rec["fallbacks"] = parse_faces(r["stdout"])
            if rec["fallbacks"]:
                rec["fallback_reasons"] = parse_fallback_reasons(r["stderr"])
        if kind.name == "mesh" and r["status"] == "ok":
            rec["mesh_triangles"] = parse_triangles(r["stdout"])
    return rec


def probe_kinds(args, step):
    """Which columns the binary supports, tried once on a small part."""
    probe_dir = args.out / "probe"
    probe_dir.mkdir(parents=True, exist_ok=True)
    supported, notes = [], {}
    for kind in KINDS:
        if not kind.probe:
            supported.append(kind.name)
            continue
        r = convert(args.cadnurbs, step, probe_dir / (step.stem + kind.suffix), kind, args.timeout)
        if r["status"] == "n/a":
            notes[kind.name] = r["error"]
        else:
            supported.append(kind.name)  # a real failure here is the part's business, not the column's
    shutil.rmtree(probe_dir, ignore_errors=True)
    return supported, notes


def load_cache(path):
    cache = {}
    if path.exists():
        for line in path.read_text().splitlines():
            try:
                entry = json.loads(line)
                cache[entry["key"]] = entry["record"]
            except (ValueError, KeyError):
                pass  # a line cut short by an interrupted run
    return cache


# ---------------------------------------------------------------------------------------------------
# FreeCAD side by side


def freecad_part(args, family, step):
    out_dir = args.out / "freecad" / family
    out_dir.mkdir(parents=True, exist_ok=True)
    stem = step.stem
    rec = {"family": family, "part": stem, "step_bytes": step.stat().st_size}
    for name, kind in (("ours_x3dv", KIND["x3dv"]), ("ours_mesh", KIND["mesh"])):
        r = convert(args.cadnurbs, step, out_dir / (stem + "-cadnurbs" + kind.suffix), kind, args.timeout)
        rec[name + "_status"] = r["status"]
        rec[name + "_seconds"] = round(r["seconds"], 4)
        if r["status"] == "ok":
            rec[name], rec[name + "_gz"] = r["bytes"], r["gz"]
            if name == "ours_mesh":
                rec["ours_mesh_triangles"] = parse_triangles(r["stdout"])
        else:
            rec[name + "_error"] = r.get("error", "")
    out = out_dir / (stem + "-freecad.wrl")
    report = out_dir / (stem + "-freecad.json")
    for p in (out, report):
        if p.exists():
            p.unlink()
    env = dict(os.environ, CADNURBS_FC_IN=str(step), CADNURBS_FC_OUT=str(out),
               CADNURBS_FC_DEVIATION=str(DEVIATION), CADNURBS_FC_REPORT=str(report))
    cmd = [args.freecadcmd, str(ROOT / "bench" / "freecad_step_to_wrl.py")]
    t0 = time.perf_counter()
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=args.timeout, env=env,
                           cwd=str(out_dir))
        rec["freecad_seconds"] = round(time.perf_counter() - t0, 4)
        rep = json.loads(report.read_text()) if report.exists() else {}
        if rep.get("ok") and out.exists():
            rec["freecad_status"] = "ok"
            rec["freecad"], rec["freecad_gz"] = sizes(out)
            rec["freecad_triangles"] = rep.get("triangles")
            rec["freecad_seconds_inside"] = round(rep["seconds_after_modules"], 4)
            rec["freecad_seconds_modules"] = round(rep["seconds_modules"], 4)
            rec["freecad_seconds_read"] = round(rep["seconds_read"], 4)
            rec["freecad_seconds_mesh"] = round(rep["seconds_mesh"], 4)
            rec["freecad_version"] = rep.get("freecad_version")
        else:
            rec["freecad_status"] = "fail"
            rec["freecad_error"] = rep.get("error") or f"exit {p.returncode}: {last_line(p.stderr)}"
    except subprocess.TimeoutExpired:
        rec["freecad_seconds"] = round(time.perf_counter() - t0, 4)
        rec["freecad_status"] = "timeout"
        rec["freecad_error"] = f"timeout after {args.timeout} s"
    kicad = step.with_suffix(".wrl")
    if kicad.exists():
        rec["kicad"], rec["kicad_gz"] = sizes(kicad)
    return rec


def freecad_sample(parts, n):
    """n parts spread evenly over the sorted list (every k-th, k = len/n)."""
    if n <= 0 or not parts:
        return []
    n = min(n, len(parts))
    return [parts[(i * len(parts)) // n] for i in range(n)]


# ---------------------------------------------------------------------------------------------------
# Report


def mb(x):
    if x is None:
        return "n/a"
    return f"{x / 1e6:.2f}" if x >= 1e6 else f"{x / 1e6:.3f}"


def ratio(a, b):
    return "n/a" if a is None or not b else f"{a / b:.2f}"


def total(records, field, require=()):
    """Sum of field over the records where it and every field in require are present; None if none."""
    vals = [r[field] for r in records if r.get(field) is not None and all(r.get(q) is not None for q in require)]
    return sum(vals) if vals else None


def family_row(name, recs):
    ok = [r for r in recs if r.get("x3dv_status") == "ok"]
    secs = [r["x3dv_seconds"] for r in ok]
    larger = [r for r in ok if r.get("kicad") is not None and r["x3dv"] > r["kicad"]]
    return [
        name, str(len(recs)), str(len(ok)),
        str(total(ok, "faces") or 0), str(total(ok, "fallbacks") or 0),
        mb(total(recs, "x3dv")), mb(total(recs, "x3dv_gz")), mb(total(recs, "x3dvz")),
        mb(total(recs, "wrl")), mb(total(recs, "wrl_gz")),
        mb(total(recs, "exact")), mb(total(recs, "exact_gz")),
        mb(total(recs, "kicad")), mb(total(recs, "kicad_gz")),
        ratio(total(recs, "x3dv", ["kicad"]), total(recs, "kicad", ["x3dv"])),
        ratio(total(recs, "x3dvz", ["kicad_gz"]), total(recs, "kicad_gz", ["x3dvz"])),
        ratio(total(recs, "x3dv_gz", ["kicad_gz"]), total(recs, "kicad_gz", ["x3dv_gz"])),
        mb(total(recs, "mesh")), mb(total(recs, "mesh_gz")),
        ratio(total(recs, "mesh", ["kicad"]), total(recs, "kicad", ["mesh"])),
        str(len(larger)),
        f"{statistics.mean(secs):.2f}" if secs else "n/a",
        f"{statistics.median(secs):.2f}" if secs else "n/a",
    ]


HEADER = [
    "family", "parts", "converted", "faces", "fell back",
    ".x3dv MB", ".x3dv gz MB", ".x3dvz MB", ".wrl MB", ".wrl gz MB", "exact .x3dv MB", "exact gz MB",
    "KiCad .wrl MB", "KiCad gz MB", "x3dv/KiCad", "x3dvz/KiCad gz", "x3dv gz/KiCad gz",
    "mesh D=0.01 MB", "mesh gz MB", "mesh/KiCad", "x3dv > KiCad", "s/part mean", "s/part median",
]


def md_table(header, rows, left=1):
    lines = ["| " + " | ".join(header) + " |",
             "|" + "|".join(["---"] * left + ["---:"] * (len(header) - left)) + "|"]
    lines += ["| " + " | ".join(r) + " |" for r in rows]
    return "\n".join(lines)


def report(args, families, records, fc_records, notes, protos_bytes, elapsed):
    out = []
    now = datetime.datetime.now().strftime("%Y-%m-%d %H:%M")
    out.append(f"# library_sizes, {now}, {os.cpu_count()} cores, --jobs {args.jobs}\n")
    out.append(f"Library: {args.library}  \ncadnurbs: {args.cadnurbs}  \n"
               f"Parts: {len(records)} ({'first ' + str(args.limit) + ' per family' if args.limit else 'all'}); "
               f"wall time of the run {elapsed / 60:.1f} min.\n")
    out.append("MB = 10^6 bytes. gz = gzip level 9 of the bytes written. Ratios are ratios of totals over the "
               "parts where both sides exist. .wrl excludes the shared " + PROTOS +
               (f" ({protos_bytes:,} bytes, once)" if protos_bytes else "") +
               ". s/part: the .x3dv conversion, whole process, with --jobs parts at a time. "
               "mesh: `--mesh --deviation 0.01` (mm).\n")
    for k, why in notes.items():
        out.append(f"- column {k}: n/a with this binary ({why})")
    if notes:
        out.append("")
    rows = [family_row(f, [r for r in records if r["family"] == f]) for f in families]
    rows.append(family_row("**total**", records))
    out.append(md_table(HEADER, rows))
    out.append("")

    # Failures.
    fails = [(r, k.name) for r in records for k in KINDS if r.get(k.name + "_status") in ("fail", "timeout")]
    out.append(f"## Failures ({len(fails)})\n")
    for r, k in fails:
        out.append(f"- {r['family']}/{r['part']} [{k}]: {r.get(k + '_error', '')}")
    if fails:
        out.append("")

    fallen = [r for r in records if r.get("fallbacks")]
    out.append(f"## Parts with faces fallen back to a mesh ({len(fallen)})\n")
    reasons = {}
    for r in fallen:
        for item in (r.get("fallback_reasons") or "").split("; "):
            m = re.match(r"(.*) x(\d+)$", item)
            if m:
                reasons[m.group(1)] = reasons.get(m.group(1), 0) + int(m.group(2))
    if reasons:
        out.append(md_table(["reason (numbers as N)", "faces"],
                            [[k, str(n)] for k, n in sorted(reasons.items(), key=lambda kv: -kv[1])]))
        out.append("")
    for r in fallen:
        out.append(f"- {r['family']}/{r['part']}: {r['fallbacks']} of {r['faces']} faces"
                   + (f" ({r['fallback_reasons']})" if r.get("fallback_reasons") else ""))
    if fallen:
        out.append("")

    # Where the bytes are.
    x3_total = total(records, "x3dv") or 0
    kc_total = total(records, "kicad") or 0
    if x3_total:
        out.append("## Share of the bytes per family\n")
        srows = []
        for f in families:
            recs = [r for r in records if r["family"] == f]
            x3, kc = total(recs, "x3dv") or 0, total(recs, "kicad") or 0
            srows.append([f, f"{100 * x3 / x3_total:.1f} %", f"{100 * kc / kc_total:.1f} %" if kc_total else "n/a"])
        out.append(md_table(["family", "share of our .x3dv bytes", "share of KiCad .wrl bytes"], srows))
        out.append("")
        big = sorted([r for r in records if r.get("x3dv")], key=lambda r: -r["x3dv"])[:15]
        out.append("## Largest .x3dv files\n")
        out.append(md_table(["part", "faces", "STEP bytes", ".x3dv bytes", "KiCad .wrl bytes", "x3dv/KiCad",
                             "x3dv gz/KiCad gz"],
                            [[f"{r['family']}/{r['part']}", str(r.get("faces")), f"{r['step_bytes']:,}",
                              f"{r['x3dv']:,}", f"{r['kicad']:,}" if r.get("kicad") else "n/a",
                              ratio(r["x3dv"], r.get("kicad")), ratio(r.get("x3dv_gz"), r.get("kicad_gz"))]
                             for r in big]))
        out.append("")

    larger = [r for r in records if r.get("x3dv") is not None and r.get("kicad") is not None and r["x3dv"] > r["kicad"]]
    out.append(f"## Parts whose .x3dv is larger than KiCad's .wrl ({len(larger)} of "
               f"{sum(1 for r in records if r.get('x3dv') is not None)})\n")
    if larger:
        out.append(md_table(["part", ".x3dv bytes", "KiCad .wrl bytes", "ratio", ".x3dv gz", "KiCad gz"],
                            [[f"{r['family']}/{r['part']}", f"{r['x3dv']:,}", f"{r['kicad']:,}",
                              ratio(r["x3dv"], r["kicad"]), f"{r['x3dv_gz']:,}", f"{r['kicad_gz']:,}"]
                             for r in larger]))
        out.append("")

    if fc_records:
        out.append(freecad_report(fc_records))
    return "\n".join(out)


def freecad_report(recs):
    out = [f"## FreeCAD side by side ({len(recs)} parts, one process at a time)\n"]
    version = next((r["freecad_version"] for r in recs if r.get("freecad_version")), "?")
    out.append(f"FreeCAD {version}, `freecadcmd bench/freecad_step_to_wrl.py`: Part reads the STEP, "
               f"MeshPart.meshFromShape(LinearDeflection={DEVIATION} mm, AngularDeflection=1.5 rad, "
               "Relative=False), Mesh writes the .wrl. Ours: `convert P.step -o P.x3dv` and "
               f"`convert P.step --mesh --deviation {DEVIATION} -o P-mesh.wrl`. Times are whole processes "
               "(FreeCAD's includes its start-up; 'inside' is after importing its modules: read, mesh, write).\n")
    rows = []
    for r in recs:
        rows.append([
            f"{r['family']}/{r['part']}",
            f"{r.get('ours_x3dv_seconds', 0):.2f}" if r.get("ours_x3dv_status") == "ok" else r.get("ours_x3dv_status", "?"),
            f"{r.get('ours_mesh_seconds', 0):.2f}" if r.get("ours_mesh_status") == "ok" else r.get("ours_mesh_status", "?"),
            f"{r['freecad_seconds']:.2f}" if r.get("freecad_status") == "ok" else r.get("freecad_status", "?"),
            f"{r['freecad_seconds_inside']:.2f}" if r.get("freecad_status") == "ok" else "",
            ratio(r.get("ours_mesh_seconds") if r.get("ours_mesh_status") == "ok" else None,
                  r.get("freecad_seconds") if r.get("freecad_status") == "ok" else None),
            f"{r['ours_x3dv']:,}" if r.get("ours_x3dv") else "n/a",
            f"{r['ours_mesh']:,}" if r.get("ours_mesh") else "n/a",
            f"{r['freecad']:,}" if r.get("freecad") else "n/a",
            f"{r['ours_mesh_gz']:,}" if r.get("ours_mesh_gz") else "n/a",
            f"{r['freecad_gz']:,}" if r.get("freecad_gz") else "n/a",
            str(r.get("ours_mesh_triangles", "n/a")), str(r.get("freecad_triangles", "n/a")),
        ])
    both = [r for r in recs if r.get("freecad_status") == "ok" and r.get("ours_mesh_status") == "ok"
            and r.get("ours_x3dv_status") == "ok"]

    def s(field):
        return sum(r.get(field) or 0 for r in both)

    if both:
        rows.append([
            f"**total ({len(both)} parts with all three)**",
            f"{s('ours_x3dv_seconds'):.2f}", f"{s('ours_mesh_seconds'):.2f}", f"{s('freecad_seconds'):.2f}",
            f"{s('freecad_seconds_inside'):.2f}", ratio(s("ours_mesh_seconds"), s("freecad_seconds")),
            f"{s('ours_x3dv'):,}", f"{s('ours_mesh'):,}", f"{s('freecad'):,}", f"{s('ours_mesh_gz'):,}",
            f"{s('freecad_gz'):,}", f"{s('ours_mesh_triangles'):,}", f"{s('freecad_triangles'):,}",
        ])
    out.append(md_table(["part", "ours .x3dv s", "ours mesh s", "FreeCAD s", "FreeCAD inside s",
                         "mesh time ours/FreeCAD", "ours .x3dv bytes", "ours mesh bytes", "FreeCAD bytes",
                         "ours mesh gz", "FreeCAD gz", "ours triangles", "FreeCAD triangles"], rows))
    out.append("")
    if both:
        out.append("Totals as ratios (ours/FreeCAD): "
                   f"time mesh/FreeCAD process {s('ours_mesh_seconds') / s('freecad_seconds'):.2f}, "
                   f"mesh/FreeCAD inside {s('ours_mesh_seconds') / s('freecad_seconds_inside'):.2f}, "
                   f".x3dv/FreeCAD process {s('ours_x3dv_seconds') / s('freecad_seconds'):.2f}, "
                   f".x3dv/FreeCAD inside {s('ours_x3dv_seconds') / s('freecad_seconds_inside'):.2f}; "
                   f"bytes mesh/FreeCAD {s('ours_mesh') / s('freecad'):.2f} "
                   f"(gz {s('ours_mesh_gz') / s('freecad_gz'):.2f}), "
                   f".x3dv/FreeCAD {s('ours_x3dv') / s('freecad'):.2f} "
                   f"(gz {s('ours_x3dv_gz') / s('freecad_gz'):.2f}); "
                   f"triangles {s('ours_mesh_triangles') / s('freecad_triangles'):.2f}. "
                   f"FreeCAD's module start-up: median "
                   f"{statistics.median(r['freecad_seconds_modules'] for r in both):.2f} s.\n")
    fails = [r for r in recs if r.get("freecad_status") != "ok"]
    for r in fails:
        out.append(f"- FreeCAD {r['family']}/{r['part']}: {r.get('freecad_status')}: {r.get('freecad_error', '')}")
    return "\n".join(out)


def write_csv(path, records):
    fields = []
    for r in records:
        for k in r:
            if k not in fields:
                fields.append(k)
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields, restval="")
        w.writeheader()
        for r in records:
            w.writerow(r)


# ---------------------------------------------------------------------------------------------------


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cadnurbs", type=Path, default=ROOT / "build" / "converters" / "cadnurbs")
    ap.add_argument("--library", type=Path, default=None,
                    help="the library folder (default: what scripts/fetch-part-library.sh prints)")
    ap.add_argument("--out", type=Path, default=ROOT / "build" / "bench-library")
    ap.add_argument("--families", default=",".join(FAMILIES))
    ap.add_argument("--limit", type=int, default=0, help="parts per family (0: all)")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--freecad", type=int, default=20, help="parts also converted with FreeCAD (0: skip)")
    ap.add_argument("--freecadcmd", default="freecadcmd")
    ap.add_argument("--timeout", type=float, default=600, help="seconds per conversion process")
    ap.add_argument("--fresh", action="store_true", help="ignore the results of earlier runs")
    args = ap.parse_args()

    args.cadnurbs = args.cadnurbs.resolve()
    if not args.cadnurbs.exists():
        sys.exit(f"library_sizes: no cadnurbs at {args.cadnurbs} (build it, or pass --cadnurbs)")
    if args.library is None:
        args.library = Path(subprocess.run([str(ROOT / "scripts" / "fetch-part-library.sh")], check=True,
                                           capture_output=True, text=True).stdout.strip())
    args.library = args.library.resolve()
    args.out = args.out.resolve()
    args.out.mkdir(parents=True, exist_ok=True)
    families = [f for f in args.families.split(",") if f]

    parts = []
    for f in families:
        d = args.library / (f + ".3dshapes")
        if not d.is_dir():
            sys.exit(f"library_sizes: no folder {d}")
        steps = sorted(d.glob("*.step"))
        parts += [(f, s) for s in (steps[: args.limit] if args.limit else steps)]
    if not parts:
        sys.exit("library_sizes: no STEP files")

    t_run = time.perf_counter()
    smallest = min(parts, key=lambda p: p[1].stat().st_size)[1]
    kinds_run, notes = probe_kinds(args, smallest)
    binary_fp = fingerprint(args.cadnurbs)

    cache_path = args.out / "library_sizes.jsonl"
    cache = {} if args.fresh else load_cache(cache_path)
    keys = {p: part_key(p[1], binary_fp, kinds_run, args.timeout) for p in parts}
    to_measure = [p for p in parts if keys[p] not in cache]
    print(f"library_sizes: {len(parts)} parts, {len(parts) - len(to_measure)} measured before, {len(to_measure)} to do; "
          f"columns run: {', '.join(kinds_run)}", file=sys.stderr)

    lock = threading.Lock()
    done = 0
    with open(cache_path, "a") as cache_file, \
            concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        futures = {pool.submit(measure_part, args, f, s, kinds_run): (f, s) for f, s in to_measure}
        for fut in concurrent.futures.as_completed(futures):
            p = futures[fut]
            try:
                rec = fut.result()
            except Exception as e:  # the driver's own trouble with one part: recorded, the run goes on
                rec = {"family": p[0], "part": p[1].stem, "step_bytes": p[1].stat().st_size,
                       "x3dv_status": "fail", "x3dv_error": f"driver: {type(e).__name__}: {e}"}
            with lock:
                cache[keys[p]] = rec
                cache_file.write(json.dumps({"key": keys[p], "record": rec}) + "\n")
                cache_file.flush()
                done += 1
                if done % 25 == 0 or done == len(to_measure):
                    print(f"library_sizes: {done}/{len(to_measure)} parts ({(time.perf_counter() - t_run) / 60:.1f} min)",
                          file=sys.stderr)
    records = [cache[keys[p]] for p in parts]

    protos_bytes = None
    for f in families:
        p = args.out / f / PROTOS
        if p.exists():
            protos_bytes = p.stat().st_size
            break

    # FreeCAD, one part at a time, ours again beside it.
    fc_records = []
    sample = freecad_sample(parts, args.freecad)
    if sample:
        if shutil.which(args.freecadcmd) is None:
            print(f"library_sizes: no {args.freecadcmd} (scripts/setup-bench.sh installs it); FreeCAD skipped",
                  file=sys.stderr)
        else:
            fc_cache_path = args.out / "freecad.jsonl"
            fc_cache = {} if args.fresh else load_cache(fc_cache_path)
            script_fp = fingerprint(ROOT / "bench" / "freecad_step_to_wrl.py")
            with open(fc_cache_path, "a") as fc_file:
                for i, (f, s) in enumerate(sample):
                    key = hashlib.sha1(("freecad|" + keys[(f, s)] + "|" + script_fp).encode()).hexdigest()
                    if key not in fc_cache:
                        print(f"library_sizes: FreeCAD {i + 1}/{len(sample)} {f}/{s.stem}", file=sys.stderr)
                        try:
                            fc_cache[key] = freecad_part(args, f, s)
                        except Exception as e:
                            fc_cache[key] = {"family": f, "part": s.stem, "freecad_status": "fail",
                                             "freecad_error": f"driver: {type(e).__name__}: {e}"}
                        fc_file.write(json.dumps({"key": key, "record": fc_cache[key]}) + "\n")
                        fc_file.flush()
                    fc_records.append(fc_cache[key])

    text = report(args, families, records, fc_records, notes, protos_bytes, time.perf_counter() - t_run)
    (args.out / "library_sizes.md").write_text(text + "\n")
    write_csv(args.out / "library_sizes.csv", records)
    if fc_records:
        write_csv(args.out / "freecad.csv", fc_records)
    print(text)
    print(f"\nlibrary_sizes: wrote {args.out / 'library_sizes.md'}, {args.out / 'library_sizes.csv'}"
          + (f", {args.out / 'freecad.csv'}" if fc_records else ""), file=sys.stderr)


if __name__ == "__main__":
    main()
