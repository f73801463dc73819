# sc_to_blender.py: renders one of our .sc scenes with Blender Cycles, for bench/compare_cycles.sh.
#
#   blender -b --factory-startup --python bench/sc_to_blender.py -- SCENE.sc -o OUT.exr
#           [--width W] [--height H] [--spp N] [--max-depth D] [--threads T] [--seed S]
#           [--segments K] [--save-blend FILE.blend] [--normals]
#
# A small parser of the bracket format (/work/shared/docs/scene-format.md §1-§7) builds the scene in
# Blender the way §9.2 (--mode path) reads it, so that Cycles and `whitted --mode path` solve the
# same light transport:
# - shapes are the unit shapes of §4 with their object->world matrices (§3), set directly in our
#   Y-up coordinates (the camera gets its matrix in the same coordinates, so the relative geometry
#   is exact and Blender's Z-up never enters). Cycles has no analytic quadrics: the sphere is a UV
#   sphere of K segments and K/2 rings, cylinder and cone have K sides (K = 128 by default), shaded
#   smooth (auto-smooth at 30 degrees keeps the caps flat); the cube is exact.
# - `diffuse` is a Diffuse BSDF (roughness 0: Lambertian), `emit` an Emission shader of strength 1
#   added to it (Cycles' mesh emitters radiate from both faces, as §9.2 says emit does). Where a
#   channel of diffuse exceeds 1, the colour is scaled down by it (§9.2). Ideal glass (`diffuse 0 0 0
#   transparent T ior n`, no gloss) is a sharp Refraction BSDF of colour T (no Fresnel term, as
#   §9.2). Materials with specular, reflect, other transparency or a texture, and
#   point/spot/directional lights, are refused: this converter covers the bench scenes (Lambertian
#   surfaces lit by emitters, glass), not the whole format.
# - the background colour is the world colour at strength 1 (a uniform environment).
# - the camera: `angle` is the full vertical field of view (sensor fit vertical); near clip 1e-4.
# - Cycles on the CPU, T threads, N samples, no adaptive sampling, no denoising, no clamping,
#   caustics on, no filter glossy, light tree off where Blender has one, light threshold 0 (all
#   lights sampled), max bounces D - 1 for every (whitted's --max-depth D counts the direct-light
#   segment as 1, Cycles' bounces do not)
#   kind, box pixel filter 1 pixel wide (each sample uniformly placed in its pixel, as whitted's),
#   Standard view transform; the output is a 32-bit float OpenEXR of linear radiance.
# Prints one line "cycles_render_seconds S": the time of the render call alone (scene sync, BVH
# build, render, EXR write), without Blender's start-up and the scene conversion.
import math
import re
import sys
import time

# ---------------------------------------------------------------- parsing (no bpy needed) ----------

NUMBER = re.compile(r'^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?,?$')


class SceneError(Exception):
    pass


def tokenize(text, path):
    """Tokens with their line and column: '[' is dropped (the format ignores it), ']' kept."""
    tokens = []
    for lineno, line in enumerate(text.splitlines(), 1):
        for m in re.finditer(r'[^\s\[\]]+|\[|\]', line):
            tok = m.group(0)
            if tok.startswith('#'):
                break
            if tok != '[':
                tokens.append((tok, path, lineno, m.start() + 1))
    return tokens


def mat_mul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]


def identity():
    return [[1.0 if i == j else 0.0 for j in range(4)] for i in range(4)]


def translate(x, y, z):
    m = identity()
    m[0][3], m[1][3], m[2][3] = x, y, z
    return m


def scale(x, y, z):
    m = identity()
    m[0][0], m[1][1], m[2][2] = x, y, z
    return m


def rotate(ax, ay, az, deg):
    n = math.sqrt(ax * ax + ay * ay + az * az)
    if n == 0:
        raise ValueError('rotate about a zero axis')
    x, y, z = ax / n, ay / n, az / n
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    t = 1 - c
    return [[t * x * x + c, t * x * y - s * z, t * x * z + s * y, 0],
            [t * x * y + s * z, t * y * y + c, t * y * z - s * x, 0],
            [t * x * z - s * y, t * y * z + s * x, t * z * z + c, 0],
            [0, 0, 0, 1]]


