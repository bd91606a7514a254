# SPDX-License-Identifier: BSD-3-Clause
"""Every keyword default of the Python module is the defaults table's value
(transforms/Defaults.h and requests/Defaults.h), and the type stubs state the
same defaults: the command, the C++ requests and Python cannot drift apart.

The table is read from the headers themselves; each keyword that has a value
by default (a string or a number: None and flags are not table entries) must
name the table entry it takes, below."""

import ast
import re

import pytest

import bandlight
from conftest import SOURCE_DIR
from test_stubs import STUB, split_params, stub_definitions, stub_tree

# The table's entries each keyword may take, by keyword name.
KEYWORD_ENTRIES = {
    "working_space": {"WORKING_SPACE", "IDT_WORKING_SPACE"},
    "test_set": {"IDT_TEST_SET"},
    "rootpoly": {"IDT_CHART_ROOTPOLY"},
    "space": {"WORKING_SPACE"},
    "method": {"METHOD", "WHITE_ADAPTATION"},
    "observer": {"OBSERVER"},
    "plates": {"PLATES", "ACCURACY_PLATES", "LIGHT_GROUP_PLATES"},
    "adaptation": {"ADAPTATION"},
    "camera_idt": {"IDT_LIGHT"},
    "lut_size": {"TRANSFORM_LUT_SIZE", "CONFIG_LUT_SIZE"},
    "rule": {"BAND_RULE"},
    "set": {"MATCHING_SET"},
    "kind": {"SPECTRAL_KIND"},
    "sampling": {"SPECTRAL_SAMPLING"},
    "threads": {"THREADS"},
    "source": {"SCENE_SOURCE", "TEXT_SOURCE"},
    "name_or_file": {"REFLECTANCES"},
    "min_nm": {"EQUAL_BANDS_MIN_NM"},
    "max_nm": {"EQUAL_BANDS_MAX_NM"},
    "start": {"PLANCK_START_NM"},
    "step": {"PLANCK_STEP_NM"},
    "count": {"PLANCK_COUNT"},
    "kL": {"CIEDE2000_K"},
    "kC": {"CIEDE2000_K"},
    "kH": {"CIEDE2000_K"},
    "shaper": {"LUT_SHAPER"},
    "encoding": {"LUT_ENCODING"},
    "base_paths": {"BASE_PATHS"},
    "size": {"LUT_SIZE"},
    "out": {"PACKAGE_DIR"},
    "illuminants": {"CONFIG_ILLUMINANTS"},
}
# Keywords whose literal default is not a setting: a spectrum's name is empty
# unless given.
NOT_SETTINGS = {("Spectrum", "name")}


def table():
    """NAME -> value of every `inline constexpr` entry of the two headers."""
    out = {}
    for header in ("transforms/Defaults.h", "requests/Defaults.h"):
        text = (SOURCE_DIR / header).read_text()
        for m in re.finditer(r"inline constexpr (?:const char\*|int|double) (\w+) = ([^;]+);",
                             text):
            value = m.group(2).strip()
            if value.startswith('"'):
                out[m.group(1)] = ast.literal_eval(value)
            elif re.fullmatch(r"-?\d+", value):
                out[m.group(1)] = int(value)
            elif re.fullmatch(r"-?[\d.]+(e-?\d+)?", value):
                out[m.group(1)] = float(value)
    return out


def literal(text):
    """A default as pybind11 or the stubs write it, as a Python value; None
    for what is not a plain string or number."""
    try:
        v = ast.literal_eval(text)
    except (ValueError, SyntaxError):
        return None
    return v if isinstance(v, (str, int, float)) and not isinstance(v, bool) else None


def runtime_defaults(obj):
    """[(keyword, default text)] of every overload, from pybind11's signature lines."""
    out = []
    for line in (obj.__doc__ or "").splitlines():
        m = re.match(rf"^(?:\d+\. )?{re.escape(obj.__name__)}\((.*)\) -> ", line.strip())
        if not m:
            continue
        for p in split_params(m.group(1)):
            if "=" in p:
                name = p.split(":")[0].split("=")[0].strip()
                out.append((name, p.split("=", 1)[1].strip()))
    return out


def callables():
    """(qualified name, object) of every pybind11 function and method."""
    for name in sorted(n for n in dir(bandlight) if not n.startswith("_")):
        # A function checking its keywords first: the extension function inside.
        obj = getattr(getattr(bandlight, name), "__wrapped__", getattr(bandlight, name))
        if isinstance(obj, type):
            for m, attr in sorted(vars(obj).items()):
                if callable(attr) and type(attr).__name__ in ("builtin_function_or_method",
                                                               "instancemethod"):
                    yield f"{name}.{m}", getattr(obj, m)
                elif isinstance(attr, staticmethod):
                    yield f"{name}.{m}", getattr(obj, m)
        elif callable(obj) and type(obj).__name__ == "builtin_function_or_method":
            yield name, obj


TABLE = table()
CALLABLES = list(callables())


def test_the_table_is_read():
    # The headers' entries this test relies on are there, with their values.
    assert TABLE["WORKING_SPACE"] == "acescg"
    assert TABLE["LUT_SIZE"] == 65 and TABLE["PLANCK_COUNT"] == 107
    assert all(k in TABLE for keys in KEYWORD_ENTRIES.values() for k in keys)


@pytest.mark.parametrize("where,obj", CALLABLES, ids=[c[0] for c in CALLABLES])
def test_python_defaults_are_the_table(where, obj):
    for name, text in runtime_defaults(obj):
        value = literal(text)
        if value is None or (where.split(".")[0], name) in NOT_SETTINGS:
            continue
        assert name in KEYWORD_ENTRIES, \
            f"{where}({name}={text}): a literal default that is not in the defaults table"
        allowed = {TABLE[k] for k in KEYWORD_ENTRIES[name]}
        assert value in allowed, f"{where}({name}={text}): the table says {sorted(map(str, allowed))}"


def stub_functions():
    defs = stub_definitions(stub_tree().body)
    for name, nodes in defs.items():
        for node in nodes:
            if isinstance(node, ast.FunctionDef):
                yield name, node
            elif isinstance(node, ast.ClassDef):
                for m, members in stub_definitions(node.body).items():
                    for f in members:
                        if isinstance(f, ast.FunctionDef):
                            yield f"{name}.{m}", f


def test_stub_defaults_equal_the_runtime_defaults():
    runtime = {}
    for where, obj in CALLABLES:
        for name, text in runtime_defaults(obj):
            runtime.setdefault((where, name), set()).add(literal(text))
    checked = 0
    for where, fn in stub_functions():
        args = fn.args.posonlyargs + fn.args.args
        pairs = list(zip(args[len(args) - len(fn.args.defaults):], fn.args.defaults))
        pairs += [(a, d) for a, d in zip(fn.args.kwonlyargs, fn.args.kw_defaults) if d is not None]
        for arg, default in pairs:
            value = literal(ast.unparse(default))
            if value is None or (where, arg.arg) not in runtime:
                continue
            assert value in runtime[(where, arg.arg)], \
                f"{STUB.name}: {where}({arg.arg}={value!r}) but the module says " \
                f"{runtime[(where, arg.arg)]}"
            checked += 1
    assert checked > 40  # the stubs state defaults for most keywords
