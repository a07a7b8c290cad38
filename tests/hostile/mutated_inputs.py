#!/usr/bin/env python3
"""Damaged variants of real files, and what cadnurbs does with them.

usage: mutated_inputs.py [--per-kind N] CADNURBS WORK_DIR SEED...

For every SEED (STEP, IGES, STL ASCII or binary, VRML97, X3D classic, X3D XML) it writes 22 variants
into WORK_DIR/inputs, seven kinds of damage an attacker or a broken exporter produces:

  truncated   the first 0 %, 1 %, 25 %, 50 %, 99 % of the bytes
  flipped     1, 8, 64 or 512 bytes XOR'd anywhere, or 4 in the first 100 bytes
  numbers     numbers replaced by inf, nan, 1e308, -1e400 or a 30-digit integer
              (binary STL: float32 inf, nan, max, -inf, a denormal)
  nesting     100,000 levels where the format nests (STEP parentheses, VRML nodes, XML elements);
              STL, which does not nest, gets a facet with 100,000 vertices instead
  huge        a 1,000,000-item list (STEP, VRML) or a count far beyond the data (IGES parameter
              and directory pointers, binary STL triangle count), an ASCII STL line of 1,000,000 numbers
  spliced     a tenth deleted, a tenth repeated, 1 KiB of random bytes inserted
  lines       two lines swapped, one line repeated 1,000 times (binary: two 50-byte blocks swapped)

and runs `CADNURBS convert VARIANT -o out.x3dv` and `CADNURBS info VARIANT` on each, each in an empty
folder of its own, two at a time. Every run must: not die by a signal, end within 30 s, stay under
4 GiB of peak RSS (its own or a child's), leave the variant unchanged; a failed run must print exactly
one stderr line that names the variant's path, and leave its folder empty (no output, no temporary);
a convert that succeeds leaves out.x3dv and nothing else. Prints the counts per seed type and kind,
and every violation; exits 1 if there was one. The variants are made from a fixed random seed, so a
run is repeatable.
"""
import concurrent.futures
import hashlib
import os
import random
import re
import shutil
import signal
import struct
import sys
import time

TIME_LIMIT_S = 30
HARD_KILL_S = 90
MEMORY_LIMIT_KB = 4 * 1024 * 1024

NUMBER = re.compile(rb'(?<![A-Za-z0-9_#.])[-+]?\d+\.\d*(?:[eEdD][-+]?\d+)?')


def seed_type(path, data):
    ext = os.path.splitext(path)[1].lower()
    if ext in ('.step', '.stp'):
        return 'step'
    if ext in ('.iges', '.igs'):
        return 'iges'
    if ext == '.stl':
        count = struct.unpack_from('<I', data, 80)[0] if len(data) >= 84 else -1
        return 'stl-binary' if len(data) == 84 + 50 * count else 'stl-ascii'
    if ext in ('.wrl', '.x3dv', '.x3d'):
        return ext[1:]
    raise SystemExit(f'mutated_inputs.py: {path}: not a seed type this script knows')


# --- the kinds of damage; each returns a list of (variant name, bytes) ---------------------------------

def truncated(kind, data, rng):
    return [(f'{int(f * 100)}pc', data[:int(len(data) * f)]) for f in (0, 0.01, 0.25, 0.5, 0.99)]


def flip(data, rng, count, limit=None):
    out = bytearray(data)
    for _ in range(count):
        i = rng.randrange(min(len(out), limit or len(out)))
        out[i] ^= rng.randrange(1, 256)
    return bytes(out)


def flipped(kind, data, rng):
    variants = [(f'{n}', flip(data, rng, n)) for n in (1, 8, 64, 512)]
    return variants + [('head4', flip(data, rng, 4, 100))]


