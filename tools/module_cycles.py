#!/usr/bin/env python3
"""Import cycles between the Rust source files of each crate of the
workspace: file A imports file B when A names (in a `use` or a path in its
code) an item that B defines. Imports are followed to the defining file;
re-exports (`pub use`, `pub(crate) use`) and `mod` lines draw no import of
their own; a file's use of what an enclosing module defines (a folder's
mod.rs: a reader's ReadError, a family's Density) is the module tree and
does not count; unit tests (`#[cfg(test)] mod tests`, `tests.rs`) are
left out. Prints every cycle with the names that tie it; exits 1 if there
is one, 0 if none.

    python3 tools/module_cycles.py [ROOT]

Reads the code as text (no macro expansion): a path written inside a
macro's arguments counts; a path built by a macro does not.
"""
import os
import re
import sys

# crate root file -> the folder its modules live in
CRATES = ["src/lib.rs", "cli/src/main.rs", "ffi/src/lib.rs", "python/src/lib.rs", "web/src/lib.rs"]


def strip(text):
    """Comments, strings and the unit tests out."""
    text = re.sub(r"//[^\n]*", "", text)
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    text = re.sub(r'(?<!\w)r(#*)"(?:.|\n)*?"\1', '""', text)
    text = re.sub(r'"(?:\\.|[^"\\])*"', '""', text)
    text = re.sub(r"'(?:\\.|[^'\\])'", "' '", text)
    cut = re.search(r"#\[cfg\(test\)\]\s*(pub(\(\w+\))?\s+)?mod\s+\w+\s*\{", text)
    if cut:
        # a test module runs to the end of the file, or to its closing brace
        depth, i = 0, text.index("{", cut.start())
        for j in range(i, len(text)):
            depth += {"{": 1, "}": -1}.get(text[j], 0)
            if depth == 0:
                text = text[: cut.start()] + text[j + 1:]
                break
    return text


def modules(root, crate_root):
    """{module path tuple: file} of one crate."""
    found = {(): crate_root}
    todo = [((), crate_root)]
    while todo:
        path, f = todo.pop()
        text = strip(open(os.path.join(root, f), encoding="utf-8").read())
        here = os.path.dirname(f) if f == crate_root or f.endswith("mod.rs") else f[:-3]
        for m in re.finditer(r"^\s*(?:pub(?:\([^)]*\))?\s+)?mod\s+(\w+)\s*;", text, flags=re.M):
            name = m.group(1)
            for cand in (f"{here}/{name}.rs", f"{here}/{name}/mod.rs"):
                if os.path.exists(os.path.join(root, cand)) and not cand.endswith("/tests.rs"):
                    found[path + (name,)] = cand
                    todo.append((path + (name,), cand))
                    break
        # Modules a macro declares (`families!`'s `mod $module;`, the law
        # registry's `registered_laws!`): the macro names them by a
        # metavariable, so take every file in a module file's folder that
        # is not a module yet.
        if f == crate_root or f.endswith("mod.rs"):
            known = set(found.values())
            for entry in sorted(os.listdir(os.path.join(root, here))):
                cand = f"{here}/{entry}"
                name = entry[:-3]
                if (entry.endswith(".rs") and entry not in ("mod.rs", "tests.rs", "main.rs", "lib.rs")
                        and cand not in known):
                    found[path + (name,)] = cand
                    todo.append((path + (name,), cand))
    return found


def use_trees(text):
    """(is_reexport, [path segments]) for every `use` item, braces expanded."""
    out = []
    for m in re.finditer(r"(\bpub(?:\([^)]*\))?\s+)?\buse\s+([^;]+);", text):
        reexport = m.group(1) is not None
        tree = re.sub(r"\s*(::|\{|\}|,)\s*", r"\1", m.group(2).strip())
        for p in expand(tree):
            out.append((reexport, p))
    return out


