#!/usr/bin/python3
"""Documentation lint: keeps the README short, the docs and comments free of work-history words,
and every repository path the docs name real.

    doc_lint.py [--root DIR]   lint the tree at DIR (default: the repository holding this file)
    doc_lint.py --self-test    lint a temporary tree with one violation of each kind and check
                               that each is reported (and that a clean tree passes)

Each finding is printed as `path:line: rule: text`; the exit code is 1 when there is one, else 0.

Rules:
  readme-length  README.md has more than README_MAX_LINES lines.
  history-word   a work-history word (see HISTORY_PATTERNS) in a Markdown, source, CMake, script
                 or scenario file. Docs and comments say what is true now and how to check it;
                 the history of the work belongs in the commit messages.
  missing-path   a backticked repository path, a relative Markdown link or a link's #heading
                 in README.md or a Markdown file under docs/ that names nothing in the tree.

Standard library only, so that it runs on a machine with nothing but /usr/bin/python3.
"""

import argparse
import glob
import os
import re
import sys
import tempfile

README_MAX_LINES = 250

# Built from pieces so that this file does not match its own patterns.
_NUMBER = "[0-9]"
HISTORY_PATTERNS = [
    re.compile("st" + "op " + _NUMBER, re.IGNORECASE),
    re.compile("iss" + "ue " + _NUMBER, re.IGNORECASE),
    re.compile(r"\b" + "V" + "M" + r"\b", re.IGNORECASE),
]

# Files whose words are checked: by extension, or by exact name.
TEXT_EXTENSIONS = {
    ".md", ".txt", ".cc", ".cpp", ".cxx", ".c", ".h", ".hpp", ".hh", ".inc", ".py", ".sh",
    ".mjs", ".js", ".html", ".css", ".cmake", ".in", ".yaml", ".yml", ".json", ".map", ".gp",
    ".clang-format",
}
TEXT_NAMES = {"CMakeLists.txt", "Makefile", "run", ".gitignore", ".clang-format"}

# Folders never walked: build trees, version control, outputs, and data (FEM results, fuzz
# corpora) whose contents are inputs, not prose.
SKIP_DIR_NAMES = {".git", "out", "__pycache__", "node_modules", "corpus"}
SKIP_DIR_PREFIXES = ("build",)
SKIP_DIR_PATHS = {os.path.join("tools", "fem", "data")}

# What a backticked token must end in to count as a file name when it has no '/'.
SOURCE_EXTENSIONS = (
    ".cc", ".cpp", ".c", ".h", ".hpp", ".py", ".sh", ".cmake", ".yaml", ".md", ".mjs", ".js",
    ".gp",
)

FENCE = re.compile(r"^\s*(```|~~~)")
BACKTICKED = re.compile(r"`([^`\n]+)`")
MARKDOWN_LINK = re.compile(r"\]\(([^)\s]+)\)")


class Finding:
    def __init__(self, path, line, rule, text):
        self.path, self.line, self.rule, self.text = path, line, rule, text

    def __str__(self):
        return f"{self.path}:{self.line}: {self.rule}: {self.text}"


def _skipped_dir(rel_dir, name):
    if name in SKIP_DIR_NAMES or name.startswith(SKIP_DIR_PREFIXES):
        return True
    return os.path.normpath(os.path.join(rel_dir, name)) in SKIP_DIR_PATHS


def walk_files(root):
    """Yields every file's path relative to root, skipping the folders above."""
    for dirpath, dirnames, filenames in os.walk(root):
        rel_dir = os.path.relpath(dirpath, root)
        if rel_dir == ".":
            rel_dir = ""
        dirnames[:] = sorted(d for d in dirnames if not _skipped_dir(rel_dir, d))
        for name in sorted(filenames):
            yield os.path.join(rel_dir, name)


def _is_text_file(rel):
    name = os.path.basename(rel)
    if name in TEXT_NAMES:
        return True
    return os.path.splitext(name)[1] in TEXT_EXTENSIONS or name in TEXT_EXTENSIONS


def _read_lines(path):
    with open(path, "rb") as f:
        data = f.read()
    if b"\0" in data:
        return None
    return data.decode("utf-8", errors="replace").splitlines()


