#!/usr/bin/env python3
"""Hostile surface files through `kefric surface` and the Python package
(issue 34): each is refused with exit 2 / ValueError, or read right, in
bounded time and memory.

The files are made here (nothing multi-MB is committed): an X3P whose
main.xml nests 20,000 elements; a 2 MB zip bomb declaring 32768 x 32768
16-bit points (2 GiB of data); a 100 MB one-column text file; a 4096 x 4096
16-bit X3P read in full; a CR-only text matrix; an archive with two
main.xml; a truncated archive; an .al3d with 2 million tags, an .opd
with 2 million directory entries, a .nid and a Nanoscope file with 4 MiB
text headers of other sections (header tables streamed or bounded by
what the surface needs, issue 46). And the instruments' files of
../shared/topographies (--topographies) with their grid size inflated:
every field of the header that holds nx or ny (16/32-bit, either byte
order, or decimal text) set, one at a time, to a size of billions of
points; each is refused (exit 2) or read, never a crash, in < 10 s and
within the file's own read peak + 100 MiB.

Peak memory is the child's maximum resident set (`ru_maxrss` from
`os.wait4`, what `/usr/bin/time -v` prints as "Maximum resident set
size"). Limits: < 100 MB and < 1 s for the refused bombs; for a file read,
<= 1.5 x its f64 array + 64 MiB over the program's own baseline (kefric
on a tiny file; Python after importing numpy and ke_friction).

usage: hostile_surfaces.py KEFRIC [--python PYTHON] [--keep DIR] [--topographies DIR]
"""

import argparse
import json
import os
import re
import struct
import subprocess
import sys
import tempfile
import time
import zipfile
import zlib

MIB = 1 << 20


