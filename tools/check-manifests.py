#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""check-manifests.py - the build-system packages stay true to the tree.

The tools that read these manifests (west, idf.py, pio) cannot be
installed here, so this parses each one and checks what it says: every
path it names exists, every version is VOR_VERSION_MAJOR.MINOR.PATCH of
include/vor.h, sources.txt lists exactly src/*.c, every vor_config.h
option has a CMake cache option and a Kconfig option, and the toolchain
files use the flags of port/<target>/port.mk. Then it breaks a copy of
the tree in one place at a time and checks that each break is caught.
Closing line "N passed, N failed" for tools/run-tests.sh.

    tools/check-manifests.py
"""
import glob
import json
import os
import re
import shutil
import sys
import tempfile


def read(root, path):
    with open(os.path.join(root, path), encoding="utf-8") as f:
        return f.read()


def parse_yaml(text):
    """The YAML these manifests use: nested mappings, lists of scalars,
    plain or double-quoted scalars, # comments."""
    root = {}
    stack = [(-1, root)]  # (indent, container)
    lines = [l for l in text.splitlines() if l.strip() and not l.strip().startswith("#")]
    for number, line in enumerate(lines):
        indent = len(line) - len(line.lstrip(" "))
        body = line.strip()
        while stack[-1][0] >= indent:
            stack.pop()
        parent = stack[-1][1]
        if body.startswith("- "):
            if not isinstance(parent, list):
                raise ValueError("list item outside a list: " + line)
            parent.append(scalar(body[2:]))
            continue
        key, sep, value = body.partition(":")
        if not sep or not isinstance(parent, dict):
            raise ValueError("not a mapping entry: " + line)
        if value.strip():
            parent[key.strip()] = scalar(value)
        else:
            following = lines[number + 1].strip() if number + 1 < len(lines) else ""
            child = [] if following.startswith("- ") else {}
            parent[key.strip()] = child
            stack.append((indent, child))
    return root


def scalar(text):
    text = text.strip()
    if len(text) >= 2 and text[0] == text[-1] == '"':
        return text[1:-1]
    return text


def listed_sources(root):
    return [l.strip() for l in read(root, "sources.txt").splitlines()
            if l.strip() and not l.startswith("#")]


def check_tree(root):
    """Every failure found in the tree at root, as messages."""
    failures = []

    def expect(ok, message):
        if not ok:
            failures.append(message)

    def exists(path, what):
        expect(os.path.exists(os.path.join(root, path)), f"{what}: {path} does not exist")

    vor_h = read(root, "include/vor.h")
    # the numbers are the one place; VOR_VERSION_STRING is made from them
    parts = [re.search(rf"^#define VOR_VERSION_{p} (\d+)$", vor_h, re.M) for p in ("MAJOR", "MINOR", "PATCH")]
    expect(all(parts), "include/vor.h: VOR_VERSION_* not found")
    version = ".".join(p.group(1) for p in parts) if all(parts) else None

    # sources.txt: the one list, exactly the C files of src/.
    sources = listed_sources(root)
    actual = sorted(os.path.relpath(p, root) for p in glob.glob(os.path.join(root, "src", "*.c")))
    for path in sources:
        exists(path, "sources.txt")
    expect(sorted(sources) == actual,
           f"sources.txt lists {sorted(set(sources) ^ set(actual))} differently from src/*.c")
    expect(len(set(sources)) == len(sources), "sources.txt names a file twice")

    # Every vor_config.h option in CMake, Kconfig and their mapping. VOR_ASSERT
    # is function-like, so both offer it as a trap switch.
    options = re.findall(r"^#ifndef (VOR_\w+)$", read(root, "include/vor_config.h"), re.M)
    options = [o for o in options if o != "VOR_CONFIG_H"]
    expect(len(options) >= 5, "include/vor_config.h: options not found")
    cmake = read(root, "CMakeLists.txt")
    kconfig = read(root, "Kconfig")
    mapping = read(root, "cmake/vor_options.cmake")
    for option in options:
        name = "VOR_ASSERT_TRAP" if option == "VOR_ASSERT" else option
        expect(re.search(rf"^(set\({name} .* CACHE |option\({name} )", cmake, re.M),
               f"CMakeLists.txt: no cache option for {option}")
        expect(re.search(rf"^(config|choice) {name}$", kconfig, re.M), f"Kconfig: no option for {option}")
        stem = name[len("VOR_"):]
        expect(re.search(rf"CONFIG_VOR_({stem}\b|\$\{{option\}})", mapping) and stem in mapping,
               f"cmake/vor_options.cmake: {option} is not mapped")

    # Paths the CMake files read, relative to their own directory.
    for cmake_file, base in (("CMakeLists.txt", ""), ("zephyr/CMakeLists.txt", "zephyr/..")):
        text = read(root, cmake_file)
        for path in re.findall(r'(?<!\\)\$\{(?:CMAKE_CURRENT_LIST_DIR|CMAKE_CURRENT_SOURCE_DIR|vor_root)\}/([\w./-]+)', text):
            exists(os.path.normpath(os.path.join(base, path)), cmake_file)

    # Toolchain files: the CPU flags of the Makefile's ports.
    for target in ("cortex-m0", "cortex-m3", "cortex-m4f"):
        port = re.search(r"^CPU_CFLAGS = (.*)$", read(root, f"port/{target}/port.mk"), re.M)
        toolchain = f"cmake/toolchains/arm-none-eabi-{target}.cmake"
        exists(toolchain, "toolchain")
        if port and os.path.exists(os.path.join(root, toolchain)):
            flags = re.search(r'^set\(vor_cpu_flags "(.*)"\)$', read(root, toolchain), re.M)
            expect(flags and flags.group(1) == port.group(1).strip(),
                   f"{toolchain}: flags differ from port/{target}/port.mk ({port.group(1).strip()})")
    riscv_port = read(root, "port/riscv32/port.mk")
    riscv_flags = re.findall(r"-m(?:arch|abi|cmodel)=\S+", riscv_port)
    riscv_toolchain = re.search(r'^set\(CMAKE_C_FLAGS_INIT "(.*)"\)$', read(root, "cmake/toolchains/riscv32.cmake"), re.M)
    expect(riscv_flags and riscv_toolchain and riscv_toolchain.group(1).split() == riscv_flags,
           "cmake/toolchains/riscv32.cmake: flags differ from port/riscv32/port.mk")

    # Zephyr module.
    module = parse_yaml(read(root, "zephyr/module.yml"))
    expect(module.get("name") == "vor", "zephyr/module.yml: name is not vor")
    build = module.get("build", {})
    expect(isinstance(build, dict) and "cmake" in build and "kconfig" in build,
           "zephyr/module.yml: build.cmake or build.kconfig missing")
    if isinstance(build, dict):
        if "cmake" in build:
            exists(os.path.join(build["cmake"], "CMakeLists.txt"), "zephyr/module.yml build.cmake")
        if "kconfig" in build:
            exists(build["kconfig"], "zephyr/module.yml build.kconfig")
    for path in re.findall(r'^\s*rsource "([^"]+)"', read(root, "zephyr/Kconfig"), re.M):
        exists(os.path.normpath(os.path.join("zephyr", path)), "zephyr/Kconfig rsource")

    # ESP-IDF component: the manifest, and the CMakeLists.txt and Kconfig
    # ESP-IDF looks for beside it.
    component = parse_yaml(read(root, "idf_component.yml"))
    expect(component.get("version") == version,
           f"idf_component.yml: version {component.get('version')}, vor.h {version}")
    expect(component.get("license") == "MIT", "idf_component.yml: license is not MIT")
    expect("idf_component_register(" in cmake, "CMakeLists.txt: no idf_component_register")
    exists("Kconfig", "ESP-IDF component")
    for pattern in component.get("files", {}).get("exclude", []):
        exists(pattern.split("*")[0] or ".", "idf_component.yml files.exclude")

    # PlatformIO library.
    library = json.loads(read(root, "library.json"))
    expect(library.get("version") == version, f"library.json: version {library.get('version')}, vor.h {version}")
    expect(library.get("license") == "MIT", "library.json: license is not MIT")
    pio = library.get("build", {})
    src_dir = pio.get("srcDir", "src")
    include_dir = pio.get("includeDir", "include")
    exists(src_dir, "library.json build.srcDir")
    exists(include_dir, "library.json build.includeDir")
    selected = set()
    for rule in pio.get("srcFilter", ["+<*>"]):
        sign, pattern = rule[0], rule[2:-1]
        matched = {os.path.relpath(p, root) for p in glob.glob(os.path.join(root, src_dir, pattern))}
        selected = selected | matched if sign == "+" else selected - matched
    expect(sorted(selected) == sorted(sources),
           f"library.json build.srcFilter builds {sorted(selected)}, not sources.txt")
    for header in library.get("headers", []):
        exists(os.path.join(include_dir, header), "library.json headers")
    for path in library.get("export", {}).get("include", []):
        exists(path, "library.json export.include")

    # Arduino: skipped (docs/porting.md says why); a manifest would be checked.
    if os.path.exists(os.path.join(root, "library.properties")):
        properties = dict(l.split("=", 1) for l in read(root, "library.properties").splitlines()
                          if "=" in l and not l.startswith("#"))
        expect(properties.get("version") == version, "library.properties: version differs from vor.h")
    return failures


# Each break of a copy of the tree, and what must then be reported.
BREAKS = [
    ("a version", "library.json", '"version": "', '"version": "9.'),
    ("a version", "idf_component.yml", 'version: "', 'version: "9.'),
    ("a source not listed", "sources.txt", "src/mesh.c\n", ""),
    ("a listed source missing", "sources.txt", "src/mesh.c", "src/mesh_gone.c"),
    ("a path in module.yml", "zephyr/module.yml", "kconfig: zephyr/Kconfig", "kconfig: zephyr/Kconfig.gone"),
    ("a CMake option", "CMakeLists.txt", "set(VOR_TRACKER_EDGES", "set(VOR_TRACKER_EDGE_COUNT"),
    ("a Kconfig option", "Kconfig", "config VOR_SITES_PER_BUCKET", "config VOR_SITES_A_BUCKET"),
    ("a toolchain flag", "cmake/toolchains/arm-none-eabi-cortex-m3.cmake", "-mcpu=cortex-m3", "-mcpu=cortex-m4"),
    ("a PlatformIO filter", "library.json", '"+<*.c>"', '"+<*.c>", "-<mesh.c>"'),
    ("a rsource", "zephyr/Kconfig", 'rsource "../Kconfig"', 'rsource "../Kconfig.gone"'),
]


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    passed = failed = 0
    failures = check_tree(root)
    for message in failures:
        print("FAIL " + message)
    passed, failed = (1, 0) if not failures else (0, 1)

    # The check can fail: a copy of what it reads passes, and each break of
    # the copy is reported.
    with tempfile.TemporaryDirectory() as scratch:
        for what, path, old, new in [("nothing", "sources.txt", "", "")] + BREAKS:
            copy = os.path.join(scratch, "tree")
            shutil.rmtree(copy, ignore_errors=True)
            for keep in ("src", "include", "cmake", "zephyr", "port"):
                shutil.copytree(os.path.join(root, keep), os.path.join(copy, keep))
            for keep in ("bench", "docs", "tests", "tools"):
                os.mkdir(os.path.join(copy, keep))
            for keep in ("sources.txt", "CMakeLists.txt", "Kconfig", "idf_component.yml", "library.json",
                         "LICENSE", "README.md", "CHANGELOG.md"):
                shutil.copy(os.path.join(root, keep), os.path.join(copy, keep))
            text = read(copy, path)
            if old not in text:
                print(f"FAIL break '{what}': {old!r} not in {path}")
                failed += 1
                continue
            with open(os.path.join(copy, path), "w", encoding="utf-8") as f:
                f.write(text.replace(old, new, 1))
            found = check_tree(copy)
            if what == "nothing":
                ok = not found
                for message in found:
                    print("FAIL copy of the tree: " + message)
            else:
                ok = bool(found)
                if not ok:
                    print(f"FAIL break '{what}' in {path} went unnoticed")
            passed, failed = passed + ok, failed + (not ok)
    print(f"{passed} passed, {failed} failed")
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
