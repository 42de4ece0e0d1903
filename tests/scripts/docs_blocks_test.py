#!/usr/bin/env python3
"""Scripts.DocsBlocks: scripts/docs-blocks.py copies a page's table, the text after it and a
line into a doc's marked parts, --check names a part that differs (exit 1), a mark the page
cannot answer is refused with DOC:LINE (exit 2, nothing written), and the repository's own
docs quote their results pages as those pages are now.

    docs_blocks_test.py SOURCE_DIR WORK_DIR
"""
import pathlib
import shutil
import subprocess
import sys

source, work = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
shutil.rmtree(work, ignore_errors=True)
(work / "results").mkdir(parents=True)
(work / "docs").mkdir()
tool = [sys.executable, str(source / "scripts" / "docs-blocks.py")]


def check(condition, message):
    if not condition:
        print(f"docs_blocks_test: {message}", file=sys.stderr)
        sys.exit(1)


def run(*args):
    return subprocess.run(tool + [str(a) for a in args], capture_output=True, text=True)


page = work / "results" / "page.md"
page.write_text("# A page\n\nintro\n\n| a | b |\n|---|---|\n| 1 | 2 |\n\nEvaluations:\n\n| c |\n|---|\n| 3 |\n"
                "\nSo far, no hybrid wins.\nIt goes on.\n\n## Next\n\nCrossover so far: none.\n")
doc = work / "docs" / "d.md"
doc.write_text("# Doc\n\n<!-- from ../results/page.md, table 1 -->\nstale\n<!-- end -->\n\nprose stays\n\n"
               "<!-- from ../results/page.md, text after table 2 -->\n<!-- end -->\n"
               '<!-- from ../results/page.md, the line starting "Crossover" -->\n<!-- end -->\n')
p = run("--check", doc)
check(p.returncode == 1 and f"{doc}:3: ../results/page.md, table 1 differs" in p.stderr, f"stale part not named: {p}")
check(doc.read_text().count("stale") == 1, "--check wrote")
p = run(doc)
check(p.returncode == 0, f"rewrite failed: {p}")
want = ("# Doc\n\n<!-- from ../results/page.md, table 1 -->\n\n| a | b |\n|---|---|\n| 1 | 2 |\n\n<!-- end -->\n\n"
        "prose stays\n\n<!-- from ../results/page.md, text after table 2 -->\n\nSo far, no hybrid wins.\nIt goes on.\n\n"
        '<!-- end -->\n<!-- from ../results/page.md, the line starting "Crossover" -->\n\nCrossover so far: none.\n\n'
        "<!-- end -->\n")
check(doc.read_text() == want, "rewritten doc:\n" + doc.read_text())
check(run("--check", doc).returncode == 0, "a doc just written differs")
before = doc.read_text()
check(run(doc).returncode == 0 and doc.read_text() == before, "a second rewrite changed the doc")

# A mark shown as an example in a code block is not a mark.
example = work / "docs" / "example.md"
example.write_text("Mark a part:\n\n```\n<!-- from ../results/none.md, table 9 -->\n<!-- end -->\n```\n")
p = run(example)
check(p.returncode == 0 and "table 9" in example.read_text(), f"a mark in a code block was read: {p}")

# The page changed: --check names it, a rewrite follows it.
page.write_text(page.read_text().replace("| 1 | 2 |", "| 1 | 5 |"))
check(run("--check", doc).returncode == 1, "a changed page went unnoticed")
run(doc)
check("| 1 | 5 |" in doc.read_text(), "the rewrite did not follow the page")

# Marks the page cannot answer: refused with DOC:LINE, nothing written (not even the good part).
good = "<!-- from ../results/page.md, table 1 -->\nold\n<!-- end -->\n"
for bad, says in [("<!-- from ../results/page.md, table 3 -->\n<!-- end -->\n", "has 2 table(s), not table 3"),
                  ("<!-- from ../results/none.md, table 1 -->\n<!-- end -->\n", "no page"),
                  ('<!-- from ../results/page.md, the line starting "Nope" -->\n<!-- end -->\n', 'no line starting "Nope"'),
                  ("<!-- from ../results/page.md, table 1 -->\nno end\n", "has no <!-- end -->")]:
    doc.write_text(good + bad)
    p = run(doc)
    check(p.returncode == 2 and f"{doc}:4: " in p.stderr and says in p.stderr, f"{bad!r}: {p}")
    check(doc.read_text() == good + bad, f"{bad!r}: written before the refusal")

# The repository's docs quote their pages as the pages are now.
docs = sorted(str(p) for p in (source / "docs").glob("*.md"))
p = run("--check", *docs)
check(p.returncode == 0, "a doc's quoted part differs from its page:\n" + p.stderr)
print("docs_blocks_test: ok")