class Parser:
    def __init__(self, path):
        with open(path, encoding='utf-8', errors='replace') as f:
            self.toks = tokenize(f.read(), path)
        self.i = 0
        self.path = path
        self.camera = {'eye': (0.0, 0.0, 1.0), 'dir': (0.0, 0.0, -1.0), 'focus': None,
                       'up': (0.0, 1.0, 0.0), 'angle': 60.0}
        self.background = (0.0, 0.0, 0.0)
        self.lights = []
        self.graphs = {}

    def fail(self, tok, msg):
        if tok is None:
            raise SceneError(f'{self.path}: error: {msg} (at end of file)')
        raise SceneError(f'{tok[1]}:{tok[2]}:{tok[3]}: error: {msg}')

    def next(self):
        if self.i >= len(self.toks):
            self.fail(None, 'unexpected end of file')
        tok = self.toks[self.i]
        self.i += 1
        return tok

    def num(self):
        tok = self.next()
        if not NUMBER.match(tok[0]):
            self.fail(tok, f"expected a number, found '{tok[0]}'")
        return float(tok[0].rstrip(','))

    def nums(self, n):
        return tuple(self.num() for _ in range(n))

    def parse(self):
        while self.i < len(self.toks):
            tok = self.next()
            w = tok[0]
            if w == 'background':
                self.block(tok, {'color': lambda: setattr(self, 'background', self.nums(3))})
            elif w == 'camera':
                cam = self.camera
                self.block(tok, {
                    'eye': lambda: cam.__setitem__('eye', self.nums(3)),
                    'look': lambda: (cam.__setitem__('dir', self.nums(3)), cam.__setitem__('focus', None)),
                    'focus': lambda: cam.__setitem__('focus', self.nums(3)),
                    'up': lambda: cam.__setitem__('up', self.nums(3)),
                    'angle': lambda: cam.__setitem__('angle', self.num()),
                    'near-far': lambda: self.nums(2)})
            elif w == 'light':
                light = {'type': 'point'}
                def light_type():
                    light['type'] = self.next()[0]
                def ambient():
                    self.nums(3)
                    light['ambient_only'] = light.get('ambient_only', True)
                def other(n):
                    return lambda: (self.nums(n), light.__setitem__('ambient_only', False))
                self.block(tok, {'type': lambda: (light_type(), light.__setitem__('ambient_only', False)),
                                 'position': other(3), 'direction': other(3), 'color': other(3),
                                 'function': other(3), 'aperture': other(1), 'exponent': other(1),
                                 'radius': other(1), 'angle': other(1), 'ambient': ambient})
                light['at'] = tok
                self.lights.append(light)
            elif w == 'mastersubgraph':
                name = self.next()
                if name[0] in self.graphs:
                    self.fail(name, f"duplicate mastersubgraph '{name[0]}'")
                self.graphs[name[0]] = self.graph()
            else:
                self.fail(tok, f"unknown keyword '{w}' at top level")
        if 'root' not in self.graphs:
            raise SceneError(f'{self.path}: error: no mastersubgraph named root')
        return self

    def block(self, opener, handlers):
        while True:
            tok = self.next()
            if tok[0] == ']':
                return
            h = handlers.get(tok[0])
            if h is None:
                self.fail(tok, f"unknown keyword '{tok[0]}' in a {opener[0]} block")
            h()

    def graph(self):
        """A mastersubgraph: a list of (matrix, [objects], [subgraph names]) for its trans blocks."""
        trans_list = []
        while True:
            tok = self.next()
            if tok[0] == ']':
                return trans_list
            if tok[0] != 'trans':
                self.fail(tok, f"expected 'trans' or ']' in a mastersubgraph, found '{tok[0]}'")
            m, objects, subgraphs = identity(), [], []
            while True:
                t = self.next()
                w = t[0]
                if w == ']':
                    break
                if w == 'translate':
                    m = mat_mul(m, translate(*self.nums(3)))
                elif w == 'scale':
                    m = mat_mul(m, scale(*self.nums(3)))
                elif w == 'rotate':
                    try:
                        m = mat_mul(m, rotate(*self.nums(4)))
                    except ValueError as e:
                        self.fail(t, str(e))
                elif w in ('matrixRC', 'matrixCR'):
                    v = self.nums(16)
                    g = [[v[4 * r + c] if w == 'matrixRC' else v[4 * c + r] for c in range(4)] for r in range(4)]
                    if g[3] != [0.0, 0.0, 0.0, 1.0]:
                        self.fail(t, f"'{w}' is not an affine transform: its last row must be 0 0 0 1")
                    m = mat_mul(m, g)
                elif w == 'object':
                    objects.append(self.shape())
                elif w == 'subgraph':
                    subgraphs.append(self.next())
                else:
                    self.fail(t, f"unknown keyword '{w}' in a trans block")
            trans_list.append((m, objects, subgraphs))

    def shape(self):
        kind = self.next()
        if kind[0] not in ('cube', 'cylinder', 'cone', 'sphere'):
            self.fail(kind, f"object type '{kind[0]}' is not converted (cube, cylinder, cone, sphere)")
        mat = {'diffuse': (1.0, 1.0, 1.0), 'emit': (0.0, 0.0, 0.0)}
        def setter(key, n):
            return lambda: mat.__setitem__(key, self.nums(n) if n > 1 else self.num())
        handlers = {k: setter(k, 3) for k in ('ambient', 'diffuse', 'specular', 'reflect', 'transparent', 'emit')}
        handlers.update({k: setter(k, 1) for k in ('shine', 'ior', 'gloss')})
        handlers['texture'] = lambda: self.fail(kind, "'texture' is not converted to Cycles")
        self.block(kind, handlers)
        for k in ('specular', 'reflect'):
            if any(mat.get(k, (0, 0, 0))):
                self.fail(kind, f"'{k}' is not converted to Cycles (only diffuse, emit and ideal glass)")
        glass = None
        if any(mat.get('transparent', (0, 0, 0))):
            # Ideal glass alone (§9.2's delta refraction, no Fresnel term): Cycles' sharp Refraction BSDF.
            if any(mat['diffuse']) or mat.get('gloss', 0) > 0 or max(mat['transparent']) > 1:
                self.fail(kind, "'transparent' is converted only as ideal glass: diffuse 0 0 0, no gloss, at most 1")
            glass = (tuple(mat['transparent']), float(mat.get('ior', 1.0)))
        d = mat['diffuse']
        if max(d) > 1:  # §9.2: a surface never creates energy
            d = tuple(c / max(d) for c in d)
        return {'type': kind[0], 'diffuse': d, 'emit': mat['emit'], 'glass': glass}

    def instances(self):
        """Every drawn shape with its object->world matrix (§3), following subgraphs from root."""
        out = []
        def walk(name, world, stack, at):
            if name not in self.graphs:
                self.fail(at, f"subgraph '{name}' is never defined")
            if name in stack:
                self.fail(at, 'cycle of subgraphs: ' + ' -> '.join(stack + [name]))
            for m, objects, subgraphs in self.graphs[name]:
                w = mat_mul(world, m)
                for o in objects:
                    out.append((w, o))
                for s in subgraphs:
                    walk(s[0], w, stack + [name], s)
        walk('root', identity(), [], None)
        return out

    def camera_frame(self):
        """eye, unit view direction, unit up (orthonormalised), vertical field of view in degrees."""
        c = self.camera
        eye = c['eye']
        d = tuple(f - e for f, e in zip(c['focus'], eye)) if c['focus'] is not None else c['dir']
        d = normalise(d)
        up = c['up']
        k = sum(u * v for u, v in zip(up, d))
        up = normalise(tuple(u - k * v for u, v in zip(up, d)))
        return eye, d, up, c['angle']


