#!/usr/bin/env python3
"""Every ```cpp block of README.md and docs/integration.md must stand verbatim in a source file the
suite compiles, so the documented code cannot drift from code that builds.
Usage: doc_snippets.py SOURCE_DIR"""
import pathlib
import re
import sys

root = pathlib.Path(sys.argv[1])
compiled = "\n".join((root / f).read_text() for f in [
    "tests/package/readme_example.cpp", "examples/host/main.cpp", "examples/host/scene_pass.cpp",
    "examples/host/host_vulkan.cpp", "tests/gpu/test_host.cpp"])
failures = 0
for doc in ["README.md", "docs/integration.md"]:
    blocks = re.findall(r"```cpp\n(.*?)```", (root / doc).read_text(), re.S)
    if not blocks:
        print(f"{doc}: no C++ code block")
        failures += 1
    for i, block in enumerate(blocks, 1):
        if block not in compiled:
            print(f"{doc}: code block {i} is not in any compiled source:\n{block}")
            failures += 1
    print(f"{doc}: {len(blocks)} code blocks checked")
sys.exit(1 if failures else 0)
