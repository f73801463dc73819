# image_error.py: the error tables of bench/compare_cycles.sh. Runs inside Blender's Python, which
# reads OpenEXR (bpy.data.images) and has numpy; also reads PFM (whitted's float output).
#
#   blender -b --factory-startup --python bench/image_error.py -- RUNS.tsv
#
# RUNS.tsv (tab-separated, one line per image, written by compare_cycles.sh):
#   role  renderer  spp  wall_s  render_s  path
# role is one of
#   ref_a, ref_b    two independent Cycles renders (different seeds, equal spp): the reference is
#                   their mean; (a - b)^2 / 4 estimates its noise variance in every pixel
#   wref_half, wref whitted at N/2 and N spp; whitted's sample sequence is nested (the N-spp image
#                   averages the N/2 first samples and N/2 more), so b = 2*wref - wref_half is the
#                   image of the second half alone and (wref_half - b)^2 / 4 estimates the noise
#                   variance of wref in every pixel
#   run             an image at low spp to measure against the reference
#
# Prints, per renderer and spp: times, RMSE against the Cycles reference (raw, and with the
# reference's own noise variance taken out), then the time each renderer needs to reach the other's
# error (log-log interpolation between measured points, extrapolated with error ~ 1/sqrt(time)
# outside them), then the per-pixel check that the two converged images agree within noise.
import math
import sys

import numpy as np


def load(path):
    """H x W x 3 float64, row 0 at the top."""
    if path.endswith('.pfm'):
        with open(path, 'rb') as f:
            kind = f.readline().strip()
            dims = f.readline().split()
            w, h = int(dims[0]), int(dims[1])
            scale = float(f.readline())
            data = np.frombuffer(f.read(), dtype='<f4' if scale < 0 else '>f4')
        channels = 3 if kind == b'PF' else 1
        img = data[:w * h * channels].reshape(h, w, channels)[::-1]  # PFM rows run bottom to top
        if channels == 1:
            img = np.repeat(img, 3, axis=2)
        return img.astype(np.float64)
    import bpy
    im = bpy.data.images.load(path, check_existing=False)
    im.colorspace_settings.name = 'Non-Color'  # the file's floats as they are
    w, h = im.size
    buf = np.empty(w * h * 4, dtype=np.float32)
    im.pixels.foreach_get(buf)
    bpy.data.images.remove(im)
    return buf.reshape(h, w, 4)[::-1, :, :3].astype(np.float64)  # Blender's rows run bottom to top


def rmse(a, b):
    return math.sqrt(float(np.mean((a - b) ** 2)))


def time_for_error(points, target):
    """Seconds to reach RMSE `target`, from (seconds, rmse) points of one renderer."""
    pts = sorted((max(t, 1e-3), e) for t, e in points)  # --stats has 1 ms resolution
    for (t0, e0), (t1, e1) in zip(pts, pts[1:]):
        if min(e0, e1) <= target <= max(e0, e1) and e0 != e1:
            s = (math.log(target) - math.log(e0)) / (math.log(e1) - math.log(e0))
            return math.exp(math.log(t0) + s * (math.log(t1) - math.log(t0))), 'interpolated'
    # Outside the measured range: error ~ 1/sqrt(time) from the nearest point.
    t, e = min(pts, key=lambda p: abs(math.log(p[1] / target)))
    return t * (e / target) ** 2, 'extrapolated'


