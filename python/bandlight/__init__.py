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

del _extension_doc
