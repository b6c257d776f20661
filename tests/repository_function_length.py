"""No function of the project is longer than MAXIMUM lines (tests aside): a longer one is split
along its concepts. Counts, with Universal Ctags, every function definition's lines from the
line of its name to its closing brace (blank and comment lines included; a lambda counts in
the function that holds it) in the C++ of fem/, reduced/ and postprocess/.

Usage: repository_function_length.py SOURCE_DIR [MAXIMUM]; exit 1 naming each function that
is longer, exit 2 when ctags is missing or is not Universal Ctags."""
import json
import os
import shutil
import subprocess
import sys

source = sys.argv[1]
maximum = int(sys.argv[2]) if len(sys.argv) > 2 else 100
ctags = shutil.which("ctags")
if not ctags or b"Universal Ctags" not in subprocess.run([ctags, "--version"],
                                                          capture_output=True).stdout:
    print("Universal Ctags is missing (Debian package universal-ctags): run ./setup.sh")
    sys.exit(2)
folders = [os.path.join(source, folder) for folder in ("fem", "reduced", "postprocess")]
result = subprocess.run([ctags, "-R", "--languages=C++", "--langmap=C++:+.cc.h.hpp.cpp",
                         "--kinds-C++=f", "--fields=+ne", "--output-format=json", "-o", "-"]
                        + folders, capture_output=True, text=True, check=True)
functions = []
for line in result.stdout.splitlines():
    tag = json.loads(line)
    if tag.get("_type") == "tag" and "end" in tag:
        name = (tag["scope"] + "::" if tag.get("scope") else "") + tag["name"]
        functions.append((tag["end"] - tag["line"] + 1, os.path.relpath(tag["path"], source),
                          tag["line"], name))
functions.sort(reverse=True)
if not functions:
    print("no function found: is SOURCE_DIR the repository?")
    sys.exit(1)
long = [f for f in functions if f[0] > maximum]
print(f"{len(functions)} functions; the longest: {functions[0][0]} lines "
      f"({functions[0][1]}:{functions[0][2]} {functions[0][3]})")
for lines, path, start, name in long:
    print(f"{path}:{start}: {name}: {lines} lines, more than {maximum}")
sys.exit(1 if long else 0)
