"""Every reference the repository makes resolves inside it: no source points to a document the
repository does not hold, and every docs page a source names exists."""

import pathlib
import re
import subprocess

ROOT = pathlib.Path(__file__).resolve().parent.parent


def tracked_text_files():
    names = subprocess.run(["git", "ls-files"], cwd=ROOT, capture_output=True, text=True, check=True).stdout.split()
    for name in names:
        path = ROOT / name
        if path.suffix in {".py", ".rs", ".md", ".toml", ".pyi", ".yml", ".cff"} and path.is_file():
            yield path


def test_no_reference_to_a_spec_outside_the_repository():
    # Spelled in two pieces so that this file does not name what it looks for.
    word = "SP" + "EC"
    hits = [f"{p.relative_to(ROOT)}:{n}" for p in tracked_text_files()
            for n, line in enumerate(p.read_text(errors="replace").splitlines(), 1) if re.search(rf"\b{word}\b", line)]
    assert hits == []


def test_docs_pages_named_in_sources_exist():
    named = {(p, m) for p in tracked_text_files()
             for m in re.findall(r"docs/[\w/.-]+\.md", p.read_text(errors="replace"))}
    assert named, "sources name docs pages"
    missing = sorted(f"{p.relative_to(ROOT)}: {m}" for p, m in named if not (ROOT / m).is_file())
    assert missing == []


def test_every_study_is_linked_from_the_docs():
    """Each study is linked from the docs page that quotes its figures."""
    pages = "\n".join(p.read_text() for p in (ROOT / "docs").rglob("*.md"))
    studies = sorted(p.name for p in (ROOT / "studies").glob("[!_]*.py"))
    unlinked = [s for s in studies if f"/studies/{s})" not in pages]
    assert unlinked == []
