# Renders one NFF scene (the SPD subset, ../shared/docs/spd-spec.md) with Blender's Cycles on the
# CPU, for raygate's blender-cycles adapter (adapters/blender-cycles.json).
#
#   blender -b --factory-startup -t 1 --python nff_cycles.py -- SCENE.nff OUT.exr \
#       --seed S --spp N [--width W --height H] [--light-scale F] [--bounces B]
#
# Writes linear float RGB OpenEXR (no view transform, no denoiser, no adaptive sampling), so
# raygate's Monte Carlo image check sees the radiance Cycles estimated from exactly N samples
# drawn with seed S. Bad input exits 2 with FILE:LINE: message on stderr.
import argparse
import math
import sys

import bpy
import mathutils

# What a commit of this script may change on purpose: bench/blender-cycles makes a "3% dimmer
# light" commit by editing this one number.
DEFAULT_LIGHT_SCALE = 1.0


class NffError(Exception):
    pass


class Scene:
    """What the NFF file says, before any Blender object exists."""

    def __init__(self):
        self.eye = (0.0, 0.0, 0.0)
        self.at = (0.0, 0.0, -1.0)
        self.up = (0.0, 1.0, 0.0)
        self.angle_deg = 45.0
        self.hither = 1e-3
        self.resolution = (256, 256)
        self.background = (0.0, 0.0, 0.0)
        self.lights = []       # (position, colour)
        self.materials = []    # (colour, kd, ks, shine, transmittance, ior)
        self.spheres = []      # (centre, radius, material index)
        self.cones = []        # (base, base radius, apex, apex radius, material index)
        self.polygons = []     # ([points], [normals] or None, material index)


def tokenize(path):
    """(text, line) for every word; '#' comments run to the end of the line."""
    tokens = []
    with open(path, encoding="utf-8") as f:
        for number, text in enumerate(f, start=1):
            for word in text.split("#", 1)[0].split():
                tokens.append((word, number))
    return tokens


class Reader:
    def __init__(self, path):
        self.path = path
        self.tokens = tokenize(path)
        self.next = 0
        self.scene = Scene()

    def fail(self, line, what):
        raise NffError(f"{self.path}:{line}: {what}")

    def number(self, what):
        if self.next >= len(self.tokens):
            self.fail(self.tokens[-1][1] if self.tokens else 1, f"expected {what}, found the end of the file")
        text, line = self.tokens[self.next]
        self.next += 1
        try:
            value = float(text)
        except ValueError:
            self.fail(line, f"expected {what}, found '{text}'")
        if not math.isfinite(value):
            self.fail(line, f"expected {what}, found '{text}'")
        return value

    def vec(self, what):
        return (self.number(what), self.number(what), self.number(what))

    def count(self, what, minimum):
        line = self.tokens[self.next][1] if self.next < len(self.tokens) else 1
        value = self.number(what)
        if value != int(value) or value < minimum:
            self.fail(line, f"{what} must be a whole number of at least {minimum}")
        return int(value)

    def material(self):
        # Shapes before the first `f` are white and diffuse.
        if not self.scene.materials:
            self.scene.materials.append(((1.0, 1.0, 1.0), 1.0, 0.0, 0.0, 0.0, 1.0))
        return len(self.scene.materials) - 1

    def entity(self, word, line):
        s = self.scene
        if word == "v":
            return
        if word == "from":
            s.eye = self.vec("a 'from' point")
        elif word == "at":
            s.at = self.vec("an 'at' point")
        elif word == "up":
            s.up = self.vec("an 'up' vector")
        elif word == "angle":
            s.angle_deg = self.number("an angle in degrees")
        elif word == "hither":
            s.hither = self.number("a hither distance")
        elif word == "resolution":
            s.resolution = (self.count("a width", 1), self.count("a height", 1))
        elif word == "b":
            s.background = self.vec("a background colour")
        elif word == "l":
            position = self.vec("a light position")
            colour = (1.0, 1.0, 1.0)
            if self.next < len(self.tokens) and self.tokens[self.next][1] == line:
                colour = self.vec("a light colour")
            s.lights.append((position, colour))
        elif word == "f":
            colour = self.vec("a colour")
            values = [self.number(w) for w in ("Kd", "Ks", "Shine", "T", "an index of refraction")]
            s.materials.append((colour, *values))
        elif word == "s":
            centre = self.vec("a sphere centre")
            s.spheres.append((centre, abs(self.number("a sphere radius")), self.material()))
        elif word == "c":
            base = self.vec("a cone base point")
            base_r = abs(self.number("a cone base radius"))
            apex = self.vec("a cone apex point")
            apex_r = abs(self.number("a cone apex radius"))
            s.cones.append((base, base_r, apex, apex_r, self.material()))
        elif word in ("p", "pp"):
            n = self.count("a vertex count", 3)
            points, normals = [], []
            for _ in range(n):
                points.append(self.vec("a vertex"))
                if word == "pp":
                    normals.append(self.vec("a vertex normal"))
            s.polygons.append((points, normals or None, self.material()))
        else:
            self.fail(line, f"unknown NFF entity '{word}'")

    def read(self):
        while self.next < len(self.tokens):
            word, line = self.tokens[self.next]
            self.next += 1
            self.entity(word, line)
        s = self.scene
        if not (s.spheres or s.cones or s.polygons):
            self.fail(self.tokens[-1][1] if self.tokens else 1, "the scene has no shapes")
        return s