def run(argv):
    """(exit code, stderr, seconds, peak RSS in bytes) of argv."""
    t0 = time.monotonic()
    proc = subprocess.Popen(argv, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    err = proc.stderr.read()
    _, status, usage = os.wait4(proc.pid, 0)
    proc.returncode = os.waitstatus_to_exitcode(status)
    return proc.returncode, err.decode(errors="replace"), time.monotonic() - t0, usage.ru_maxrss * 1024


def main_xml(nx, ny, z_type="D", extra="", feature="SUR"):
    return f"""<?xml version="1.0" encoding="UTF-8"?>
<p:ISO5436_2 xmlns:p="http://www.opengps.eu/2008/ISO5436_2">
 <Record1><Revision>ISO5436 - 2000</Revision><FeatureType>{feature}</FeatureType>
  <Axes><CX><AxisType>I</AxisType><DataType>D</DataType><Increment>1e-6</Increment><Offset>0</Offset></CX>
  <CY><AxisType>I</AxisType><DataType>D</DataType><Increment>1e-6</Increment><Offset>0</Offset></CY>
  <CZ><AxisType>A</AxisType><DataType>{z_type}</DataType><Increment>1e-9</Increment><Offset>0</Offset></CZ></Axes></Record1>
 <Record2><Date>2026-01-01T00:00:00+00:00</Date></Record2>{extra}
 <Record3><MatrixDimension><SizeX>{nx}</SizeX><SizeY>{ny}</SizeY><SizeZ>1</SizeZ></MatrixDimension>
  <DataLink><PointDataLink>bindata/data.bin</PointDataLink></DataLink></Record3>
</p:ISO5436_2>
"""


def write_streamed_member(zf, name, total, piece):
    """A deflated member of `total` bytes repeating `piece`, written in
    pieces (never held whole)."""
    # By name: the archive's compression and level (1: fast on zeros).
    with zf.open(name, "w", force_zip64=total >= 1 << 31) as out:
        block = piece * (MIB // len(piece))
        left = total
        while left:
            n = min(left, len(block))
            out.write(block[:n])
            left -= n


def make_files(d):
    files = {}
    # 20,000 nested elements in a 24 KB main.xml.
    p = os.path.join(d, "deep.x3p")
    deep = "<a>" * 20000 + "</a>" * 20000
    with zipfile.ZipFile(p, "w", zipfile.ZIP_DEFLATED) as z:
        z.writestr("main.xml", main_xml(3, 2, extra=deep))
        z.writestr("bindata/data.bin", struct.pack("<6d", *range(6)))
    files["deep"] = p
    # The bomb: 32768 x 32768 int16 declared, 2 GiB of zeros deflated to
    # ~2 MB (zlib's own stream, written raw: fast).
    p = os.path.join(d, "bomb.x3p")
    total = 32768 * 32768 * 2
    with zipfile.ZipFile(p, "w", zipfile.ZIP_DEFLATED, allowZip64=True, compresslevel=1) as z:
        z.writestr("main.xml", main_xml(32768, 32768, "I"))
        write_streamed_member(z, "bindata/data.bin", total, b"\0" * 4096)
    files["bomb"] = p
    # A 4096 x 4096 int16 map, read in full: 128 MiB of f64 heights.
    p = os.path.join(d, "big.x3p")
    n = 4096
    # A piece one point longer than a row: each row is shifted by one.
    row = struct.pack(f"<{n + 1}h", *[(i * 37) % 2001 - 1000 for i in range(n + 1)])
    with zipfile.ZipFile(p, "w", zipfile.ZIP_DEFLATED, allowZip64=True, compresslevel=1) as z:
        z.writestr("main.xml", main_xml(n, n, "I"))
        write_streamed_member(z, "bindata/data.bin", n * n * 2, row)
    files["big_x3p"] = (p, n * n)
    # 100 MB of one-column text: 10,000,000 lines of "%.6e\n" minus a few.
    p = os.path.join(d, "big.txt")
    lines = 0
    with open(p, "w") as f:
        chunk = "".join(f"{((k * 7919) % 10007 - 5003) * 1e-3:.5e}\n" for k in range(10007))
        size = 0
        while size + len(chunk) <= 100_000_000:
            f.write(chunk)
            size += len(chunk)
            lines += 10007
    files["big_txt"] = (p, lines)
    # A 48 x 64 matrix with CR line ends only.
    p = os.path.join(d, "cr.txt")
    with open(p, "wb") as f:
        rows = [" ".join(str((i * 7 + j * 3) % 11) for i in range(64)) for j in range(48)]
        f.write("\r".join(rows).encode() + b"\r")
    files["cr"] = p
    # Two members named main.xml.
    p = os.path.join(d, "twice.x3p")
    with zipfile.ZipFile(p, "w") as z:
        z.writestr("main.xml", main_xml(3, 2))
        z.writestr("bindata/data.bin", struct.pack("<6d", *range(6)))
        with __import__("warnings").catch_warnings():
            __import__("warnings").simplefilter("ignore")
            z.writestr("main.xml", main_xml(3, 2))
    files["twice"] = p
    # A valid archive cut short.
    p = os.path.join(d, "cut.x3p")
    with zipfile.ZipFile(p, "w", zipfile.ZIP_DEFLATED) as z:
        z.writestr("main.xml", main_xml(64, 64))
        z.writestr("bindata/data.bin", os.urandom(64 * 64 * 8))
    with open(p, "r+b") as f:
        f.truncate(os.path.getsize(p) // 2)
    files["cut"] = p
    files.update(header_tables(d))
    return files


def lines_to(limit, line):
    """line(0), line(1), ... until their lengths add up to ``limit``."""
    lines, size, i = [], 0, 0
    while size < limit:
        lines.append(line(i))
        size += len(lines[-1])
        i += 1
    return lines


def header_tables(d):
    """Instrument files whose header tables hold 2 million entries (issue
    46): an Alicona .al3d with 2,000,000 tags before a 200 x 296 map
    (104 MB) and a Bruker .opd with 2,000,000 directory entries of float
    blocks before a 640 x 480 raster (56 MB), each of its own name.
    Written in pieces."""
    files = {}
    junk = 2_000_000
    # AL3D: 52-byte tags (20-byte key, 30-byte value, CR LF).
    def tag(key, value):
        return key.encode().ljust(20, b"\0") + value.encode().ljust(30, b"\0") + b"\r\n"
    nx, ny = 200, 296
    count = junk + 6
    header = 17 + 52 * (2 + count) + 256
    p = os.path.join(d, "tags.al3d")
    with open(p, "wb") as f:
        f.write(b"AliconaImaging\x00\r\n" + tag("Version", "1") + tag("TagCount", str(count)))
        # Each of its own name (a table of all would hold them all).
        for k in range(0, junk, 10000):
            f.write(b"".join(tag(f"Tag{i}", str(i)) for i in range(k, k + 10000)))
        for k, v in [("Cols", nx), ("Rows", ny), ("PixelSizeXMeter", "1e-6"), ("PixelSizeYMeter", "1e-6"),
                     ("DepthImageOffset", header), ("InvalidPixelValue", "nan")]:
            f.write(tag(k, str(v)))
        f.write(b"\0" * 256)
        for j in range(ny):
            f.write(struct.pack(f"<{nx}f", *[((i * 37 + j * 53) % 101) * 1e-8 for i in range(nx)]))
    files["tags_al3d"] = (p, nx * ny)
    # OPD: 24-byte directory entries (16-byte name, type, length, attributes).
    def entry(name, kind, length):
        return name.encode().ljust(16, b"\0") + struct.pack("<hiH", kind, length, 0)
    nx, ny = 640, 480
    entries = junk + 3
    p = os.path.join(d, "directory.opd")
    with open(p, "wb") as f:
        f.write(b"\0\0" + entry("Directory", 3, 24 * (entries + 1)))
        f.write(entry("Wavelength", 7, 4) + entry("Pixel_size", 7, 4))
        # Each a 4-byte float block of its own name.
        for k in range(0, junk, 10000):
            f.write(b"".join(entry(f"Block{i}", 7, 4) for i in range(k, k + 10000)))
        f.write(entry("RAW DATA", 3, 6 + 4 * nx * ny))
        f.write(struct.pack("<ff", 600.0, 0.001))
        f.write(struct.pack("<f", 1.5) * junk)
        f.write(struct.pack("<HHH", nx, ny, 4))
        for i in range(nx):
            f.write(struct.pack(f"<{ny}f", *[((i * 37 + j * 53) % 101) * 0.01 for j in range(ny)]))
    files["tags_opd"] = (p, nx * ny)
    # Text headers of 4 MiB, of short sections nobody reads, before a
    # 32 x 32 map: a .nid (each "[S1]", "Points=1", "K1=v") and a
    # Nanoscope file (each "\\*S1", "\\K1: v").
    n = 32
    data = struct.pack(f"<{n * n}h", *[(i * 37 + i // n * 53) % 1001 - 500 for i in range(n * n)])
    lines = lines_to((4 << 20) - 4096, lambda i: f"[S{i}]\r\nPoints={i}\r\nK{i}=v\r\n")
    head = (
        "[DataSet]\r\nGroupCount=1\r\nGr0-Count=1\r\nGr0-Ch0=DataSet-0:0\r\n" + "".join(lines)
        + f"[DataSet-0:0]\r\nFrame=Scan forward\r\nPoints={n}\r\nLines={n}\r\nSaveMode=Binary\r\nSaveBits=16\r\n"
        "SaveSign=Signed\r\nSaveOrder=Intel\r\nDim0Range=1e-6\r\nDim1Range=1e-6\r\nDim2Range=1e-7\r\nDim2Unit=m\r\n"
        "Dim2Name=Z\r\n#!"
    )
    p = os.path.join(d, "sections.nid")
    with open(p, "wb") as f:
        f.write(head.encode() + data)
    files["sections_nid"] = (p, n * n)
    lines = lines_to((4 << 20) - 8192, lambda i: f"\\*S{i}\r\n\\K{i}: v\r\n")
    head = (
        "\\*File list\r\n\\Version: 0x05120000\r\n\\*Scanner list\r\n\\@Sens. Zsens: V 20 nm/V\r\n"
        "\\*Ciao scan list\r\n\\Scan Size: 1 1 ~m\r\n" + "".join(lines)
        + f"\\*Ciao image list\r\n\\Data offset: {4 << 20}\r\n\\Data length: {2 * n * n}\r\n\\Samps/line: {n}\r\n"
        f"\\Number of lines: {n}\r\n\\Scan Size: 1 1 ~m\r\n\\@2:Image Data: S [Height] \"Height\"\r\n"
        "\\@2:Z scale: V [Sens. Zsens] (0.006 V/LSB) 2 V\r\n\\*File list end\r\n"
    ).encode("latin-1")
    p = os.path.join(d, "sections.spm")
    with open(p, "wb") as f:
        f.write(head.ljust(4 << 20, b"\0") + data)
    files["sections_spm"] = (p, n * n)
    return files


FAILED = []


def check(ok, what):
    print(("ok    " if ok else "FAIL  ") + what)
    if not ok:
        FAILED.append(what)


def cli(kefric, files, d):
    tiny = os.path.join(d, "tiny.txt")
    with open(tiny, "w") as f:
        f.write("1 2 3 4\n4 3 2 1\n2 2 1 1\n")
    base_args = ["--dx", "1e-6", "--z-unit", "um"]
    _, _, _, base = run([kefric, "surface", tiny, *base_args])
    print(f"kefric baseline peak {base / MIB:.1f} MiB")
    for key, want in [
        ("deep", "nest deeper than 64"),
        ("bomb", "over the limit of 268435456"),
        ("twice", "two members are named main.xml"),
        ("cut", "truncated"),
    ]:
        rc, err, secs, peak = run([kefric, "surface", files[key]])
        check(rc == 2 and want in err, f"kefric {key}: exit {rc}, {err.strip()[:160]!r}")
        check(secs < 1.0 and peak < 100e6, f"kefric {key}: {secs:.2f} s, peak {peak / MIB:.1f} MiB (< 1 s, < 100 MB)")
    # The bomb's points limit is an option.
    rc, err, _, _ = run([kefric, "surface", files["cr"], *base_args, "--max-points", "3000"])
    check(rc == 2 and "3072 points, over the limit of 3000" in err, f"kefric --max-points 3000: exit {rc}, {err.strip()[:160]!r}")
    rc, err, _, _ = run([kefric, "surface", files["cr"], *base_args, "--json"])
    check(rc == 0, f"kefric cr.txt (48 x 64, CR line ends): exit {rc} {err.strip()[:200]}")
    out = subprocess.run([kefric, "surface", files["cr"], *base_args, "--json"], capture_output=True, text=True).stdout
    check('"nx":64' in out.replace(" ", "") and '"ny":48' in out.replace(" ", ""), "kefric cr.txt reads as 64 x 48")
    # Text from a file is escaped in messages; a device is refused as one
    # (issue 46).
    esc = os.path.join(d, "esc.nid")
    with open(esc, "wb") as f:
        f.write(
            b"[DataSet]\r\nGroupCount=1\r\nGr0-Count=1\r\nGr0-Ch0=DataSet-0:0\r\n[DataSet-0:0]\r\n"
            b"Frame=\x1b[2J\x1b]0;pwned\x07\rforged\r\nPoints=4\r\nLines=4\r\nSaveMode=Binary\r\nSaveBits=16\r\n"
            b"Dim0Range=1e-6\r\nDim1Range=1e-6\r\nDim2Range=1\r\nDim2Unit=V\r\nDim2Name=Z\r\n#!" + b"\0" * 32
        )
    rc, err, _, _ = run([kefric, "surface", esc, "--channel", "0"])
    check(
        rc == 2 and "\\u{1b}[2J" in err and not any(c in err for c in "\x1b\x07\r"),
        f"kefric esc.nid: exit {rc}, control characters escaped: {err.strip()[:160]!r}",
    )
    if os.path.exists("/dev/zero"):
        rc, err, secs, _ = run([kefric, "surface", "/dev/zero"])
        check(rc in (1, 2) and "character device" in err and secs < 1.0, f"kefric /dev/zero: exit {rc}, {err.strip()[:160]!r}")
    for key in ["big_txt", "big_x3p", "tags_al3d", "tags_opd", "sections_nid", "sections_spm"]:
        path, points = files[key]
        args = base_args if key in ("big_txt", "big_x3p") else []
        rc, err, secs, peak = run([kefric, "surface", path, *args])
        bound = 1.5 * 8 * points + 64 * MIB
        check(rc == 0, f"kefric {key}: exit {rc} {err.strip()[:200]}")
        check(
            peak - base <= bound,
            f"kefric {key}: {points} points ({8 * points / MIB:.0f} MiB as f64), {secs:.1f} s, peak {peak / MIB:.0f} MiB "
            f"- baseline {base / MIB:.0f} MiB <= {bound / MIB:.0f} MiB",
        )


def inflations(data, nx, ny, header):
    """(what, offset, old length, new bytes) for each field of the first
    `header` bytes that holds nx or ny: binary (u16, u32; little- and
    big-endian) set to the largest of its width, decimal text to
    2000000000. Offsets, not patched copies: the caller patches one at a
    time (this process's own memory counts in its children's peaks)."""
    head = data[:header]
    out = []
    for n in sorted({nx, ny}):
        for fmt, big in [("<H", 0xFFFF), (">H", 0xFFFF), ("<I", 2_000_000_000), (">I", 2_000_000_000)]:
            if n >= 1 << (8 * struct.calcsize(fmt)):
                continue
            pattern = struct.pack(fmt, n)
            at = head.find(pattern)
            while at >= 0:
                out.append((f"{fmt} {n} at {at}", at, len(pattern), struct.pack(fmt, big)))
                at = head.find(pattern, at + 1)
        for m in re.finditer(rb"(?<![0-9.])%d(?![0-9.])" % n, head):
            out.append((f"text {n} at {m.start()}", m.start(), m.end() - m.start(), b"2000000000"))
    return out


def instruments(kefric, topographies, d):
    """Each instrument file with its grid size inflated (module docstring)."""
    names = sorted(f for f in os.listdir(topographies) if not f.endswith(".md"))
    check(len(names) >= 8, f"{len(names)} instrument files in {topographies} (>= 8)")
    for name in names:
        path = os.path.join(topographies, name)
        rc, err, _, base = run([kefric, "surface", path, "--json"])
        out = subprocess.run([kefric, "surface", path, "--json"], capture_output=True, text=True).stdout
        if rc != 0:
            check(False, f"kefric {name}: exit {rc} {err.strip()[:160]}")
            continue
        grid = json.loads(out)["surface"]
        nx, ny = grid["nx"], grid["ny"]
        with open(path, "rb") as f:
            data = f.read()
        cases = inflations(data, nx, ny, 65536)[:24]
        worst, slowest, codes = 0, 0.0, {}
        bad = os.path.join(d, "inflated-" + name)
        for what, at, length, new in cases:
            with open(bad, "wb") as f:
                f.write(data[:at])
                f.write(new)
                f.write(data[at + length:])
            rc, err, secs, peak = run([kefric, "surface", bad])
            codes[rc] = codes.get(rc, 0) + 1
            worst, slowest = max(worst, peak), max(slowest, secs)
            check(rc in (0, 2) and "panicked" not in err, f"kefric {name} {what}: exit {rc} {err.strip()[:160]!r}")
        check(
            worst <= base + 100 * MIB and slowest < 10.0,
            f"kefric {name} ({nx} x {ny}), {len(cases)} inflated sizes (exits {codes}): peak {worst / MIB:.0f} MiB "
            f"<= read peak {base / MIB:.0f} + 100 MiB, slowest {slowest:.2f} s (< 10 s)",
        )
        check(len(cases) > 0, f"kefric {name}: its header holds nx = {nx} or ny = {ny}")


PY_READ = """
import sys, warnings
import numpy, ke_friction as kf
path, kind = sys.argv[1], sys.argv[2]
if kind == "baseline":
    sys.exit(0)
try:
    s = kf.Surface.read(path, dx=1e-6, z_unit=1e-6) if path.endswith(".txt") else kf.Surface.read(path)
    print("read", s.stats["nx"], s.stats["ny"])
except ValueError as e:
    print("ValueError", e, file=sys.stderr)
    sys.exit(3)
"""


def python(py, files):
    _, _, _, base = run([py, "-c", PY_READ, "-", "baseline"])
    print(f"python baseline peak {base / MIB:.1f} MiB")
    for key, want in [("deep", "nest deeper"), ("bomb", "268435456"), ("twice", "two members"), ("cut", "truncated")]:
        rc, err, secs, peak = run([py, "-c", PY_READ, files[key], "read"])
        check(rc == 3 and want in err, f"python {key}: exit {rc} (3 = ValueError), {err.strip()[-160:]!r}")
        check(peak - base < 100e6, f"python {key}: {secs:.2f} s, peak {peak / MIB:.0f} MiB - baseline (< 100 MB)")
    for key in ["big_txt", "tags_al3d", "tags_opd", "sections_nid", "sections_spm"]:
        path, points = files[key]
        rc, err, secs, peak = run([py, "-c", PY_READ, path, "read"])
        bound = 1.5 * 8 * points + 64 * MIB
        check(rc == 0, f"python {key}: exit {rc} {err.strip()[-200:]}")
        check(
            peak - base <= bound,
            f"python {key}: {secs:.1f} s, peak {peak / MIB:.0f} MiB - baseline {base / MIB:.0f} <= {bound / MIB:.0f} MiB",
        )


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("kefric")
    ap.add_argument("--python", help="a Python with ke_friction installed")
    ap.add_argument("--keep", help="write the files here and keep them")
    here = os.path.dirname(os.path.abspath(__file__))
    ap.add_argument(
        "--topographies",
        default=os.environ.get("KEF_TOPOGRAPHIES", os.path.join(here, "..", "..", "shared", "topographies")),
        help="the instruments' example files (default $KEF_TOPOGRAPHIES or ../shared/topographies)",
    )
    a = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        d = a.keep or tmp
        os.makedirs(d, exist_ok=True)
        t0 = time.monotonic()
        files = make_files(d)
        print(f"files made in {time.monotonic() - t0:.1f} s")
        cli(a.kefric, files, d)
        instruments(a.kefric, a.topographies, d)
        if a.python:
            python(a.python, files)
    if FAILED:
        print(f"{len(FAILED)} checks failed")
        sys.exit(1)
    print("all hostile-surface checks passed")


if __name__ == "__main__":
    main()
