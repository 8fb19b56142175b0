"""What the web page's WebAssembly is made of: code bytes by crate.

    python3 tools/wasm_sizes.py target/wasm32-unknown-unknown/web/ke_friction_web.wasm

Reads the module's code section and its `name` section (function names,
which cargo's build keeps and wasm-bindgen strips from the shipped file)
and sums each function body's size under the crate its demangled-enough
name starts with. Prints the sections and the top crates.
"""

import collections
import re
import sys


def leb(data, i):
    value = shift = 0
    while True:
        b = data[i]
        i += 1
        value |= (b & 0x7F) << shift
        shift += 7
        if b < 0x80:
            return value, i


def crate_of(name):
    """The crate of a (legacy-mangled) symbol: `_ZN11ke_friction5model…`
    is ke_friction (`_R…C…4core…`: core); an impl `<T as Trait>::f` counts under T's crate."""
    if name.startswith("__wbindgen_describe"):
        return "(wasm-bindgen descriptors: not shipped)"
    v0 = re.match(r"_R.*?C(?:s[0-9A-Za-z]*_)?(\d+)", name)
    if v0:  # v0 mangling (the precompiled std): the first crate root
        return name[v0.end():v0.end() + int(v0.group(1))]
    m = re.match(r"_ZN(\d+)", name)
    if not m:
        return name.split("::")[0] if "::" in name else "(other)"
    first = name[m.end():m.end() + int(m.group(1))]
    first = first.removeprefix("_").removeprefix("$LT$").lstrip("&$RF$")
    return re.split(r"\.\.|\$", first)[0] or "(other)"


def main(path):
    data = open(path, "rb").read()
    assert data[:4] == b"\0asm", f"{path}: not WebAssembly"
    i = 8
    sections = collections.Counter()
    bodies, names, imported = [], {}, 0
    while i < len(data):
        sid = data[i]
        size, j = leb(data, i + 1)
        end = j + size
        if sid == 0:
            n, k = leb(data, j)
            name = data[k:k + n].decode()
            sections[f"custom {name}"] += end - i
            if name == "name":
                k += n
                while k < end:
                    sub, k = leb(data, k)
                    sub_size, k = leb(data, k)
                    if sub == 1:
                        count, m = leb(data, k)
                        for _ in range(count):
                            idx, m = leb(data, m)
                            ln, m = leb(data, m)
                            names[idx] = data[m:m + ln].decode(errors="replace")
                            m += ln
                    k += sub_size
        else:
            sections[{1: "type", 2: "import", 3: "function", 5: "memory", 6: "global", 7: "export",
                      10: "code", 11: "data"}.get(sid, f"section {sid}")] += end - i
            if sid == 2:
                count, k = leb(data, j)
                for _ in range(count):
                    for _ in range(2):
                        ln, k = leb(data, k)
                        k += ln
                    kind = data[k]
                    k += 1
                    if kind == 0:
                        _, k = leb(data, k)
                        imported += 1
                    elif kind == 1:
                        k += 1
                        flags, k = leb(data, k)
                        _, k = leb(data, k)
                        if flags & 1:
                            _, k = leb(data, k)
                    elif kind == 2:
                        flags, k = leb(data, k)
                        _, k = leb(data, k)
                        if flags & 1:
                            _, k = leb(data, k)
                    else:
                        k += 2
            if sid == 10:
                count, k = leb(data, j)
                for _ in range(count):
                    body, k = leb(data, k)
                    bodies.append(body)
                    k += body
        i = end
    print(f"{path}: {len(data)} bytes")
    for name, size in sections.most_common():
        print(f"  {name:24} {size:9d}")
    crates = collections.Counter()
    for n, body in enumerate(bodies):
        name = names.get(imported + n, "?")
        crates[crate_of(name)] += body
    total = sum(bodies)
    print(f"code by crate ({total} bytes of function bodies):")
    for crate, size in crates.most_common(12):
        print(f"  {crate:24} {size:9d}  {100 * size / total:5.1f} %")


if __name__ == "__main__":
    main(sys.argv[1])
