#!/usr/bin/env python3
"""ci/format-check on files of its own: a misformatted file is named and fails the check, --fix
reformats it as .clang-format says, and a formatted file passes. Then the tree itself: every
C++ file of raygate formatted (the lead runs `ci/format-check --fix` after merging).
Usage: format_check_test.py SOURCE_DIR. Exit 77 (skipped) when clang-format 14 is missing."""
import os
import subprocess
import sys
import tempfile

SKIP = 77


def check(source_dir, *args):
    return subprocess.run([sys.executable, os.path.join(source_dir, 'ci', 'format-check'), *args],
                          capture_output=True, text=True)


def expect(condition, what, run):
    if not condition:
        print(f'FAIL: {what}\n--- stdout\n{run.stdout}--- stderr\n{run.stderr}')
        sys.exit(1)


def main(source_dir):
    with tempfile.TemporaryDirectory() as folder:
        messy = os.path.join(folder, 'messy.cpp')
        with open(messy, 'w') as f:
            f.write('int   twice( int x ){return 2*x;}\n')
        run = check(source_dir, messy)
        if run.returncode == SKIP:
            print(run.stderr.strip())
            return SKIP
        expect(run.returncode == 1 and 'messy.cpp: ' in run.stdout
               and '1 of 1 C++ files are not formatted' in run.stdout,
               'a misformatted file fails the check, named', run)
        run = check(source_dir, '--fix', messy)
        expect(run.returncode == 0, '--fix succeeds', run)
        with open(messy) as f:
            fixed = f.read()
        expect(fixed == 'int twice(int x) { return 2 * x; }\n',
               f'--fix formats as .clang-format says (got {fixed!r})', run)
        run = check(source_dir, messy)
        expect(run.returncode == 0 and 'all 1 C++ files formatted' in run.stdout,
               'the fixed file passes', run)
        run = check(source_dir, os.path.join(folder, 'absent.cpp'))
        expect(run.returncode == 2 and 'no such file' in run.stderr, 'a missing file is a usage error', run)
    run = check(source_dir)
    lines = run.stdout.strip().splitlines()
    if run.returncode != 0:
        shown = lines[:20] + ([f'... and {len(lines) - 21} more files'] if len(lines) > 21 else []) + lines[-1:]
        print('FAIL: the tree is not formatted as .clang-format says; run ci/format-check --fix\n'
              + '\n'.join(shown) + run.stderr)
        return 1
    print(lines[-1])
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1]))