# ---- Blender side -------------------------------------------------------------------------

def empty_scene():
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj, do_unlink=True)
    return bpy.context.scene


def make_material(index, colour, kd, ks, shine, transmittance, ior):
    """Diffuse (colour x Kd) plus a glossy lobe (Ks, roughness from the Phong exponent), mixed
    with glass by T: the NFF material as a path tracer reads it."""
    mat = bpy.data.materials.new(f"nff{index}")
    mat.use_nodes = True
    nodes, links = mat.node_tree.nodes, mat.node_tree.links
    nodes.clear()
    out = nodes.new("ShaderNodeOutputMaterial")
    diffuse = nodes.new("ShaderNodeBsdfDiffuse")
    diffuse.inputs["Color"].default_value = (*[c * kd for c in colour], 1.0)
    glossy = nodes.new("ShaderNodeBsdfGlossy")
    glossy.inputs["Color"].default_value = (ks, ks, ks, 1.0)
    # A Phong exponent n has about the lobe width of a microfacet roughness alpha = sqrt(2/(n+2)).
    glossy.inputs["Roughness"].default_value = min(1.0, math.sqrt(2.0 / (max(shine, 0.0) + 2.0)))
    opaque = nodes.new("ShaderNodeAddShader")
    links.new(diffuse.outputs[0], opaque.inputs[0])
    links.new(glossy.outputs[0], opaque.inputs[1])
    surface = opaque.outputs[0]
    if transmittance > 0.0:
        glass = nodes.new("ShaderNodeBsdfGlass")
        glass.inputs["Color"].default_value = (1.0, 1.0, 1.0, 1.0)
        glass.inputs["IOR"].default_value = ior if ior > 0.0 else 1.0
        glass.inputs["Roughness"].default_value = 0.0
        mix = nodes.new("ShaderNodeMixShader")
        mix.inputs["Fac"].default_value = min(1.0, transmittance)
        links.new(surface, mix.inputs[1])
        links.new(glass.outputs[0], mix.inputs[2])
        surface = mix.outputs[0]
    links.new(surface, out.inputs["Surface"])
    return mat


def add_mesh(scene, name, vertices, faces, material, smooth=False, normals=None):
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata(vertices, [], faces)
    mesh.validate()
    mesh.materials.append(material)
    if smooth:
        mesh.polygons.foreach_set("use_smooth", [True] * len(mesh.polygons))
    if normals is not None:
        mesh.use_auto_smooth = True  # Blender 3.x needs it for custom normals to count
        mesh.normals_split_custom_set_from_vertices(normals)
    mesh.update()
    obj = bpy.data.objects.new(name, mesh)
    scene.collection.objects.link(obj)
    return obj


