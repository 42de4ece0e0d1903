#!/usr/bin/env python3
"""Keep the tables a doc quotes from a results page equal to that page (one source of truth).

A doc marks each quoted part between two comments; the path is the page's, relative to the doc:

    <!-- from ../experiments/scaling/results/compare.md, table 1 -->
    ...copied here...
    <!-- end -->

The parts:
    table K                       the K-th table of the page (1-based)
    text after table K            the first paragraph after that table
    the line starting "TEXT"      the page's first line that starts with TEXT

    docs-blocks.py DOC...           rewrite each marked part from its page (atomically)
    docs-blocks.py --check DOC...   change nothing: exit 1 naming each part that differs

A doc with no marks is left alone, and so is a mark inside a ``` code block (an example). A mark the page cannot answer (no such file, table or
line), or one without its end, is refused with DOC:LINE, exit 2, and nothing is written.
Standard library only."""
import os
import re
import sys

MARK = re.compile(r'^<!-- from (\S+), (table (\d+)|text after table (\d+)|the line starting "([^"]+)") -->$')
END = "<!-- end -->"


class Refusal(Exception):
    pass


def tables(lines):
    """The page's tables: runs of lines that start with '|', each as (first index, last index)."""
    out, start = [], None
    for i, line in enumerate(lines + [""]):
        if line.startswith("|") and start is None:
            start = i
        elif not line.startswith("|") and start is not None:
            out.append((start, i - 1))
            start = None
    return out


def part(page_path, m, where):
    """The lines the mark M asks of the page at PAGE_PATH."""
    if not os.path.isfile(page_path):
        raise Refusal(f"{where}: no page {page_path}")
    lines = open(page_path).read().splitlines()
    if m.group(5) is not None:
        for line in lines:
            if line.startswith(m.group(5)):
                return [line]
        raise Refusal(f'{where}: {page_path} has no line starting "{m.group(5)}"')
    k = int(m.group(3) or m.group(4))
    found = tables(lines)
    if not 1 <= k <= len(found):
        raise Refusal(f"{where}: {page_path} has {len(found)} table(s), not table {k}")
    first, last = found[k - 1]
    if m.group(3) is not None:
        return lines[first:last + 1]
    i = last + 1
    while i < len(lines) and not lines[i].strip():
        i += 1
    para = []
    while i < len(lines) and lines[i].strip() and not lines[i].startswith(("|", "#")):
        para.append(lines[i])
        i += 1
    if not para:
        raise Refusal(f"{where}: {page_path} has no text after table {k}")
    return para


def filled(doc):
    """(the doc's text with every marked part from its page, [the marks whose part differed])."""
    lines = open(doc).read().splitlines()
    out, changed, i, fenced = [], [], 0, False
    while i < len(lines):
        fenced ^= lines[i].lstrip().startswith("```")   # a mark shown in a code block is an example
        m = None if fenced else MARK.match(lines[i].strip())
        out.append(lines[i])
        if not m:
            i += 1
            continue
        where = f"{doc}:{i + 1}"
        try:
            end = next(j for j in range(i + 1, len(lines)) if lines[j].strip() == END)
        except StopIteration:
            raise Refusal(f"{where}: the mark has no {END} after it")
        want = [""] + part(os.path.join(os.path.dirname(os.path.abspath(doc)), m.group(1)), m, where) + [""]
        if lines[i + 1:end] != want:
            changed.append(f"{where}: {m.group(1)}, {m.group(2)}")
        out += want + [lines[end]]
        i = end + 1
    return "\n".join(out) + "\n", changed


def main(argv):
    check = "--check" in argv
    docs = [a for a in argv[1:] if a != "--check"]
    if not docs or any(a.startswith("--") for a in docs):
        print(__doc__, file=sys.stderr)
        return 2
    try:
        results = [(doc, *filled(doc)) for doc in docs]   # every doc read before any is written
    except (Refusal, OSError) as e:
        print(f"docs-blocks.py: {e}", file=sys.stderr)
        return 2
    differ = [c for _, _, changed in results for c in changed]
    if check:
        for c in differ:
            print(f"docs-blocks.py: {c} differs from its page (scripts/docs-blocks.py DOC rewrites it)",
                  file=sys.stderr)
        return 1 if differ else 0
    for doc, text, changed in results:
        if changed:
            tmp = doc + ".tmp"
            with open(tmp, "w") as f:
                f.write(text)
            os.replace(tmp, doc)
            print(f"docs-blocks.py: {doc}: {len(changed)} part(s) rewritten", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
