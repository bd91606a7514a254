#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# A Slurm array job: each array task relights one chunk of CHUNK frames.
#   sbatch --array=0-23 slurm_array.sh
#SBATCH --job-name=bandlight-relight
#SBATCH --cpus-per-task=2
set -euo pipefail
FIRST=${FIRST:-1001}
CHUNK=${CHUNK:-10}
START=$((FIRST + SLURM_ARRAY_TASK_ID * CHUNK))
END=$((START + CHUNK - 1))
exec "${BANDLIGHT:-bandlight}" apply "${INPUT:-/show/plates/A001.####.exr}" \
    "${OUTPUT:-/show/relit/A001.####.exr}" \
    --look "${LOOK:-bradford_A_to_D65}" --config "${CONFIG:-/show/ocio/bandlight-package}" \
    --frames "${START}-${END}" --threads "${SLURM_CPUS_PER_TASK:-0}" --skip-existing --keep-going