def unit_sphere(segments=32, rings=16):
    vertices = [(0.0, 0.0, 1.0)]
    for r in range(1, rings):
        theta = math.pi * r / rings
        for s in range(segments):
            phi = 2.0 * math.pi * s / segments
            vertices.append((math.sin(theta) * math.cos(phi), math.sin(theta) * math.sin(phi), math.cos(theta)))
    vertices.append((0.0, 0.0, -1.0))
    bottom = len(vertices) - 1
    faces = []
    ring = lambda r, s: 1 + (r - 1) * segments + s % segments
    for s in range(segments):
        faces.append((0, ring(1, s), ring(1, s + 1)))
        faces.append((bottom, ring(rings - 1, s + 1), ring(rings - 1, s)))
    for r in range(1, rings - 1):
        for s in range(segments):
            faces.append((ring(r, s), ring(r + 1, s), ring(r + 1, s + 1), ring(r, s + 1)))
    return vertices, faces


def cone_mesh(base, base_r, apex, apex_r, segments=32):
    """An open cone (no caps), as NFF's `c` is."""
    b, a = mathutils.Vector(base), mathutils.Vector(apex)
    axis = a - b
    if axis.length == 0.0:
        return None
    axis.normalize()
    u = axis.orthogonal().normalized()
    v = axis.cross(u)
    vertices = []
    for centre, radius in ((b, base_r), (a, apex_r)):
        for s in range(segments):
            phi = 2.0 * math.pi * s / segments
            vertices.append(tuple(centre + radius * (math.cos(phi) * u + math.sin(phi) * v)))
    faces = [(s, (s + 1) % segments, segments + (s + 1) % segments, segments + s) for s in range(segments)]
    return vertices, faces


def build_geometry(scene, nff, materials):
    sphere_vertices, sphere_faces = unit_sphere()
    for i, (centre, radius, m) in enumerate(nff.spheres):
        verts = [(centre[0] + radius * x, centre[1] + radius * y, centre[2] + radius * z) for x, y, z in sphere_vertices]
        add_mesh(scene, f"sphere{i}", verts, sphere_faces, materials[m], smooth=True)
    for i, (base, base_r, apex, apex_r, m) in enumerate(nff.cones):
        mesh = cone_mesh(base, base_r, apex, apex_r)
        if mesh:
            add_mesh(scene, f"cone{i}", mesh[0], mesh[1], materials[m], smooth=True)
    # Polygons in one mesh per material and per kind (flat / with vertex normals): SPD scenes
    # have thousands of them, and one Blender object each would take longer than the render.
    groups = {}
    for points, normals, m in nff.polygons:
        group = groups.setdefault((m, normals is not None), ([], [], []))
        start = len(group[0])
        group[0].extend(points)
        group[1].append(tuple(range(start, start + len(points))))
        if normals is not None:
            group[2].extend(normals)
    for (m, smooth), (verts, faces, normals) in groups.items():
        add_mesh(scene, f"polygons{m}{'s' if smooth else ''}", verts, faces, materials[m],
                 smooth=smooth, normals=normals if smooth else None)


def build_camera(scene, nff, width, height):
    eye, at, up = (mathutils.Vector(x) for x in (nff.eye, nff.at, nff.up))
    forward = (at - eye).normalized()
    right = forward.cross(up).normalized()
    true_up = right.cross(forward)
    camera = bpy.data.cameras.new("camera")
    camera.sensor_fit = "VERTICAL" if height >= width else "HORIZONTAL"
    camera.angle = math.radians(nff.angle_deg)  # NFF's angle spans the (square) image
    camera.clip_start = max(nff.hither, 1e-4)
    camera.clip_end = 1e6
    obj = bpy.data.objects.new("camera", camera)
    rotation = mathutils.Matrix((right, true_up, -forward)).transposed()  # columns: x, y, -view
    obj.matrix_world = mathutils.Matrix.Translation(eye) @ rotation.to_4x4()
    scene.collection.objects.link(obj)
    scene.camera = obj


def build_lights(scene, nff, light_scale):
    """NFF point lights do not fall off with distance; a Cycles point light does. Each light's
    power is set so that it gives the NFF colour as irradiance at the camera's target point,
    which keeps SPD scenes (lights far from or near the objects) equally bright."""
    at = mathutils.Vector(nff.at)
    for i, (position, colour) in enumerate(nff.lights):
        distance_sq = max((mathutils.Vector(position) - at).length_squared, 1e-6)
        light = bpy.data.lights.new(f"light{i}", type="POINT")
        light.color = colour
        light.energy = 4.0 * math.pi * distance_sq * light_scale  # W; irradiance P/(4 pi d^2)
        light.shadow_soft_size = 0.0
        obj = bpy.data.objects.new(f"light{i}", light)
        obj.location = position
        scene.collection.objects.link(obj)


