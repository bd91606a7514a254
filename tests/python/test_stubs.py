# SPDX-License-Identifier: BSD-3-Clause
"""The type stubs (bandlight/__init__.pyi) describe the module as it is, and
everything public has a docstring."""

import ast
import inspect
import pathlib
import re

import pytest

import bandlight

STUB = pathlib.Path(bandlight.__file__).with_name("__init__.pyi")
# Names only the stubs have: type aliases and TypedDicts of the results.
STUB_ONLY = {"FloatArray", "Float32Array", "StrPath", "LightLike", "RemittancesLike",
             "BandsLike", "ObserverLike", "CriResult", "RgbSpaceInfo", "LutResult",
             "AccuracyRow", "AccuracyCamera", "AccuracyCost", "AccuracySetupCost",
             "AccuracyDocument", "ApplyResult"}


def stub_tree():
    return ast.parse(STUB.read_text())


def public_names():
    return {n for n in dir(bandlight) if not n.startswith("_")}


def stub_definitions(body):
    """name -> list of FunctionDef (overloads), ClassDef, or the assignment."""
    out = {}
    for node in body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            out.setdefault(node.name, []).append(node)
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            out.setdefault(node.target.id, []).append(node)
        elif isinstance(node, ast.Assign):
            for t in node.targets:
                if isinstance(t, ast.Name):
                    out.setdefault(t.id, []).append(node)
    return out


def split_params(text):
    """The parameters of a signature's text, split at its top-level commas."""
    params, depth, cur = [], 0, ""
    for ch in text:
        if ch in "([{":
            depth += 1
        elif ch in ")]}":
            depth -= 1
        if ch == "," and depth == 0:
            params.append(cur.strip())
            cur = ""
        else:
            cur += ch
    if cur.strip():
        params.append(cur.strip())
    return params


def pybind_signatures(obj):
    """(parameter names, keyword-only names) of each overload, from the
    signatures pybind11 writes at the head of __doc__."""
    name = obj.__name__
    sigs = []
    for line in (obj.__doc__ or "").splitlines():
        m = re.match(rf"^(?:\d+\. )?{re.escape(name)}\((.*)\) -> ", line.strip())
        if not m:
            continue
        params = split_params(m.group(1))
        names, kwonly, star = [], set(), False
        for p in params:
            if p == "*":
                star = True
                continue
            n = p.split(":")[0].split("=")[0].strip()
            if n == "self":
                continue
            names.append(n)
            if star:
                kwonly.add(n)
        sigs.append((names, kwonly))
    return sigs


def stub_signature(fn):
    a = fn.args
    names = [x.arg for x in a.posonlyargs + a.args if x.arg != "self"]
    kwonly = {x.arg for x in a.kwonlyargs}
    return names + [x.arg for x in a.kwonlyargs], kwonly


def check_callable(obj, stub_defs, where):
    sigs = pybind_signatures(obj)
    assert sigs, f"{where}: no pybind11 signature in its docstring"
    stubs = [stub_signature(f) for f in stub_defs if isinstance(f, ast.FunctionDef)]
    assert stubs, f"{where}: not a function in the stubs"
    for names, kwonly in sigs:
        assert (names, kwonly) in stubs, f"{where}: {names} (keyword-only {kwonly}) " \
                                         f"is not in the stubs: {stubs}"


def test_every_public_name_is_in_the_stubs_and_back():
    defs = stub_definitions(stub_tree().body)
    assert STUB_ONLY <= set(defs)
    assert public_names() == {n for n in set(defs) - STUB_ONLY if not n.startswith("_")}
    assert "__version__" in defs and bandlight.__version__


@pytest.mark.parametrize("name", sorted(public_names()))
def test_signatures_match(name):
    # A function checking its keywords first: the extension function inside.
    obj = getattr(getattr(bandlight, name), "__wrapped__", getattr(bandlight, name))
    defs = stub_definitions(stub_tree().body)[name]
    if isinstance(obj, type) and not issubclass(obj, Warning):
        cls = next(d for d in defs if isinstance(d, ast.ClassDef))
        members = stub_definitions(cls.body)
        public = {m for m in dir(obj) if not m.startswith("_")}
        public |= {m for m in ("__init__", "__call__", "__len__", "__mul__", "__add__",
                               "__sub__", "__truediv__", "__rmul__") if m in vars(obj)}
        for m in sorted(public):
            assert m in members, f"{name}.{m} is not in the stubs"
            attr = getattr(obj, m)
            if callable(attr) and getattr(attr, "__doc__", None) and \
                    type(attr).__name__ in ("builtin_function_or_method", "instancemethod"):
                check_callable(attr, members[m], f"{name}.{m}")
    elif inspect.isfunction(obj):
        # Written in Python (bandlight/__init__.py): its own signature.
        sig = inspect.signature(obj)
        names = [p.name for p in sig.parameters.values()
                 if p.kind not in (p.VAR_KEYWORD, p.VAR_POSITIONAL)]
        kwonly = {p.name for p in sig.parameters.values() if p.kind == p.KEYWORD_ONLY}
        stubs = [stub_signature(f) for f in defs if isinstance(f, ast.FunctionDef)]
        assert (names, kwonly) in stubs, f"{name}: {names} is not in the stubs: {stubs}"
    elif callable(obj) and not isinstance(obj, type):
        check_callable(obj, defs, name)


@pytest.mark.parametrize("name", sorted(public_names()))
def test_everything_has_a_docstring(name):
    obj = getattr(bandlight, name)
    if not callable(obj):
        return
    doc = obj.__doc__ or ""
    # More than pybind11's own signature line.
    text = "\n".join(line for line in doc.splitlines() if not re.match(r"^\w+\(.*\) ->", line))
    assert len(text.strip()) > 20, f"{name} has no docstring"
    if isinstance(obj, type):
        for m, attr in vars(obj).items():
            if m.startswith("_") and m not in ("__init__", "__call__"):
                continue
            doc = getattr(attr, "__doc__", None) or ""
            text = "\n".join(line for line in doc.splitlines()
                             if not re.match(r"^\s*(\d+\. )?\w+\(.*\) ->", line)
                             and line.strip() != "Overloaded function.")
            assert len(text.strip()) > 10, f"{name}.{m} has no docstring"


def test_mypy_stubtest_agrees():
    # Optional: Debian's python3-mypy, when installed, checks the stubs
    # against the runtime module the way type checkers read them.
    pytest.importorskip("mypy.stubtest")
    import subprocess
    import sys
    import tempfile

    with tempfile.TemporaryDirectory() as tmp:
        ini = pathlib.Path(tmp) / "mypy.ini"
        ini.write_text("[mypy]\nignore_missing_imports = True\ncache_dir = /dev/null\n")
        p = subprocess.run([sys.executable, "-m", "mypy.stubtest", "--mypy-config-file",
                            str(ini), "bandlight"], capture_output=True, text=True, cwd=tmp)
    errors = [line for line in p.stdout.splitlines() if line.startswith("error:")]
    assert errors, p.stdout + p.stderr  # it ran and saw the expected differences
    # Expected: the stub-only typing names, and pybind11's own metaclass.
    unexpected = [e for e in errors
                  if not (e.endswith("is not present at runtime")
                          and e.split()[1].split(".")[-1] in STUB_ONLY)
                  and not e.endswith("is inconsistent, metaclass differs")]
    assert not unexpected, "\n".join(unexpected)
