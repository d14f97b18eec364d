#!/bin/sh
# Accuracy of gi.upsample (bilinear, bilateral, temporal) at half and quarter resolution against
# full-resolution GI, per camera path (studies/findings/gi-upsampling.md, "GI upsampling"). Hardware-independent
# figures (llvmpipe rounding aside). Usage, from the repository root after a Release build:
#   studies/upsample_accuracy.sh [OUT_DIR (build/upsample-accuracy)] [WIDTHxHEIGHT (640x360)]
# Writes OUT_DIR/<resolution>/<mode>/<path>/{frame_NNNN.png,errors.csv,errors.json} and prints
# the summary table (studies/upsample_table.py).
set -eu
out=${1:-build/upsample-accuracy}
size=${2:-640x360}
width=${size%x*}
height=${size#*x}
bin=build/probebench
mkdir -p "$out"
# --dense: the figures in studies/README.md were measured before auto placement stored sparse.
"$bin" bake --scene rooms --dense --out "$out/rooms.pbp" > "$out/bake.log"
for res in half quarter; do
    for mode in bilinear bilateral temporal; do
        for path in static slow_pan fast_turn doorway_walk bench/paths/rooms_cut.toml; do
            name=$(basename "$path" .toml)
            echo "$res $mode $name" >&2
            mkdir -p "$out/$res/$mode"
            "$bin" render --scene rooms --view doorway --width "$width" --height "$height" \
                --probes "$out/rooms.pbp" --set gi.resolution=$res --set gi.upsample=$mode \
                --path "$path" --out-dir "$out/$res/$mode/$name" --compare-to full \
                > "$out/$res/$mode/$name.log" 2> /dev/null ||
                { echo "failed: $res $mode $name (see $out/$res/$mode/$name.log)" >&2; exit 1; }
        done
    done
done
python3 studies/upsample_table.py "$out"
