#!/usr/bin/env python3
"""Writes piglit's GLSL 1.10/1.20 test lists from the test lists Debian's piglit package installs
(tests/shader.xml.gz, tests/glslparser.xml.gz), in the format run.sh reads: one test per line,
`NAME<TAB>COMMAND`, the command relative to piglit's root (/usr/lib/x86_64-linux-gnu/piglit).

  glsl-shader-tests.txt  shader_runner over spec/glsl-1.10 and spec/glsl-1.20, with the generated
                         built-in function tests (execution@built-in-functions)
  glsl-parser-tests.txt  glslparsertest over every desktop parser test of GLSL 1.10 and 1.20,
                         whatever spec folder it is in (extensions included)

Usage: make_glsl_lists.py [--piglit DIR] [--out DIR]
"""
import argparse
import ast
import gzip
import os
import xml.etree.ElementTree as ET


def tests(path):
    with gzip.open(path) as f:
        for test in ET.parse(f).getroot().iter('Test'):
            options = {o.get('name'): o.get('value') for o in test.iter('option')}
            yield test.get('name'), test.get('type'), options


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument('--piglit', default='/usr/lib/x86_64-linux-gnu/piglit')
    ap.add_argument('--out', default=os.path.dirname(os.path.abspath(__file__)))
    args = ap.parse_args()

    shader = []
    for name, kind, opt in tests(os.path.join(args.piglit, 'tests', 'shader.xml.gz')):
        if kind != 'shader' or not name.startswith(('spec@glsl-1.10@', 'spec@glsl-1.20@')):
            continue
        command = ast.literal_eval(opt['command'])
        # Window mode (-auto without -fbo): -fbo needs framebuffer objects (LIST.md).
        shader.append((name, ' '.join(command + ['-auto'])))

    parser = []
    for name, kind, opt in tests(os.path.join(args.piglit, 'tests', 'glslparser.xml.gz')):
        if kind != 'glsl_parser' or opt.get('shader_version') not in ('1.1', '1.2'):
            continue
        command = ast.literal_eval(opt['command'])
        if command[0] != 'glslparsertest':  # the GLSL ES binary
            continue
        parser.append((name, ' '.join(command)))

    for filename, rows, what in (('glsl-shader-tests.txt', shader, 'shader_runner'),
                                 ('glsl-parser-tests.txt', parser, 'glslparsertest')):
        with open(os.path.join(args.out, filename), 'w') as f:
            f.write(f'# piglit {what} tests of GLSL 1.10/1.20, written by make_glsl_lists.py\n')
            for name, command in sorted(rows):
                f.write(f'{name}\t{command}\n')
        print(f'{filename}: {len(rows)} tests')


if __name__ == '__main__':
    main()
