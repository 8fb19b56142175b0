#!/usr/bin/env python3
"""Writes the hostile seeds of the surface_container fuzz target
(fuzz/seeds/surface_container/, issue 50): small files that start the
fuzzer at the containers a reader must refuse cleanly.

* lying_meta.bin: meta.yml gives a map's size (two values) and a unit for
  a profile; the target zips it with the data file p.txt;
* missing_member.zip: meta.yml names a data file not in the archive;
* deep_yaml.bin: meta.yml nested 200 levels deep (over the reader's 64);
* bomb.zip: a data file of 2 MiB of zeros deflated to a few KiB (over the
  fuzz target's 1 MiB a member);
* bomb_lying.zip: the same, its headers claiming 100 bytes inflated;
* netcdf_only.zip: a measurement with only a `squeezed-netcdf` file (a
  tiny NetCDF-3 classic file written by hand here, as SurfaceTopography
  writes them: dimensions x (and y), a variable `heights`, attributes).

Usage: python3 tools/container_fuzz_seeds.py [DIR]
"""
import io
import os
import struct
import sys
import zipfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DIR = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, 'fuzz', 'seeds', 'surface_container')


def zipped(members):
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, 'w', zipfile.ZIP_DEFLATED) as z:
        for name, data in members:
            z.writestr(name, data)
    return buf.getvalue()


def lie_about_size(data, name, size):
    """Sets the inflated size of `name` in its local and central headers."""
    b = bytearray(data)
    n = name.encode()
    # (signature, offset of the name's length, of the name, of the size)
    for sig, name_len, name_at, size_at in ((b'PK\x03\x04', 26, 30, 22), (b'PK\x01\x02', 28, 46, 24)):
        at = b.find(sig)
        while at >= 0:
            ln = struct.unpack_from('<H', b, at + name_len)[0]
            if bytes(b[at + name_at:at + name_at + ln]) == n:
                struct.pack_into('<I', b, at + size_at, size)
            at = b.find(sig, at + 4)
    return bytes(b)


def netcdf_classic(nx, heights):
    """A NetCDF-3 classic file: dimension x, variable heights(x) double,
    a global attribute and a variable attribute `unit`."""
    def name(s):
        s = s.encode()
        return struct.pack('>i', len(s)) + s + b'\0' * (-len(s) % 4)

    def attr(key, text):
        t = text.encode()
        return name(key) + struct.pack('>ii', 2, len(t)) + t + b'\0' * (-len(t) % 4)

    header = b'CDF\x01' + struct.pack('>i', 0)
    header += struct.pack('>ii', 10, 1) + name('x') + struct.pack('>i', nx)
    header += struct.pack('>ii', 12, 1) + attr('title', 'seed')
    var = name('heights') + struct.pack('>i', 1) + struct.pack('>i', 0)
    var += struct.pack('>ii', 12, 1) + attr('unit', 'nm')
    var += struct.pack('>ii', 6, 8 * nx)
    begin_at = len(header) + 8 + len(var)
    data = struct.pack('>%dd' % nx, *heights)
    header += struct.pack('>ii', 11, 1) + var + struct.pack('>i', begin_at + 4)
    return header + data


def main():
    os.makedirs(DIR, exist_ok=True)
    seeds = {}
    seeds['lying_meta.bin'] = (b'surfaces:\n- topographies:\n  - datafile: {original: p.txt}\n'
                               b'    unit: nm\n    size: [8.0, 3.0]\n    height_scale: 2\n'
                               b'\x001\n2\n3\n2\n1\n0\n1\n2\n')
    seeds['missing_member.zip'] = zipped([('meta.yml', 'surfaces:\n- topographies:\n'
                                                       '  - datafile: {original: gone.txt}\n    unit: nm\n'),
                                          ('p.txt', '1\n2\n3\n')])
    seeds['deep_yaml.bin'] = b'surfaces: ' + b'[' * 200 + b']' * 200 + b'\n\x001\n2\n'
    meta = 'surfaces:\n- topographies:\n  - datafile: {original: p.txt}\n    unit: nm\n    size: [8.0]\n'
    bomb = zipped([('meta.yml', meta), ('p.txt', b'0\n' * (1 << 20))])
    seeds['bomb.zip'] = bomb
    seeds['bomb_lying.zip'] = lie_about_size(bomb, 'p.txt', 100)
    nc_meta = ('surfaces:\n- topographies:\n  - datafile: {squeezed-netcdf: m.nc}\n'
               '    unit: nm\n    size: [8.0]\n')
    seeds['netcdf_only.zip'] = zipped([('meta.yml', nc_meta),
                                       ('m.nc', netcdf_classic(8, [1, 2, 3, 2, 1, 0, 1, 2]))])
    for name, data in seeds.items():
        with open(os.path.join(DIR, name), 'wb') as f:
            f.write(data)
        print(f'{name}: {len(data)} bytes')


if __name__ == '__main__':
    main()