def normalise(v):
    n = math.sqrt(sum(x * x for x in v))
    if n == 0:
        raise SceneError('zero-length camera direction or up parallel to it')
    return tuple(x / n for x in v)


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


# ---------------------------------------------------------------- Blender side -------------------

def unit_meshes(bpy, segments):
    """One mesh per shape type, built once and shared by every object of that type (instancing)."""
    import bmesh
    from mathutils import Matrix
    to_y_up = Matrix.Rotation(-math.pi / 2, 4, 'X')  # Blender's primitives stand along +Z; ours along +Y
    meshes = {}
    for kind in ('cube', 'cylinder', 'cone', 'sphere'):
        bm = bmesh.new()
        if kind == 'cube':
            bmesh.ops.create_cube(bm, size=1.0)
        elif kind == 'sphere':
            bmesh.ops.create_uvsphere(bm, u_segments=segments, v_segments=segments // 2, radius=0.5)
        elif kind == 'cylinder':
            bmesh.ops.create_cone(bm, cap_ends=True, cap_tris=False, segments=segments,
                                  radius1=0.5, radius2=0.5, depth=1.0, matrix=to_y_up)
        else:
            bmesh.ops.create_cone(bm, cap_ends=True, cap_tris=False, segments=segments,
                                  radius1=0.5, radius2=0.0, depth=1.0, matrix=to_y_up)
        mesh = bpy.data.meshes.new('unit_' + kind)
        bm.to_mesh(mesh)
        bm.free()
        if kind != 'cube':
            for p in mesh.polygons:
                p.use_smooth = True
            if hasattr(mesh, 'use_auto_smooth'):  # Blender < 4.1: keeps the caps' edges sharp
                mesh.use_auto_smooth = True
                mesh.auto_smooth_angle = math.radians(30)
        if kind == 'cone':
            cone_normals(mesh)
        mesh.materials.append(None)  # one slot; each object links its own material into it
        meshes[kind] = mesh
    return meshes


def cone_normals(mesh):
    """The exact normals of the cone's side, (cos phi, 1/2, sin phi) normalised, on every corner.

    Smooth shading would average the faces around the apex into a normal pointing straight up, a
    wrong shading across the top of every cone; the apex corner of each side face gets the normal
    at the face's own angle instead. The base keeps its flat normal (0, -1, 0)."""
    normals = []
    for poly in mesh.polygons:
        flat_base = poly.normal.y < -0.99
        centre_phi = math.atan2(poly.center.z, poly.center.x)
        for li in poly.loop_indices:
            if flat_base:
                normals.append((0.0, -1.0, 0.0))
                continue
            v = mesh.vertices[mesh.loops[li].vertex_index].co
            phi = math.atan2(v.z, v.x) if v.x * v.x + v.z * v.z > 1e-12 else centre_phi
            n = (math.cos(phi), 0.5, math.sin(phi))
            k = math.sqrt(sum(c * c for c in n))
            normals.append(tuple(c / k for c in n))
    mesh.normals_split_custom_set(normals)


def material(bpy, cache, diffuse, emit, glass=None):
    key = (tuple(diffuse), tuple(emit), glass)
    if key in cache:
        return cache[key]
    mat = bpy.data.materials.new(f'mat{len(cache)}')
    mat.use_nodes = True
    nt = mat.node_tree
    for n in list(nt.nodes):
        nt.nodes.remove(n)
    out = nt.nodes.new('ShaderNodeOutputMaterial')
    if glass:
        bsdf = nt.nodes.new('ShaderNodeBsdfRefraction')
        bsdf.distribution = 'SHARP'
        bsdf.inputs['Color'].default_value = (*glass[0], 1.0)
        bsdf.inputs['IOR'].default_value = glass[1]
        bsdf.inputs['Roughness'].default_value = 0.0
    else:
        bsdf = nt.nodes.new('ShaderNodeBsdfDiffuse')
        bsdf.inputs['Color'].default_value = (*diffuse, 1.0)
        bsdf.inputs['Roughness'].default_value = 0.0
    shader = bsdf.outputs['BSDF']
    if any(emit):
        em = nt.nodes.new('ShaderNodeEmission')
        em.inputs['Color'].default_value = (*emit, 1.0)
        em.inputs['Strength'].default_value = 1.0
        add = nt.nodes.new('ShaderNodeAddShader')
        nt.links.new(shader, add.inputs[0])
        nt.links.new(em.outputs['Emission'], add.inputs[1])
        shader = add.outputs['Shader']
        if hasattr(mat.cycles, 'emission_sampling'):  # Blender >= 3.5
            mat.cycles.emission_sampling = 'BOTH'
        elif hasattr(mat.cycles, 'sample_as_light'):  # Blender 3.4: MIS on, the default
            mat.cycles.sample_as_light = True
    nt.links.new(shader, out.inputs['Surface'])
    cache[key] = mat
    return mat


def normals_material(bpy):
    """Emission 0.5 * (N + 1) with N the (smooth) normal: the image of `whitted --mode normals`."""
    mat = bpy.data.materials.new('normals')
    mat.use_nodes = True
    nt = mat.node_tree
    for n in list(nt.nodes):
        nt.nodes.remove(n)
    geo = nt.nodes.new('ShaderNodeNewGeometry')
    half = nt.nodes.new('ShaderNodeVectorMath')
    half.operation = 'MULTIPLY_ADD'
    half.inputs[1].default_value = (0.5, 0.5, 0.5)
    half.inputs[2].default_value = (0.5, 0.5, 0.5)
    em = nt.nodes.new('ShaderNodeEmission')
    out = nt.nodes.new('ShaderNodeOutputMaterial')
    nt.links.new(geo.outputs['Normal'], half.inputs[0])
    nt.links.new(half.outputs['Vector'], em.inputs['Color'])
    nt.links.new(em.outputs['Emission'], out.inputs['Surface'])
    return mat


def set_if(obj, name, value):
    if hasattr(obj, name):
        setattr(obj, name, value)


def build_and_render(args):
    import bpy
    from mathutils import Matrix
    scene_file = Parser(args.scene).parse()
    for light in scene_file.lights:
        if not light.get('ambient_only', True):
            scene_file.fail(light['at'], f"{light['type']} lights are not converted (only emissive shapes)")

    # An empty scene: factory startup has a cube, a light and a camera.
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj, do_unlink=True)
    scene = bpy.context.scene

    meshes = unit_meshes(bpy, args.segments)
    mats = {}
    normals = normals_material(bpy) if args.normals else None
    for n, (m, shape) in enumerate(scene_file.instances()):
        obj = bpy.data.objects.new(f'{shape["type"]}{n}', meshes[shape['type']])
        obj.matrix_world = Matrix(m)
        scene.collection.objects.link(obj)
        # The mesh is shared, so the material goes on the object's slot.
        obj.material_slots[0].link = 'OBJECT'
        obj.material_slots[0].material = normals or material(bpy, mats, shape['diffuse'], shape['emit'], shape['glass'])

    eye, d, up, angle = scene_file.camera_frame()
    right = cross(d, up)
    cam_data = bpy.data.cameras.new('camera')
    cam_data.sensor_fit = 'VERTICAL'
    cam_data.angle_y = math.radians(angle)
    cam_data.clip_start = 1e-4
    cam_data.clip_end = 1e6
    cam = bpy.data.objects.new('camera', cam_data)
    # A Blender camera looks down its local -Z with +Y up: columns right, up, -view, eye.
    cam.matrix_world = Matrix([[right[i], up[i], -d[i], eye[i]] for i in range(3)] + [[0, 0, 0, 1]])
    scene.collection.objects.link(cam)
    scene.camera = cam

    world = bpy.data.worlds.new('world')
    world.use_nodes = True
    bg = world.node_tree.nodes['Background']
    bg.inputs['Color'].default_value = (0, 0, 0, 1) if args.normals else (*scene_file.background, 1.0)
    bg.inputs['Strength'].default_value = 1.0
    scene.world = world

    r = scene.render
    r.engine = 'CYCLES'
    r.resolution_x, r.resolution_y, r.resolution_percentage = args.width, args.height, 100
    r.threads_mode = 'FIXED'
    r.threads = args.threads
    r.use_persistent_data = False
    r.film_transparent = False
    r.image_settings.file_format = 'OPEN_EXR'
    r.image_settings.color_depth = '32'
    r.image_settings.color_mode = 'RGB'
    r.image_settings.exr_codec = 'ZIP'
    r.filepath = args.output
    r.use_file_extension = False
    vs = scene.view_settings
    vs.view_transform = 'Standard'
    vs.look = 'None'
    vs.exposure = 0.0
    vs.gamma = 1.0
    scene.display_settings.display_device = 'sRGB'

    c = scene.cycles
    c.device = 'CPU'
    c.samples = args.spp
    c.use_adaptive_sampling = False
    c.use_denoising = False
    set_if(c, 'use_preview_denoising', False)
    c.seed = args.seed
    c.use_animated_seed = False
    c.sample_clamp_direct = 0.0
    c.sample_clamp_indirect = 0.0
    c.blur_glossy = 0.0
    c.caustics_reflective = True
    c.caustics_refractive = True
    set_if(c, 'use_light_tree', False)
    c.light_sampling_threshold = 0.0  # else lights below 1% of the total are skipped (a bias)
    # whitted's --max-depth 1 is direct light only, which is Cycles' 0 bounces.
    bounces = max(args.max_depth - 1, 0)
    c.max_bounces = bounces
    for kind in ('diffuse_bounces', 'glossy_bounces', 'transmission_bounces', 'volume_bounces',
                 'transparent_max_bounces'):
        setattr(c, kind, bounces)
    c.pixel_filter_type = 'BOX'
    c.filter_width = 0.01 if args.normals else 1.0  # --normals: every sample through the pixel centre
    c.film_exposure = 1.0
    set_if(c, 'use_auto_tile', False)
    scene.view_layers[0].use_pass_combined = True

    if args.save_blend:
        bpy.ops.wm.save_as_mainfile(filepath=args.save_blend)
    t0 = time.perf_counter()
    bpy.ops.render.render(write_still=True)
    print(f'cycles_render_seconds {time.perf_counter() - t0:.3f}', flush=True)


