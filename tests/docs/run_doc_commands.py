#!/usr/bin/env python3
"""Runs every shell command and Python example shown in README.md and docs/*.md, so the
docs cannot rot.

Three kinds of fenced blocks are run:

  ```sh        every line is run (a line ending in a backslash continues on the next),
               as one bash script with `set -e`, so each command must succeed;
  ```console   a transcript: lines starting with "$ " are run, and the lines after
               each one are its expected output, compared line by line. A line that
               ends in seconds ("0.0039 s") compares only the text before the number;
               a line that is only "..." stands for any number of lines (none too), so
               a page can show the part of a long output it talks about, such as the
               lines of `exactgeo inside --help` for the options it explains;
  ```python    the whole block, by Debian's /usr/bin/python3 with the package of the
               build tree (PYTHONPATH=build/python), which must exit with status 0.

A block preceded by the comment `<!-- docs-test: skip: REASON -->` is not run (the
build itself, which CI runs as the README's first command; measurements that take
minutes; commands for several machines). The reason is required, and every file the
skipped block names under scripts/, examples/ or tests/data/ must still exist.

Blocks run in a scratch directory that mirrors the repository (its folders linked, docs/
copied, new files land in the scratch directory) with `build` the build tree under test,
its bin/ first on PATH (`exactgeo` is the tool just built) and HOME a scratch folder (an
install to $HOME/.local stays inside it).

usage: run_doc_commands.py SOURCE_DIR BUILD_DIR
"""

import os
import re
import shutil
import subprocess
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path

FENCE = re.compile(r"^```(\w*)\s*$")
SKIP = re.compile(r"^<!--\s*docs-test:\s*skip:\s*(.*?)\s*-->\s*$")
SECONDS = re.compile(r"^(.*?)[0-9][0-9.e+-]* s$")
ELISION = "..."
NAMED_FILE = re.compile(r"(?<![\w/])((?:scripts|examples|tests/data)/[\w./-]+)")
TIMEOUT_SECONDS = 300


@dataclass
class Block:
    path: Path
    line: int  # of the opening fence, 1-based
    kind: str  # "sh" or "console"
    lines: list
    skip_reason: str = None

    def where(self):
        return f"{self.path}:{self.line}"


def command_blocks(path):
    """The sh and console blocks of one Markdown file, in order."""
    blocks, current, pending_skip = [], None, None
    for number, text in enumerate(path.read_text().splitlines(), start=1):
        if current is not None:
            if FENCE.match(text):
                blocks.append(current)
                current = None
            else:
                current.lines.append(text)
            continue
        fence = FENCE.match(text)
        if fence:
            kind = fence.group(1)
            if kind in ("sh", "console", "python"):
                current = Block(path, number, kind, [], pending_skip)
            else:
                current = Block(path, number, "other", [])
            pending_skip = None
            continue
        skip = SKIP.match(text)
        if skip:
            pending_skip = skip.group(1)
        elif text.strip():
            pending_skip = None
    if current is not None:
        raise SystemExit(f"{path}:{current.line}: fenced block never closed")
    return [b for b in blocks if b.kind != "other"]


def scratch_tree(source, build):
    """A directory with every top-level entry of `source` linked and `build` -> build."""
    root = Path(tempfile.mkdtemp(prefix="exactgeo-docs-"))
    work = root / "repo"
    work.mkdir()
    for entry in source.iterdir():
        if entry.name.startswith(".") or entry.name.startswith("build"):
            continue
        if entry.name == "docs":
            shutil.copytree(entry, work / entry.name)
        else:
            (work / entry.name).symlink_to(entry.resolve())
    (work / "build").symlink_to(build.resolve())
    home = root / "home"
    home.mkdir()
    return root, work, home


def environment(build, home):
    env = dict(os.environ)
    env["PATH"] = f"{build.resolve() / 'bin'}:{env.get('PATH', '')}"
    env["HOME"] = str(home)
    env["PYTHONDONTWRITEBYTECODE"] = "1"
    env["PYTHONPATH"] = str(build.resolve() / "python")
    return env


def run_script(script, cwd, env):
    return subprocess.run(["bash", "-c", "set -eo pipefail\n" + script], cwd=cwd, env=env,
                          capture_output=True, text=True, timeout=TIMEOUT_SECONDS)


