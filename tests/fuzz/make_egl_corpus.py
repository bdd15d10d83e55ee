#!/usr/bin/env python3
"""Writes the seed corpus of egl_fuzzer (tests/fuzz/egl_corpus): call programs in the byte
encoding egl_fuzzer.cpp decodes (arguments in call order; clang evaluates them left to right),
so that fuzzing starts from inputs that reach rendering on a current pbuffer."""
import os
import random

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'egl_corpus')

CHOOSE = [2, 2, 16, 15, 17, 17, 0, 1, 8]          # pbuffer + OpenGL configs
PBUFFER = [4, 2, 0, 7, 1, 7, 0, 0]                 # 16x16 pbuffer of the first config
CONTEXT = [6, 0, 0, 0, 0]                          # a context of it
CURRENT = [8, 0, 0, 1, 0]                          # current on the pbuffer
RENDER = [20, 2, 0, 0, 2, 92, 92, 100, 108, 92, 100, 100, 108, 100]
READ = [21, 15, 15, 16, 16]
SWAP = [12, 0, 0]
SYNC = [16, 0, 0, 4, 0, 17, 0, 0, 1]
SURFACELESS = [8, 210, 0, 0, 0]                    # no surfaces, the context
TERMINATE = [1, 0]

SEEDS = {
    'render_pbuffer': CHOOSE + PBUFFER + CONTEXT + CURRENT + RENDER + READ + SWAP,
    'sync': CHOOSE + PBUFFER + CONTEXT + CURRENT + SYNC,
    'surfaceless_context': CHOOSE + CONTEXT + SURFACELESS + RENDER + READ,
    'terminate_current': CHOOSE + PBUFFER + CONTEXT + CURRENT + TERMINATE + RENDER + READ,
    'destroy_current': CHOOSE + PBUFFER + CONTEXT + CURRENT + [5, 0, 0, 7, 0, 0] + RENDER,
}


def main():
    os.makedirs(OUT, exist_ok=True)
    for name, data in SEEDS.items():
        with open(os.path.join(OUT, name), 'wb') as handle:
            handle.write(bytes(data))
    rng = random.Random(18)
    for i in range(4):
        with open(os.path.join(OUT, 'random_%d' % i), 'wb') as handle:
            handle.write(bytes(CHOOSE + [rng.randrange(256) for _ in range(400)]))


if __name__ == '__main__':
    main()
