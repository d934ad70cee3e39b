# SPDX-License-Identifier: MIT
"""The package surface: version, stub in step with the module, docstrings on everything."""

import ast
import inspect
import pathlib

import roiclip

STUB = pathlib.Path(roiclip.__file__).with_name("__init__.pyi")
STUB_ONLY = {"_Enum", "PathLike", "Paths", "Shape", "FillRuleLike", "ClipOpLike", "LinePartLike"}


def _stub_names():
    tree = ast.parse(STUB.read_text())
    names = set()
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            names.add(node.name)
        elif isinstance(node, ast.AnnAssign):
            names.add(node.target.id)
        elif isinstance(node, ast.Assign):
            names.update(t.id for t in node.targets)
    return names


def test_stub_matches_module():
    assert (STUB.parent / "py.typed").exists()
    assert _stub_names() - STUB_ONLY == set(roiclip.__all__)
    assert all(hasattr(roiclip, name) for name in roiclip.__all__)


def test_docstrings_everywhere():
    assert roiclip.__doc__ and "y DOWN" in roiclip.__doc__
    missing = []
    for name in roiclip.__all__:
        obj = getattr(roiclip, name)
        if not (inspect.isclass(obj) or callable(obj)):
            continue
        # pybind11 puts the signature first; a documented function has text after it.
        doc = (obj.__doc__ or "").strip()
        if len(doc.splitlines()) < (1 if inspect.isclass(obj) else 2):
            missing.append(name)
        if inspect.isclass(obj) and not issubclass(obj, BaseException):
            for attr, member in vars(obj).items():
                if attr.startswith("_") or attr in ("name", "value"):
                    continue
                if not (getattr(member, "__doc__", None) or "").strip():
                    missing.append(f"{name}.{attr}")
    assert not missing, f"no docstring: {missing}"


def test_to_contours_documents_rounding():
    assert "snap-rounded" in roiclip.PolygonSet.to_contours.__doc__
    assert "snap-rounded" in STUB.read_text()