def check_readme_length(root):
    path = os.path.join(root, "README.md")
    if not os.path.isfile(path):
        return []
    lines = _read_lines(path) or []
    if len(lines) > README_MAX_LINES:
        return [Finding("README.md", len(lines), "readme-length",
                        f"{len(lines)} lines, at most {README_MAX_LINES}")]
    return []


def check_history_words(root, files):
    findings = []
    for rel in files:
        if not _is_text_file(rel):
            continue
        lines = _read_lines(os.path.join(root, rel))
        if lines is None:
            continue
        for number, line in enumerate(lines, 1):
            for pattern in HISTORY_PATTERNS:
                match = pattern.search(line)
                if match:
                    findings.append(Finding(rel, number, "history-word",
                                            f"'{match.group(0)}' in: {line.strip()[:160]}"))
                    break
    return findings


def _top_level_entries(root):
    entries = set()
    for name in os.listdir(root):
        if name.startswith(".") or name.startswith(SKIP_DIR_PREFIXES) or name == "out":
            continue
        entries.add(name)
    return entries


def _path_candidates(span):
    """The tokens of a backticked span that may be paths, trailing punctuation removed."""
    for token in span.split():
        token = token.strip("\"'(),;")
        token = token.rstrip(".:")
        if not token or "://" in token or token.startswith(("-", "$", "~")):
            continue
        if any(c in token for c in "<>{}[]=|@"):
            continue
        token = token.split("#", 1)[0]
        token = re.sub(r":[0-9]+(:[0-9]+)?$", "", token)  # file.cc:123
        if token.startswith("/"):
            continue  # a system path (/usr/bin/python3, /dev/null)
        yield token


def _exists(base, token):
    path = os.path.join(base, token)
    if any(c in token for c in "*?"):
        return bool(glob.glob(path))
    return os.path.exists(path)


def _heading_anchors(path):
    """The anchors GitHub gives a Markdown file's headings (lower case, punctuation dropped,
    spaces as hyphens, repeats numbered)."""
    anchors, seen, in_fence = set(), {}, False
    for line in _read_lines(path) or []:
        if FENCE.match(line):
            in_fence = not in_fence
        if in_fence or not line.startswith("#"):
            continue
        text = line.lstrip("#").strip().lower()
        slug = re.sub(r"[^\w\- ]", "", text).replace(" ", "-")
        count = seen.get(slug, 0)
        seen[slug] = count + 1
        anchors.add(slug if count == 0 else f"{slug}-{count}")
    return anchors


def check_paths(root, files):
    """Backticked repository paths and relative links in README.md and docs/**/*.md."""
    top = _top_level_entries(root)
    basenames = {os.path.basename(rel) for rel in files}
    docs = [rel for rel in files
            if rel == "README.md" or (rel.startswith("docs" + os.sep) and rel.endswith(".md"))]
    findings = []
    for rel in docs:
        doc_dir = os.path.join(root, os.path.dirname(rel))
        lines = _read_lines(os.path.join(root, rel)) or []
        in_fence = False
        for number, line in enumerate(lines, 1):
            if FENCE.match(line):
                in_fence = not in_fence
                continue
            if in_fence:
                continue
            for span in BACKTICKED.findall(line):
                for token in _path_candidates(span):
                    first = token.split("/", 1)[0]
                    if "/" in token and first in top:
                        if not _exists(root, token):
                            findings.append(Finding(rel, number, "missing-path",
                                                    f"`{token}` does not exist"))
                    elif "/" in token and os.path.dirname(rel) and \
                            not _skipped_dir("", first) and first not in (".", "..") and \
                            os.path.exists(os.path.join(doc_dir, first)):
                        if not _exists(doc_dir, token):
                            findings.append(Finding(rel, number, "missing-path",
                                                    f"`{token}` does not exist"))
                    elif "/" not in token and token.endswith(SOURCE_EXTENSIONS) and \
                            not any(c in token for c in "*?"):
                        if token not in basenames and not _exists(doc_dir, token):
                            findings.append(Finding(rel, number, "missing-path",
                                                    f"`{token}` names no file in the tree"))
            for target in MARKDOWN_LINK.findall(line):
                if "://" in target or target.startswith("mailto:"):
                    continue
                target, _, anchor = target.partition("#")
                target_path = os.path.join(doc_dir, target) if target else \
                    os.path.join(root, rel)
                if target and not os.path.exists(target_path):
                    findings.append(Finding(rel, number, "missing-path",
                                            f"link target `{target}` does not exist"))
                elif anchor and target_path.endswith(".md") and \
                        anchor not in _heading_anchors(target_path):
                    findings.append(Finding(rel, number, "missing-path",
                                            f"link `{target}#{anchor}`: no such heading"))
    return findings


