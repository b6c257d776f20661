#!/usr/bin/env python3
"""The commands of the READMEs and the manual name no path outside the repository.

A user runs them in a fresh clone, from its top folder. In README.md, every folder's README.md
and every page of doc/, the code (fenced blocks, indented blocks and inline code spans) must not
name
  - an absolute path other than a system program (/usr/bin/..., /bin/...) or /dev/null:
    a folder of one machine, an install prefix, a temporary folder;
  - a home folder (~/..., $HOME/...);
  - a relative path whose ../ leaves the repository (resolved from its top);
  - a dynamic-loader path (LD_LIBRARY_PATH) set to an absolute or home folder.
Fails (exit 1) naming file, line and the offending path; exit 0 otherwise.

    repository_doc_commands.py REPOSITORY
"""
import pathlib
import re
import sys

SYSTEM = ("/usr/bin/", "/bin/", "/dev/null")
FENCE = re.compile(r"^\s*(```+|~~~+)")
INLINE = re.compile(r"(`+)(.+?)\1")
LOADER = "LD_" + "LIBRARY_PATH"  # split, so that this file is not a finding of other checks
LOADER_VALUE = re.compile(LOADER + r"\s*=\s*[\"']?([^\s\"':]+)")
# A path starts after a delimiter: the start, a space, a double quote, '=', '(', ',' or ':'
# (not after '>' or a letter: `<Output/Directory>/mesh.msh` and `Sphere/Elastic` are relative).
PATH = re.compile(r"(?:^|(?<=[\s\"=(,:]))((?:~/|\$HOME|\$\{HOME\}|/)[^\s\"'`),;]*)")
RELATIVE = re.compile(r"(?:^|(?<=[\s\"=(,:]))((?:[\w.$-]+/)*\.\./[^\s\"'`),;]*)")


def documents(root):
    pages = [root / "README.md"] + sorted(root.glob("*/README.md"))
    pages += sorted(p for p in (root / "doc").rglob("*.md") if "_build" not in p.parts)
    return [p for p in pages if p.is_file()]


def code_lines(text):
    """(line number, code) for each line of a code block and each inline code span."""
    fenced = False
    directive = False  # a MyST directive ({toctree}, {doxygenfile}): manual pages, not commands
    for number, line in enumerate(text.splitlines(), 1):
        fence = FENCE.match(line)
        if fence:
            fenced = not fenced
            directive = fenced and line[fence.end():].strip().startswith("{")
            continue
        if directive:
            continue
        if fenced or line.startswith("    ") or line.startswith("\t"):
            yield number, line
        else:
            for span in INLINE.finditer(line):
                # A MyST role ({doc}`../guide/x`) names a page of the manual, not a path.
                if span.start() > 0 and line[span.start() - 1] == "}":
                    continue
                yield number, span.group(2)


def findings(code, root):
    for match in LOADER_VALUE.finditer(code):
        value = match.group(1)
        if value.startswith(("/", "~", "$HOME", "${HOME}", "$TMPDIR", "${TMPDIR}")):
            yield f"{LOADER} set to a folder outside the repository: {value}"
    for match in PATH.finditer(code):
        path = match.group(1)
        if path.startswith(("~", "$HOME", "${HOME}")):
            yield f"a home folder: {path}"
        elif re.match(r"/[A-Za-z_.]", path) and not path.startswith(SYSTEM):
            yield f"an absolute path outside the repository: {path}"
    for match in RELATIVE.finditer(code):
        path = match.group(1)
        if path.startswith("..."):  # an ellipsis, not a folder
            continue
        resolved = (root / path).resolve()
        if root not in resolved.parents and resolved != root:
            yield f"a relative path that leaves the repository: {path}"


def main(arguments):
    if len(arguments) != 1 or not pathlib.Path(arguments[0]).is_dir():
        sys.stderr.write(__doc__)
        return 2
    root = pathlib.Path(arguments[0]).resolve()
    pages = documents(root)
    if not pages:
        print(f"no README.md or doc/ page under {root}")
        return 1
    count = 0
    for page in pages:
        text = page.read_text(encoding="utf-8")
        for number, code in code_lines(text):
            for finding in findings(code, root):
                print(f"{page.relative_to(root)}:{number}: {finding}")
                count += 1
    if count:
        print(f"{count} command(s) above name a path outside the repository; a user's clone "
              "has none of them: use a path inside it (build/, results/) or a system program")
        return 1
    print(f"{len(pages)} pages: no command names a path outside the repository")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
