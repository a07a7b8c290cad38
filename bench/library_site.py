#!/usr/bin/env python3
"""library_site: what a site written by `cadnurbs batch LIBRARY -o OUT --inputs step --site SITE` weighs, by
family and kind of file, against the meshes the library ships beside the same parts.

Measures the files on disk, independently of the command's own figure: SITE/cadnurbs-assets/ (shared
once), and per part SITE/<family>/<part>.html, .cnb and .png; and for each part with a page, the library's
LIBRARY/<family>/<part>.wrl (KiCad's shipped mesh), raw and gzip'd at level 9. Prints Markdown: a row per
family and the total, each with the ratio site ÷ library meshes (the shared files counted once, in the
total only), raw and gzip'd against gzip'd.

  bench/library_site.py LIBRARY SITE
Standard library only.
"""
import argparse
import collections
import gzip
from pathlib import Path


def sizes(path):
    data = path.read_bytes()
    return len(data), len(gzip.compress(data, compresslevel=9, mtime=0))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("library", type=Path)
    parser.add_argument("site", type=Path)
    args = parser.parse_args()
    kinds = (".html", ".cnb", ".png")
    families = collections.defaultdict(lambda: collections.Counter())
    for page in sorted(args.site.glob("*/*.html")):
        family = page.parent.name
        if family == "cadnurbs-assets":
            continue
        part = page.name[: -len(".html")]  # NAME.step
        f = families[family]
        f["parts"] += 1
        for kind in kinds:
            path = page.parent / (part + kind) if kind != ".html" else page
            if path.exists():
                raw, gz = sizes(path)
                f[kind] += raw
                f[kind + " gz"] += gz
        mesh = args.library / family / (Path(part).stem + ".wrl")
        if mesh.exists():
            raw, gz = sizes(mesh)
            f["mesh"] += raw
            f["mesh gz"] += gz
    shared = collections.Counter()
    for path in sorted((args.site / "cadnurbs-assets").iterdir()):
        raw, gz = sizes(path)
        shared["raw"] += raw
        shared["gz"] += gz
    index_raw, index_gz = sizes(args.site / "index.html")

    def mb(n):
        return f"{n / 1e6:.2f}"

    print("| family | parts | pages MB | .cnb MB | pictures MB | site MB | site gz MB | KiCad .wrl MB | KiCad gz MB | site/KiCad | site gz/KiCad gz |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    total = collections.Counter()
    for family, f in sorted(families.items()):
        site = f[".html"] + f[".cnb"] + f[".png"]
        site_gz = f[".html gz"] + f[".cnb gz"] + f[".png gz"]
        print(f"| {family} | {f['parts']} | {mb(f['.html'])} | {mb(f['.cnb'])} | {mb(f['.png'])} | {mb(site)} | {mb(site_gz)} | "
              f"{mb(f['mesh'])} | {mb(f['mesh gz'])} | {site / f['mesh']:.3f} | {site_gz / f['mesh gz']:.3f} |")
        total.update(f)
    site = total[".html"] + total[".cnb"] + total[".png"] + shared["raw"] + index_raw
    site_gz = total[".html gz"] + total[".cnb gz"] + total[".png gz"] + shared["gz"] + index_gz
    print(f"| **total** (with the shared files, {mb(shared['raw'])} MB, and the index, {mb(index_raw)} MB) | {total['parts']} | "
          f"{mb(total['.html'])} | {mb(total['.cnb'])} | {mb(total['.png'])} | {mb(site)} | {mb(site_gz)} | {mb(total['mesh'])} | "
          f"{mb(total['mesh gz'])} | **{site / total['mesh']:.3f}** | {site_gz / total['mesh gz']:.3f} |")


if __name__ == "__main__":
    main()
