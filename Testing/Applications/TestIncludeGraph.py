# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The include graph of the module's classes (Filters/) has no circle, and the
folders depend on each other only as the README's layout table says.

    python3 TestIncludeGraph.py --source SOURCE_DIR [--print]

A class is a header/source pair; class A depends on class B when A's header or
source includes B's header. --print lists the edges. Every check prints
ok/FAIL; the exit code is 1 when any check failed.
"""
import argparse
import os
import re
import sys

# Which folder may include which (Kernels are plain C++ at the bottom; the
# vtkP* subclasses of Parallel sit on top of the serial filters).
ALLOWED = {
    "Kernels": {"Kernels"},
    "IO": {"IO"},
    "Sampling": {"Sampling", "Kernels"},
    "Spectrum": {"Spectrum", "Kernels"},
    "Parallel": {"Parallel", "Sampling", "Spectrum", "Kernels"},
}


def classes(root):
    """Class name -> folder, for every header under Filters/."""
    found = {}
    for folder in sorted(os.listdir(root)):
        path = os.path.join(root, folder)
        if os.path.isdir(path):
            for name in os.listdir(path):
                if name.endswith(".h"):
                    found[name[:-2]] = folder
    return found


def edges(root, known):
    include = re.compile(r'^\s*#\s*include\s+"(vtk\w+)\.h"', re.M)
    graph = {name: set() for name in known}
    for name, folder in known.items():
        for ext in (".h", ".cxx"):
            path = os.path.join(root, folder, name + ext)
            if os.path.exists(path):
                with open(path) as f:
                    for target in include.findall(f.read()):
                        if target in known and target != name:
                            graph[name].add(target)
    return graph


def circles(graph):
    """Strongly connected components of more than one class (Tarjan)."""
    index, low, stack, on, found = {}, {}, [], set(), []
    counter = [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in sorted(graph[v]):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return found


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--source", required=True)
    parser.add_argument("--print", action="store_true")
    args = parser.parse_args()
    root = os.path.join(args.source, "Filters")
    known = classes(root)
    graph = edges(root, known)
    if args.print:
        for a in sorted(graph):
            for b in sorted(graph[a]):
                print("%s/%s -> %s/%s" % (known[a], a, known[b], b))
    failures = []

    def check(ok, message):
        print(("ok:   " if ok else "FAIL: ") + message)
        if not ok:
            failures.append(message)

    check(len(known) > 10, "%d classes found under %s" % (len(known), root))
    found = circles(graph)
    check(not found, "no include circle among them (%s)" % found)
    crossing = ["%s/%s -> %s/%s" % (known[a], a, known[b], b) for a in sorted(graph)
                for b in sorted(graph[a]) if known[b] not in ALLOWED.get(known[a], set())]
    check(not crossing, "folders depend as the layout says (%s)" % crossing)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
