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

from ._bandlight import _apply

del _extension_doc


def _apply_chunk(input, output, frames, options):
    # A module-level function, so workers unpickle it by name (bandlight's
    # extension functions themselves do not pickle).
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
