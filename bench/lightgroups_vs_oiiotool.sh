#!/usr/bin/env bash
# Wall-clock of relighting the light groups of a 4K render against
# `oiiotool` copying the same file: the bytes read, decompressed, compressed
# and written are the floor any relight stands on.
#   bench/lightgroups_vs_oiiotool.sh [build-dir] [runs]
# The shot is a 4096x2160 single-part multi-layer EXR as Blender/Cycles
# writes one with two view-layer light groups: ViewLayer.Combined.R/G/B/A
# (the beauty: the groups plus a little emission, the residual) and
# ViewLayer.Combined_key.R/G/B, ViewLayer.Combined_fill.R/G/B, all half
# float, ZIP compressed (Blender's default EXR codec). Its pixels are smooth
# gradients with render noise (gaussian, clamped at 0), so ZIP has what it
# has on a render to work on, not incompressible noise.
# Runs alternate (copy, relight, copy, relight, ...) so that load from the
# machine's other users falls on both; prints min and median of `runs`
# runs of each (default 5), wall-clock and CPU time, and their ratios.
set -euo pipefail
build=${1:-build}
runs=${2:-5}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
size=${LIGHTGROUPS_BENCH_SIZE:-4096x2160}  # another size only to try the script

# One light's layer: a gradient across the frame (corner colours in
# ACEScg) with render noise.
layer() {
    oiiotool --pattern "fill:topleft=$1:topright=$2:bottomleft=$3:bottomright=$4" $size 3 \
        --pattern noise:type=gaussian:mean=0:stddev=0.03:seed="$5" $size 3 --add \
        --clamp:min=0 -o "$6"
}
layer 0.9,0.5,0.2 0.4,0.25,0.1 0.6,0.35,0.12 0.1,0.06,0.03 1 "$work/key.exr"
layer 0.05,0.1,0.12 0.3,0.5,0.45 0.02,0.04,0.05 0.25,0.4,0.4 2 "$work/fill.exr"
# Beauty = key + fill + emission (the residual), alpha 1.
oiiotool "$work/key.exr" "$work/fill.exr" --add --addc 0.02,0.015,0.01 \
    --pattern constant:color=1 $size 1 --chappend -o "$work/beauty.exr"
oiiotool "$work/beauty.exr" "$work/key.exr" "$work/fill.exr" --chappend --chappend \
    --chnames ViewLayer.Combined.R,ViewLayer.Combined.G,ViewLayer.Combined.B,ViewLayer.Combined.A,ViewLayer.Combined_key.R,ViewLayer.Combined_key.G,ViewLayer.Combined_key.B,ViewLayer.Combined_fill.R,ViewLayer.Combined_fill.G,ViewLayer.Combined_fill.B \
    -d half --compression zip -o "$work/shot.exr"
rm -f "$work/key.exr" "$work/fill.exr" "$work/beauty.exr"

describe() {
    oiiotool --info -v "$1" |
        awk 'NR == 2 {sub(/^[^:]*: */, ""); print "    " $0} /^ *(channel list|compression):/ {$1 = $1; print "    " $0}'
    echo "    $(( $(stat -c %s "$1") / 1000000 )) MB"
}

# "WALL CPU" seconds of one run (CPU: user + system, all threads): the CPU
# time is what the program itself spends, less disturbed by other users.
elapsed() {
    local TIMEFORMAT='%R %U %S' t
    t=$({ time "$@" > /dev/null 2>&1; } 2>&1) || { echo "failed: $*" >&2; return 1; }
    awk '{printf "%.3f %.3f\n", $1, $2 + $3}' <<< "$t"
}

relight=("$build/bandlight" apply "$work/shot.exr" "$work/relit.exr"
         --light-group key=A:D65 --light-group fill=F11:D50 --method rootpoly)
# -a: every subimage, as bandlight carries every part (this file has one).
copy=(oiiotool -a "$work/shot.exr" -o "$work/copy.exr")

# One untimed run of each: the file in the page cache, the programs loaded.
"${relight[@]}" > /dev/null 2>&1
"${copy[@]}"

ours=() theirs=() ours_cpu=() theirs_cpu=()
for _ in $(seq "$runs"); do
    read -r wall cpu <<< "$(elapsed "${copy[@]}")"
    theirs+=("$wall") theirs_cpu+=("$cpu")
    read -r wall cpu <<< "$(elapsed "${relight[@]}")"
    ours+=("$wall") ours_cpu+=("$cpu")
done

stats() { printf '%s\n' "$@" | sort -n | awk '{a[NR]=$1} END {printf "%s %s\n", a[1], a[int((NR+1)/2)]}'; }
read -r ours_min ours_med <<< "$(stats "${ours[@]}")"
read -r theirs_min theirs_med <<< "$(stats "${theirs[@]}")"
read -r ours_cmin ours_cmed <<< "$(stats "${ours_cpu[@]}")"
read -r theirs_cmin theirs_cmed <<< "$(stats "${theirs_cpu[@]}")"

printf '%s half EXR, beauty + 2 Cycles light groups, ZIP (%s MB); %s runs each, %s cores, load %s\n' \
    "$size" "$(( $(stat -c %s "$work/shot.exr") / 1000000 ))" "$runs" "$(nproc)" \
    "$(cut -d' ' -f1-3 /proc/loadavg)"
printf '  input:\n'; describe "$work/shot.exr"
printf '  relit (what bandlight wrote):\n'; describe "$work/relit.exr"
printf '  copy (what oiiotool wrote):\n'; describe "$work/copy.exr"
printf '                                              wall min   median    CPU min   median\n'
row() { printf '  %-42s %6.2f s %6.2f s   %6.2f s %6.2f s\n' "$@"; }
row "oiiotool -a shot.exr -o copy.exr" "$theirs_min" "$theirs_med" "$theirs_cmin" "$theirs_cmed"
row "bandlight apply --light-group x2 (rootpoly)" "$ours_min" "$ours_med" "$ours_cmin" "$ours_cmed"
awk -v a="$ours_min" -v b="$theirs_min" -v c="$ours_med" -v d="$theirs_med" \
    -v e="$ours_cmin" -v f="$theirs_cmin" -v g="$ours_cmed" -v h="$theirs_cmed" \
    'BEGIN {printf "  %-42s %6.2f   %6.2f     %6.2f   %6.2f\n", "relight / copy", a / b, c / d, e / f, g / h}'
printf '  every run, wall (copy / relight): %s / %s\n' "${theirs[*]}" "${ours[*]}"
printf '  every run, CPU  (copy / relight): %s / %s\n' "${theirs_cpu[*]}" "${ours_cpu[*]}"
