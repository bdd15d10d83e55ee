#!/usr/bin/env python3
"""Extracts the GLSL programs of piglit's GLSL 1.10/1.20 tests into one small text file each.

The tests are the ones conformance/piglit/glsl-shader-tests.txt (shader_runner .shader_test
files: their vertex and fragment shaders, "[vertex shader passthrough]" as the passthrough shader
shader_runner uses) and glsl-parser-tests.txt (glslparsertest .vert/.frag files: one shader)
list. Tests that need an extension, another shader stage or a GLSL version above 1.20 are left
out. Each output file is the framing the GLSL fuzzer (tests/fuzz/glsl_fuzzer.cpp) and the
compile-time tool (bench/glsl_compile_time.cpp) read:

    # piglit tests/spec/glsl-1.10/execution/foo.shader_test
    [vertex shader]
    ...
    [fragment shader]
    ...

Lines before the first section are comments. A stage may have several shaders (each section is
one shader object) or none (fixed function).

Usage: piglit_glsl_pairs.py --out DIR [--piglit DIR] [--lists FILE...] [--kind shader|parser|all]
                            [--max N] [--max-bytes N] [--every N]
"""
import argparse
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
LISTS = [os.path.join(ROOT, 'conformance', 'piglit', name)
         for name in ('glsl-shader-tests.txt', 'glsl-parser-tests.txt')]

# shader_runner's "[vertex shader passthrough]" (piglit's shader_runner.c passes gl_Vertex on).
PASSTHROUGH_VS = '#version 110\nvoid main() { gl_Position = gl_Vertex; }\n'

SECTION = re.compile(r'^\s*\[(.*)\]\s*$')


def shader_test_program(text):
    """[(stage, source)] of a .shader_test, or None when the test needs what we leave out."""
    shaders = []
    section, body = None, []
    glsl120 = False

    def flush():
        if section in ('vertex shader', 'fragment shader'):
            shaders.append((section.split()[0], ''.join(body)))

    for line in text.splitlines(keepends=True):
        m = SECTION.match(line)
        if m:
            flush()
            section, body = m.group(1), []
            if section == 'vertex shader passthrough':
                shaders.append(('vertex', PASSTHROUGH_VS))
            elif section not in ('require', 'vertex shader', 'fragment shader', 'test',
                                 'vertex data', 'config'):
                return None  # geometry shaders, shader files, ...
            continue
        if section == 'require':
            w = line.split()
            if not w or w[0].startswith('#'):
                continue
            if w[0] == 'GLSL' and len(w) >= 3:
                if w[1] == 'ES':
                    return None
                try:
                    v = float(w[2])
                except ValueError:
                    return None
                if (w[1] == '>=' and v > 1.201) or (w[1] == '>' and v >= 1.2):
                    return None
                if w[1] == '>=' and v > 1.101:
                    glsl120 = True
            elif w[0].startswith('GL_') and not w[0].startswith('GL_MAX'):
                return None
            elif w[0] == 'GL' and len(w) >= 2 and w[1] == 'ES':
                return None
        elif section in ('vertex shader', 'fragment shader'):
            body.append(line)
    flush()
    if not shaders:
        return None
    # shader_runner puts the required version in front of a shader without one.
    if glsl120:
        shaders = [(st, src if '#version' in src else '#version 120\n' + src)
                   for st, src in shaders]
    return shaders


def parser_test_program(path, text):
    stage = 'vertex' if path.endswith('.vert') else 'fragment' if path.endswith('.frag') else None
    return [(stage, text)] if stage else None


def entries(list_files, kind):
    for list_file in list_files:
        with open(list_file) as f:
            for line in f:
                if line.startswith('#') or '\t' not in line:
                    continue
                name, command = line.rstrip('\n').split('\t', 1)
                words = command.split()
                if words[0] == 'shader_runner' and kind in ('shader', 'all'):
                    yield name, words[1]
                elif words[0] == 'glslparsertest' and kind in ('parser', 'all'):
                    # Arguments: file, expected result, version, then required extensions
                    # ("!GL_x" means the test wants it absent, which Pineda satisfies).
                    if any(not w.startswith(('!', '--')) for w in words[4:]):
                        continue
                    yield name, words[1]


def framed(rel, shaders):
    out = ['# piglit %s\n' % rel]
    for stage, src in shaders:
        out.append('[%s shader]\n' % stage)
        out.append(src if src.endswith('\n') else src + '\n')
    return ''.join(out)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument('--piglit', default='/usr/lib/x86_64-linux-gnu/piglit')
    ap.add_argument('--lists', nargs='+', default=LISTS)
    ap.add_argument('--kind', choices=('shader', 'parser', 'all'), default='all')
    ap.add_argument('--out', required=True)
    ap.add_argument('--every', type=int, default=1, help='take every Nth test of the lists')
    ap.add_argument('--max', type=int, default=0, help='at most N files (0: no limit)')
    ap.add_argument('--max-bytes', type=int, default=0,
                    help='leave out programs larger than N bytes (0: no limit)')
    args = ap.parse_args()

    os.makedirs(args.out, exist_ok=True)
    written = skipped = 0
    for i, (name, rel) in enumerate(entries(args.lists, args.kind)):
        if i % args.every:
            continue
        path = os.path.join(args.piglit, rel)
        try:
            with open(path, encoding='utf-8', errors='replace') as f:
                text = f.read()
        except OSError:
            skipped += 1
            continue
        if rel.endswith('.shader_test'):
            shaders = shader_test_program(text)
        else:
            shaders = parser_test_program(rel, text)
        if not shaders:
            skipped += 1
            continue
        data = framed(rel, shaders)
        if args.max_bytes and len(data.encode()) > args.max_bytes:
            skipped += 1
            continue
        file_name = re.sub(r'[^A-Za-z0-9_.-]+', '_', name.replace('@', '.')) + '.txt'
        with open(os.path.join(args.out, file_name), 'w') as f:
            f.write(data)
        written += 1
        if args.max and written >= args.max:
            break
    print('%d programs written to %s, %d tests left out' % (written, args.out, skipped),
          file=sys.stderr)


if __name__ == '__main__':
    main()
