#!/usr/bin/env python3
"""The structural rules of doc/design.md, checked on the source tree.

* Layers: a header or source of layer k (include/psmpm/<layer>/,
  source/<layer>/) includes psmpm headers of layers 1..k only. The order
  is read from doc/design.md's numbered list "N. **layer**", so that the
  map and the check cannot disagree.
* Function length: no function definition in source/ or include/ is
  longer than --max-lines lines, counted from the first line of its
  signature to its closing brace.
* Class size: the classes named with --max-members NAME=N (header path
  relative to include/psmpm) declare at most N non-static data members.

Prints every violation with its file and line; exits 1 if there is one.
  check_structure.py SOURCE_DIR [--max-lines 100]
      [--max-members simulator/simulator.h:Simulator=25 ...]
"""
import argparse
import os
import re
import sys


def layer_order(root):
    text = open(os.path.join(root, "doc", "design.md")).read()
    layers = re.findall(r"^(\d+)\. \*\*(\w+)\*\*", text, re.M)
    if not layers:
        sys.exit("doc/design.md: no numbered list of layers '1. **base**'")
    return {name: int(n) for n, name in layers}


def sources(root):
    for top in ("include/psmpm", "source"):
        for dirpath, _, files in os.walk(os.path.join(root, top)):
            for f in sorted(files):
                if f.endswith((".h", ".cc")):
                    path = os.path.join(dirpath, f)
                    layer = os.path.relpath(path, os.path.join(root, top))
                    yield path, layer.split(os.sep)[0]


def check_layers(root, problems):
    rank = layer_order(root)
    include = re.compile(r"\s*#\s*include\s*<psmpm/(\w+)/")
    for path, layer in sources(root):
        if layer not in rank:
            continue
        for n, line in enumerate(open(path, errors="replace"), 1):
            m = include.match(line)
            if m and m.group(1) in rank and rank[m.group(1)] > rank[layer]:
                problems.append(
                    f"{path}:{n}: layer '{layer}' includes the higher layer "
                    f"'{m.group(1)}': {line.strip()}")


CONTROL = re.compile(r"^\s*(\}\s*)?(if|for|while|switch|else|catch|do|try)\b")
SIGNATURE_END = re.compile(r"(\)|\bconst|override|noexcept|final|mutable)\s*$")


def function_bodies(lines):
    """(first signature line, last line, name) of each function definition
    written in deal.II style: the body's '{' alone on a line after the
    signature, its '}' at the same indentation."""
    i = 0
    while i < len(lines):
        m = re.match(r"^(\s*)\{\s*$", lines[i])
        j = i - 1
        while j >= 0 and not lines[j].strip():
            j -= 1
        if m and j >= 0 and SIGNATURE_END.search(lines[j].rstrip()) \
                and not CONTROL.match(lines[j]):
            close = re.compile("^" + m.group(1) + r"\}")
            k = i + 1
            while k < len(lines) and not close.match(lines[k]):
                k += 1
            s = j
            while s > 0 and lines[s - 1].strip() and not re.search(
                    r"[;{}]\s*$|^\s*(//|/\*|\*|#)", lines[s - 1]):
                s -= 1
            name = re.search(r"([\w:~<>]+)\s*\(", " ".join(lines[s:j + 1]))
            yield s + 1, k + 1, name.group(1) if name else "?"
            i = k
        i += 1


def check_lengths(root, max_lines, problems):
    for path, _ in sources(root):
        lines = open(path, errors="replace").read().split("\n")
        for first, last, name in function_bodies(lines):
            if last - first + 1 > max_lines:
                problems.append(f"{path}:{first}: {name} is "
                                f"{last - first + 1} lines (at most "
                                f"{max_lines})")


def data_members(text, name):
    """The non-static data members a class declares (at brace depth one of
    its body, outside functions), counting 'int a, b;' as two."""
    m = re.search(r"\b(class|struct)\s+" + name + r"\b[^;{]*\{", text)
    if not m:
        return None
    depth, start, count = 1, m.end(), 0
    statement = ""
    for ch in text[start:]:
        if ch == "{":
            depth += 1
        elif ch == "}":
            depth -= 1
            if depth == 0:
                break
            if depth == 1:
                statement = ""
            continue
        if depth != 1:
            continue
        if ch == ";":
            s = re.sub(r"//[^\n]*", "", statement)
            s = re.sub(r"\b(public|private|protected)\s*:", "", s).strip()
            statement = ""
            if not s or re.match(r"(using|typedef|friend|static|template|"
                                 r"enum|class|struct)\b", s):
                continue
            # A declaration with parentheses is a function unless they
            # belong to an initialiser after '=' or '{'.
            head = re.split(r"=|\{", s)[0]
            if "(" in head:
                continue
            depth_angle, commas = 0, 0
            for c in head:
                depth_angle += (c == "<") - (c == ">")
                commas += c == "," and depth_angle == 0
            count += 1 + commas
        else:
            statement += ch
    return count


def check_members(root, limits, problems):
    for spec in limits:
        where, limit = spec.rsplit("=", 1)
        header, name = where.split(":")
        path = os.path.join(root, "include", "psmpm", header)
        n = data_members(open(path).read(), name)
        if n is None:
            problems.append(f"{path}: no class {name}")
        elif n > int(limit):
            problems.append(f"{path}: {name} has {n} data members (at "
                            f"most {limit})")
        else:
            print(f"{name}: {n} data members (at most {limit})")


def self_test():
    """Each rule must catch a tree made to break it: a material header that
    includes a solver one, a 101-line function, a class of 3 members."""
    import tempfile
    with tempfile.TemporaryDirectory() as root:
        os.makedirs(os.path.join(root, "doc"))
        os.makedirs(os.path.join(root, "include", "psmpm", "material"))
        os.makedirs(os.path.join(root, "source", "solver"))
        open(os.path.join(root, "doc", "design.md"), "w").write(
            "1. **material**: a\n2. **solver**: b\n")
        open(os.path.join(root, "include", "psmpm", "material", "m.h"),
             "w").write("#include <psmpm/solver/s.h>\n"
                        "class M\n{\n  int a, b;\n  std::map<int, int> c;"
                        "\n  void f(int x);\n  static int d;\n};\n")
        body = "".join("    x += %d;\n" % i for i in range(97))
        open(os.path.join(root, "source", "solver", "s.cc"), "w").write(
            "#include <psmpm/material/m.h>\nvoid\nf(int x)\n{\n" + body +
            "}\n")
        problems = []
        check_layers(root, problems)
        check_lengths(root, 100, problems)
        check_members(root, ["material/m.h:M=2"], problems)
        expected = ["includes the higher layer 'solver'",
                    "f is 101 lines", "M has 3 data members"]
        for e in expected:
            if not any(e in p for p in problems):
                sys.exit(f"self test: the rule '{e}' was not caught:\n" +
                         "\n".join(problems))
        if len(problems) != len(expected):
            sys.exit("self test: unexpected findings:\n" +
                     "\n".join(problems))
        print("self test: each rule catches its violation")


def main():
    self_test()
    parser = argparse.ArgumentParser()
    parser.add_argument("root")
    parser.add_argument("--max-lines", type=int, default=100)
    parser.add_argument("--max-members", nargs="*", default=[])
    args = parser.parse_args()
    problems = []
    check_layers(args.root, problems)
    check_lengths(args.root, args.max_lines, problems)
    check_members(args.root, args.max_members, problems)
    print("\n".join(problems))
    print(f"{len(problems)} violations")
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