def block_means(img, k):
    h, w = (img.shape[0] // k) * k, (img.shape[1] // k) * k
    return img[:h, :w].reshape(h // k, k, w // k, k, -1).mean(axis=(1, 3))


def main(runs_path):
    rows = []
    with open(runs_path) as f:
        for line in f:
            role, renderer, spp, wall, render, path = line.rstrip('\n').split('\t')
            rows.append(dict(role=role, renderer=renderer, spp=int(spp), wall=float(wall),
                             render=float(render), path=path))
    by_role = {r['role']: r for r in rows if r['role'] != 'run'}
    ref_a, ref_b = load(by_role['ref_a']['path']), load(by_role['ref_b']['path'])
    ref = (ref_a + ref_b) / 2
    var_ref = (ref_a - ref_b) ** 2 / 4  # per pixel and channel, one degree of freedom
    ref_spp = by_role['ref_a']['spp'] + by_role['ref_b']['spp']
    ref_noise = float(np.mean(var_ref))
    print(f'reference: Cycles {ref_spp} spp (two seeds of {by_role["ref_a"]["spp"]}), '
          f'mean {ref.mean():.4f}, its own noise RMSE {math.sqrt(ref_noise):.5f} '
          f'(render {by_role["ref_a"]["render"] + by_role["ref_b"]["render"]:.1f} s)')

    print()
    print(f'{"renderer":<9} {"spp":>5} {"wall_s":>8} {"render_s":>9} {"rmse":>9} {"rmse_corr":>10}')
    points = {}
    for r in rows:
        if r['role'] != 'run':
            continue
        img = load(r['path'])
        e = rmse(img, ref)
        corr = math.sqrt(max(e * e - ref_noise, 0.0))
        r['rmse'], r['rmse_corr'] = e, corr
        points.setdefault(r['renderer'], []).append((r['render'], corr))
        print(f'{r["renderer"]:<9} {r["spp"]:>5} {r["wall"]:>8.2f} {r["render"]:>9.2f} {e:>9.5f} {corr:>10.5f}')
    print('(render_s: whitted: flatten + textures + build + render of --stats; Cycles: the render call, '
          'with its scene sync and BVH build; wall_s: the whole process, Blender start-up included; '
          'rmse_corr: RMSE with the reference\'s own noise variance taken out)')

    if 'whitted' in points and 'cycles' in points:
        print()
        print('time to equal error (render_s; whitted\'s time interpolated at each Cycles error):')
        print(f'{"cycles_spp":>10} {"rmse_corr":>10} {"cycles_s":>9} {"whitted_s":>10} {"speedup":>8}')
        for r in rows:
            if r['role'] == 'run' and r['renderer'] == 'cycles':
                tw, how = time_for_error(points['whitted'], r['rmse_corr'])
                print(f'{r["spp"]:>10} {r["rmse_corr"]:>10.5f} {r["render"]:>9.2f} {tw:>10.2f} '
                      f'{r["render"] / tw:>7.1f}x  ({how})')

    if 'wref' in by_role:
        wref_half, wref = load(by_role['wref_half']['path']), load(by_role['wref']['path'])
        second_half = 2 * wref - wref_half
        var_w = (wref_half - second_half) ** 2 / 4
        # Where neither image has noise (the sky seen directly: the background colour exactly) the
        # difference is float rounding: a variance floor of (1e-4 of the value)^2 keeps z finite there.
        var_floor = (1e-4 * np.abs(ref)) ** 2 + 1e-12
        d = wref - ref
        print()
        print(f'converged images: whitted {by_role["wref"]["spp"]} spp '
              f'(render {by_role["wref"]["render"]:.1f} s) against the Cycles reference')
        means_w, means_c = wref.reshape(-1, 3).mean(0), ref.reshape(-1, 3).mean(0)
        se = np.sqrt((var_w + var_ref).reshape(-1, 3).sum(0)) / (d.shape[0] * d.shape[1])
        print('  image mean per channel: whitted ' + ' '.join(f'{x:.5f}' for x in means_w) +
              ', Cycles ' + ' '.join(f'{x:.5f}' for x in means_c) +
              ', difference / its standard error: ' + ' '.join(f'{x:+.1f}' for x in (means_w - means_c) / se))
        print(f'  RMSE between them {rmse(wref, ref):.5f}; expected from noise alone '
              f'{math.sqrt(float(np.mean(var_w + var_ref))):.5f}')
        for k in (4, 8):
            # Block means of the difference against their standard error: the sum of the pixels'
            # variance estimates (k*k*3 of them, so the estimate has ~k*k degrees of freedom).
            db = block_means(d, k)
            vb = block_means(var_w + var_ref + var_floor, k) / (k * k)
            z = db / np.sqrt(np.maximum(vb, 1e-30))
            n = z.size
            expected = n * math.erfc(4 / math.sqrt(2))
            print(f'  {k}x{k}-pixel blocks, per channel: z = mean difference / standard error over '
                  f'{n} values: mean {z.mean():+.3f}, sd {z.std():.3f} (1 if they agree), '
                  f'|z|>3: {int((np.abs(z) > 3).sum())} ({100 * float(np.mean(np.abs(z) > 3)):.2f}%; 0.27% by chance), '
                  f'|z|>4: {int((np.abs(z) > 4).sum())} ({expected:.2f} by chance)')
            if k == 8:
                bad = np.argwhere(np.abs(z).max(axis=2) > 4)
                if len(bad):
                    print('    blocks with |z| > 4 (row, column of the block, top-left origin): ' +
                          ' '.join(f'({y},{x})' for y, x in bad[:20]) + (' ...' if len(bad) > 20 else ''))


if __name__ == '__main__':
    argv = sys.argv[sys.argv.index('--') + 1:] if '--' in sys.argv else sys.argv[1:]
    main(argv[0])