def expand(tree):
    """`a::{b,c::{d,e}}` -> [[a,b],[a,c,d],[a,c,e]]; `as` renames dropped."""
    i = tree.find("{")
    if i < 0:
        tree = tree.split(" as ")[0]
        return [[s for s in tree.split("::") if s]]
    prefix = [s for s in tree[:i].split("::") if s]
    inner, depth, parts, start = tree[i + 1: tree.rindex("}")], 0, [], 0
    for j, c in enumerate(inner):
        depth += {"{": 1, "}": -1}.get(c, 0)
        if c == "," and depth == 0:
            parts.append(inner[start:j])
            start = j + 1
    parts.append(inner[start:])
    return [prefix + sub for part in parts if part for sub in expand(part)]


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..")
    cycles = 0
    for crate_root in CRATES:
        if not os.path.exists(os.path.join(root, crate_root)):
            continue
        mods = modules(root, crate_root)
        files = {f: p for p, f in mods.items()}
        texts = {f: strip(open(os.path.join(root, f), encoding="utf-8").read()) for f in files}
        # names a file imports or re-exports: (file, name) -> absolute path
        reexports = {}
        for f, text in texts.items():
            for is_re, segs in use_trees(text):
                if segs:
                    absolute = absolute_path(files[f], segs, mods)
                    if absolute:
                        reexports[(f, segs[-1])] = absolute

        def resolve(path, seen=0):
            """The file defining the item at absolute `path`."""
            for k in range(len(path), -1, -1):
                if path[:k] in mods:
                    f = mods[path[:k]]
                    rest = path[k:]
                    if rest and (f, rest[0]) in reexports and seen < 16:
                        return resolve(reexports[(f, rest[0])] + rest[1:], seen + 1)
                    return f
            return None

        edges = {}
        for f, text in texts.items():
            for module, part in regions(text, files[f]):
                for segs in paths_in(part):
                    absolute = absolute_path(module, segs, mods)
                    if absolute is None:
                        continue
                    target = resolve(absolute)
                    # A file may use what an enclosing module defines (the
                    # folder's shared types: a reader's ReadError, a
                    # family's Density): that is the module tree, not a
                    # cycle; siblings and other folders count.
                    if target and target != f and not encloses(files[target], files[f]):
                        edges.setdefault(f, {}).setdefault(target, set()).add(absolute[-1])
        for scc in strongly_connected(edges):
            cycles += 1
            print(f"cycle: {', '.join(sorted(scc))}")
            for a in sorted(scc):
                for b, names in sorted(edges.get(a, {}).items()):
                    if b in scc:
                        print(f"  {a} -> {b}: {', '.join(sorted(names))}")
    if cycles:
        sys.exit(1)
    print("no import cycles between source files")


def encloses(outer, inner):
    """Whether module `outer` is an ancestor of module `inner`."""
    return len(outer) < len(inner) and tuple(inner[: len(outer)]) == tuple(outer)


def regions(text, module):
    """(module path, text) of a file's own text and of each inline
    `mod name { ... }` in it (where `super::` is the file's module)."""
    out, rest = [], text
    while True:
        m = re.search(r"^\s*(?:pub(?:\([^)]*\))?\s+)?mod\s+(\w+)\s*\{", rest, flags=re.M)
        if not m:
            break
        depth, i = 0, rest.index("{", m.start())
        for j in range(i, len(rest)):
            depth += {"{": 1, "}": -1}.get(rest[j], 0)
            if depth == 0:
                break
        out += regions(rest[i + 1: j], tuple(module) + (m.group(1),))
        rest = rest[: m.start()] + rest[j + 1:]
    return [(tuple(module), rest)] + out


def paths_in(text):
    """The paths a text names: its `use` items (not re-exports) and the
    paths of its code (those into this crate count)."""
    paths = [segs for is_re, segs in use_trees(text) if not is_re]
    body = re.sub(r"\buse\s+[^;]+;", "", text)
    # crate::, super::, self:: paths and paths from a child module (`x3p::ENTRY`)
    paths += [m.group(0).split("::") for m in re.finditer(r"(?<![\w:])[a-z_]\w*(?:::\w+)+", body)]
    return paths


def absolute_path(module, segs, mods):
    """The absolute module path `segs` names from inside `module`, or None
    (another crate, std, a local name)."""
    segs = [s for s in segs if s != "*"]
    if not segs:
        return None
    if segs[0] == "crate":
        return tuple(segs[1:])
    if segs[0] in ("self", "super"):
        base = list(module)
        while segs and segs[0] in ("self", "super"):
            if segs[0] == "super":
                if not base:
                    return None
                base.pop()
            segs = segs[1:]
        return tuple(base) + tuple(segs)
    if tuple(module) + (segs[0],) in mods:  # a child module, named relatively
        return tuple(module) + tuple(segs)
    return None


def strongly_connected(edges):
    """Tarjan's components of more than one file."""
    index, low, stack, on, out, counter = {}, {}, [], set(), [], [0]
    sys.setrecursionlimit(10000)

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in edges.get(v, {}):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = set()
            while True:
                w = stack.pop()
                on.discard(w)
                comp.add(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(comp)

    for v in list(edges):
        if v not in index:
            visit(v)
    return out


if __name__ == "__main__":
    main()
