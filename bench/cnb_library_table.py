#!/usr/bin/env python3
"""cnb_library_table: sums bench/cnb_library_sizes' lines (stdin or files) per family and D.

For each D and family: parts, .cnb bytes, Draco bytes, meshoptimizer gzip'd bytes (over the parts where
all three exist), Draco / .cnb and meshopt / .cnb as ratios of totals, and how many parts have a .cnb no
larger than both; then every part where the .cnb is larger, and every part a codec refused. Markdown on
stdout. Standard library only.

  cnb_library_sizes 0.01,1 PARTS... > sizes.tsv; bench/cnb_library_table.py sizes.tsv
"""
import collections
import fileinput


def main():
    rows = []
    for line in fileinput.input():
        f = line.rstrip("\n").split("\t")
        if len(f) < 10 or not f[2]:
            rows.append({"family": f[0], "part": f[1], "d": None, "note": f[-1]})
            continue
        rows.append({"family": f[0], "part": f[1], "d": float(f[2]), "cnb": int(f[3]), "draco": int(f[4]),
                     "meshopt": int(f[5]), "bodies": int(f[6]), "meshed": int(f[7]), "bound": float(f[8]),
                     "note": f[9]})
    measured = [r for r in rows if r["d"] is not None and r["cnb"] and r["draco"] and r["meshopt"]]
    for d in sorted({r["d"] for r in measured}):
        print(f"\n## D = {d:g} mm\n")
        print("| family | parts | .cnb | Draco | meshopt gz | Draco / .cnb | meshopt / .cnb | .cnb <= both | bodies meshed |")
        print("|---|---|---|---|---|---|---|---|---|")
        by_family = collections.defaultdict(list)
        for r in measured:
            if r["d"] == d:
                by_family[r["family"]].append(r)
        everything = [r for rs in by_family.values() for r in rs]
        for family, rs in sorted(by_family.items()) + [("all", everything)]:
            cnb = sum(r["cnb"] for r in rs)
            draco = sum(r["draco"] for r in rs)
            meshopt = sum(r["meshopt"] for r in rs)
            wins = sum(1 for r in rs if r["cnb"] <= min(r["draco"], r["meshopt"]))
            meshed = sum(r["meshed"] for r in rs)
            bodies = sum(r["bodies"] for r in rs)
            print(f"| {family} | {len(rs)} | {cnb} | {draco} | {meshopt} | {draco / cnb:.2f} | {meshopt / cnb:.2f} | "
                  f"{wins} of {len(rs)} | {meshed} of {bodies} |")
        losses = [r for r in everything if r["cnb"] > min(r["draco"], r["meshopt"])]
        if losses:
            print(f"\n{len(losses)} parts where .cnb is larger than the smaller mesh file:\n")
            for r in sorted(losses, key=lambda r: r["cnb"] / min(r["draco"], r["meshopt"]), reverse=True):
                print(f"- {r['part']}: .cnb {r['cnb']}, Draco {r['draco']}, meshopt gz {r['meshopt']}")
    refused = [r for r in rows if r["d"] is None or not (r["cnb"] and r["draco"] and r["meshopt"])]
    if refused:
        print(f"\n{len(refused)} part-deviations not measured on all three:\n")
        for r in refused:
            print(f"- {r['part']} at D = {r['d']}: {r['note']}")


if __name__ == "__main__":
    main()
