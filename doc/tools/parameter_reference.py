#!/usr/bin/env python3
"""The manual's parameter reference from `impact-fem --print-parameters`.

impact-fem prints its declared entries in deal.II's PRM format (ParameterHandler::PRM): nested
`subsection NAME` ... `end`, each entry as its help text in `#` comment lines followed by
`set NAME = VALUE` (the default, since nothing is read). This turns that listing into a MyST
page, one heading per subsection and one item per entry.

    parameter_reference.py IMPACT_FEM [OUTPUT.md]     write the page (stdout without OUTPUT)
    parameter_reference.py --check IMPACT_FEM PAGE.md exit 1 when PAGE.md is not what the
                                                      program prints now (test doc.parameters_current)
"""
import difflib
import pathlib
import subprocess
import sys

# The repository this script belongs to: defaults that name a file of the source tree the
# program was built from (Mesh/Geometry file) are written relative to it, so that the page is
# the same in every checkout.
REPOSITORY = pathlib.Path(__file__).resolve().parents[2]


def parse(listing):
    """[(path, [(entry, default, help)])] in the order printed; path is a tuple of names."""
    sections = {(): []}
    order = [()]
    path = []
    comment = []
    for number, raw in enumerate(listing.splitlines(), 1):
        line = raw.strip()
        if not line:
            comment = []
        elif line.startswith("#"):
            text = line[1:].strip()
            if text in ("Listing of Parameters", "---------------------"):
                continue
            comment.append(text)
        elif line.startswith("subsection "):
            path.append(line[len("subsection "):].strip())
            sections.setdefault(tuple(path), [])
            if tuple(path) not in order:
                order.append(tuple(path))
            comment = []
        elif line == "end":
            if not path:
                raise ValueError(f"line {number}: 'end' outside a subsection")
            path.pop()
            comment = []
        elif line.startswith("set "):
            name, sep, value = line[4:].partition("=")
            if not sep:
                raise ValueError(f"line {number}: no '=' in {raw!r}")
            sections[tuple(path)].append((name.strip(), value.strip(), " ".join(comment)))
            comment = []
        else:
            raise ValueError(f"line {number}: not PRM: {raw!r}")
    if path:
        raise ValueError("a subsection is not closed")
    return [(p, sections[p]) for p in order if sections[p] or any(
        q[:len(p)] == p and sections[q] for q in order)]


def source_relative(value):
    """An absolute path into the source tree as `<source tree>/...`; other values unchanged."""
    if not value.startswith("/"):
        return value
    root = str(REPOSITORY) + "/"
    if value.startswith(root):
        return "<source tree>/" + value[len(root):]
    for folder in ("/meshes/", "/fem/"):
        if folder in value:
            return "<source tree>" + value[value.rindex(folder):]
    return value


def escape(text):
    # Markdown would read these as markup; the help texts are plain text.
    for character in "\\*_`[]<>|":
        text = text.replace(character, "\\" + character)
    return text


def page(listing):
    lines = [
        "# Parameter reference",
        "",
        "Every entry of a scenario file of `impact-fem`, with its default and its help text (unit",
        "and allowed range). Generated from `build/bin/impact-fem --print-parameters` by",
        "`doc/tools/parameter_reference.py`; the test `doc.parameters_current` fails when this page",
        "is not what the built program prints. To write it again:",
        "",
        "```sh",
        "python3 doc/tools/parameter_reference.py build/bin/impact-fem doc/reference/parameters.md",
        "```",
        "",
        "An entry is set in the file (`set Entry = value` inside its `subsection`) or on the command",
        "line (`--set \"Section/Entry=value\"`). A value outside the range is refused at the start,",
        "naming the entry (exit 2).",
    ]
    for path, entries in parse(listing):
        entries = [(name, source_relative(default), text) for name, default, text in entries]
        if not path:
            continue
        level = min(len(path) + 1, 4)
        lines += ["", "#" * level + " " + "/".join(path)]
        if not entries:
            continue
        lines.append("")
        for name, default, help_text in entries:
            shown = f"`{default}`" if default else "empty"
            item = f"- **{escape(name)}** (default {shown})"
            if help_text:
                item += ": " + escape(help_text)
            lines.append(item)
    return "\n".join(lines) + "\n"


def listing_of(program):
    result = subprocess.run([program, "--print-parameters"], capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"{program} --print-parameters failed ({result.returncode}): {result.stderr}")
    return result.stdout


def main(arguments):
    if len(arguments) == 3 and arguments[0] == "--check":
        program, committed = arguments[1], arguments[2]
        expected = page(listing_of(program))
        with open(committed, encoding="utf-8") as file:
            actual = file.read()
        if actual != expected:
            sys.stdout.writelines(difflib.unified_diff(
                actual.splitlines(True), expected.splitlines(True), committed, "impact-fem now"))
            print(f"{committed} is not what {program} --print-parameters gives now: write it "
                  "again with doc/tools/parameter_reference.py (command at the top of the page)")
            return 1
        print(f"{committed}: the same as {program} --print-parameters")
        return 0
    if len(arguments) in (1, 2) and not arguments[0].startswith("-"):
        text = page(listing_of(arguments[0]))
        if len(arguments) == 2:
            with open(arguments[1], "w", encoding="utf-8") as file:
                file.write(text)
        else:
            sys.stdout.write(text)
        return 0
    sys.stderr.write(__doc__)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