def replace_numbers(data, rng, word):
    """Every number in a random stretch of 1/20 of the file, and one more picked anywhere."""
    matches = list(NUMBER.finditer(data))
    if not matches:
        return data + b' ' + word
    start = rng.randrange(len(matches))
    chosen = set(range(start, min(len(matches), start + max(1, len(matches) // 20))))
    chosen.add(rng.randrange(len(matches)))
    out, last = bytearray(), 0
    for i, m in enumerate(matches):
        if i in chosen:
            out += data[last:m.start()] + word
            last = m.end()
    return bytes(out + data[last:])


def numbers(kind, data, rng):
    if kind == 'stl-binary':
        values = {'inf': float('inf'), 'nan': float('nan'), 'max': 3.4028234e38, 'neginf': float('-inf'),
                  'denormal': 1e-45}
        count = (len(data) - 84) // 50
        variants = []
        for name, value in values.items():
            out = bytearray(data)
            for _ in range(max(1, count // 20)):
                t = rng.randrange(count)
                struct.pack_into('<f', out, 84 + 50 * t + 12 + 4 * rng.randrange(9), value)
            variants.append((name, bytes(out)))
        return variants
    words = {'inf': b'inf', 'nan': b'NaN', 'e308': b'1e308', 'e400': b'-1e400',
             'digits30': b'123456789012345678901234567890'}
    return [(name, replace_numbers(data, rng, word)) for name, word in words.items()]


def insert_after(data, pattern, text):
    """data with text inserted after the first match of the regular expression pattern."""
    m = re.search(pattern, data)
    if not m:
        raise SystemExit(f'mutated_inputs.py: a seed lacks {pattern!r}')
    return data[:m.end()] + text + data[m.end():]


STEP_POINT_LIST = rb"CARTESIAN_POINT\('[^']*',\("
VRML_POINT_LIST = rb'[Pp]oint\s*\['


def nesting(kind, data, rng):
    depth = 100_000
    if kind == 'step':
        out = insert_after(data, STEP_POINT_LIST, b'(' * depth + b'1.' + b')' * depth + b',')
    elif kind == 'iges':  # IGES does not nest; a Hollerith string that claims to hold 100,000 characters
        out = re.sub(rb'(\d+)H', b'100000H', data, count=1)
    elif kind in ('wrl', 'x3dv'):
        out = data + b'\nGroup { children [ ' * depth + b'] } ' * depth
    elif kind == 'x3d':
        out = insert_after(data, rb'<Scene[^>]*>', b'<Group>' * depth + b'</Group>' * depth)
    elif kind == 'stl-ascii':
        out = insert_after(data, rb'outer loop\s*\n', b'      vertex 0 0 0\n' * depth)
    else:  # stl-binary: a triangle count of 100,000 more than the data holds
        out = bytearray(data)
        struct.pack_into('<I', out, 80, struct.unpack_from('<I', data, 80)[0] + depth)
        out = bytes(out)
    return [('100000', out)]


def huge(kind, data, rng):
    million = 1_000_000
    if kind == 'step':
        out = insert_after(data, STEP_POINT_LIST, b'0.,' * million)
    elif kind == 'iges':  # the first directory entry's parameter-data pointer far past the file
        lines = data.split(b'\n')
        d = next(i for i, line in enumerate(lines) if len(line) >= 73 and line[72:73] == b'D')
        lines[d] = lines[d][:8] + b'99999999' + lines[d][16:]
        out = b'\n'.join(lines)
    elif kind in ('wrl', 'x3dv'):
        out = insert_after(data, VRML_POINT_LIST, b' 0 0 0,' * million)
    elif kind == 'x3d':
        out = insert_after(data, rb"[Pp]oint='", b' 0 0 0' * million)
    elif kind == 'stl-ascii':
        out = insert_after(data, rb'vertex', b' 1' * million)
    else:  # stl-binary: the largest count a uint32 holds
        out = bytearray(data)
        struct.pack_into('<I', out, 80, 0xFFFFFFFF)
        out = bytes(out)
    return [('1000000', out)]


def spliced(kind, data, rng):
    n = len(data)
    a = rng.randrange(n - n // 10)
    b = a + n // 10
    garbage = bytes(rng.randrange(256) for _ in range(1024))
    at = rng.randrange(n)
    return [('delete', data[:a] + data[b:]), ('repeat', data[:b] + data[a:b] + data[b:]),
            ('garbage', data[:at] + garbage + data[at:])]


def lines(kind, data, rng):
    if kind == 'stl-binary':
        count = (len(data) - 84) // 50
        i, j = sorted(rng.sample(range(count), 2))
        a, b = 84 + 50 * i + 7, 84 + 50 * j + 7  # misaligned by 7 bytes
        out = data[:a] + data[b:b + 50] + data[a + 50:b] + data[a:a + 50] + data[b + 50:]
        return [('swap', out), ('repeat', data[:a] + data[a:a + 50] * 1000 + data[a:])]
    rows = data.split(b'\n')
    i, j = sorted(rng.sample(range(len(rows)), 2))
    swapped = rows[:]
    swapped[i], swapped[j] = swapped[j], swapped[i]
    k = rng.randrange(len(rows))
    repeated = rows[:k] + [rows[k]] * 1000 + rows[k + 1:]
    return [('swap', b'\n'.join(swapped)), ('repeat', b'\n'.join(repeated))]


KINDS = [('truncated', truncated), ('flipped', flipped), ('numbers', numbers), ('nesting', nesting),
         ('huge', huge), ('spliced', spliced), ('lines', lines)]


# --- running cadnurbs on a variant -----------------------------------------------------------------------

def run(command, folder):
    """Runs command in folder; returns (exit status or -signal, seconds, peak RSS in KiB, stderr)."""
    stderr_path = folder + '.stderr'
    with open(stderr_path, 'wb') as stderr, open(os.devnull, 'wb') as devnull:
        start = time.monotonic()
        pid = os.posix_spawn(command[0], command, os.environ,
                             file_actions=[(os.POSIX_SPAWN_OPEN, 0, os.devnull, os.O_RDONLY, 0),
                                           (os.POSIX_SPAWN_DUP2, devnull.fileno(), 1),
                                           (os.POSIX_SPAWN_DUP2, stderr.fileno(), 2)],
                             setpgroup=0)
        # chdir is not a posix_spawn action before Python 3.13: commands use absolute paths and
        # `folder` only receives the output.
        killed = False
        while True:
            done, status, usage = os.wait4(pid, os.WNOHANG)
            if done:
                break
            if time.monotonic() - start > HARD_KILL_S and not killed:
                os.killpg(pid, signal.SIGKILL)
                killed = True
            time.sleep(0.02)
        seconds = time.monotonic() - start
    with open(stderr_path, 'rb') as f:
        text = f.read().decode('utf-8', 'replace')
    os.remove(stderr_path)
    code = -os.WTERMSIG(status) if os.WIFSIGNALED(status) else os.WEXITSTATUS(status)
    return code, seconds, usage.ru_maxrss, text


def check(cadnurbs, variant, folder, command_name):
    os.makedirs(folder)
    before = hashlib.sha256(open(variant, 'rb').read()).hexdigest()
    output = os.path.join(folder, 'out.x3dv')
    command = [cadnurbs, 'convert', variant, '-o', output] if command_name == 'convert' else [cadnurbs, 'info', variant]
    code, seconds, rss_kb, stderr = run(command, folder)
    problems = []
    if code < 0:
        problems.append(f'died by signal {-code}')
    if seconds > TIME_LIMIT_S:
        problems.append(f'took {seconds:.1f} s')
    if rss_kb > MEMORY_LIMIT_KB:
        problems.append(f'peak RSS {rss_kb // 1024} MiB')
    if hashlib.sha256(open(variant, 'rb').read()).hexdigest() != before:
        problems.append('changed its input')
    left = sorted(os.listdir(folder))
    if code != 0:
        error_lines = stderr.splitlines()
        if len(error_lines) != 1:
            problems.append(f'{len(error_lines)} stderr lines: {stderr[:300]!r}')
        elif variant not in error_lines[0]:
            problems.append(f'stderr does not name the input: {error_lines[0][:300]!r}')
        if left:
            problems.append(f'left {left} after failing')
    elif command_name == 'convert' and left != ['out.x3dv']:
        problems.append(f'succeeded leaving {left}')
    shutil.rmtree(folder)
    return code == 0, seconds, rss_kb, problems


def main():
    args = sys.argv[1:]
    per_kind = None
    if args[:1] == ['--per-kind']:
        if len(args) < 2 or not args[1].isdigit() or int(args[1]) < 1:
            raise SystemExit(__doc__)
        per_kind, args = int(args[1]), args[2:]
    if len(args) < 3:
        raise SystemExit(__doc__)
    cadnurbs, work, seeds = os.path.abspath(args[0]), os.path.abspath(args[1]), args[2:]
    shutil.rmtree(work, ignore_errors=True)
    inputs, runs = os.path.join(work, 'inputs'), os.path.join(work, 'runs')
    os.makedirs(inputs)
    os.makedirs(runs)
    rng = random.Random(20261126)
    variants = []  # (seed type, kind, path)
    for seed in seeds:
        data = open(seed, 'rb').read()
        kind_of_seed = seed_type(seed, data)
        stem, ext = os.path.splitext(os.path.basename(seed))
        for kind, make in KINDS:
            for n, (name, damaged) in enumerate(make(kind_of_seed, data, rng)):
                if per_kind is not None and n >= per_kind:
                    continue  # made all the same, so that the random numbers stay those of a whole run
                path = os.path.join(inputs, f'{stem}.{kind}-{name}{ext}')
                with open(path, 'wb') as f:
                    f.write(damaged)
                variants.append((kind_of_seed, kind, path))
    print(f'{len(variants)} variants of {len(seeds)} seeds in {inputs}')

    jobs = [(v, c) for v in variants for c in ('convert', 'info')]
    results = {}
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        futures = {pool.submit(check, cadnurbs, path, os.path.join(runs, f'{i}-{command}'), command):
                   (seed_kind, kind, path, command) for i, ((seed_kind, kind, path), command) in enumerate(jobs)}
        for future in concurrent.futures.as_completed(futures):
            results[futures[future]] = future.result()

    # counts per seed type and kind: variants, convert succeeded / refused, info succeeded / refused
    table = {}
    violations = []
    slowest, largest = 0.0, 0
    for (seed_kind, kind, path, command), (ok, seconds, rss_kb, problems) in sorted(results.items()):
        row = table.setdefault((seed_kind, kind), {'convert': [0, 0], 'info': [0, 0]})
        row[command][0 if ok else 1] += 1
        slowest, largest = max(slowest, seconds), max(largest, rss_kb)
        violations += [f'{command} {path}: {p}' for p in problems]
    print(f'{"seed type":<11} {"kind":<10} {"files":>5} {"convert ok":>10} {"refused":>7} {"info ok":>7} {"refused":>7}')
    totals = [0, 0, 0, 0, 0]
    for (seed_kind, kind), row in sorted(table.items()):
        counts = [row['convert'][0] + row['convert'][1], *row['convert'], *row['info']]
        totals = [t + c for t, c in zip(totals, counts)]
        print(f'{seed_kind:<11} {kind:<10} {counts[0]:>5} {counts[1]:>10} {counts[2]:>7} {counts[3]:>7} {counts[4]:>7}')
    print(f'{"all":<11} {"":<10} {totals[0]:>5} {totals[1]:>10} {totals[2]:>7} {totals[3]:>7} {totals[4]:>7}')
    print(f'slowest run {slowest:.1f} s, largest peak RSS {largest // 1024} MiB')
    for v in violations:
        print('VIOLATION ' + v)
    return 1 if violations else 0


if __name__ == '__main__':
    sys.exit(main())
