#!/usr/bin/env python3
"""Cross-check of kefric's contact.engineering container reading and
combined power spectrum against SurfaceTopography (issue 50).

For each container (../shared/containers/container-2.zip and a synthetic
one this tool builds: one self-affine surface "measured" at three
resolutions, a map as .npy, a profile as x z text, a nonuniform x z text
profile with a tip radius; the same without the nonuniform profile; and the
uniform one as SurfaceTopography writes a container, squeezed.zip: its
measurements as `squeezed-netcdf` NetCDF-3 files only), compares

* the measurements: count, grid points, physical sizes (metres);
* the moments m0, m2, m4 of the whole combined spectrum (the container's
  `c1d_moment(n)`: trapezoids of qⁿ·C over its bins, divided by π);
* the combined 1-D PSD, SurfaceTopography's container
  `power_spectrum(unit='m', nb_points_per_decade=10)`: the same bins, q and
  C within 1e-9 relative at every bin;
* the combined scale-dependent mean square slope and curvature, the
  container's `scale_dependent_statistical_property(lambda x, y=None:
  np.mean(x * x), n=1 or 2, unit='m', nb_points_per_decade=10)`, nonuniform
  line scans included: the same distances, 1e-9 relative at each;

against `cargo run --example container_dump` (or the binary given with
--dump). With --write it stores the synthetic container and the reference
values in tests/data/container/ for the Rust tests (tests/it/container.rs).

Usage: python tools/container_check.py [--dump PATH] [--write]
"""
import argparse
import io
import json
import os
import subprocess
import sys
import zipfile

import numpy as np
from SurfaceTopography.Container.IO import read_container

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DATA = os.path.join(ROOT, 'tests', 'data', 'container')
REAL = os.path.join(ROOT, '..', 'shared', 'containers', 'container-2.zip')
TOL = 1e-9


def synthetic_container(path, nonuniform=True):
    """One self-affine surface (Hurst 0.8) sampled at three resolutions."""
    rng = np.random.default_rng(50)
    n = 4096
    size = 1e-3  # mm, i.e. 1 µm... in the meta unit below (mm)
    q = np.fft.rfftfreq(n, d=size / n) * 2 * np.pi
    amp = np.zeros_like(q)
    amp[1:] = q[1:] ** (-1 - 0.8)
    line = np.fft.irfft(amp * np.exp(2j * np.pi * rng.random(len(q))), n)
    line *= 1e-5 / line.std()
    # 1) a coarse profile (every 8th point) as x z text, uniform
    coarse = line[::8]
    xs = np.arange(len(coarse)) * size / len(coarse)
    coarse_txt = '\n'.join(f'{x:.9e} {z:.9e}' for x, z in zip(xs, coarse)) + '\n'
    # 2) a map of the first 64 x 64 points, indexed [x, y] (.npy)
    fine = line[:64]
    m = np.add.outer(fine, fine[::-1] * 0.5)
    buf = io.BytesIO()
    np.save(buf, m)
    # 3) a nonuniform profile of the first 300 points, as x z text
    pick = np.sort(rng.choice(np.arange(300), 120, replace=False))
    xn = pick * size / n
    nonuniform_txt = '\n'.join(f'{x:.9e} {z:.9e}' for x, z in zip(xn, line[pick])) + '\n'
    meta = f"""surfaces:
- name: synthetic
  topographies:
  - datafile:
      original: coarse.txt
    detrend_mode: height
    is_periodic: false
    size: !!python/tuple
    - {size}
    unit: mm
  - datafile:
      original: map.npy
    detrend_mode: center
    height_scale: 2.0
    is_periodic: false
    size: !!python/tuple
    - {size * 64 / n}
    - {size * 64 / n}
    unit: mm
"""
    if nonuniform:
        meta += """  - datafile:
      original: nonuniform.txt
    detrend_mode: curvature
    instrument:
      parameters:
        tip_radius:
          value: 40
          unit: nm
    unit: mm
"""
    with zipfile.ZipFile(path, 'w', zipfile.ZIP_DEFLATED) as z:
        z.writestr('meta.yml', meta)
        z.writestr('coarse.txt', coarse_txt)
        z.writestr('map.npy', buf.getvalue())
        if nonuniform:
            z.writestr('nonuniform.txt', nonuniform_txt)


def squeezed_container(path, source, only=None):
    """The container at `source` as SurfaceTopography writes one
    (`write_containers`): each measurement a `squeezed-netcdf` file
    (NetCDF-3 64-bit offset, its pipeline applied), index.json and meta.yml;
    `only`: just that measurement (index)."""
    from SurfaceTopography.Container.SurfaceContainer import InMemorySurfaceContainer
    from SurfaceTopography.Container.IO.CE import write_containers
    containers = read_container(source)
    if only is not None:
        containers = [InMemorySurfaceContainer([containers[0][only]])]
    write_containers(containers, path)


def reference(path):
    c = read_container(path)[0]
    measurements = []
    for t in c:
        t = t.to_unit('m')
        measurements.append({'nb_grid_pts': [int(v) for v in t.nb_grid_pts],
                             'physical_sizes': [float(v) for v in t.physical_sizes]})
    q, C = c.power_spectrum(unit='m', nb_points_per_decade=10)
    keep = ~np.ma.getmaskarray(q)
    moments = [float(c.c1d_moment(n, unit='m', nb_points_per_decade=10)) for n in (0, 2, 4)]
    scale = {}
    for name, n in (('slope', 1), ('curvature', 2)):
        d, v = c.scale_dependent_statistical_property(lambda x, y=None: np.mean(x * x), n=n, unit='m',
                                                      nb_points_per_decade=10)
        # NaN (no measurement with 4 values there) is null in JSON.
        scale[name] = {'d': [float(x) for x in d],
                       'v': [float(x) if np.isfinite(x) else None for x in np.asarray(v, float)]}
    return {'measurements': measurements, 'moments': moments, **scale,
            'combined': {'q': [float(v) for v in np.asarray(q)[keep]],
                         'c': [float(v) for v in np.asarray(C)[keep]]}}


