"""The house's shape, read from the imports: the library never imports the run machinery or an
application, the run machinery no application, no application another, and no module of
polymimic imports another that imports it back."""

import ast
import pathlib

import pytest

PACKAGE = pathlib.Path(__file__).resolve().parent.parent / "python" / "polymimic"


def _module_name(path):
    parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _imports():
    """Every polymimic module and the polymimic modules it imports, wherever the import stands."""
    modules = {_module_name(p): p for p in PACKAGE.rglob("*.py")}
    graph = {}
    for name, path in modules.items():
        found = set()
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Import):
                found |= {alias.name for alias in node.names}
            elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
                found.add(node.module)
                found |= {f"{node.module}.{alias.name}" for alias in node.names}
        graph[name] = {m for m in found if m in modules and m != name and m != "polymimic"}
    return graph


GRAPH = _imports()
RUNS = ("polymimic.runs",)
APPLICATIONS = ("polymimic.reproduce", "polymimic.benchmark", "polymimic.matrix")
COMMAND = ("polymimic.cli", "polymimic.__main__")
APPLICATION = RUNS + APPLICATIONS + COMMAND


def _within(name, packages):
    return any(name == a or name.startswith(a + ".") for a in packages)


def _is_application(name):
    return _within(name, APPLICATION)


@pytest.mark.parametrize("module", sorted(m for m in GRAPH if not _is_application(m)))
def test_the_library_never_imports_the_application(module):
    assert not [m for m in GRAPH[module] if _is_application(m)]


@pytest.mark.parametrize("module", sorted(m for m in GRAPH if _within(m, RUNS)))
def test_the_run_machinery_imports_no_application(module):
    assert not [m for m in GRAPH[module] if _within(m, APPLICATIONS + COMMAND)]


@pytest.mark.parametrize("application", APPLICATIONS)
def test_no_application_imports_another(application):
    others = tuple(a for a in APPLICATIONS if a != application) + COMMAND
    found = {(m, t) for m in GRAPH if _within(m, (application,)) for t in GRAPH[m] if _within(t, others)}
    assert not found


def test_no_module_imports_itself_back():
    cycles = []

    def visit(name, path):
        for target in sorted(GRAPH[name]):
            if target == path[0]:
                cycles.append(" -> ".join((*path, target)))
            elif target not in path and len(path) < len(GRAPH):
                visit(target, (*path, target))

    for name in sorted(GRAPH):
        visit(name, (name,))
    assert not cycles, cycles[:5]


def test_the_graph_is_read():
    # A guard on the reader itself: known edges are there.
    assert "polymimic.field" in GRAPH["polymimic.learning"]
    assert "polymimic.runs.config" in GRAPH["polymimic.reproduce.stages"]
    assert _is_application("polymimic.reproduce.stages") and not _is_application("polymimic.recognition")


def test_the_practice_command_knows_runs_only_through_their_practice_source():
    # Each kind of run says what its practice needs (polymimic.runs.practising.PracticeSource).
    assert not [m for m in GRAPH["polymimic.cli.practice"] if _within(m, APPLICATIONS)]
    assert "polymimic.runs.practising" in GRAPH["polymimic.cli.practice"]