def build_world(scene, nff):
    """The background colour is what missing rays see (camera and reflections), as in NFF, but
    it lights nothing diffusely: NFF scenes are lit by their lights only."""
    world = bpy.data.worlds.new("nff")
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Color"].default_value = (*nff.background, 1.0)
    world.cycles_visibility.diffuse = False
    world.cycles_visibility.scatter = False
    scene.world = world


def configure_render(scene, width, height, seed, spp, bounces, output):
    scene.render.engine = "CYCLES"
    cycles = scene.cycles
    cycles.device = "CPU"
    cycles.samples = spp
    cycles.seed = seed
    cycles.use_animated_seed = False
    cycles.use_adaptive_sampling = False  # exactly spp samples in every pixel
    cycles.use_denoising = False          # Debian's build has no OpenImageDenoise anyway
    cycles.max_bounces = bounces
    cycles.diffuse_bounces = bounces
    cycles.glossy_bounces = bounces
    cycles.transmission_bounces = bounces
    cycles.sample_clamp_direct = 0.0      # no clamping: clamping biases with noise
    cycles.sample_clamp_indirect = 0.0
    scene.view_layers[0].cycles.use_denoising = False
    scene.render.resolution_x = width
    scene.render.resolution_y = height
    scene.render.resolution_percentage = 100
    scene.render.use_persistent_data = False
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.render.film_transparent = False
    settings = scene.render.image_settings
    settings.file_format = "OPEN_EXR"
    settings.color_mode = "RGB"
    settings.color_depth = "32"
    settings.exr_codec = "ZIP"
    scene.render.filepath = output
    scene.render.use_file_extension = False


def parse_arguments(argv):
    parser = argparse.ArgumentParser(prog="nff_cycles.py", description="Render an NFF scene with Cycles.")
    parser.add_argument("scene")
    parser.add_argument("output", help="OpenEXR file to write (linear float RGB)")
    parser.add_argument("--seed", type=int, required=True, help="Cycles' seed, 0 to 2^31-1")
    parser.add_argument("--spp", type=int, default=16, help="samples per pixel")
    parser.add_argument("--width", type=int, help="image width (default: the scene's resolution)")
    parser.add_argument("--height", type=int, help="image height (default: the scene's resolution)")
    parser.add_argument("--bounces", type=int, default=4, help="maximum path depth")
    parser.add_argument("--light-scale", type=float, default=DEFAULT_LIGHT_SCALE,
                        help="multiplies every light's power (default %(default)s)")
    args = parser.parse_args(argv)
    if not 0 <= args.seed <= 2**31 - 1:
        parser.error("--seed must be 0 to 2147483647")
    if args.spp < 1 or args.bounces < 0 or args.light_scale < 0:
        parser.error("--spp must be at least 1, --bounces and --light-scale not negative")
    if (args.width is None) != (args.height is None) or (args.width is not None and min(args.width, args.height) < 1):
        parser.error("--width and --height go together and are at least 1")
    return args


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    args = parse_arguments(argv)
    try:
        nff = Reader(args.scene).read()
    except OSError as e:
        print(f"{args.scene}: cannot read the scene: {e.strerror}", file=sys.stderr)
        sys.exit(2)
    except NffError as e:
        print(e, file=sys.stderr)
        sys.exit(2)
    width, height = (args.width, args.height) if args.width else nff.resolution
    scene = empty_scene()
    materials = [make_material(i, *m) for i, m in enumerate(nff.materials)]
    build_geometry(scene, nff, materials)
    build_camera(scene, nff, width, height)
    build_lights(scene, nff, args.light_scale)
    build_world(scene, nff)
    configure_render(scene, width, height, args.seed, args.spp, args.bounces, args.output)
    bpy.ops.render.render(write_still=True)


if __name__ == "__main__":
    try:
        main()
    except SystemExit as e:
        # Blender's --python swallows sys.exit; leave with the status the script chose.
        import os
        sys.stdout.flush()
        sys.stderr.flush()
        os._exit(e.code if isinstance(e.code, int) else 2)
    except Exception as e:  # a Blender error (render failed): "could not measure"
        import os
        print(f"nff_cycles.py: {e}", file=sys.stderr)
        sys.stderr.flush()
        os._exit(3)
