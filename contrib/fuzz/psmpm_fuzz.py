#!/usr/bin/python3
"""Seeded fuzzer of the psmpm executable: hostile input of every kind.

Every case runs build/psmpm as a subprocess with a time limit, in a
directory of its own, on one of the scenes in prm/ cut to one time step
(Time/End time = 1e-9; the mass matrix study to one degree and one mesh).
The cases substitute hostile values for every entry of every scene (by
--set and inside a copy of the scene file; a list of numbers also moved
1e6 away, made degenerate, reversed and shrunk), mangle --set syntax and the
command line, the parameter file (includes, structure, special files),
the JSON form of the scene (structure and types, null), Gmsh files
(truncation, duplicate or missing node ids, MeshFormat versions, element
types, special files), checkpoints given to --resume (flipped bytes,
truncation, another scene's) and output directories (a file in the way,
special files, stale or garbled lock files). The function expressions
(initial velocities, prescribed and driven velocities, the stress
function, the projected function, their constants) have one component
made hostile (an unknown name, a syntax error, a variable the function
does not have, an empty component, one component too many or too few, a
constant removed or zeroed); the functions of t take a component that is
valid at t = 0 and singular, nan, inf or huge a few steps in (these cases
run TIME_STEPS steps of the scene's time step), the functions of x, y one
that fails at some particles only.

The oracle, for every run:
  * exit 0: summary.json valid JSON with finite numbers and status
    "completed", statistics.txt not empty, no inf or nan in a table
    (statistics.txt, tracked_particle.txt, solver_study.tsv) or in a
    data array of a particle or grid VTU file, every
    VTU/PVD file complete, no lock file or temporary file left;
  * exit 2: one message that names the entry (or the file) the case
    changed, no deal.II source location or stack trace, and nothing
    written: a new output directory does not exist, an existing one
    holds the same files as before;
  * exit 3-9: a reason on the screen, summary.json (if any) valid, no lock
    left;
  * never a signal, an exit code 1 (internal error) or another code,
    never past the time limit.

  contrib/fuzz/psmpm_fuzz.py [--cases N] [--seed S] [--jobs J] [--every-scene]
      a sample of N cases (default: every case, the full sweep), drawn
      with seed S so that every kind of mutation is in it (round robin
      over the kinds); --every-scene: every hostile value for every entry
      of every scene, both by --set and in the file (about 55,000 cases;
      without it each entry path takes each value on one of the scenes
      that set it, in turn); prints a report of every failure by kind and the
      counts of cases and kinds; exit status 1 if any case failed.
  --psmpm PATH (default build/psmpm), --scenes DIR (default prm/),
  --work DIR (default a new temporary directory, removed afterwards
  unless --keep), --timeout SECONDS (default 30), --list (print the
  cases, run nothing), --only SUBSTRING (cases whose kind or description
  contains it).
"""
import argparse
import collections
import concurrent.futures
import json
import math
import os
import random
import re
import shutil
import socket
import stat
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
END_TIME = "1e-9"
OUT = "out"  # the output directory of every case, relative to its directory

# ---------------------------------------------------------------------------
# Hostile values: (kind, value). Values are bytes (argv and files take any).
LONG = b"a" * 5000
VALUES = [
    ("nan", b"nan"),
    ("nan", b"NaN"),
    ("inf", b"inf"),
    ("inf", b"-inf"),
    ("inf", b"Infinity"),
    ("overflow", b"1e309"),
    ("huge", b"1e308"),
    ("huge", b"-1e308"),
    ("tiny", b"1e-308"),
    ("tiny", b"4.9e-324"),
    ("zero", b"-0"),
    ("zero", b"0"),
    ("negative", b"-1"),
    ("integer overflow", b"2147483648"),
    ("integer overflow", b"18446744073709551616"),
    ("empty", b""),
    ("blank", b"   "),
    ("very long", LONG),
    ("very long number", b"1" * 400),
    ("non-UTF-8", b"\xff\xfe\xc3("),
    ("not a number", b"abc"),
    ("hex", b"0x10"),
    ("list", b"1, 2"),
    ("list", b";;"),
    ("expression syntax", b"sin("),
    ("expression syntax", b"x+"),
    ("expression syntax", b"1/(x-0.5"),
    ("expression singular", b"1/(x-0.5)"),
    ("expression singular", b"sqrt(-1)"),
    ("expression singular", b"log(0)"),
    ("expression singular", b"1/0"),
    ("variable name", b"x"),
    ("variable name", b"t"),
    ("variable name", b"y"),
    ("unknown name", b"undefined_name*2"),
    ("separator", b"="),
    ("separator", b"a=b=c"),
    ("format", b"%s%n%d"),
    ("boolean", b"true"),
]
# Function constants (name=value lists): names that shadow the variables
# and functions of the expressions, malformed pairs.
CONSTANTS = [
    ("constant shadows x", b"x=1"),
    ("constant shadows y", b"y=2"),
    ("constant shadows t", b"t=3"),
    ("constant shadows pi", b"pi=3"),
    ("constant shadows function", b"sin=1"),
    ("constant shadows function", b"sqrt=1"),
    ("constant name", b"1a=2"),
    ("constant name", b"a b=1"),
    ("constant name", b"=1"),
    ("constant name", b"a-b=1"),
    ("constant name", b"_a=1"),
    ("constant name", b"\xff=1"),
    ("constant value", b"a="),
    ("constant value", b"a=nan"),
    ("constant value", b"a=1e309"),
    ("constant duplicate", b"a=1, a=2"),
    ("constant list", b"a=1,,b=2"),
    ("constant list", b"a==1"),
]


def is_constants(path):
    return path.endswith("constants")


# ---------------------------------------------------------------------------
# Scenes


class Scene:
    """A parameter file: its lines and its entries (path, line index)."""

    def __init__(self, file):
        self.file = file
        self.name = os.path.basename(file)
        with open(file, "rb") as f:
            self.lines = f.read().split(b"\n")
        self.entries = []  # (path, line index)
        self.values = {}
        # The last line of each entry's value: deal.II joins a line that
        # ends in a backslash with the next one, so an edited value must
        # replace the continuation lines too.
        self.last_line = {}
        stack = []
        i = 0
        while i < len(self.lines):
            first, joined = i, self.lines[i].rstrip()
            while joined.endswith(b"\\") and i + 1 < len(self.lines):
                i += 1
                joined = joined[:-1] + b" " + self.lines[i].strip()
            i += 1
            line = joined.split(b"#")[0].strip()
            if line.startswith(b"subsection "):
                stack.append(line[11:].strip().decode())
            elif line == b"end":
                stack.pop()
            elif line.startswith(b"set "):
                key, _, value = line[4:].partition(b"=")
                path = "/".join(stack + [key.strip().decode()])
                self.entries.append((path, first))
                self.last_line[first] = i - 1
                self.values[path] = value.strip()
        self.problem = self.values.get("Problem", b"mpm").decode()

    def cut(self):
        """--set arguments that make the scene a run of well under a second."""
        if self.problem == "mass matrix study":
            return [b"Mass matrix study/Degrees=1", b"Mass matrix study/Inverse h=8"]
        if self.problem == "l2 projection":
            return []
        return [b"Time/End time=" + END_TIME.encode()]

    def with_value(self, index, value):
        """The scene's text with line @p index set to @p value."""
        lines = list(self.lines)
        raw = lines[index]
        indent = raw[: len(raw) - len(raw.lstrip())]
        key = raw.strip()[4:].split(b"=")[0].strip()
        lines[index : self.last_line[index] + 1] = [
            indent + b"set " + key + b" = " + value]
        return b"\n".join(lines)

    def json(self):
        """The scene as deal.II reads JSON: nested objects of strings."""
        tree = collections.OrderedDict()
        for path, _ in self.entries:
            parts = path.split("/")
            node = tree
            for p in parts[:-1]:
                node = node.setdefault(p, collections.OrderedDict())
            node[parts[-1]] = self.values[path].decode("utf-8", "replace")
        return tree


