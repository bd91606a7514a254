#!/usr/bin/env bash
# Wall-clock of `bandlight apply` against `oiiotool --colorconvert` on one
# 3840x2160 float RGBA EXR, same machine, same config, same run.
#   bench/apply_vs_oiiotool.sh [build-dir] [runs]
# Prints the median of `runs` runs of each (default 5).
set -euo pipefail
build=${1:-build}
runs=${2:-5}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$build/bandlight" config --out "$work/cfg" > /dev/null
oiiotool --pattern noise:type=uniform:min=0:max=4 3840x2160 4 -d float \
    --attrib compression none -o "$work/plate.exr"

median() { sort -n | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
time_it() {
    local t0 t1
    t0=$(date +%s.%N)
    "$@" > /dev/null
    t1=$(date +%s.%N)
    awk -v a="$t0" -v b="$t1" 'BEGIN {print b - a}'
}

ours=$(for _ in $(seq "$runs"); do
    time_it "$build/bandlight" apply "$work/plate.exr" "$work/ours.exr" \
        --look bradford_A_to_D65 --config "$work/cfg"
done | median)
theirs=$(for _ in $(seq "$runs"); do
    time_it oiiotool "$work/plate.exr" --colorconfig "$work/cfg/config.ocio" \
        --colorconvert ACEScg "Linear Rec.709 (sRGB)" -o "$work/theirs.exr"
done | median)
theirs_look=$(for _ in $(seq "$runs"); do
    time_it oiiotool "$work/plate.exr" --colorconfig "$work/cfg/config.ocio" \
        --ociolook:from=ACEScg:to=ACEScg bradford_A_to_D65 -o "$work/theirs_look.exr"
done | median)
printf 'UHD float RGBA EXR (uncompressed), median of %s runs, %s cores\n' "$runs" "$(nproc)"
printf '  bandlight apply --look bradford_A_to_D65       %6.3f s\n' "$ours"
printf '  oiiotool --colorconvert ACEScg "Linear Rec.709" %6.3f s\n' "$theirs"
printf '  oiiotool --ociolook bradford_A_to_D65           %6.3f s\n' "$theirs_look"
