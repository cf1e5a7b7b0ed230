"""Copies the compiled core's docstrings into its type stub, ``python/polymimic/_native.pyi``.

The Rust bindings' ``///`` comments are the one source of ``polymimic._native``'s documentation:
they become ``__doc__`` at run time (``help()``), and this script writes the same text into the
stub, which is what the API reference is generated from (griffe reads stubs, not compiled
modules), rewrapping a line too long for the stub. ``tests/test_docstrings.py`` fails when the
two differ in more than their line breaks. Run after changing a doc
comment and rebuilding::

    python docs/stub_docstrings.py
"""

from __future__ import annotations

import ast
import inspect
import pathlib
import textwrap
from typing import Any

import polymimic._native as native

STUB = pathlib.Path(__file__).resolve().parent.parent / "python" / "polymimic" / "_native.pyi"


def runtime_doc(path: list[str]) -> str | None:
    """The compiled object's cleaned docstring at ``path`` (a class, or a class and a member)."""
    value: Any = native
    for part in path:
        value = inspect.getattr_static(value, part, None)
        if value is None:
            return None
        if isinstance(value, (staticmethod, classmethod)):
            # the function's own docstring, not the wrapper's (CPython's own text, which differs by release)
            value = value.__func__
    doc = getattr(value, "__doc__", None)
    return inspect.cleandoc(doc) if isinstance(doc, str) and doc.strip() else None


def documented(source: str) -> dict[tuple[str, ...], tuple[ast.AST, str | None]]:
    """Every stub class and member that has a runtime docstring: its node and the stub's docstring."""
    found: dict[tuple[str, ...], tuple[ast.AST, str | None]] = {}
    for node in ast.parse(source).body:
        if not isinstance(node, ast.ClassDef) or node.name.startswith("_"):
            continue
        found[(node.name,)] = (node, ast.get_docstring(node))
        for member in node.body:
            if isinstance(member, ast.FunctionDef) and not (member.name.startswith("_") and member.name != "__new__"):
                found[(node.name, member.name)] = (member, ast.get_docstring(member))
    return found


def quoted(doc: str, indent: str) -> list[str]:
    """The docstring as stub lines at ``indent``, a line too long for the stub rewrapped."""
    text = doc.replace("\\", "\\\\").replace('"""', '\\"\\"\\"')
    lines = [part for line in text.split("\n")
             for part in (textwrap.wrap(line, 96) if len(indent) + len(line) + 6 > 120 else [line])]
    if len(lines) == 1:
        return [f'{indent}"""{text}"""']
    return [f'{indent}"""{lines[0]}', *[(indent + line) if line else "" for line in lines[1:]], f'{indent}"""']


def write_stub() -> int:
    """Rewrites the stub with the runtime docstrings; returns how many it set."""
    source = STUB.read_text()
    lines = source.split("\n")
    edits: list[tuple[int, int, list[str]]] = []
    for path, (node, _) in documented(source).items():
        name = "__new__" if path[-1] == "__new__" else path[-1]
        doc = runtime_doc(list(path[:-1]) + [name]) if len(path) > 1 else runtime_doc(list(path))
        if doc is None or path[-1] == "__new__":
            continue  # a constructor is documented in its class's docstring
        assert isinstance(node, (ast.ClassDef, ast.FunctionDef))
        indent = " " * (node.col_offset + 4)
        first = node.body[0]
        assert first.end_lineno is not None
        inline = isinstance(first, ast.Expr) and isinstance(first.value, ast.Constant)
        if inline and isinstance(first.value.value, str):  # a docstring already: replace it
            edits.append((first.lineno - 1, first.end_lineno - first.lineno + 1, quoted(doc, indent)))
        elif inline and lines[first.lineno - 1].rstrip().endswith(": ..."):  # `def f(...) -> T: ...`
            line = lines[first.lineno - 1].rstrip()
            edits.append((first.lineno - 1, 1, [line[: -len(" ...")], *quoted(doc, indent)]))
        else:  # before the first statement and its decorators
            decorators = getattr(first, "decorator_list", [])
            start = min([first.lineno, *(d.lineno for d in decorators)])
            edits.append((start - 1, 0, quoted(doc, indent)))
    for start, count, new in sorted(edits, reverse=True):
        lines[start:start + count] = new
    STUB.write_text("\n".join(lines))
    return len(edits)


if __name__ == "__main__":
    print(f"{write_stub()} docstrings written to {STUB}")