# ---------------------------------------------------------------------------
# Cases


class Case:
    def __init__(self, kind, description, scene, args, names, setup=None,
                 fresh_output=True, run_output=True):
        self.kind = kind  # the kind of mutation, e.g. "value: nan"
        self.description = description
        self.scene = scene  # Scene or None
        self.args = args  # argv after the executable, bytes; "{scene}" = scene path
        self.names = names  # an exit-2 message must contain one of these
        self.setup = setup  # setup(case directory) before the run
        self.fresh_output = fresh_output  # OUT does not exist before the run
        self.run_output = run_output  # exit 0 means a completed run into OUT
        self.out = OUT.encode()  # the output directory a run writes into
        self.env = {}  # extra environment variables
        self.expect_code = None  # the one exit code the case must end with
        self.kept = []  # files of OUT that must exist after the run
        self.build = None  # build() -> args, when they need a run first

    def argv(self, scene_path):
        if self.args is None:
            self.args = self.build()
        return [a.replace(b"{scene}", scene_path.encode()) for a in self.args]


def base_args(scene):
    args = [b"{scene}", b"--set", b"Output directory=" + OUT.encode()]
    for c in scene.cut():
        args += [b"--set", c]
    return args


def copy_scene_dir(case_dir, text, name="case.prm"):
    """Write @p text as the scene, beside copies of the mesh and geometry
    files it refers to (relative to the scene file)."""
    for d in ("meshes", "geometry"):
        src = os.path.join(ROOT, "prm", d)
        dst = os.path.join(case_dir, d)
        if os.path.isdir(src) and not os.path.exists(dst):
            os.symlink(src, dst)
    with open(os.path.join(case_dir, name), "wb") as f:
        f.write(text)


# Well-formed lists of numbers that describe a geometry the mesh
# contradicts: (kind, function of the list's numbers).
LIST_MUTATIONS = [
    ("far away", lambda x: [v + 1e6 for v in x]),
    ("degenerate list", lambda x: [x[0]] * len(x)),
    ("reversed list", lambda x: x[::-1]),
    ("shrunk list", lambda x: [v * 1e-9 for v in x]),
]


def list_values(values):
    """For an entry that some scene sets to a list of at least two
    numbers (coordinates, a box, a vector): the first such list moved
    1e6 away (off every mesh), with every number equal to the first
    (a box or polygon of no area), reversed (corners swapped) and scaled
    by 1e-9 (smaller than the particle spacing). Well formed, so only
    the geometry can refuse them: a region, body, point or segment that
    misses the domain or holds nothing must be refused or run to a
    finite result, not run on nothing."""
    for value in values:
        parts = re.split(rb"([,;])", value)
        numbers = parts[0::2]
        if len(numbers) < 2:
            continue
        try:
            x = [float(n) for n in numbers]
        except ValueError:
            continue
        cases = []
        for kind, mutate in LIST_MUTATIONS:
            parts[0::2] = [b"%.17g" % v for v in mutate(x)]
            cases.append((kind, b"".join(parts)))
        return cases
    return []


def value_cases(scenes, every_scene=False):
    """Hostile values for every entry path of the scenes: each value by
    --set and each kind of value inside a copy of the scene file, on the
    scenes that set the entry in turn (with @p every_scene: every value
    in every scene, both ways)."""
    scenes_of = collections.OrderedDict()
    for scene in scenes:
        for path, index in scene.entries:
            scenes_of.setdefault(path, []).append((scene, index))
    cases = []
    for path, where in scenes_of.items():
        pool = CONSTANTS if is_constants(path) else VALUES + list_values(
            [scene.values[path] for scene, _ in where])
        entry = path.split("/")[-1].encode()
        kinds_in_file = set()
        for k, (kind, value0) in enumerate(pool):
            for j, (scene, index) in enumerate(where):
                if not every_scene and j != k % len(where):
                    continue
                # A hostile constant joins the scene's own constants (its
                # expressions keep theirs).
                value = value0
                if is_constants(path) and scene.values[path]:
                    value = scene.values[path] + b", " + value0
                # By --set: the message names the --set path.
                c = Case(
                    "value by --set: " + kind,
                    "%s: --set %s=%r" % (scene.name, path, value[:40]),
                    scene,
                    base_args(scene) + [b"--set", path.encode() + b"=" + value],
                    [entry])
                # An empty name leaves OUT of the first --set, which must
                # not be created (the case's own directory is no output).
                if path == "Output directory" and value.strip():
                    c.out = value.strip()
                cases.append(c)
                if not every_scene and kind in kinds_in_file:
                    continue
                kinds_in_file.add(kind)
                # Inside the file: the message names the entry and the file.
                text = scene.with_value(index, value)

                def setup(d, text=text):
                    copy_scene_dir(d, text)

                args = base_args(scene)
                args[0] = b"case.prm"
                cases.append(Case(
                    "value in file: " + kind,
                    "%s: %s = %r in the file" % (scene.name, path, value[:40]),
                    scene, args, [entry], setup))
    return cases


def set_syntax_cases(scene):
    """Mangled --set arguments and command lines."""
    b = base_args(scene)
    mangled = [
        ("no =", b"Time/End time"),
        ("empty path", b"=1"),
        ("empty entry", b"Time/=1"),
        ("empty subsection", b"/End time=2e-9"),
        ("leading /", b"/Time/End time=2e-9"),
        ("double /", b"Time//End time=2e-9"),
        ("trailing /", b"Time/=1"),
        ("unknown subsection", b"Nowhere/End time=2e-9"),
        ("unknown entry", b"Time/Nothing=1"),
        ("subsection as entry", b"Time=1"),
        ("entry as subsection", b"Time/End time/x=1"),
        ("==", b"Time/End time==2e-9"),
        ("spaces", b" Time / End time =2e-9"),
        ("newline in value", b"Time/End time=2e-9\nset Output directory = elsewhere"),
        ("newline in path", b"Time\n/End time=2e-9"),
        ("non-UTF-8 path", b"\xff\xfe/\xc3(=1"),
        ("very long path", LONG + b"=1"),
        ("deep path", b"a/" * 300 + b"b=1"),
        ("only =", b"="),
        ("empty", b""),
        ("subsection with =", b"Time=/End time=1"),
        ("nested unknown", b"Materials/Material 99/Density=1"),
        ("body out of range", b"Bodies/Body 0/Shape=gmsh"),
    ]
    cases = []
    for kind, s in mangled:
        names = [s.split(b"=")[0].split(b"\n")[0][:60] or b"--set", b"--set"]
        cases.append(Case("--set syntax: " + kind, "--set %r" % s[:60], scene,
                          b + [b"--set", s], names))
    options = [
        ("--set without argument", b + [b"--set"], [b"--set"]),
        ("--set followed by option", b + [b"--set", b"--validate"], [b"--validate"]),
        ("unknown option", b + [b"--frobnicate"], [b"--frobnicate"]),
        ("--set=", b + [b"--set=Time/End time=2e-9"], [b"--set=Time"]),
        ("two scene files", b + [b"{scene}"], [b"more than one"]),
        ("empty argument", b + [b""], [b"''"]),
        ("dash", b + [b"-"], [b"-"]),
        ("--resume into a new directory", b + [b"--resume"], [b"--resume"]),
    ]
    for kind, args, names in options:
        cases.append(Case("command line: " + kind, kind, scene, args, names))
    for kind, args in [("--print-parameters with a scene", b + [b"--print-parameters"]),
                       ("--validate", b + [b"--validate"]),
                       ("--validate and --resume", b + [b"--validate", b"--resume"]),
                       ("--help among --set", b + [b"--help"])]:
        cases.append(Case("command line: " + kind, kind, scene, args, [],
                          run_output=False))
    return cases


