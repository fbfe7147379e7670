#!/usr/bin/python3
"""Checks the docs' relative links: every [text](target) and ![alt](target) in README.md and
docs/*.md (outside code) names a file or folder that exists, and every #anchor a heading of the
file it names (GitHub's heading slugs). Usage: python3 tools/check-doc-links.py [SOURCE_DIR].
Prints each broken link as file:line: target, then "N passed, N failed"; exit 1 when any is broken."""
import glob
import os
import re
import sys

root = sys.argv[1] if len(sys.argv) > 1 else "."
LINK = re.compile(r"!?\[(?:[^\]\[]|\[[^\]]*\])*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")


def slug(heading):
    s = heading.strip().lower()
    s = re.sub(r"[`*_]", "", s)           # emphasis and code marks
    s = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", s)
    s = re.sub(r"[^\w\- ]", "", s)         # punctuation and symbols go; letters, digits, -, _ stay
    return s.replace(" ", "-")


def lines_outside_code(path):
    fence = False
    with open(path, encoding="utf-8") as f:
        for n, line in enumerate(f, 1):
            if line.lstrip().startswith("```"):
                fence = not fence
                continue
            if not fence:
                yield n, line


def anchors(path, cache={}):
    if path not in cache:
        seen, out = {}, set()
        for _, line in lines_outside_code(path):
            m = re.match(r"#{1,6}\s+(.*?)\s*#*\s*$", line)
            if m:
                s = slug(m.group(1))
                k = seen.get(s, 0)
                seen[s] = k + 1
                out.add(s if k == 0 else "%s-%d" % (s, k))
        cache[path] = out
    return cache[path]


files = [os.path.join(root, "README.md")] + sorted(glob.glob(os.path.join(root, "docs", "*.md")))
passed = failed = 0
for md in files:
    for n, line in lines_outside_code(md):
        line = re.sub(r"`[^`]*`", "", line)  # inline code is not a link
        for target in LINK.findall(line):
            if re.match(r"^[a-z][a-z0-9+.-]*:", target):  # http:, mailto: ...: not checked here
                continue
            path, _, frag = target.partition("#")
            dest = os.path.normpath(os.path.join(os.path.dirname(md), path)) if path else md
            ok = os.path.exists(dest)
            if ok and frag and dest.endswith(".md"):
                ok = frag in anchors(dest)
            if ok:
                passed += 1
            else:
                failed += 1
                print("%s:%d: %s does not resolve" % (os.path.relpath(md, root), n, target),
                      file=sys.stderr)
print("%d passed, %d failed" % (passed, failed))
sys.exit(1 if failed else 0)
