#!/usr/bin/env python3
"""Summary table of studies/upsample_accuracy.sh's runs (markdown, for studies/README.md).

Per path, resolution and gi.upsample mode, from each run's errors.json:
  GI err     mean over frames of the GI irradiance's relative MAE vs full resolution
             (sum |test - ref| / sum |ref| over RGB: the upsampling's own error)
  PSNR       mean PSNR of the final 8-bit image over the frames that differ (inf: all identical)
  FLIP       mean LDR-FLIP of the final image
  converge   frames after each cut until the GI error stays within 10% (or 1e-4) of the
             segment's last frame; only for paths that end still (static, fast_turn - whose
             turn stops at frame 30 -, rooms_cut), "-" for paths moving to the end
  entered    pixels entering at the screen borders, summed over frames (no history exists)
  disocc.    pixels that were hidden behind another surface in the previous frame, summed
  disocc. GI err   GI relative MAE over those pixels, all frames (the ghosting measure)
  ghost      disocc. GI err of this mode / that of bilateral on the same path and resolution
             ("-" below 1000 disoccluded pixels: too few to compare)
"""
import json
import os
import sys

MODES = ["bilinear", "bilateral", "temporal"]
ENDS_STILL = {"static", "fast_turn", "rooms_cut"}


def load(root, res, mode, path):
    with open(os.path.join(root, res, mode, path, "errors.json")) as f:
        return json.load(f)


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else "build/upsample-accuracy"
    paths = sorted(
        {p for res in ("half", "quarter") for m in MODES
         for p in os.listdir(os.path.join(root, res, m))
         if os.path.isdir(os.path.join(root, res, m, p))},
        key=lambda p: ["static", "slow_pan", "fast_turn", "doorway_walk"].index(p)
        if p in ("static", "slow_pan", "fast_turn", "doorway_walk") else 9)
    print("| path | res | mode | frames | GI err | PSNR dB | FLIP | converge | entered px "
          "| disocc. px | disocc. GI err | ghost |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for path in paths:
        for res in ("half", "quarter"):
            base = load(root, res, "bilateral", path)["summary"]["disoccluded_gi_rel_mae"]
            for mode in MODES:
                j = load(root, res, mode, path)
                s = j["summary"]
                conv = ", ".join("-" if c["frames_to_converge"] is None
                                 else str(c["frames_to_converge"]) for c in s["convergence"])
                if path not in ENDS_STILL:
                    conv = "-"
                ghost = (s["disoccluded_gi_rel_mae"] / base) if base > 0 else float("nan")
                disocc = s["disoccluded_pixels"]
                derr = "-" if disocc < 1000 else f"{s['disoccluded_gi_rel_mae']:.4f}"
                # null: every frame identical (PSNR inf); older runs wrote a number
                psnr = "inf" if s["psnr_mean_db"] is None else f"{s['psnr_mean_db']:.1f}"
                print(f"| {path} | {res} | {mode} | {len(j['frames'])} | {s['gi_rel_mae_mean']:.4f} "
                      f"| {psnr} | {s['flip_mean']:.4f} | {conv} "
                      f"| {s['entered_pixels']} | {disocc} "
                      f"| {derr} | "
                      f"{'-' if disocc < 1000 else f'{ghost:.2f}'} |")


if __name__ == "__main__":
    main()
