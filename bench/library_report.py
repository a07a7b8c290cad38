#!/usr/bin/env python3
"""library_report: `cadnurbs report` over a spread of the part library, totals per family.

For each family of Debian's kicad-packages3d (fetched by scripts/fetch-part-library.sh), every k-th STEP
model in sorted order (--per-family N of them) goes through one `cadnurbs report P.step --deviation D
--records OUT/records-D` run per part (one process per part, with a timeout), so that a crash or a hang
costs one part. From the records it sums, per family, the bytes of: our binary NURBS (.cnb, within D),
the smallest Draco mesh within D, the meshoptimizer mesh within D (gzip'd, as gltfpack users compare),
our compact X3D NURBS (gzip'd), and the mesh VRML KiCad ships for the part (gzip'd, level 9, measured
here). Ratios are ratios of totals, never means of ratios. It also counts the parts where .cnb is the
smaller, and lists every mesh deviation measured above D (none expected).

Run (not part of ctest):
  python3 bench/library_report.py --cadnurbs build/converters/cadnurbs --deviation 1 --per-family 10 \
      --out /tmp/library-report
Writes OUT/library_report-D.md and prints it.
"""
import argparse, gzip, json, os, subprocess, sys

FAMILIES = ["Connector_Phoenix_MC", "Connector_PinHeader_2.54mm", "Inductor_THT", "LED_THT", "Package_BGA",
            "Package_DFN_QFN", "Package_DIP", "Package_QFP", "Resistor_THT"]


def library_root():
    cache = os.environ.get("CADNURBS_CACHE", os.path.expanduser("~/.cache/cadnurbs"))
    return os.path.join(cache, "kicad-packages3d-6.0.10-1")


def gz_size(path):
    with open(path, "rb") as f:
        return len(gzip.compress(f.read(), 9))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cadnurbs", required=True)
    ap.add_argument("--deviation", type=float, default=1.0)
    ap.add_argument("--per-family", type=int, default=10)
    ap.add_argument("--timeout", type=int, default=600)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    records = os.path.join(a.out, "records-%g" % a.deviation)
    os.makedirs(records, exist_ok=True)
    rows, failures, above = [], [], []
    for family in FAMILIES:
        folder = os.path.join(library_root(), family + ".3dshapes")
        steps = sorted(f for f in os.listdir(folder) if f.endswith(".step"))
        k = max(1, len(steps) // a.per_family)
        chosen = steps[::k][:a.per_family]
        totals = {"parts": 0, "cnb": 0, "draco": 0, "meshopt": 0, "x3dv": 0, "kicad": 0, "cnb_smaller": 0, "with_mesh": 0,
                  "cnb_with_mesh": 0}
        for step in chosen:
            path = os.path.join(folder, step)
            record = os.path.join(records, step[:-5] + ".json")
            if not os.path.exists(record):
                try:
                    subprocess.run([a.cadnurbs, "report", path, "--deviation", str(a.deviation), "--records", records,
                                    "-o", os.devnull], timeout=a.timeout, capture_output=True)
                except subprocess.TimeoutExpired:
                    failures.append((step, "timeout"))
                    continue
            if not os.path.exists(record):
                failures.append((step, "no record"))
                continue
            r = json.load(open(record))
            if r["status"] != "ok":
                failures.append((step, r.get("error", "")))
                continue
            rep = {x["key"]: x for x in r["representations"]}
            for x in r["representations"]:
                if x["kind"] == "mesh" and x["deviation"] is not None and x["deviation"] > r["deviation"]:
                    above.append((step, x["key"], x["deviation"]))
            totals["parts"] += 1
            totals["cnb"] += rep["cnb"]["bytes"]
            totals["x3dv"] += rep["x3dv-compact"]["gzip_bytes"]
            wrl = path[:-5] + ".wrl"
            totals["kicad"] += gz_size(wrl) if os.path.exists(wrl) else 0
            if "draco" in rep and "meshopt" in rep:
                totals["with_mesh"] += 1
                totals["cnb_with_mesh"] += rep["cnb"]["bytes"]
                totals["draco"] += rep["draco"]["bytes"]
                totals["meshopt"] += rep["meshopt"]["gzip_bytes"]
                totals["cnb_smaller"] += rep["cnb"]["bytes"] < min(rep["draco"]["bytes"], rep["meshopt"]["gzip_bytes"])
        rows.append((family, totals))
    lines = ["# cadnurbs report over the part library, D = %g mm" % a.deviation, "",
             "Bytes summed per family (every k-th part, %d per family); Draco/meshopt totals, and the ratios to .cnb, "
             "over the parts where they were measured (`with mesh`)." % a.per_family, "",
             "| family | parts | with mesh | .cnb | Draco | meshopt gz | X3D gz | KiCad .wrl gz | Draco / .cnb | "
             "meshopt / .cnb | KiCad / .cnb | .cnb smaller than both |", "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for family, t in rows + [("all", {k: sum(r[1][k] for r in rows) for k in rows[0][1]})]:
        ratio = lambda x, y: "%.2f" % (x / y) if y else "-"
        lines.append("| %s | %d | %d | %d | %d | %d | %d | %d | %s | %s | %s | %d of %d |" % (
            family, t["parts"], t["with_mesh"], t["cnb"], t["draco"], t["meshopt"], t["x3dv"], t["kicad"],
            ratio(t["draco"], t["cnb_with_mesh"]), ratio(t["meshopt"], t["cnb_with_mesh"]), ratio(t["kicad"], t["cnb"]),
            t["cnb_smaller"], t["with_mesh"]))
    lines += ["", "Failures: %d" % len(failures)] + ["- %s: %s" % f for f in failures]
    lines += ["", "Mesh deviations measured above D: %d" % len(above)] + ["- %s %s %g" % x for x in above]
    text = "\n".join(lines) + "\n"
    open(os.path.join(a.out, "library_report-%g.md" % a.deviation), "w").write(text)
    print(text)


if __name__ == "__main__":
    sys.exit(main())