def parameter_file_cases(scene):
    text = b"\n".join(scene.lines)
    b = base_args(scene)
    b[0] = b"case.prm"

    def write(content, name="case.prm"):
        return lambda d: copy_scene_dir(d, content, name)

    def fifo(d):
        os.mkfifo(os.path.join(d, "case.prm"))

    def mutual(d):
        copy_scene_dir(d, b"include other.prm\n" + text)
        copy_scene_dir(d, b"include case.prm\n", "other.prm")

    def directory(d):
        os.mkdir(os.path.join(d, "case.prm"))

    def link(target):
        return lambda d: os.symlink(target, os.path.join(d, "case.prm"))

    def loop(d):
        os.symlink("loop2.prm", os.path.join(d, "case.prm"))
        os.symlink("case.prm", os.path.join(d, "loop2.prm"))

    # (kind, setup, names the message must contain one of)
    file_names = [b"case.prm"]
    variants = [
        ("includes itself", write(b"include case.prm\n" + text), file_names),
        ("includes itself by path", write(text + b"\ninclude ./case.prm\n"), file_names),
        ("mutual include", mutual, [b"case.prm", b"other.prm"]),
        ("includes a missing file", write(b"include missing.prm\n" + text), [b"missing.prm"]),
        ("includes a FIFO", lambda d: (os.mkfifo(os.path.join(d, "fifo.prm")),
                                       copy_scene_dir(d, b"include fifo.prm\n" + text)),
         [b"fifo.prm"]),
        ("includes /dev/zero", write(b"include /dev/zero\n" + text), [b"/dev/zero"]),
        ("includes a directory", write(b"include meshes\n" + text), [b"meshes"]),
        ("empty include", write(b"include\n" + text), file_names),
        ("FIFO", fifo, file_names),
        ("directory", directory, file_names),
        ("/dev/zero", link("/dev/zero"), file_names),
        ("/dev/null", link("/dev/null"), file_names),
        ("dangling symlink", link("nothing.prm"), file_names),
        ("symlink loop", loop, file_names),
        ("missing", lambda d: None, file_names),
        ("empty file", write(b""), None),
        ("binary", write(bytes(random.Random(1).randrange(256) for _ in range(4096))), file_names),
        ("NUL bytes", write(text.replace(b"\n", b"\0\n", 3)), file_names),
        ("extra end", write(text + b"\nend\n"), file_names),
        ("missing end", write(text + b"\nsubsection Time\n"), file_names),
        ("unknown subsection", write(text + b"\nsubsection Nowhere\nset a = 1\nend\n"),
         [b"Nowhere"]),
        ("unknown entry", write(text + b"\nset Nothing = 1\n"), [b"Nothing"]),
        ("set without =", write(text + b"\nset Problem\n"), file_names),
        ("very long line", write(text + b"\n# " + b"x" * 2000000 + b"\n"), None),
        ("continuation at end", write(text + b"\nset Problem = mpm \\"), None),
        ("CRLF", write(text.replace(b"\n", b"\r\n")), None),
        ("byte order mark", write(b"\xef\xbb\xbf" + text), file_names),
        ("non-UTF-8 comment", write(b"# \xff\xfe\n" + text), None),
        ("JSON extension, prm content", write(text, "case.json"), [b"case.json"]),
        ("XML extension, prm content", write(text, "case.xml"), [b"case.xml"]),
    ]
    cases = []
    for kind, setup, names in variants:
        args = list(b)
        if "extension" in kind:
            args[0] = b"case.json" if "JSON" in kind else b"case.xml"
            names = names or [args[0]]
        cases.append(Case("parameter file: " + kind, "%s: %s" % (scene.name, kind),
                          scene, args, names or file_names, setup))
    return cases


