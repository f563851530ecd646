#!/usr/bin/env python3
"""The layering of kernels/ (docs/contributing.md, "One folder per capability").

1. The capability folders are ordered simd, core, interpolation, coverage, texture,
   antialiasing, draw (its stage folders included), occlusion: a file includes nothing from a
   folder later in that order. The kernel table (core/kernel_table.hpp), which lists every capability's
   kernels with their call types, is the only exception.
2. Kernels written once over xsimd batches (*-inl.hpp) do not include the kernel table: they
   take their inputs' headers, and another kernel of their ISA through core/isa_kernels.hpp.
3. Raw intrinsics (_mm*) appear in simd/ only.
4. Every quoted include of kernels/ names a file that exists.

Usage: include_layers.py <source root>. Prints each breach and exits 1 if there is any.
"""
import os
import re
import sys

ORDER = [
    "simd", "core", "interpolation", "coverage", "texture", "antialiasing", "draw", "occlusion"
]
TABLE_FILES = {"core/kernel_table.hpp"}
INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"', re.M)
INTRINSIC = re.compile(r"\b_mm\w*")


def folder_of(relative):
    return relative.split("/")[0]


def breaches(root):
    kernels = os.path.join(root, "kernels")
    found = []
    for directory, _, names in os.walk(kernels):
        for name in sorted(names):
            if not name.endswith((".hpp", ".cpp")):
                continue
            path = os.path.join(directory, name)
            relative = os.path.relpath(path, kernels)
            folder = folder_of(relative)
            if folder == "include":
                continue
            if folder not in ORDER:
                found.append(f"{relative}: in no capability folder of {ORDER}")
                continue
            with open(path, encoding="utf-8") as f:
                text = f.read()
            if folder != "simd" and INTRINSIC.search(text):
                found.append(f"{relative}: raw intrinsic outside simd/")
            for target in INCLUDE.findall(text):
                local = os.path.normpath(os.path.join(directory, target))
                public = os.path.join(kernels, "include", target)
                if os.path.isfile(public) and not os.path.isfile(local):
                    continue
                if not os.path.isfile(local):
                    found.append(f'{relative}: includes "{target}", which does not exist')
                    continue
                included = os.path.relpath(local, kernels)
                if ORDER.index(folder_of(included)) > ORDER.index(folder) and (
                    relative not in TABLE_FILES
                ):
                    found.append(f"{relative}: includes {included}, from a later folder")
                if name.endswith("-inl.hpp") and included == "core/kernel_table.hpp":
                    found.append(f"{relative}: a kernel includes the kernel table")
    return found


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: include_layers.py <source root>")
    found = breaches(sys.argv[1])
    for line in found:
        print(line)
    print(f"{len(found)} breaches of the layering of kernels/")
    sys.exit(1 if found else 0)


if __name__ == "__main__":
    main()