def run_sh(block, cwd, env):
    """None, or what went wrong."""
    result = run_script("\n".join(block.lines), cwd, env)
    if result.returncode != 0:
        return (f"exit code {result.returncode}\n--- stdout\n{result.stdout[-2000:]}"
                f"--- stderr\n{result.stderr[-2000:]}")
    return None


def run_python(block, cwd, env):
    """None, or what went wrong."""
    result = subprocess.run(["/usr/bin/python3", "-"], input="\n".join(block.lines), cwd=cwd,
                            env=env, capture_output=True, text=True, timeout=TIMEOUT_SECONDS)
    if result.returncode != 0:
        return f"exit code {result.returncode}\n--- stderr\n{result.stderr[-2000:]}"
    return None


def same_line(expected, actual):
    timed = SECONDS.match(expected)
    if timed:
        return actual.startswith(timed.group(1)) and SECONDS.match(actual) is not None
    return expected.rstrip() == actual.rstrip()


def same_lines(expected, actual):
    """Whether `actual` is `expected` line by line, each "..." line standing for any run
    of lines. The shown runs between the elisions are found in order, each as early as
    it can be; the first is anchored at the start and the last at the end (unless an
    elision comes first or last)."""
    runs = [[]]
    for line in expected:
        if line.strip() == ELISION:
            runs.append([])
        else:
            runs[-1].append(line)
    if len(runs) == 1:
        return len(actual) == len(expected) and all(map(same_line, expected, actual))

    def matches_at(run, at):
        return at + len(run) <= len(actual) and all(map(same_line, run, actual[at:]))

    first, middle, last = runs[0], runs[1:-1], runs[-1]
    if not matches_at(first, 0):
        return False
    at = len(first)
    for run in middle:
        while at + len(run) <= len(actual) and not matches_at(run, at):
            at += 1
        if not matches_at(run, at):
            return False
        at += len(run)
    return len(actual) - len(last) >= at and matches_at(last, len(actual) - len(last))


def run_console(block, cwd, env):
    """Runs each "$ " line and compares its output with the lines that follow it."""
    steps = []
    for text in block.lines:
        if text.startswith("$ "):
            steps.append((text[2:], []))
        elif steps:
            steps[-1][1].append(text)
        elif text.strip():
            return f"output before the first '$ ' command: {text!r}"
    if not steps:
        return "a console block without a '$ ' command"
    for command, expected in steps:
        result = run_script(command, cwd, env)
        if result.returncode != 0:
            return f"`{command}`: exit code {result.returncode}\n{result.stderr[-2000:]}"
        actual = result.stdout.splitlines()
        while expected and not expected[-1].strip():
            expected.pop()
        if not same_lines(expected, actual):
            shown = "\n".join(actual)
            return f"`{command}` printed\n{shown}\ninstead of\n" + "\n".join(expected)
    return None


def check_skipped(block, source):
    if not block.skip_reason:
        return "skipped without a reason"
    missing = [name for line in block.lines for name in NAMED_FILE.findall(line)
               if not (source / name).exists()]
    return f"names files that do not exist: {', '.join(missing)}" if missing else None


def main():
    if len(sys.argv) != 3:
        raise SystemExit(__doc__.strip().splitlines()[-1])
    source, build = Path(sys.argv[1]), Path(sys.argv[2])
    pages = [source / "README.md"] + sorted((source / "docs").glob("*.md"))
    blocks = [b for page in pages for b in command_blocks(page)]
    root, work, home = scratch_tree(source, build)
    env = environment(build, home)
    failures, ran, skipped = [], 0, 0
    try:
        for block in blocks:
            name = block.where().replace(str(source) + "/", "")
            if block.skip_reason is not None:
                problem = check_skipped(block, source)
                skipped += 1
                print(f"skip {name}: {block.skip_reason}")
            else:
                runner = {"sh": run_sh, "console": run_console, "python": run_python}[block.kind]
                problem = runner(block, work, env)
                ran += 1
                print(f"{'ran ' if problem is None else 'FAIL'} {name}")
            if problem is not None:
                failures.append(f"{name}: {problem}")
    finally:
        shutil.rmtree(root, ignore_errors=True)
    print(f"{ran} blocks run, {skipped} skipped, {len(failures)} failed")
    for failure in failures:
        print(f"\n{failure}")
    if ran == 0:
        print("no command block found: the extraction is broken", file=sys.stderr)
        return 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
