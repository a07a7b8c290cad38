#!/usr/bin/env python3
"""Every input file of the given folders converted to every output kind: .x3dv, .wrl, .cnb and .stl (the
last through the certified mesh). Issue 38 items 3 and 5: one repair for every path, nothing empty called
success. For each input, either
  - every conversion succeeds, writes a non-empty file, and that file converts again (to .x3dv: convert
    refuses a file without geometry); or
  - every conversion fails with exit status 1, leaves no file behind, and prints the same one line (the
    output's name aside) naming the input.
One difference is allowed, and said: an input holding curves only converts to the NURBS formats and fails
for .stl ("... curves have no place in .stl").

usage: convert_every_input.py CADNURBS [FOLDER...] [--folder-from-env NAME] [--timeout SECONDS]
Prints one line per input and exits 1 when any input breaks the rule. --folder-from-env adds the folder
the environment variable NAME names (files that cannot be fetched where the tests run, such as
openNURBS's example files); when it is unset or not a folder the run prints why and exits 77 (skipped).
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

OUTPUTS = [".x3dv", ".wrl", ".cnb", ".stl"]
INPUTS = (".step", ".stp", ".iges", ".igs", ".3dm", ".stl", ".wrl", ".x3dv", ".x3d", ".cnb")
SKIPPED = 77
CURVES_HAVE_NO_PLACE = re.compile(r"curves have no place in \.stl$")


def inputs_of(folders):
    for folder in folders:
        for name in sorted(os.listdir(folder)):
            path = os.path.join(folder, name)
            if os.path.isfile(path) and name.lower().endswith(INPUTS) and name != "cadnurbs-nurbs-protos.wrl":
                yield path


def convert(cadnurbs, source, output, timeout):
    """Returns (status, message): status 'ok' or 'failed'; message the error line or a fault of the run."""
    try:
        run = subprocess.run([cadnurbs, "convert", source, "-o", output], capture_output=True, text=True,
                             timeout=timeout)
    except subprocess.TimeoutExpired:
        return "fault", f"no answer within {timeout} s"
    if run.returncode == 0:
        if not os.path.exists(output) or os.path.getsize(output) == 0:
            return "fault", "exit 0 with no file or an empty one"
        # Read back by converting again: convert refuses a file without geometry (`info` would do, but
        # its areas cost minutes on heavily trimmed parts).
        again = output + ".x3dv"
        back = subprocess.run([cadnurbs, "convert", output, "-o", again], capture_output=True, text=True,
                              timeout=timeout)
        if back.returncode != 0 or not os.path.exists(again):
            lines = back.stderr.strip().splitlines() or ["(nothing printed)"]
            return "fault", "written file does not read back: " + lines[-1]
        os.remove(again)
        return "ok", ""
    if os.path.exists(output):
        return "fault", f"exit {run.returncode} left {os.path.basename(output)} behind"
    lines = run.stderr.strip().splitlines()
    if run.returncode != 1 or not lines:
        return "fault", f"exit {run.returncode}: {' / '.join(lines[-2:])}"
    last = lines[-1]
    if not last.startswith("cadnurbs convert: ") or source not in last:
        return "fault", "error line does not name the input: " + last
    return "failed", last.replace(output, "OUT")


def judge(results):
    """Returns '' when the input's conversions keep the rule, else why not."""
    faults = [f"{ext}: {message}" for ext, (status, message) in results.items() if status == "fault"]
    if faults:
        return "; ".join(faults)
    failed = {ext: message for ext, (status, message) in results.items() if status == "failed"}
    if not failed:
        return ""
    if list(failed) == [".stl"] and CURVES_HAVE_NO_PLACE.search(failed[".stl"]):
        return ""
    if len(failed) < len(results):
        return "fails for " + ", ".join(failed) + " only: " + next(iter(failed.values()))
    if len(set(failed.values())) > 1:
        return "different errors: " + " | ".join(f"{ext}: {m}" for ext, m in failed.items())
    return ""


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("cadnurbs")
    parser.add_argument("folders", nargs="*")
    parser.add_argument("--folder-from-env", metavar="NAME")
    parser.add_argument("--timeout", type=float, default=900)
    args = parser.parse_args()
    if args.folder_from_env:
        named = os.environ.get(args.folder_from_env, "")
        if not os.path.isdir(named):
            print(f"skipped: {args.folder_from_env} does not name a folder ({named!r})")
            return SKIPPED
        args.folders.append(named)
    broken = 0
    count = 0
    with tempfile.TemporaryDirectory(prefix="every-input-") as folder:
        for source in inputs_of(args.folders):
            count += 1
            stem = os.path.basename(source).replace(".", "_")
            results = {ext: convert(args.cadnurbs, source, os.path.join(folder, stem + ext), args.timeout)
                       for ext in OUTPUTS}
            why = judge(results)
            broken += bool(why)
            states = " ".join(f"{ext}:{results[ext][0]}" for ext in OUTPUTS)
            failure = next((m for s, m in results.values() if s == "failed"), "")
            print(f"{'BROKEN' if why else 'ok    '} {source}: {states}" + (f" ({why})" if why else "") +
                  (f" [{failure}]" if failure and not why else ""), flush=True)
    print(f"{count - broken} of {count} inputs keep the rule")
    return 1 if broken or count == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
