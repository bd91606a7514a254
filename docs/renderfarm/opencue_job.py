#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""An OpenCue job: bandlight apply over a show's plates, in chunks of frames.

OpenCue's pyoutline runs the Shell layer once per chunk, replacing
#FRAME_START# and #FRAME_END# with the chunk's first and last frame. A
re-queued chunk skips the frames it already wrote (--skip-existing); a bad
frame fails the chunk only after the others are written (--keep-going,
exit code 2).

    python3 opencue_job.py /show/plates/A001.####.exr /show/relit/A001.####.exr 1001-1240
"""

import sys

# The command each chunk runs (OpenCue replaces the two tokens).
COMMAND = ["bandlight", "apply", "{input}", "{output}",
           "--look", "bradford_A_to_D65", "--config", "/show/ocio/bandlight-package",
           "--frames", "#FRAME_START#-#FRAME_END#", "--skip-existing", "--keep-going"]
CHUNK = 10


def command(input_pattern, output_pattern):
    return [a.format(input=input_pattern, output=output_pattern) for a in COMMAND]


def main():
    from outline import Outline, cuerun  # OpenCue's pyoutline
    from outline.modules.shell import Shell

    input_pattern, output_pattern, frames = sys.argv[1:4]
    job = Outline("bandlight-relight")
    job.add_layer(Shell("relight", command=command(input_pattern, output_pattern),
                        range=frames, chunk=CHUNK))
    cuerun.launch(job, use_pycuerun=False)


if __name__ == "__main__":
    main()
