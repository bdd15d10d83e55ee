#!/usr/bin/env python3
"""Writes glsl-sample-tests.txt, the shader_runner tests the ctest test piglit.glsl_sample runs:
a deterministic sample of glsl-shader-tests.txt, spread over its folders, of tests that pass on
Mesa and run fast on Pineda, chosen from the results.tsv of a full run
(run.sh --list glsl-shader: test, pineda result, mesa result, seconds).

Each folder (the test name up to its last '@') gives its tests in the order of their names'
SHA-1 (a fixed shuffle, so that a folder's share is not just its first names: fs-abs-*), the
folders take turns, and the first --count tests of that order are the sample; so every folder is
represented before any gives a second test, and the large built-in-functions folder does not
crowd out the rest. A test is a candidate when Mesa passes it and Pineda took at most --max-seconds.

Usage: make_glsl_sample.py RESULTS_TSV [--count N] [--max-seconds S] [--out FILE]
"""
import argparse
import hashlib
import os
from collections import defaultdict


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument('results')
    ap.add_argument('--count', type=int, default=300)
    ap.add_argument('--max-seconds', type=int, default=0)
    ap.add_argument('--out', default=os.path.join(here, 'glsl-sample-tests.txt'))
    args = ap.parse_args()

    commands = {}
    with open(os.path.join(here, 'glsl-shader-tests.txt')) as f:
        for line in f:
            if line.startswith('#') or '\t' not in line:
                continue
            name, command = line.rstrip('\n').split('\t', 1)
            commands[name] = command

    folders = defaultdict(list)
    with open(args.results) as f:
        for line in f:
            name, _pineda, mesa, seconds = line.rstrip('\n').split('\t')
            if name in commands and mesa == 'pass' and int(seconds) <= args.max_seconds:
                folders[name.rsplit('@', 1)[0]].append(name)

    queues = [sorted(folders[k], key=lambda n: hashlib.sha1(n.encode()).hexdigest())
              for k in sorted(folders)]
    chosen = []
    turn = 0
    while len(chosen) < args.count and any(queues):
        for q in queues:
            if turn < len(q) and len(chosen) < args.count:
                chosen.append(q[turn])
        turn += 1

    with open(args.out, 'w') as f:
        f.write('# A sample of glsl-shader-tests.txt for the ctest test piglit.glsl_sample, written\n'
                '# by make_glsl_sample.py from a full run: tests that pass on Mesa at GL 2.1 and\n'
                f'# took at most {args.max_seconds} s on Pineda, spread over {len(queues)} folders.\n')
        for name in sorted(chosen):
            f.write(f'{name}\t{commands[name]}\n')
    print(f'{args.out}: {len(chosen)} tests from {len(queues)} folders')


if __name__ == '__main__':
    main()