def main(argv):
    import argparse
    ap = argparse.ArgumentParser(prog='sc_to_blender.py')
    ap.add_argument('scene')
    ap.add_argument('-o', '--output', required=True)
    ap.add_argument('--width', type=int, default=256)
    ap.add_argument('--height', type=int, default=256)
    ap.add_argument('--spp', type=int, default=64)
    ap.add_argument('--max-depth', type=int, default=64)
    ap.add_argument('--threads', type=int, default=2)
    ap.add_argument('--seed', type=int, default=0)
    ap.add_argument('--segments', type=int, default=128)
    ap.add_argument('--save-blend')
    ap.add_argument('--normals', action='store_true',
                    help='a geometry check: every shape shows 0.5 (N + 1), rays through pixel centres, '
                         'as `whitted --mode normals` renders it')
    ap.add_argument('--parse-only', action='store_true', help='print the shapes and camera, no Blender')
    args = ap.parse_args(argv)
    try:
        if args.parse_only:
            p = Parser(args.scene).parse()
            print('camera', p.camera_frame(), 'background', p.background)
            for m, shape in p.instances():
                print(shape, [[round(x, 6) for x in row] for row in m])
            return 0
        build_and_render(args)
    except SceneError as e:
        print(e, file=sys.stderr)
        return 1
    return 0


if __name__ == '__main__':
    argv = sys.argv[sys.argv.index('--') + 1:] if '--' in sys.argv else sys.argv[1:]
    code = main(argv)
    if code:
        sys.exit(code)