def json_cases(scene):
    """The scene as JSON with its structure and types mangled."""
    tree = scene.json()
    entries = [p for p, _ in scene.entries]
    rnd = random.Random(scene.name)
    b = base_args(scene)
    b[0] = b"case.json"

    def write(obj_or_bytes):
        data = obj_or_bytes if isinstance(obj_or_bytes, bytes) else \
            json.dumps(obj_or_bytes, indent=1).encode()
        return lambda d: copy_scene_dir(d, data, "case.json")

    def set_path(path, value):
        t = json.loads(json.dumps(tree))
        node = t
        parts = path.split("/")
        for p in parts[:-1]:
            node = node[p]
        node[parts[-1]] = value
        return t

    whole = json.dumps(tree, indent=1).encode()
    cases = [Case("json: as is", scene.name + " as JSON", scene, b, [b"case.json"],
                  write(tree))]
    path = rnd.choice(entries)
    entry = path.split("/")[-1].encode()
    for kind, value in [("null", None), ("number", 1.5), ("integer", 7),
                        ("boolean", True), ("array", [1, 2]), ("object", {}),
                        ("object with value", {"value": "1"}), ("nested null", {"a": None}),
                        ("empty string", ""), ("NaN", float("nan"))]:
        cases.append(Case("json: " + kind, "%s: %s = %r" % (scene.name, path, value),
                          scene, b, [entry, b"case.json"], write(set_path(path, value))))
    sub = path.split("/")[0]
    if "/" in path:
        cases.append(Case("json: subsection null", "%s: %s = null" % (scene.name, sub),
                          scene, b, [sub.encode(), b"case.json"],
                          write(set_path(sub, None))))
        cases.append(Case("json: subsection as string", "%s: %s = \"x\"" % (scene.name, sub),
                          scene, b, [sub.encode(), b"case.json"],
                          write(set_path(sub, "x"))))
    for kind, data in [
        ("truncated", whole[: len(whole) // 2]),
        ("truncated early", whole[:3]),
        ("empty", b""),
        ("top-level array", b"[]"),
        ("top-level null", b"null"),
        ("top-level string", b"\"scene\""),
        ("top-level number", b"1"),
        ("duplicate key", whole.replace(b"{", b"{\"Problem\": \"mpm\", \"Problem\": \"l2 projection\",", 1)),
        ("deep nesting", b"[" * 100000 + b"]" * 100000),
        ("non-UTF-8 string", whole.replace(b"{", b"{\"Problem\": \"\xff\xfe\",", 1)),
        ("byte order mark", b"\xef\xbb\xbf" + whole),
        ("trailing garbage", whole + b"}}"),
        ("comments", b"// scene\n" + whole),
        ("unknown key", whole.replace(b"{", b"{\"Nothing\": \"1\",", 1)),
    ]:
        cases.append(Case("json: " + kind, "%s: JSON %s" % (scene.name, kind), scene, b,
                          [b"case.json"], write(data)))
    return cases


# Gmsh files ------------------------------------------------------------------


def gmsh_sections(text):
    lines = text.split(b"\n")
    sections = {}
    for i, l in enumerate(lines):
        if l.startswith(b"$") and not l.startswith(b"$End"):
            sections[l.strip()[1:]] = i
    return lines, sections


def gmsh_cases(scenes):
    cases = []
    for scene in scenes:
        for path, _ in scene.entries:
            if not path.endswith("File") or scene.values[path] == b"":
                continue
            original = scene.values[path].decode()
            with open(os.path.join(ROOT, "prm", original), "rb") as f:
                text = f.read()
            lines, sec = gmsh_sections(text)
            nodes = sec[b"Nodes"]
            elements = sec[b"Elements"]
            n_nodes = int(lines[nodes + 1])
            first_node = nodes + 2
            first_element = elements + 2

            def edit(fn):
                l = list(lines)
                fn(l)
                return b"\n".join(l)

            def element_with_node(l, node):
                # the first triangle (type 2): its first node becomes @p node
                for i in range(first_element, len(l)):
                    f = l[i].split()
                    if len(f) > 4 and f[1] == b"2":
                        f[-3] = node
                        l[i] = b" ".join(f)
                        return

            def replace_line(index, fn):
                def g(l):
                    l[index] = fn(l[index])
                return g

            def set_type(t):
                def g(l):
                    for i in range(first_element, len(l)):
                        f = l[i].split()
                        if len(f) > 4 and f[1] == b"2":
                            f[1] = t
                            l[i] = b" ".join(f)
                return g

            def duplicate_id(l):
                f = l[first_node + 1].split()
                f[0] = l[first_node].split()[0]
                l[first_node + 1] = b" ".join(f)

            def missing_id(l):
                f = l[first_node + 5].split()
                f[0] = b"%d" % (n_nodes + 1000)
                l[first_node + 5] = b" ".join(f)

            def coordinate(v):
                def g(l):
                    f = l[first_node + 3].split()
                    f[1] = v
                    l[first_node + 3] = b" ".join(f)
                return g

            def count(v):
                return replace_line(nodes + 1, lambda _: v)

            def drop(section):
                def g(l):
                    i = l.index(b"$End" + section)
                    del l[i]
                return g

            def fmt(v):
                return replace_line(sec[b"MeshFormat"] + 1, lambda _: v)

            def all_elements_collapsed(l):
                for i in range(first_element, len(l)):
                    f = l[i].split()
                    if len(f) > 4 and f[1] == b"2":
                        f[-1] = f[-2] = f[-3]
                        l[i] = b" ".join(f)

            variants = [
                ("as is", text),
                ("truncated in the nodes", text[: len(b"\n".join(lines[:first_node + 3])) + 5]),
                ("truncated in the elements", text[: len(text) * 3 // 4]),
                ("truncated after the header", b"\n".join(lines[:4])),
                ("empty", b""),
                ("binary garbage", bytes(random.Random(2).randrange(256) for _ in range(8192))),
                ("duplicate node id", edit(duplicate_id)),
                ("missing node id", edit(missing_id)),
                ("element with node 0", edit(lambda l: element_with_node(l, b"0"))),
                ("element with an unknown node", edit(lambda l: element_with_node(l, b"99999999"))),
                ("element with node -1", edit(lambda l: element_with_node(l, b"-1"))),
                ("degenerate triangles", edit(all_elements_collapsed)),
                ("quadrilaterals", edit(set_type(b"3"))),
                ("unknown element type", edit(set_type(b"99"))),
                ("points only", edit(set_type(b"15"))),
                ("node count too large", edit(count(b"%d" % (n_nodes + 10)))),
                ("node count 1e12", edit(count(b"1000000000000"))),
                ("node count negative", edit(count(b"-5"))),
                ("node count not a number", edit(count(b"many"))),
                ("NaN coordinate", edit(coordinate(b"nan"))),
                ("huge coordinate", edit(coordinate(b"1e308"))),
                ("no $EndNodes", edit(drop(b"Nodes"))),
                ("no $EndElements", edit(drop(b"Elements"))),
                ("MeshFormat 9.9", edit(fmt(b"9.9 0 8"))),
                ("MeshFormat 4.1 with 2.2 content", edit(fmt(b"4.1 0 8"))),
                ("MeshFormat binary flag", edit(fmt(b"2.2 1 8"))),
                ("MeshFormat 1.0", edit(fmt(b"1.0 0 8"))),
                ("MeshFormat not a number", edit(fmt(b"abc"))),
                ("MeshFormat data size 4", edit(fmt(b"2.2 0 4"))),
                ("no MeshFormat", b"\n".join(lines[3:])),
            ]
            entry = path.split("/")[-1].encode()
            for kind, data in variants:
                def setup(d, data=data):
                    with open(os.path.join(d, "mesh.msh"), "wb") as f:
                        f.write(data)
                cases.append(Case("gmsh: " + kind, "%s: %s of %s" % (scene.name, kind, path),
                                  scene, base_args(scene) + [b"--set", path.encode() + b"=mesh.msh"],
                                  [b"mesh.msh"], setup))
            specials = [
                ("FIFO", lambda d: os.mkfifo(os.path.join(d, "mesh.msh"))),
                ("/dev/zero", lambda d: os.symlink("/dev/zero", os.path.join(d, "mesh.msh"))),
                ("/dev/null", lambda d: os.symlink("/dev/null", os.path.join(d, "mesh.msh"))),
                ("/dev/urandom", lambda d: os.symlink("/dev/urandom", os.path.join(d, "mesh.msh"))),
                ("directory", lambda d: os.mkdir(os.path.join(d, "mesh.msh"))),
                ("missing", lambda d: None),
                ("symlink loop", lambda d: os.symlink("mesh.msh", os.path.join(d, "mesh.msh"))),
            ]
            for kind, setup in specials:
                cases.append(Case("gmsh special file: " + kind,
                                  "%s: %s as %s" % (scene.name, kind, path), scene,
                                  base_args(scene) + [b"--set", path.encode() + b"=mesh.msh"],
                                  [b"mesh.msh"], setup))
    return cases


# Output directories ------------------------------------------------------------


def output_cases(scene):
    host = socket.gethostname().encode()
    b = base_args(scene)

    def lock(content):
        def setup(d):
            os.mkdir(os.path.join(d, OUT))
            with open(os.path.join(d, OUT, "psmpm.lock"), "wb") as f:
                f.write(content)
        return setup

    def lock_special(make):
        def setup(d):
            os.mkdir(os.path.join(d, OUT))
            make(os.path.join(d, OUT, "psmpm.lock"))
        return setup

    def in_the_way(make):
        return lambda d: make(os.path.join(d, OUT))

    def write(p, data=b"x"):
        with open(p, "wb") as f:
            f.write(data)

    variants = [
        # (kind, setup, names, fresh output)
        ("a file in the way", in_the_way(write), [OUT.encode()]),
        ("a FIFO in the way", in_the_way(os.mkfifo), [OUT.encode()]),
        ("a dangling symlink in the way", in_the_way(lambda p: os.symlink("nowhere/deeper", p)),
         [OUT.encode()]),
        ("a symlink loop in the way", in_the_way(lambda p: os.symlink(OUT, p)), [OUT.encode()]),
        ("a symlink to /dev/null", in_the_way(lambda p: os.symlink("/dev/null", p)), [OUT.encode()]),
        ("garbled lock", lock(bytes(random.Random(3).randrange(256) for _ in range(64))),
         [b"psmpm.lock"]),
        ("empty lock", lock(b""), [b"psmpm.lock"]),
        ("lock of another host", lock(b"12345 some-other-host\n"), [b"psmpm.lock"]),
        ("lock of a dead process", lock(b"99999999 " + host + b"\n"), [b"psmpm.lock"]),
        ("lock with pid 0", lock(b"0 " + host + b"\n"), [b"psmpm.lock"]),
        ("lock with pid -1", lock(b"-1 " + host + b"\n"), [b"psmpm.lock"]),
        ("lock with a huge pid", lock(b"99999999999999999999999 " + host + b"\n"), [b"psmpm.lock"]),
        ("lock with a live process", lock(b"1 " + host + b"\n"), [b"psmpm.lock"]),
        ("lock without host", lock(b"99999999\n"), [b"psmpm.lock"]),
        ("lock of 10 MB", lock(b"7" * 10000000), [b"psmpm.lock"]),
        ("lock is a directory", lock_special(os.mkdir), [b"psmpm.lock"]),
        ("lock is a FIFO", lock_special(os.mkfifo), [b"psmpm.lock"]),
        ("lock is a dangling symlink", lock_special(lambda p: os.symlink("nowhere", p)),
         [b"psmpm.lock"]),
        ("lock is a symlink to /dev/zero", lock_special(lambda p: os.symlink("/dev/zero", p)),
         [b"psmpm.lock"]),
        ("statistics.txt is a directory",
         lambda d: (os.mkdir(os.path.join(d, OUT)), os.mkdir(os.path.join(d, OUT, "statistics.txt"))),
         [b"statistics.txt"]),
        ("summary.json is a FIFO",
         lambda d: (os.mkdir(os.path.join(d, OUT)), os.mkfifo(os.path.join(d, OUT, "summary.json"))),
         [b"summary.json"]),
        ("log.txt is a FIFO",
         lambda d: (os.mkdir(os.path.join(d, OUT)), os.mkfifo(os.path.join(d, OUT, "log.txt"))),
         [b"log.txt"]),
    ]
    cases = []
    for kind, setup, names in variants:
        cases.append(Case("output directory: " + kind, "%s: %s" % (scene.name, kind), scene, b,
                          names, setup, fresh_output=False))
    for kind, value in [("/proc/self", b"/proc/self"), ("/dev/null", b"/dev/null"),
                        ("/sys", b"/sys/psmpm_fuzz"), ("very long", LONG),
                        ("long component chain", b"d/" * 2000 + b"x")]:
        cases.append(Case("output directory: " + kind, "%s: %s" % (scene.name, kind), scene,
                          b + [b"--set", b"Output directory=" + value],
                          [b"Output directory"], None))
    return cases


# Checkpoints ---------------------------------------------------------------------


def checkpoint_cases(scene, other):
    """--resume from a damaged checkpoint (the scene's own run first)."""
    b = base_args(scene)

    def prepare(d, scene_args):
        args = [a.replace(b"{scene}", scene_args.file.encode()) for a in base_args(scene_args)]
        subprocess.run([PSMPM] + args, cwd=d, stdout=subprocess.DEVNULL,
                       stderr=subprocess.DEVNULL, timeout=60)
        out = os.path.join(d, OUT)
        cp = [f for f in os.listdir(out) if f.startswith("checkpoint-")] \
            if os.path.isdir(out) else []
        return os.path.join(d, OUT, sorted(cp)[-1]) if cp else None

    def damage(fn, source=None):
        def setup(d):
            p = prepare(d, source or scene)
            if p:
                with open(p, "rb") as f:
                    data = bytearray(f.read())
                with open(p, "wb") as f:
                    f.write(fn(data))
        return setup

    def flip(offset_fraction):
        def fn(data):
            i = int(len(data) * offset_fraction)
            data[i] ^= 0xFF
            return bytes(data)
        return fn

    variants = [
        ("intact", damage(lambda x: bytes(x))),
        ("byte flipped at 1%", damage(flip(0.01))),
        ("byte flipped at 50%", damage(flip(0.5))),
        ("byte flipped at 99%", damage(flip(0.99))),
        ("truncated", damage(lambda x: bytes(x[: len(x) // 2]))),
        ("empty", damage(lambda x: b"")),
        ("from another scene", damage(lambda x: bytes(x), other)),
    ]
    cases = []
    for kind, setup in variants:
        cases.append(Case("checkpoint: " + kind, "%s: resume, checkpoint %s" % (scene.name, kind),
                          scene, b + [b"--set", b"Time/End time=3e-9", b"--resume"],
                          [b"checkpoint"], setup, fresh_output=False))
    return cases


def write_failure_cases(scene):
    """Disk full at the n-th write of each kind of output file
    (PSMPM_FAIL_WRITE_AT, PSMPM_FAIL_WRITE_MATCH): exit 8 naming the
    file, the lock released, an earlier checkpoint kept."""
    cases = []
    args = base_args(scene) + [b"--set", b"Time/End time=3e-5",
                               b"--set", b"Checkpoint/Interval=1",
                               b"--set", b"Output/Interval=1"]
    for match in ("statistics.txt", ".vtu", ".pvtu", ".pvd", "checkpoint",
                  "summary.json", "parameters.prm", "particles-", "grid"):
        for at in (1, 2):
            # Written once per run: summary.json, parameters.prm; ring
            # impact's automatic step gives one checkpoint by 3e-5 s.
            if at == 2 and (match in ("summary.json", "parameters.prm") or
                            (match == "checkpoint" and scene.name == "ring_impact.prm")):
                continue
            c = Case("write failure: " + match,
                     "%s: write %d of %s fails" % (scene.name, at, match), scene,
                     args, [match.encode()], fresh_output=False)
            c.env = {"PSMPM_FAIL_WRITE_AT": str(at), "PSMPM_FAIL_WRITE_MATCH": match}
            c.expect_code = 8
            if match == "checkpoint" and at == 2:
                c.kept = [b"checkpoint-00000001.h5"]
            cases.append(c)
    return cases


# Function expressions -----------------------------------------------------------
#
# The entries whose value is a muParser expression or a ';'-separated
# vector of them: (path pattern, the variables: "time" for t, "space" for
# x, y). Boundary conditions/Prescribed velocity holds one such vector per
# boundary ('name: e1; e2, name: ...').
FUNCTION_ENTRIES = [
    (r"^Initial conditions/Velocity$", "space"),
    (r"^Bodies/Body \d+/Initial velocity$", "space"),
    (r"^Bodies/Body \d+/Velocity$", "time"),
    (r"^Boundary conditions/Prescribed velocity$", "time"),
    (r"^Initial conditions/Stress function$", "space"),
    (r"^Projection/Function$", "space"),
]
# Steps into the run at which a time-dependent expression fails.
FAIL_STEP = 4
# Steps a time-dependent case runs.
TIME_STEPS = 10


def function_entry(path):
    """The variables ("time" or "space") of an expression entry @p path,
    or None."""
    for pattern, variables in FUNCTION_ENTRIES:
        if re.match(pattern, path):
            return variables
    return None


def split_outside(text, sep):
    """@p text split at @p sep outside parentheses ('min(t, 1)' is one)."""
    parts, depth, start = [], 0, 0
    for i, ch in enumerate(text):
        if ch == "(":
            depth += 1
        elif ch == ")":
            depth -= 1
        elif ch == sep and depth == 0:
            parts.append(text[start:i])
            start = i + 1
    parts.append(text[start:])
    return parts


def expression_groups(path, value):
    """The vectors of an expression entry: [(prefix, [components])] with
    prefix 'name: ' for each boundary of a prescribed velocity."""
    if path.endswith("Prescribed velocity"):
        groups = []
        for item in split_outside(value, ","):
            name, _, rest = item.partition(":")
            groups.append((name.strip() + ": ", [c.strip() for c in rest.split(";")]))
        return groups
    return [("", [c.strip() for c in value.split(";")])]


def join_groups(groups):
    return ", ".join(prefix + "; ".join(components) for prefix, components in groups)


def scene_dimension(scene):
    return int(scene.values.get("Geometry/Dimension", b"2") or b"2")


def body_x0(scene, path):
    """An x inside the particles of the body of @p path (the middle of its
    rectangle or disk, else of the domain)."""
    m = re.match(r"^(Bodies/Body \d+)/", path)
    if m:
        corners = scene.values.get(m.group(1) + "/Corners", b"").split(b",")
        if len(corners) == 4:
            return 0.5 * (float(corners[0]) + float(corners[2]))
        center = scene.values.get(m.group(1) + "/Center", b"").split(b",")
        if len(center) == 2:
            return float(center[0])
    return 0.5 * float(scene.values.get("Geometry/Length", b"25") or b"25")


def component_mutations(variables, dim):
    """(kind, how): how(components, index) -> new components, the
    component @p index (or the count) made hostile."""
    def put(expression):
        return lambda c, i: c[:i] + [expression] + c[i + 1:]

    foreign = ["x", "y", "z"] if variables == "time" else \
        (["t", "z"] if dim == 2 else ["t", "y", "z"])
    mutations = [
        ("unknown name", put("q*t" if variables == "time" else "q*x")),
        ("unknown name", put("undefined_name")),
        ("syntax error", put("sin(")),
        ("syntax error", put("1+")),
        ("syntax error", put("(1")),
        ("syntax error", put("1)")),
        ("syntax error", put("1 2")),
        ("empty component", put("")),
        ("one component too many", lambda c, i: c + ["0"]),
        ("one component too few", lambda c, i: c[:-1]),
        ("non-finite constant", put("0/0")),
        ("non-finite constant", put("1e309")),
        ("non-finite constant", put("sqrt(-1)")),
    ]
    for v in foreign:
        mutations.append(("variable not in the function", put(v)))
        mutations.append(("variable not in the function", put("1 + 0*" + v)))
    return mutations


def expression_cases(scenes):
    """Component mutations: one component (or the count) of every
    expression entry of every scene made hostile (by --set, one step);
    the constants of the expressions made hostile (a constant removed or
    zeroed)."""
    cases = []
    for scene in scenes:
        dim = scene_dimension(scene)
        for path, _ in scene.entries:
            variables = function_entry(path)
            value = scene.values[path].decode("utf-8", "replace")
            entry = path.split("/")[-1].encode()
            if variables is None or not value.strip():
                continue
            groups = expression_groups(path, value)
            for k, (kind, how) in enumerate(component_mutations(variables, dim)):
                g = k % len(groups)
                prefix, c = groups[g]
                new = list(groups)
                new[g] = (prefix, how(c, k % len(c)))
                mutated = join_groups(new)
                cases.append(Case(
                    "expression: " + kind,
                    "%s: --set %s=%r" % (scene.name, path, mutated[:60]),
                    scene,
                    base_args(scene) + [b"--set", path.encode() + b"=" + mutated.encode()],
                    [entry]))
        # The constants the expressions use: one removed (an unknown name
        # in the expression), one zeroed (L = 0: v0*sin(pi*x/L) not finite).
        constants = scene.values.get("Initial conditions/Function constants", b"").decode()
        pairs = [p.strip() for p in constants.split(",") if "=" in p]
        names = [b"Function constants", b"Velocity", b"Stress function"]
        for i, pair in enumerate(pairs):
            name = pair.split("=")[0].strip()
            for kind, others in [
                    ("constant removed", pairs[:i] + pairs[i + 1:]),
                    ("constant zero", pairs[:i] + [name + "=0"] + pairs[i + 1:]),
                    ("constant not finite", pairs[:i] + [name + "=1e309"] + pairs[i + 1:])]:
                text = ", ".join(others)
                cases.append(Case(
                    "expression: " + kind,
                    "%s: --set Initial conditions/Function constants=%r" % (scene.name, text),
                    scene,
                    base_args(scene) + [b"--set", b"Initial conditions/Function constants="
                                        + text.encode()],
                    names))
    return cases


# The automatic time step of each scene (from its one-step run's screen),
# for the time-dependent cases; None where the run fails.
_DT = {}


def scene_dt(scene):
    if scene.name not in _DT:
        fixed = float(scene.values.get("Time/Time step", b"0") or b"0")
        dt = fixed if fixed > 0 else None
        if dt is None:
            d = tempfile.mkdtemp(prefix="psmpm_fuzz_dt.")
            args = [a.replace(b"{scene}", scene.file.encode()) for a in base_args(scene)]
            try:
                p = subprocess.run([PSMPM.encode()] + args, cwd=d, stdout=subprocess.PIPE,
                                   stderr=subprocess.DEVNULL, timeout=120,
                                   env=dict(ENV, TMPDIR=d))
                m = re.search(rb"dt = ([-+0-9.eE]+)", p.stdout)
                dt = float(m.group(1)) if m else None
            except subprocess.TimeoutExpired:
                dt = None
            shutil.rmtree(d, ignore_errors=True)
        _DT[scene.name] = dt
    return _DT[scene.name]


def time_failures(variables, T, x0):
    """(kind, expression): valid at the start, not finite (or huge) after
    time @p T (functions of t) or at the particles beyond x = @p x0
    (functions of x, y)."""
    if variables == "time":
        return [
            ("pole 1/(t-T)", "1e-3/(t-%.17g)" % T),
            ("sqrt(T-t)", "1e-3*sqrt(%.17g-t)" % T),
            ("log(T-t)", "1e-3*log(%.17g-t)" % T),
            ("exp overflow", "1e-3*exp(800*t/%.17g)" % T),
            ("nan after T", "t > %.17g ? 0/0 : 0" % T),
            ("inf after T", "t > %.17g ? 1/0 : 0" % T),
            ("huge after T", "t > %.17g ? 1e300 : 0" % T),
        ]
    return [
        ("pole 1/(x-x0)", "1e-3/(x-%.17g)" % x0),
        ("sqrt(x0-x)", "1e-3*sqrt(%.17g-x)" % x0),
        ("log(x-x0)", "1e-3*log(x-%.17g)" % x0),
        ("nan beyond x0", "x > %.17g ? 0/0 : 0" % x0),
        ("inf beyond x0", "x > %.17g ? 1/0 : 0" % x0),
        ("huge beyond x0", "x > %.17g ? 1e300 : 0" % x0),
    ]


def time_dependent_cases(scenes):
    """Expressions valid at t = 0 that fail later: a component of every
    expression entry replaced by one that becomes singular, nan, inf or
    huge a few steps into the run (functions of t; the run goes
    TIME_STEPS steps) or at some particles only (functions of x, y)."""
    cases = []
    for scene in scenes:
        dim = scene_dimension(scene)
        # (path, value, extra arguments): the scene's expression entries
        # and, in a scene of free bodies in multi-velocity contact, its
        # last body made a driven one (a function of t more to fail).
        entries = [(path, scene.values[path].decode("utf-8", "replace"), [])
                   for path, _ in scene.entries]
        n_bodies = int(scene.values.get("Bodies/Number of bodies", b"0") or b"0")
        if scene.values.get("Contact/Type") == b"multi-velocity" and n_bodies >= 2 and \
                not any(p.endswith("/Motion") for p, _ in scene.entries):
            body = "Bodies/Body %d" % n_bodies
            entries.append((body + "/Velocity", "; ".join(["0"] * dim),
                            [b"--set", body.encode() + b"/Motion=prescribed"]))
        for path, value, extra in entries:
            variables = function_entry(path)
            if variables is None or not value.strip():
                continue
            groups = expression_groups(path, value)
            entry = path.split("/")[-1].encode()
            x0 = body_x0(scene, path)
            n_failures = len(time_failures(variables, 1., x0))
            for k in range(n_failures):
                g = k % len(groups)
                prefix, c = groups[g]
                i = (k // len(groups)) % len(c)
                kind = time_failures(variables, 1., x0)[k][0]

                def build(scene=scene, path=path, groups=groups, g=g, i=i, k=k,
                          variables=variables, x0=x0, extra=extra):
                    """The arguments: the mutated entry and, for a function
                    of t, an end time TIME_STEPS steps in."""
                    args = base_args(scene) + extra
                    T = 1.
                    if variables == "time":
                        # A scene whose one-step run fails: a step of
                        # END_TIME / TIME_STEPS, as if it ran.
                        dt = scene_dt(scene) or float(END_TIME) / TIME_STEPS
                        T = FAIL_STEP * dt
                        args += [b"--set", b"Time/End time=%.17g" % (TIME_STEPS * dt)]
                    prefix, c = groups[g]
                    new = list(groups)
                    new[g] = (prefix, c[:i] + [time_failures(variables, T, x0)[k][1]] + c[i + 1:])
                    return args + [b"--set", path.encode() + b"=" + join_groups(new).encode()]

                case = Case(("time-dependent: " if variables == "time" else "space-dependent: ")
                            + kind,
                            "%s: %s component %d of %s" % (scene.name, kind, i, path),
                            scene, None, [entry])
                case.build = build
                cases.append(case)
    return cases


def all_cases(scenes, every_scene=False):
    by_name = {s.name: s for s in scenes}
    small = by_name.get("vibrating_bar_small.prm", scenes[0])
    cases = value_cases(scenes, every_scene)
    cases += set_syntax_cases(small)
    for s in scenes:
        cases += parameter_file_cases(s) if s is small else []
    cases += parameter_file_cases(by_name.get("ring_impact.prm", small))
    for name in ("vibrating_bar_small.prm", "ring_impact.prm", "strip_footing.prm",
                 "chapter_bar_1d.prm", "solver_study.prm", "l2_projection.prm"):
        if name in by_name:
            cases += json_cases(by_name[name])
    cases += gmsh_cases(scenes)
    cases += expression_cases(scenes)
    cases += time_dependent_cases(scenes)
    cases += output_cases(small)
    mpm = [s for s in scenes if s.problem == "mpm"]
    for name in ("vibrating_bar_small.prm", "ring_impact.prm"):
        if name in by_name:
            cases += write_failure_cases(by_name[name])
    for s in (small, by_name.get("ring_impact.prm"), by_name.get("vibrating_bar_small_ps.prm")):
        if s is not None:
            cases += checkpoint_cases(s, by_name.get("cantilever.prm", mpm[-1]))
    return cases


def sample(cases, n, seed):
    """@p n cases, round robin over the kinds (each kind's cases shuffled
    with @p seed): every kind is in a sample of at least as many cases as
    there are kinds."""
    rnd = random.Random(seed)
    by_kind = collections.OrderedDict()
    for c in cases:
        by_kind.setdefault(c.kind, []).append(c)
    for k in by_kind:
        rnd.shuffle(by_kind[k])
    kinds = list(by_kind)
    rnd.shuffle(kinds)
    chosen = []
    i = 0
    while len(chosen) < n and any(by_kind.values()):
        k = kinds[i % len(kinds)]
        if by_kind[k]:
            chosen.append(by_kind[k].pop())
        i += 1
    return chosen


# ---------------------------------------------------------------------------
# Running and the oracle


def strict_json(text):
    def refuse(name):
        raise ValueError("non-finite number " + name)
    return json.loads(text, parse_constant=refuse)


def numbers_finite(obj):
    # psmpm writes a number that is not finite as null.
    if obj is None:
        return False
    if isinstance(obj, float):
        return math.isfinite(obj)
    if isinstance(obj, dict):
        return all(numbers_finite(v) for v in obj.values())
    if isinstance(obj, list):
        return all(numbers_finite(v) for v in obj)
    return True


def listing(d):
    if not os.path.isdir(d) or os.path.islink(d):
        return None
    return sorted(os.listdir(d))


def table_rows(path):
    """The data rows of a text table (lines that are not empty and do not
    start with #) and its first inf or nan entry, or None."""
    rows, token = 0, None
    with open(path, "rb") as f:
        for line in f:
            if line.startswith(b"#") or not line.strip():
                continue
            rows += 1
            for tok in line.split():
                if token is None and re.match(rb"^[-+]?(nan|inf)", tok, re.I):
                    token = tok.decode("utf-8", "replace")
    return rows, token


def vtu_non_finite(path):
    """The name of the first data array of the VTU file @p path (deal.II's
    zlib-compressed base64 binary, or ASCII) with an inf or nan, or None
    (also for a file this reader does not understand: its completeness is
    checked elsewhere)."""
    import base64
    import zlib
    try:
        import numpy
    except ImportError:
        return None
    with open(path, "rb") as f:
        text = f.read()
    compressed = b"vtkZLibDataCompressor" in text[:1000]
    for m in re.finditer(rb"<DataArray([^>]*)>(.*?)</DataArray>", text, re.S):
        attributes, data = m.group(1), m.group(2).strip()
        t = re.search(rb'type="(Float32|Float64)"', attributes)
        if not t:
            continue
        name = re.search(rb'Name="([^"]*)"', attributes)
        name = name.group(1).decode("utf-8", "replace") if name else "Points"
        dtype = numpy.float32 if t.group(1) == b"Float32" else numpy.float64
        try:
            if b'format="ascii"' in attributes:
                values = numpy.array(data.split(), dtype=numpy.float64)
            elif compressed:
                # A header of uint32: blocks, block size, last block size,
                # each block's compressed size; base64 of its own, then
                # the blocks' base64.
                blocks = numpy.frombuffer(base64.b64decode(data[:8])[:4], numpy.uint32)[0]
                header_chars = -(-(3 + int(blocks)) * 4 // 3) * 4
                header = numpy.frombuffer(base64.b64decode(data[:header_chars]), numpy.uint32)
                raw = base64.b64decode(data[header_chars:])
                out, at = [], 0
                for size in header[3:3 + blocks]:
                    out.append(zlib.decompress(raw[at:at + int(size)]))
                    at += int(size)
                values = numpy.frombuffer(b"".join(out), dtype)
            else:
                values = numpy.frombuffer(base64.b64decode(data)[4:], dtype)
        except (ValueError, zlib.error, IndexError):
            continue
        if not numpy.all(numpy.isfinite(values)):
            return name
    return None


def check_completed(out):
    """Failures of a run that ended with exit 0."""
    problems = []
    summary = os.path.join(out, b"summary.json")
    try:
        with open(summary, "rb") as f:
            s = strict_json(f.read().decode("utf-8"))
        if s.get("status") != "completed":
            problems.append("silent: exit 0 with status %r" % s.get("status"))
        if not numbers_finite(s):
            problems.append("silent: non-finite number in summary.json")
    except (OSError, ValueError, UnicodeDecodeError) as e:
        problems.append("silent: exit 0 without a valid summary.json (%s)" % e)
    stats = os.path.join(out, b"statistics.txt")
    if os.path.isfile(stats) and table_rows(stats)[0] == 0:
        problems.append("silent: exit 0 with an empty statistics.txt")
    for name in listing(out) or []:
        p = os.path.join(out, name)
        # Every table a run writes (statistics.txt, tracked_particle.txt,
        # solver_study.tsv): a row with inf or nan is no result.
        if name.endswith((b".txt", b".tsv")) and name != b"log.txt" and os.path.isfile(p):
            token = table_rows(p)[1]
            if token:
                problems.append("silent: exit 0 with %s in %s" % (token, name.decode()))
        if name == b"psmpm.lock":
            problems.append("stale: lock left after exit 0")
        elif name.endswith(b".tmp"):
            problems.append("half-written: temporary file %r left" % name)
        elif name.endswith((b".vtu", b".pvtu", b".pvd")) and os.path.isfile(p):
            with open(p, "rb") as f:
                f.seek(max(0, os.path.getsize(p) - 64))
                if b"</VTKFile>" not in f.read():
                    problems.append("half-written: %r incomplete" % name)
                    continue
            # Particle and grid values of a simulation: a nan or inf (a
            # Float32 overflow too) is no result. (An l2 projection of a
            # function beyond the Float32 range, such as 1e308, is
            # projected exactly in double and accepted: its
            # projection.vtu is not checked.)
            if name.endswith(b".vtu") and name.startswith((b"particles-", b"grid-")):
                array = vtu_non_finite(p)
                if array:
                    problems.append("silent: exit 0 with inf or nan in %s of %s"
                                    % (array, name.decode("utf-8", "replace")))
    return problems


def run_case(case, case_dir, timeout):
    os.makedirs(case_dir)
    if case.setup:
        case.setup(case_dir)
    out = os.path.join(case_dir.encode(), case.out)
    before = listing(out)
    scene_path = case.scene.file if case.scene else ""
    argv = [PSMPM.encode()] + case.argv(scene_path)
    start = time.time()
    # Open MPI's session directory of its own (under TMPDIR): concurrent
    # singletons that share one in /tmp can remove it under each other.
    env = dict(ENV, TMPDIR=os.path.join(case_dir, "tmp"), **case.env)
    os.makedirs(env["TMPDIR"], exist_ok=True)
    try:
        p = subprocess.run(argv, cwd=case_dir, stdout=subprocess.PIPE,
                           stderr=subprocess.PIPE, stdin=subprocess.DEVNULL,
                           timeout=timeout, env=env)
        code, screen, errors = p.returncode, p.stdout, p.stderr
    except subprocess.TimeoutExpired as e:
        code, screen, errors = None, e.stdout or b"", e.stderr or b""
    seconds = time.time() - start
    problems = []
    if case.expect_code is not None and code is not None and code >= 0 \
            and code != case.expect_code:
        problems.append("exit code: %d, expected %d" % (code, case.expect_code))
    for k in case.kept:
        if not os.path.isfile(os.path.join(out, k)):
            problems.append("lost: %s removed" % k.decode())
    if code is None:
        problems.append("hang: no end within %g s" % timeout)
    elif code < 0:
        problems.append("signal: killed by signal %d" % -code)
    elif code == 1:
        problems.append("internal error: exit code 1")
    elif code == 0:
        if case.run_output:
            problems += check_completed(out)
    elif code == 2:
        message = errors
        if not any(n.lower() in message.lower() for n in case.names):
            problems.append("message: exit 2 without naming %s" %
                            " or ".join(repr(n.decode("utf-8", "replace")) for n in case.names))
        if errors.count(b"psmpm: error") != 1:
            problems.append("message: exit 2 with %d error lines" % errors.count(b"psmpm: error"))
        after = listing(out)
        if case.fresh_output and after is not None:
            problems.append("half-written: output directory created on exit 2")
        elif not case.fresh_output and after != before:
            problems.append("half-written: output directory changed on exit 2")
    elif 3 <= code <= 9:
        if not (errors.strip() or b"psmpm:" in screen):
            problems.append("message: exit %d without a reason" % code)
        if case.expect_code == 8 and not any(n in errors for n in case.names):
            problems.append("message: exit 8 without naming the file")
        summary = os.path.join(out, b"summary.json")
        if os.path.isfile(summary):
            try:
                with open(summary, "rb") as f:
                    strict_json(f.read().decode("utf-8"))
            except (ValueError, UnicodeDecodeError) as e:
                problems.append("silent: invalid summary.json on exit %d (%s)" % (code, e))
        if os.path.exists(os.path.join(out, b"psmpm.lock")) and code != 2:
            problems.append("stale: lock left after exit %d" % code)
    else:
        problems.append("exit code: %d" % code)
    if code is not None and (b"Stacktrace" in errors or b"An error occurred in line" in errors):
        problems.append("message: deal.II source location or stack trace")
    return dict(code=code, seconds=seconds, problems=problems,
                message=errors.decode("utf-8", "replace").strip()[:400])


def main():
    global PSMPM, ENV
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--psmpm", default=os.path.join(ROOT, "build", "psmpm"))
    ap.add_argument("--scenes", default=os.path.join(ROOT, "prm"))
    ap.add_argument("--work", default=None)
    ap.add_argument("--keep", action="store_true")
    ap.add_argument("--cases", type=int, default=0)
    ap.add_argument("--seed", type=int, default=49)
    ap.add_argument("--jobs", type=int, default=1)
    ap.add_argument("--timeout", type=float, default=30)
    ap.add_argument("--list", action="store_true")
    ap.add_argument("--only", default=None)
    ap.add_argument("--every-scene", action="store_true")
    a = ap.parse_args()
    PSMPM = os.path.abspath(a.psmpm)
    ENV = dict(os.environ)
    ENV.pop("PSMPM_FAIL_WRITE_AT", None)
    # Absolute: every case runs in a directory of its own.
    a.scenes = os.path.abspath(a.scenes)
    scenes = [Scene(os.path.join(a.scenes, f)) for f in sorted(os.listdir(a.scenes))
              if f.endswith(".prm")]
    cases = all_cases(scenes, a.every_scene)
    if a.only:
        cases = [c for c in cases if a.only in c.kind or a.only in c.description]
    n_kinds = len({c.kind for c in cases})
    if a.cases:
        cases = sample(cases, a.cases, a.seed)
    if a.list:
        for c in cases:
            print("%-45s %s" % (c.kind, c.description))
        print("%d cases, %d kinds" % (len(cases), len({c.kind for c in cases})))
        return 0
    if not os.access(PSMPM, os.X_OK):
        print("psmpm_fuzz: no executable %s (build the target psmpm)" % PSMPM)
        return 1
    work = a.work or tempfile.mkdtemp(prefix="psmpm_fuzz.")
    os.makedirs(work, exist_ok=True)
    start = time.time()
    results = [None] * len(cases)

    def one(i):
        d = os.path.join(work, "case-%05d" % i)
        shutil.rmtree(d, ignore_errors=True)
        results[i] = run_case(cases[i], d, a.timeout)
        if not results[i]["problems"] and not a.keep:
            shutil.rmtree(d, ignore_errors=True)

    with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as pool:
        list(pool.map(one, range(len(cases))))

    failures = collections.OrderedDict()
    codes = collections.Counter()
    for i, (c, r) in enumerate(zip(cases, results)):
        codes[r["code"]] += 1
        for p in r["problems"]:
            failures.setdefault((p.split(":")[0], c.kind), []).append((i, c, r, p))
    print("psmpm_fuzz: seed %d, %d cases of %d kinds (%d kinds in the full sweep), "
          "%.0f s" % (a.seed, len(cases), len({c.kind for c in cases}), n_kinds,
                      time.time() - start))
    print("exit codes: " + ", ".join("%s: %d" % ("timeout" if k is None else k, v)
                                     for k, v in sorted(codes.items(), key=lambda x: str(x[0]))))
    n_failed = len({i for v in failures.values() for i, _, _, _ in v})
    by_class = collections.Counter()
    for (cls, kind), v in failures.items():
        by_class[cls] += len(v)
    print("failures: %d cases, %d kinds (%s)" % (
        n_failed, len(failures),
        ", ".join("%s %d" % kv for kv in sorted(by_class.items())) or "none"))
    for (cls, kind), v in failures.items():
        print("\n[%s] %s: %d case(s)" % (cls, kind, len(v)))
        for i, c, r, p in v[:5]:
            print("  case-%05d %s\n    %s (%.1f s)\n    argv: %s\n    message: %s" % (
                i, c.description, p, r["seconds"],
                " ".join(repr(x)[1:] if b" " in x or not x else x.decode("utf-8", "replace")
                         for x in c.argv(c.scene.file if c.scene else "")[:12])[:300],
                r["message"][:300].replace("\n", " | ")))
        if len(v) > 5:
            print("  ... and %d more" % (len(v) - 5))
    if not a.work and not a.keep:
        shutil.rmtree(work, ignore_errors=True)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
