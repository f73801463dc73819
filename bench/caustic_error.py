# caustic_error.py: the table of bench/caustics_cycles.sh. Runs inside Blender's Python (OpenEXR via
# bpy, numpy), as bench/image_error.py, whose image loader and log-log interpolation it uses.
#
#   blender -b --factory-startup --python bench/caustic_error.py -- RUNS.tsv X0 X1 Y0 Y1
#
# RUNS.tsv: renderer  role  spp  wall_s  render_s  path; role `ref` (each renderer's own long
# render, another seed) or `run`. X0 X1 Y0 Y1: the caustic's box, as fractions of the width and
# height (row 0 at the top). The error of a run is the RMS difference from its renderer's reference
# over the box, over the reference's mean there (relative); the target error is Cycles' at its most
# samples, and each renderer's time to reach it is interpolated in log-log between its runs.
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from image_error import load, time_for_error  # noqa: E402


def main(runs_path, box):
    rows = [line.rstrip('\n').split('\t') for line in open(runs_path) if line.strip()]
    refs, runs = {}, {}
    for renderer, role, spp, wall, render, path in rows:
        img = load(path)
        h, w = img.shape[:2]
        x0, x1, y0, y1 = int(box[0] * w), int(box[1] * w), int(box[2] * h), int(box[3] * h)
        crop = img[y0:y1, x0:x1]
        if role == 'ref':
            refs[renderer] = (int(spp), float(render), crop)
        else:
            runs.setdefault(renderer, []).append((int(spp), float(wall), float(render), crop))
    print(f"caustic box: x {box[0]:.2f}-{box[1]:.2f}, y {box[2]:.2f}-{box[3]:.2f} of the image")
    for r, (spp, t, crop) in sorted(refs.items()):
        print(f"reference {r}: {spp} spp, {t:.1f} s; mean radiance in the box {crop.mean():.5f}")
    points = {}
    print(f"{'renderer':9} {'spp':>6} {'wall s':>8} {'render s':>9} {'rel. RMS error':>15}")
    for r in sorted(runs):
        ref = refs[r][2]
        for spp, wall, render, crop in sorted(runs[r]):
            err = math.sqrt(float(np.mean((crop - ref) ** 2))) / float(ref.mean())
            points.setdefault(r, []).append((render, err))
            print(f"{r:9} {spp:6d} {wall:8.2f} {render:9.2f} {err:15.4f}")
    target = sorted(points['cycles'])[-1][1]
    tc, how_c = time_for_error(points['cycles'], target)
    tw, how_w = time_for_error(points['whitted'], target)
    print(f"target error {target:.4f} (Cycles at its most samples): Cycles {tc:.2f} s ({how_c}), "
          f"whitted {tw:.2f} s ({how_w}); whitted reaches it {tc / tw:.1f}x sooner")
    # Measured points alone: whitted's fastest run at or below the target bounds the ratio from below.
    below = [t for t, e in points['whitted'] if e <= target]
    if below:
        print(f"without extrapolation: whitted's fastest run at or below that error took {min(below):.2f} s: "
              f"at least {tc / min(below):.0f}x sooner")
    # The other way: Cycles' time to whitted's error at its most samples (error ~ 1/sqrt(time) beyond
    # Cycles' runs).
    wt, we = sorted(points['whitted'])[-1]
    tc2, how2 = time_for_error(points['cycles'], we)
    print(f"whitted's error at its most samples, {we:.4f} in {wt:.2f} s: Cycles {tc2:.0f} s ({how2}), {tc2 / wt:.0f}x longer")


if __name__ == '__main__':
    argv = sys.argv[sys.argv.index('--') + 1:] if '--' in sys.argv else sys.argv[1:]
    main(argv[0], [float(v) for v in argv[1:5]])