def lint(root):
    files = list(walk_files(root))
    return check_readme_length(root) + check_history_words(root, files) + check_paths(root, files)


def _write(root, rel, text):
    path = os.path.join(root, rel)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)


def self_test():
    """Lints a clean fake tree (no finding expected), then one with each kind of violation."""
    failures = []
    with tempfile.TemporaryDirectory(prefix=f"doc_lint_{os.getpid()}_") as root:
        _write(root, "README.md", "# x\n\nSee `framework/core/a.h` and [docs](docs/a.md#the-why-here).\n")
        _write(root, "docs/a.md", "# The why, here\n\nReads `framework/core/a.h` and `a.h`; runs "
                                  "`/usr/bin/python3 tools/t.py --out DIR` and `build/bin/fitfeel`.\n")
        _write(root, "framework/core/a.h", "// Why, not when.\n")
        _write(root, "tools/t.py", "# A tool.\n")
        _write(root, "docs/figures/README.md", "Drawn by `draw.sh` (`data/d.csv`).\n")
        _write(root, "docs/figures/draw.sh", "# Draws.\n")
        _write(root, "docs/figures/data/d.csv", "x\n")
        _write(root, "build/x.cc", "// " + "st" + "op 9 (a build tree is not linted)\n")
        _write(root, "tools/fem/data/d.csv", "iss" + "ue 9\n")
        clean = lint(root)
        if clean:
            failures.append("a clean tree gave findings: " + "; ".join(map(str, clean)))

        # One violation of each kind.
        _write(root, "README.md", "# x\n" + "line\n" * README_MAX_LINES)
        _write(root, "docs/b.md", "Measured in " + "St" + "op 12.\n"
                                  "See `framework/core/missing.cc` and `gone_file.cc`.\n"
                                  "And [a link](missing.md), [a heading](a.md#gone).\n")
        _write(root, "framework/core/a.cc", "int a;  // see " + "iss" + "ue 4\n")
        _write(root, "scenarios/s.yaml", "# on the shared " + "V" + "M\n")
        found = [str(f) for f in lint(root)]
        expected = [
            ("README.md:", "readme-length"),
            ("docs/b.md:1:", "history-word"),
            ("framework/core/a.cc:1:", "history-word"),
            ("scenarios/s.yaml:1:", "history-word"),
            ("docs/b.md:2:", "framework/core/missing.cc"),
            ("docs/b.md:2:", "gone_file.cc"),
            ("docs/b.md:3:", "missing.md"),
            ("docs/b.md:3:", "a.md#gone"),
        ]
        for where, what in expected:
            if not any(f.startswith(where) and what in f for f in found):
                failures.append(f"not reported: {where} {what}")
        if len(found) != len(expected):
            failures.append(f"{len(found)} findings, expected {len(expected)}: " +
                            "; ".join(found))
    for failure in failures:
        print("self-test: " + failure)
    print("self-test: " + ("FAILED" if failures else "passed"))
    return 1 if failures else 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--root", default=os.path.dirname(os.path.dirname(
        os.path.dirname(os.path.abspath(__file__)))))
    parser.add_argument("--self-test", action="store_true")
    args = parser.parse_args()
    if args.self_test:
        return self_test()
    findings = lint(os.path.abspath(args.root))
    for finding in findings:
        print(finding)
    print(f"doc_lint: {len(findings)} finding(s) in {os.path.abspath(args.root)}")
    return 1 if findings else 0


if __name__ == "__main__":
    sys.exit(main())
