#!/usr/bin/env python3
"""batch_against_kicad: a `cadnurbs batch` run over the part library, set against the meshes KiCad ships.

Reads OUT_DIR's per-part records (OUT_DIR/<family>/<part>.step.json, written by
`cadnurbs batch LIBRARY -o OUT_DIR --inputs step ...`) and, for each part, KiCad's LIBRARY/<part>.wrl
(the mesh VRML97 shipped beside the STEP, measured here raw and gzip'd at level 9). Prints Markdown:
parts and failures by reason; per representation the bytes summed over the converted parts against
KiCad's .wrl summed over the same parts (ratios of totals, raw and gzip'd); the parts per minute from
the records' own seconds (the sum of per-part seconds over --jobs, which is the run's wall time only
when nothing else ran) and, with --wall SECONDS, from the run's measured wall time.

  bench/batch_against_kicad.py LIBRARY OUT_DIR [--jobs 2] [--wall SECONDS]
Standard library only.
"""
import argparse
import collections
import gzip
import json
import re
import sys
from pathlib import Path


def sizes(path):
    data = path.read_bytes()
    return len(data), len(gzip.compress(data, compresslevel=9, mtime=0))


def reason(error):
    """The error's common form, as the batch's HTML report groups failures (report/library_summary)."""
    error = re.sub(r"^((line \d+|entity #\d+|object \d+( \([^)]*\))?|face \d+)(, [^:]*)?|[^:]*/[^:]*|[^\s:]+\.[A-Za-z0-9]+): ",
                   "", error, count=1)
    error = re.sub(r"\s*\([^()]*\)\s*$", "", error)
    return re.sub(r"\d+", "N", error) or error


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("library", type=Path)
    ap.add_argument("out", type=Path)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--wall", type=float, default=None, help="the batch's measured wall seconds")
    args = ap.parse_args()
    records = [json.loads(p.read_text()) for p in sorted(args.out.rglob("*.step.json"))]
    if not records:
        sys.exit(f"batch_against_kicad: no records under {args.out}")
    failed = [r for r in records if r["status"] != "ok"]
    converted = [r for r in records if r["status"] == "ok"]
    by_reason = collections.Counter(reason(r.get("error", "")) for r in failed)
    kicad_raw = kicad_gz = 0
    totals = {}
    labels = {}
    for r in converted:
        wrl = (args.library / r["batch"]["part"]).with_suffix(".wrl")
        raw, gz = sizes(wrl)
        kicad_raw, kicad_gz = kicad_raw + raw, kicad_gz + gz
        for rep in r["representations"]:
            # Each representation against KiCad's files of the parts it holds (some are not measured
            # on every part: the record's warnings say why).
            t = totals.setdefault(rep["key"], [0, 0, 0, 0, 0])
            t[0], t[1], t[2] = t[0] + 1, t[1] + rep["bytes"], t[2] + rep["gzip_bytes"]
            t[3], t[4] = t[3] + raw, t[4] + gz
            labels[rep["key"]] = rep["label"]
    seconds = sum(r["batch"]["seconds"] for r in records)
    out = [f"# cadnurbs batch over {args.library.name}: {len(records)} parts", "",
           f"- converted {len(converted)}, failed {len(failed)}"]
    for text, n in by_reason.most_common():
        out.append(f"  - {n} x {text}")
    out.append(f"- parts per minute from the records' seconds over {args.jobs} workers: "
               f"{60 * len(records) / (seconds / args.jobs):.1f} (mean {seconds / len(records):.2f} s per part)")
    if args.wall:
        out.append(f"- parts per minute over the measured wall time ({args.wall:.0f} s): {60 * len(records) / args.wall:.1f}")
    out += ["", f"Bytes over the {len(converted)} converted parts, against KiCad's shipped .wrl of the same parts "
            f"({kicad_raw:,} bytes raw, {kicad_gz:,} gzip'd):", "",
            "| representation | parts | bytes | gzip'd | bytes / KiCad's of those parts | gzip'd / KiCad's gzip'd |",
            "|---|---:|---:|---:|---:|---:|"]
    for key, (n, raw, gz, k_raw, k_gz) in totals.items():
        out.append(f"| {labels[key]} | {n} | {raw:,} | {gz:,} | {raw / k_raw:.3f} | {gz / k_gz:.3f} |")
    out.append(f"| KiCad's shipped .wrl | {len(converted)} | {kicad_raw:,} | {kicad_gz:,} | 1.000 | 1.000 |")
    print("\n".join(out))


if __name__ == "__main__":
    main()