def dump(path, binary):
    if binary:
        cmd = [binary, path]
    else:
        cmd = ['cargo', 'run', '-q', '--release', '--example', 'container_dump', '--features', 'topography', '--',
               path]
    return json.loads(subprocess.run(cmd, check=True, capture_output=True, text=True, cwd=ROOT).stdout)


def rel(a, b):
    a, b = np.asarray(a, float), np.asarray(b, float)
    return float(np.max(np.abs(a - b) / np.maximum(np.abs(b), 1e-300)))


def compare(name, ref, got):
    ok = True
    s = got['surfaces'][0]
    ms = s['measurements']
    if len(ms) != len(ref['measurements']):
        print(f'{name}: {len(ms)} measurements, SurfaceTopography {len(ref["measurements"])}')
        return False
    for i, (m, r) in enumerate(zip(ms, ref['measurements'])):
        grid = [m['nx']] + ([m['ny']] if len(r['nb_grid_pts']) == 2 else [])
        size = [v for v in m['size'] if v is not None]
        uniform = m['uniform']
        # A nonuniform profile: SurfaceTopography's grid is its points too.
        if grid != r['nb_grid_pts'] or rel(size, r['physical_sizes']) > TOL:
            print(f'{name}: measurement {i}: grid {grid} size {size}, SurfaceTopography '
                  f'{r["nb_grid_pts"]} {r["physical_sizes"]} (uniform={uniform})')
            ok = False
    q, c = s['combined']['q'], s['combined']['c']
    rq, rc = ref['combined']['q'], ref['combined']['c']
    if len(q) != len(rq):
        print(f'{name}: {len(q)} combined bins, SurfaceTopography {len(rq)}')
        return False
    eq, ec = rel(q, rq), rel(c, rc)
    em = rel(s['moments'], ref['moments'])
    print(f'{name}: {len(q)} bins, max relative difference q {eq:.2e}, C {ec:.2e}, '
          f'm0 m2 m4 (c1d_moment) {em:.2e}; read + PSD {got["seconds"]:.3f} s')
    ok = ok and eq <= TOL and ec <= TOL and em <= TOL
    # Scale-dependent slope and curvature, nonuniform profiles included.
    for kind in ('slope', 'curvature'):
        d, v = s[kind]['d'], s[kind]['v']
        rd, rv = ref[kind]['d'], np.asarray(ref[kind]['v'], float)
        if len(d) != len(rd):
            print(f'{name}: {kind}: {len(d)} distances, SurfaceTopography {len(rd)}')
            ok = False
            continue
        ed = rel(d, rd)
        both = np.isfinite(rv)
        ev = rel(np.asarray(v, float)[both], np.asarray(rv)[both]) if both.any() else 0.0
        same_nan = bool(np.all(np.isnan(np.asarray(v, float)) == ~both))
        print(f'{name}: scale-dependent {kind}: {len(d)} distances, max relative difference '
              f'distance {ed:.2e}, mean square {ev:.2e}')
        ok = ok and ed <= TOL and ev <= TOL and same_nan
    return ok


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--dump', help='the container_dump binary (default: cargo run --release --example)')
    ap.add_argument('--real', default=REAL, help='container-2.zip (default: ../shared/containers/)')
    ap.add_argument('--write', action='store_true', help='store the synthetic container and references')
    args = ap.parse_args()
    os.makedirs(DATA, exist_ok=True)
    synthetic = os.path.join(DATA, 'synthetic.zip')
    uniform = os.path.join(DATA, 'uniform.zip')
    if args.write or not os.path.exists(synthetic):
        synthetic_container(synthetic)
    if args.write or not os.path.exists(uniform):
        synthetic_container(uniform, nonuniform=False)
    # SurfaceTopography 1.27 cannot read back a container it wrote with a
    # nonuniform line scan (its meta.yml gives the scan a size, which the
    # NetCDF reader refuses): squeezed.zip is the uniform one, and the
    # nonuniform scan alone (squeezed-nonuniform.zip) is checked by the Rust
    # tests against the same scan of synthetic.zip.
    squeezed = os.path.join(DATA, 'squeezed.zip')
    if args.write or not os.path.exists(squeezed):
        squeezed_container(squeezed, uniform)
        squeezed_container(os.path.join(DATA, 'squeezed-nonuniform.zip'), synthetic, only=2)
    ok = True
    for name, path in [('container-2', args.real), ('synthetic', synthetic), ('uniform', uniform),
                       ('squeezed', squeezed)]:
        if not os.path.exists(path):
            print(f'{name}: {path} not found, skipped')
            continue
        ref = reference(path)
        if args.write:
            with open(os.path.join(DATA, f'{name}.json'), 'w') as f:
                json.dump(ref, f)
        ok &= compare(name, ref, dump(path, args.dump))
    print('OK' if ok else 'FAILED')
    sys.exit(0 if ok else 1)


if __name__ == '__main__':
    main()
