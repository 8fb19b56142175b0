#!/usr/bin/env python3
"""Builds the container of the speed target of issue 50 (docs/PERFORMANCE.md):
ten 1024 x 1024 X3P maps of examples/rough_surface (1 µm a point, the same
waves: the speed, not the statistics, is measured), listed in meta.yml as
ten measurements of one surface (detrend_mode height), deflated into a zip.

Usage: python3 tools/container_ten_maps.py OUT.zip [MAP.x3p]

Without MAP.x3p it runs `cargo run --release --example rough_surface --
TMP.x3p 1024` first (about a minute on a loaded 2-core machine).
"""
import os
import subprocess
import sys
import tempfile
import zipfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
COUNT = 10


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    out = sys.argv[1]
    with tempfile.TemporaryDirectory() as tmp:
        if len(sys.argv) == 3:
            x3p = sys.argv[2]
        else:
            x3p = os.path.join(tmp, 'map.x3p')
            subprocess.run(['cargo', 'run', '-q', '--release', '--features', 'topography', '--example',
                            'rough_surface', '--', x3p, '1024'], check=True, cwd=ROOT)
        with open(x3p, 'rb') as f:
            data = f.read()
    meta = 'surfaces:\n- name: ten maps\n  topographies:\n'
    for k in range(COUNT):
        meta += f'  - datafile:\n      original: map{k}.x3p\n    detrend_mode: height\n    name: map{k}\n'
    with zipfile.ZipFile(out, 'w', zipfile.ZIP_DEFLATED) as z:
        z.writestr('meta.yml', meta)
        for k in range(COUNT):
            z.writestr(f'map{k}.x3p', data)
    print(f'wrote {out}: {COUNT} maps, {os.path.getsize(out)} bytes')


if __name__ == '__main__':
    main()
