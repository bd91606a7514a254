# SPDX-License-Identifier: BSD-3-Clause
"""bandlight: the 3-band model of coloured light and surfaces as OpenColorIO
transforms, measured against an exact spectral core.

Transforms are PyOpenColorIO objects, spectra and colours numpy arrays::

    import bandlight, PyOpenColorIO as OCIO
    t = bandlight.illuminant_change("A", "D65", method="bradford", working_space="acescg")
    cpu = OCIO.Config.CreateRaw().getProcessor(t).getDefaultCPUProcessor()

Errors are ValueError (bad names and values, malformed files, whose message
names the file and line) or OSError (files that cannot be read or written),
with the message the ``bandlight`` command prints.
"""

from ._bandlight import *  # noqa: F401,F403  (the extension holds the whole API)
from ._bandlight import __doc__ as _extension_doc, __version__  # noqa: F401

from ._bandlight import _apply, _quality

del _extension_doc


def _frames_text(frames):
    """frames= as the command takes it: "1001-1100" as it is; a range
    (range(1001, 1101, 2)) or any iterable of frame numbers as their list."""
    if frames is None or isinstance(frames, str):
        return frames
    if isinstance(frames, range):
        if len(frames) == 0:
            raise ValueError("frames= is an empty range")
        last = frames[-1]
        step = frames.step
        if step == 1:
            return f"{frames.start}-{last}"
        if step > 1:
            return f"{frames.start}-{last}x{step}"
    try:
        numbers = [int(f) for f in frames]
    except (TypeError, ValueError):
        raise TypeError("frames= takes \"1001-1100\", a range or a list of frame numbers, "
                        f"not {type(frames).__name__}") from None
    if not numbers:
        raise ValueError("frames= is an empty list")
    return ",".join(map(str, numbers))


def _keywords(function):
    """The keywords an extension function takes, from its signature line."""
    import re
    first = (function.__doc__ or "").split("\n", 1)[0]
    inside = first[first.find("(") + 1:first.rfind(")")]
    return [n for n in re.findall(r"(\w+)\s*:", inside)]


def _check_keywords(function, given):
    """Refuses a keyword `function` does not take with one line naming it,
    the nearest it does take and all of them (as the command does for an
    option it does not know), instead of pybind11's list of signatures."""
    import difflib
    names = _keywords(function)
    for key in given:
        if names and key not in names:
            near = difflib.get_close_matches(key, names, n=1)
            hint = f" (did you mean {near[0]}=?)" if near else ""
            raise TypeError(f"{function.__name__.lstrip('_')}() takes no keyword {key}={hint}; "
                            "it takes " + ", ".join(n + "=" for n in names))


def _checked(function):
    """The extension function `function` checking its keywords first (its
    docstring and pybind11 signature kept: `__wrapped__` is the function)."""
    import functools
    names = frozenset(_keywords(function))  # read once, not per call

    @functools.wraps(function)
    def checked(*args, **kwargs):
        if not names.issuperset(kwargs):
            _check_keywords(function, kwargs)
        return function(*args, **kwargs)

    checked.__module__ = __name__
    checked.__qualname__ = function.__name__
    return checked


def _check_every_function():
    from . import _bandlight
    for name in dir(_bandlight):
        value = getattr(_bandlight, name)
        if not name.startswith("__") and type(value).__name__ == "builtin_function_or_method" \
                and _keywords(value):
            globals()[name] = _checked(value)


_check_every_function()


def _apply_chunk(input, output, frames, options):
    # A module-level function, so workers unpickle it by name.
    return _apply(input, output, frames=frames, **options)


def apply(input, output, *, frames=None, client=None, **options):
    """Applies a look, or an illuminant change, to an image file or a frame
    sequence: the job of ``bandlight apply`` (see ``_apply`` for every
    keyword: look, config, colorspace, src, dst, method, working_space,
    observer, training, plates, adaptation, camera, camera_idt, threads,
    skip_existing, keep_going). Returns the summary: {"applied", "frames",
    "skipped", "failed": [(frame, error)], "seconds"}.

    client: a ``distributed.Client``; the frames are then spread over its
    workers in chunks, each worker reading, relighting and writing its own
    frames (the workers import bandlight and see the same files). The
    summary adds the chunks' counts; "seconds" is the wall time of the call.
    """
    frames = _frames_text(frames)
    _check_keywords(_apply, options)
    if client is None:
        return _apply(input, output, frames=frames, **options)
    import os
    import time

    if not all(callable(getattr(client, name, None))
               for name in ("submit", "gather", "scheduler_info")):
        raise TypeError("client= must be a distributed.Client (it submits and gathers the "
                        f"chunks), got {type(client).__name__}")
    if frames is None:
        raise ValueError("client= spreads a frame sequence: give frames=")
    every = frame_set(frames)
    workers = max(1, len(client.scheduler_info().get("workers", {})))
    # A few chunks a worker, so a slow frame does not hold the rest back.
    size = max(1, -(-len(every) // (4 * workers)))
    chunks = [every[i:i + size] for i in range(0, len(every), size)]
    start = time.perf_counter()
    futures = [client.submit(_apply_chunk, os.fspath(input), os.fspath(output),
                             ",".join(map(str, chunk)), options, pure=False)
               for chunk in chunks]
    results = client.gather(futures)
    summary = {"applied": results[0]["applied"] if results else "",
               "frames": sum(r["frames"] for r in results),
               "skipped": sum(r["skipped"] for r in results),
               "failed": [f for r in results for f in r["failed"]],
               "seconds": time.perf_counter() - start}
    return summary


import dataclasses as _dataclasses


@_dataclasses.dataclass(frozen=True)
class Quality:
    """The light-quality scores of one light, as ``bandlight quality --json``
    gives them (docs/quality.md). A score its standard gives no value for
    is None, and ``warnings`` says why; each score is a dict of its named
    values ("Ra", "R": [R1..R15]; "Rf", "Rg", "Rf_h": [16 bins], ...) and
    "reference" when it compares with one. Plain data: it pickles, so a
    farm or Dask worker can return it."""
    light: str
    cct: float
    duv: float
    cri: dict
    cie2017: dict
    tm30: dict
    ssi: dict
    tlci: dict
    tlmf: dict
    warnings: tuple


Quality.__init__.__doc__ = """A record of each score as the JSON of ``bandlight quality`` holds it
(bandlight.quality() makes them; None for a score not given)."""


def quality(light, reference=None, *, threads=0):
    """The light-quality scores of a light, or of each light of a list: CCT
    and Duv, CIE 13.3 Ra/R1-R15, CIE 224:2017 Rf, TM-30 Rf/Rg and hue bins,
    SSI, TLCI-2012, and TLMF against ``reference`` (which SSI then uses
    too). A light is a name ("D65", "3200K", "daylight:5600",
    "planck:3200"), a spectrum file or a Spectrum. Returns a Quality, or a
    list of them for a list; the lights are scored on ``threads`` threads
    (0: all cores) with the GIL released."""
    import json
    many = isinstance(light, (list, tuple))
    lights = list(light) if many else [light]
    names = {f.name for f in _dataclasses.fields(Quality)}
    records = []
    for d in json.loads(_quality(lights, reference, threads)):
        d["warnings"] = tuple(d.get("warnings", ()))
        records.append(Quality(**{k: d.get(k) for k in names}))
    return records if many else records[0]
