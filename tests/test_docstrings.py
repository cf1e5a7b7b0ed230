"""Every public name of polymimic has a docstring: its classes, functions, methods and properties.

Source-reading linters cannot see the Rust-backed classes of ``polymimic._native``; this walks
the imported package, so they are checked as the Python ones are.
"""

import enum
import importlib
import inspect
import pkgutil

import pytest

import polymimic

MODULES = [polymimic] + [
    importlib.import_module(info.name)
    for info in pkgutil.walk_packages(polymimic.__path__, prefix="polymimic.")
    if not any(part.startswith("_") for part in info.name.split(".")[1:])
]

# Members every class inherits whose docstrings are Python's, not ours to write.
INHERITED = {"__init__", "__new__"}


def public_names(module):
    """The names a module offers: its __all__, else what it defines without a leading underscore."""
    if hasattr(module, "__all__"):
        return [name for name in module.__all__ if name != "__version__"]
    return [
        name
        for name, value in vars(module).items()
        if not name.startswith("_")
        and (inspect.isclass(value) or inspect.isfunction(value) or inspect.isbuiltin(value))
        and getattr(value, "__module__", None) == module.__name__
    ]


def own_doc(value):
    doc = inspect.getdoc(value)
    return doc is not None and doc.strip() != ""


def class_members(cls):
    """Public methods and properties a class defines itself (not those it inherits)."""
    for name, value in vars(cls).items():
        if name.startswith("_") or name in INHERITED:
            continue
        if isinstance(value, (staticmethod, classmethod)):
            value = value.__func__
        if isinstance(value, property) or inspect.isroutine(value) or inspect.isdatadescriptor(value):
            yield name, value


def missing(module):
    gaps = []
    for name in public_names(module):
        value = getattr(module, name)
        if not (inspect.isclass(value) or inspect.isroutine(value)):
            continue  # constants and type aliases are described by their module's docstring
        qualified = f"{module.__name__}.{name}"
        if not own_doc(value):
            gaps.append(qualified)
        if inspect.isclass(value) and not issubclass(value, (BaseException, enum.Enum)):
            for member, attribute in class_members(value):
                if type(attribute).__name__ == "member_descriptor":
                    # A __slots__ attribute cannot carry a docstring: its class's "Attributes" must name it.
                    if f"\n{member} :" not in "\n" + inspect.getdoc(value).split("Attributes\n", 1)[-1]:
                        gaps.append(f"{qualified}.{member}")
                elif attribute.__doc__ is None or not attribute.__doc__.strip():
                    gaps.append(f"{qualified}.{member}")
    return gaps


@pytest.mark.parametrize("module", MODULES, ids=lambda m: m.__name__)
def test_public_names_have_docstrings(module):
    assert own_doc(module), f"{module.__name__} has no module docstring"
    assert missing(module) == []


def test_the_walk_sees_rust_backed_members():
    """The walk reaches the Rust-backed classes' methods and fitted attributes, so it can fail on them."""
    names = dict(class_members(polymimic.DiscreteHMM))
    assert {"fit", "from_params", "transmat_", "emissionprob_", "converged_"} <= set(names)
    assert "polymimic.DiscreteHMM" not in missing(polymimic)


def test_the_stub_carries_the_compiled_docstrings():
    """The API reference is generated from ``_native.pyi``; its docstrings are the Rust doc comments'
    (``python docs/stub_docstrings.py`` copies them after a rebuild)."""
    import importlib.util
    import pathlib

    script = pathlib.Path(__file__).resolve().parent.parent / "docs" / "stub_docstrings.py"
    spec = importlib.util.spec_from_file_location("stub_docstrings", script)
    assert spec is not None and spec.loader is not None
    stub_docstrings = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(stub_docstrings)
    stale = []
    for path, (_, stub_doc) in stub_docstrings.documented(stub_docstrings.STUB.read_text()).items():
        if path[-1] == "__new__":
            continue
        runtime = stub_docstrings.runtime_doc(list(path))
        if runtime is not None and " ".join(runtime.split()) != " ".join((stub_doc or "").split()):
            stale.append(".".join(path))
    assert stale == [], "run python docs/stub_docstrings.py"
