#!/usr/bin/env python3
"""Fails when a Markdown file of the repository names a repository path that does not exist.

Usage: check_doc_paths.py SOURCE_DIR [FILE.md ...]   (default: every *.md under SOURCE_DIR
outside build trees, node_modules, web/deb-src (Debian's unpacked sources) and hidden folders)

What counts as a path, in each Markdown file:
  - a link target `[text](target)` that is not a URL or a bare #anchor: resolved against the
    file's own folder, its #anchor dropped;
  - a token in `backticks` or in a fenced code block whose first part is one of the
    repository's top-level folders (src/, tests/, docs/, scripts/, web/, bench/, examples/,
    scenes/, sweeps/, ...): resolved against the repository's root.
A path that does not exist as written may be a pattern: a glob (`src/output/atomic_output.*`)
or with placeholders, `<stage>`, `…` and all-capital words (`NAME`, `explorer-MACHINE.csv`,
`shard-K-of-N.csv`), each read as `*`; the pattern must match something. Every offence is
printed as FILE:LINE: PATH, and the exit status is 1.
"""
import glob
import os
import re
import sys
from pathlib import Path

LINK = re.compile(r"\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")
CODE = re.compile(r"`([^`\n]+)`")
# A path-looking word: letters, digits and . _ - / * < > … (a placeholder may follow).
WORD = re.compile(r"[A-Za-z0-9_.\-/*<>…]+")
SKIPPED_DIRS = {"node_modules", "build", "out", "deb-src"}


def top_folders(root):
    return {p.name for p in root.iterdir() if p.is_dir() and not p.name.startswith(".")
            and p.name not in SKIPPED_DIRS}


def markdown_files(root):
    for folder, dirs, files in os.walk(root):
        dirs[:] = sorted(d for d in dirs if not d.startswith(".") and d not in SKIPPED_DIRS
                         and not d.startswith("build"))
        for name in sorted(files):
            if name.endswith(".md"):
                yield Path(folder) / name


PLACEHOLDER = re.compile(r"<[^>/]*>|…|\.\.\.|[A-Z]{2,}|(?<![A-Za-z])[A-Z](?![A-Za-z])")


def exists(root, path):
    """Whether `path` (relative to root) exists; where it does not as written, the pattern
    made of it, each placeholder (<stage>, NAME, K, …) and glob as `*`, matches something."""
    if (root / path).exists():
        return True
    return bool(glob.glob(str(root / PLACEHOLDER.sub("*", path))))


def paths_in_line(line, tops, in_fence):
    """(path, relative_to_file) for each path the line names."""
    found = []
    if not in_fence:
        for target in LINK.findall(line):
            if re.match(r"[a-z][a-z0-9+.-]*:", target) or target.startswith("#"):
                continue  # a URL (http:, mailto:, data:) or an anchor on this page
            found.append((target.split("#", 1)[0], True))
        spans = CODE.findall(line)
    else:
        spans = [line]
    for span in spans:
        for word in WORD.findall(span):
            word = word.rstrip(".,:;")
            if "/" in word and word.split("/", 1)[0] in tops:
                found.append((word, False))
    return found


def check(root, files):
    tops = top_folders(root)
    offences = []
    for md in files:
        in_fence = False
        for number, line in enumerate(md.read_text(encoding="utf-8").splitlines(), 1):
            if line.lstrip().startswith("```"):
                in_fence = not in_fence
                continue
            for path, relative_to_file in paths_in_line(line, tops, in_fence):
                full = os.path.relpath(os.path.normpath(md.parent / path), root) \
                    if relative_to_file else path.rstrip("/")
                if full.startswith("..") or not exists(root, full):
                    offences.append(f"{md.relative_to(root)}:{number}: {path}")
    return offences


def main():
    if len(sys.argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    root = Path(sys.argv[1]).resolve()
    files = [Path(f).resolve() for f in sys.argv[2:]] or list(markdown_files(root))
    offences = check(root, files)
    if offences:
        print(f"{len(offences)} path(s) named in the docs do not exist:", file=sys.stderr)
        print("\n".join(offences), file=sys.stderr)
        return 1
    print(f"every repository path named in {len(files)} Markdown files exists")
    return 0


if __name__ == "__main__":
    sys.exit(main())
