#!/usr/bin/env python3
"""Writes facet's small glTF 2.0 scenes.

    python3 scripts/make_scenes.py

Two sets, each file self-contained (.gltf JSON, its buffer and its PNG
images embedded as base64 data URIs):

  assets/scenes/               feature models the tests render: sparse
                               accessors, sampler wraps, mipmapping (material
                               defaults, COLOR_0 and doubleSided are
                               scripts/make_material_scenes.py's)
  assets/                      the course tour, one scene per chapter

Units are meters, +y is up. Every scene has a perspective camera looking at
its content and KHR_lights_punctual lights; scenes[0].extras.description says
what the picture should show.

The output is deterministic: the same bytes on every run (JSON with sorted
keys, numbers written as the shortest decimal that reads back as the same
float32, PNGs compressed with zlib at level 9; a zlib other than the
reference one, e.g. zlib-ng, may compress the images to other bytes, which
decode to the same pixels). Only the Python 3 standard library is used.
"""

import base64
import json
import math
import os
import struct
import zlib

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MATERIALS_DIR = os.path.join(ROOT, "assets", "scenes")
ASSETS_DIR = os.path.join(ROOT, "assets")

# glTF 2.0 enumerations
UNSIGNED_BYTE, UNSIGNED_SHORT, UNSIGNED_INT, FLOAT = 5121, 5123, 5125, 5126
ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER = 34962, 34963
NEAREST, LINEAR, LINEAR_MIPMAP_LINEAR = 9728, 9729, 9987
NEAREST_MIPMAP_NEAREST, LINEAR_MIPMAP_NEAREST, NEAREST_MIPMAP_LINEAR = 9984, 9985, 9986
REPEAT, CLAMP_TO_EDGE, MIRRORED_REPEAT = 10497, 33071, 33648

COMPONENTS = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4}
PACK = {UNSIGNED_BYTE: "B", UNSIGNED_SHORT: "H", UNSIGNED_INT: "I", FLOAT: "f"}


# ---------------------------------------------------------------- numbers

def f32(x):
    """x rounded to the nearest float32, as a Python float."""
    return struct.unpack("<f", struct.pack("<f", x))[0]


def num(x):
    """x for the JSON: an int when whole, else the shortest decimal that
    reads back as the same float32 (what the renderer will hold)."""
    v = f32(x)
    if v == int(v) and abs(v) < 2 ** 24:
        return int(v)
    for digits in range(1, 10):
        shortest = float("%.*g" % (digits, v))
        if f32(shortest) == v:
            return shortest
    return v


def nums(values):
    return [num(v) for v in values]


# ---------------------------------------------------------------- vectors

def add(a, b):
    return tuple(x + y for x, y in zip(a, b))


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def mul(a, s):
    return tuple(x * s for x in a)


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def normalize(a):
    length = math.sqrt(dot(a, a))
    return mul(a, 1.0 / length)


def axis_angle(axis, degrees):
    """The rotation quaternion [x, y, z, w] about `axis` by `degrees`."""
    half = math.radians(degrees) / 2
    x, y, z = mul(normalize(axis), math.sin(half))
    return [x, y, z, math.cos(half)]


def quat_from_axes(x, y, z):
    """The quaternion of the rotation whose matrix has columns x, y, z."""
    m00, m01, m02 = x[0], y[0], z[0]
    m10, m11, m12 = x[1], y[1], z[1]
    m20, m21, m22 = x[2], y[2], z[2]
    trace = m00 + m11 + m22
    if trace > 0:
        s = 2 * math.sqrt(trace + 1)
        return [(m21 - m12) / s, (m02 - m20) / s, (m10 - m01) / s, s / 4]
    if m00 > m11 and m00 > m22:
        s = 2 * math.sqrt(1 + m00 - m11 - m22)
        return [s / 4, (m01 + m10) / s, (m02 + m20) / s, (m21 - m12) / s]
    if m11 > m22:
        s = 2 * math.sqrt(1 + m11 - m00 - m22)
        return [(m01 + m10) / s, s / 4, (m12 + m21) / s, (m02 - m20) / s]
    s = 2 * math.sqrt(1 + m22 - m00 - m11)
    return [(m02 + m20) / s, (m12 + m21) / s, s / 4, (m10 - m01) / s]


def look_at(eye, target, up=(0, 1, 0)):
    """The rotation that turns a glTF camera or light (which looks down its
    local -z with +y up) at `eye` towards `target`."""
    back = normalize(sub(eye, target))
    if abs(dot(back, normalize(up))) > 0.999:
        up = (0, 0, -1)
    right = normalize(cross(up, back))
    return quat_from_axes(right, cross(back, right), back)


# ---------------------------------------------------------------- meshes

class Mesh:
    """Vertex attributes (lists of tuples) and a triangle list, counter-
    clockwise seen from the side the normals point to."""

    def __init__(self, positions, normals, indices, uvs=None):
        self.positions, self.normals, self.indices, self.uvs = positions, normals, indices, uvs
        for t in range(0, len(indices), 3):
            a, b, c = (positions[i] for i in indices[t:t + 3])
            face = cross(sub(b, a), sub(c, a))
            vertex = add(add(normals[indices[t]], normals[indices[t + 1]]), normals[indices[t + 2]])
            assert dot(face, face) < 1e-12 or dot(face, vertex) > 0, "triangle %d winds against its normals" % (t // 3)


def quad_indices(a, b, c, d):
    """Two triangles of the quad a b c d, counter-clockwise."""
    return [a, b, c, a, c, d]


# Cube faces: outward normal and the face's "up" (the top of its texture).
# Its "right" is up x normal, so that each face is counter-clockwise from outside.
CUBE_FACES = [
    ("+x", (1, 0, 0), (0, 1, 0)),
    ("-x", (-1, 0, 0), (0, 1, 0)),
    ("+y", (0, 1, 0), (0, 0, -1)),
    ("-y", (0, -1, 0), (0, 0, 1)),
    ("+z", (0, 0, 1), (0, 1, 0)),
    ("-z", (0, 0, -1), (0, 1, 0)),
]


def cube(size=1.0, skip=()):
    """A cube centred on the origin, 4 vertices per face (per-face normals,
    each face textured 0..1 upright seen from outside); `skip` names faces
    left out, e.g. ("+y",) for an open box."""
    positions, normals, uvs, indices = [], [], [], []
    h = size / 2
    for name, n, up in CUBE_FACES:
        if name in skip:
            continue
        right = cross(up, n)
        first = len(positions)
        for du, dv, uv in ((-1, -1, (0, 1)), (1, -1, (1, 1)), (1, 1, (1, 0)), (-1, 1, (0, 0))):
            positions.append(add(mul(n, h), add(mul(right, du * h), mul(up, dv * h))))
            normals.append(n)
            uvs.append(uv)
        indices += quad_indices(first, first + 1, first + 2, first + 3)
    return Mesh(positions, normals, indices, uvs)


def quad(width, height, uv_min=(0, 0), uv_max=(1, 1)):
    """An upright quad in the xy plane, centred on the origin, facing +z;
    u runs left to right, v top to bottom (glTF's image orientation)."""
    w, h = width / 2, height / 2
    positions = [(-w, -h, 0), (w, -h, 0), (w, h, 0), (-w, h, 0)]
    (u0, v0), (u1, v1) = uv_min, uv_max
    uvs = [(u0, v1), (u1, v1), (u1, v0), (u0, v0)]
    return Mesh(positions, [(0, 0, 1)] * 4, quad_indices(0, 1, 2, 3), uvs)


def plane(width, depth, uv_repeat=1.0):
    """A ground quad in the xz plane at y = 0, facing +y; the texture's top
    lies towards -z, and it repeats `uv_repeat` times across."""
    w, d = width / 2, depth / 2
    positions = [(-w, 0, d), (w, 0, d), (w, 0, -d), (-w, 0, -d)]
    r = uv_repeat
    uvs = [(0, r), (r, r), (r, 0), (0, 0)]
    return Mesh(positions, [(0, 1, 0)] * 4, quad_indices(0, 1, 2, 3), uvs)


def grid_positions(columns, rows, spacing):
    """columns x rows vertices of a flat grid in the xz plane, centred on the
    origin, row by row from -z to +z."""
    x0, z0 = -(columns - 1) * spacing / 2, -(rows - 1) * spacing / 2
    return [(x0 + c * spacing, 0.0, z0 + r * spacing) for r in range(rows) for c in range(columns)]


def grid_indices(columns, rows):
    indices = []
    for r in range(rows - 1):
        for c in range(columns - 1):
            a = r * columns + c
            indices += quad_indices(a + columns, a + columns + 1, a + 1, a)  # facing +y
    return indices


def uv_sphere(radius, segments, rings):
    """A sphere of `segments` meridians and `rings` bands, smooth normals;
    u goes once around, v from the north pole (0) to the south pole (1)."""
    positions, normals, uvs, indices = [], [], [], []
    for i in range(rings + 1):
        theta = math.pi * i / rings
        for j in range(segments + 1):
            phi = 2 * math.pi * j / segments
            n = (math.sin(theta) * math.sin(phi), math.cos(theta), math.sin(theta) * math.cos(phi))
            positions.append(mul(n, radius))
            normals.append(n)
            uvs.append((j / segments, i / rings))
    for i in range(rings):
        for j in range(segments):
            a = i * (segments + 1) + j
            b = a + segments + 1
            if i > 0:
                indices += [a, b, a + 1]
            if i < rings - 1:
                indices += [a + 1, b, b + 1]
    return Mesh(positions, normals, indices, uvs)


def cylinder(radius, height, segments, caps=True):
    """An upright cylinder standing on y = 0, smooth sides; with `caps`, flat
    discs close it; without, it is an open tube."""
    positions, normals, uvs, indices = [], [], [], []
    for j in range(segments + 1):
        phi = 2 * math.pi * j / segments
        n = (math.sin(phi), 0, math.cos(phi))
        for y, v in ((0, 1), (height, 0)):
            positions.append((radius * n[0], y, radius * n[2]))
            normals.append(n)
            uvs.append((j / segments, v))
    for j in range(segments):
        a = 2 * j
        indices += quad_indices(a, a + 2, a + 3, a + 1)
    if caps:
        for y, ny in ((0, -1), (height, 1)):
            centre = len(positions)
            positions.append((0, y, 0))
            normals.append((0, ny, 0))
            uvs.append((0.5, 0.5))
            for j in range(segments):
                phi = 2 * math.pi * j / segments
                positions.append((radius * math.sin(phi), y, radius * math.cos(phi)))
                normals.append((0, ny, 0))
                uvs.append((0.5 + 0.5 * math.sin(phi), 0.5 - 0.5 * math.cos(phi)))
            for j in range(segments):
                a, b = centre + 1 + j, centre + 1 + (j + 1) % segments
                indices += [centre, a, b] if ny > 0 else [centre, b, a]
    return Mesh(positions, normals, indices, uvs)


def torus(major, minor, segments, sides):
    """A torus around the y axis: `segments` around the ring, `sides` around
    the tube, smooth normals."""
    positions, normals, uvs, indices = [], [], [], []
    for i in range(segments + 1):
        phi = 2 * math.pi * i / segments
        ring = (math.sin(phi), 0, math.cos(phi))
        for j in range(sides + 1):
            theta = 2 * math.pi * j / sides
            n = add(mul(ring, math.cos(theta)), (0, math.sin(theta), 0))
            positions.append(add(mul(ring, major), mul(n, minor)))
            normals.append(n)
            uvs.append((i / segments, j / sides))
    for i in range(segments):
        for j in range(sides):
            a = i * (sides + 1) + j
            b = a + sides + 1
            indices += quad_indices(a, b, b + 1, a + 1)
    return Mesh(positions, normals, indices, uvs)


def smooth_normals(positions, indices):
    """Area-weighted vertex normals of a triangle list."""
    sums = [(0.0, 0.0, 0.0)] * len(positions)
    for t in range(0, len(indices), 3):
        a, b, c = indices[t:t + 3]
        face = cross(sub(positions[b], positions[a]), sub(positions[c], positions[a]))
        for v in (a, b, c):
            sums[v] = add(sums[v], face)
    return [normalize(s) for s in sums]


# ---------------------------------------------------------------- PNG

def png(width, height, pixel, alpha=False):
    """An 8-bit RGB PNG of pixel(x, y) -> (r, g, b), or RGBA with `alpha`
    (pixel -> (r, g, b, a)), row 0 at the top."""
    raw = bytearray()
    for y in range(height):
        raw.append(0)  # filter: none
        for x in range(width):
            raw += bytes(pixel(x, y))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    colour_type = 6 if alpha else 2  # RGBA or RGB
    header = struct.pack(">IIBBBBB", width, height, 8, colour_type, 0, 0, 0)  # 8 bits, deflate, no filter, no interlace
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(bytes(raw), 9)) + chunk(b"IEND", b"")


def checker(size, square, dark, light):
    return lambda x, y: dark if (x // square + y // square) % 2 else light


# The letter F on a 5 x 7 cell raster (top row first): asymmetric under
# every flip and rotation, so it shows how a texture is oriented.
LETTER_F = ["#####", "#....", "#....", "####.", "#....", "#....", "#...."]


def letter_f(x, y, left, top, cell):
    """Whether texel (x, y) lies in an F whose top-left corner is (left, top)."""
    c, r = (x - left) // cell, (y - top) // cell
    return 0 <= r < len(LETTER_F) and 0 <= c < len(LETTER_F[0]) and LETTER_F[r][c] == "#"


def wrap_texture():
    """8 x 8 texels: a one-texel checker of two greys, texel column 0 red and
    row 0 (the top) yellow, so every wrap and mirror shows at the edges."""
    def pixel(x, y):
        if x == 0:
            return (220, 30, 30)
        if y == 0:
            return (240, 200, 30)
        return (40, 60, 120) if (x + y) % 2 else (235, 235, 235)
    return png(8, 8, pixel)


def brick_texture(size=64):
    """Red bricks (16 x 8 texels, every other row shifted by half a brick)
    in grey mortar, each brick a slightly different shade, and a cream
    letter F in the top-left corner."""
    def pixel(x, y):
        if letter_f(x, y, 4, 3, 3):
            return (250, 235, 190)
        row = y // 8
        shifted = x + (8 if row % 2 else 0)
        if y % 8 == 7 or shifted % 16 == 15:
            return (170, 165, 155)
        shade = ((row * 7 + (shifted // 16) * 13) % 5) * 9
        return (150 + shade, 55 + shade // 2, 40)
    return png(size, size, pixel)


# ---------------------------------------------------------------- document

class Gltf:
    """One glTF document being built: every add_* returns the new index."""

    def __init__(self, description):
        self.doc = {
            "asset": {"version": "2.0", "generator": "facet scenes"},
            "scene": 0,
            "scenes": [{"nodes": [], "extras": {"description": description}}],
        }
        self.buffer = bytearray()
        self.mesh_accessors = {}  # id(Mesh) -> its attributes and indices, written once

    def append(self, key, item):
        self.doc.setdefault(key, []).append(item)
        return len(self.doc[key]) - 1

    # -- buffer data

    def add_view(self, data, target=None):
        """A bufferView of `data`, starting on a 4-byte boundary of the buffer."""
        self.buffer += b"\0" * (-len(self.buffer) % 4)
        view = {"buffer": 0, "byteOffset": len(self.buffer), "byteLength": len(data)}
        if target is not None:
            view["target"] = target
        self.buffer += data
        return self.append("bufferViews", view)

    @staticmethod
    def pack(rows, component_type):
        flat = [v for row in rows for v in (row if isinstance(row, tuple) else (row,))]
        return struct.pack("<%d%s" % (len(flat), PACK[component_type]), *flat)

    def add_accessor(self, rows, kind, component_type=FLOAT, target=ARRAY_BUFFER, normalized=False, bounds=False):
        """An accessor of `rows` (tuples, or numbers for SCALAR) in a bufferView
        of its own; `bounds` adds min and max (required for POSITION)."""
        accessor = {
            "bufferView": self.add_view(self.pack(rows, component_type), target),
            "componentType": component_type,
            "count": len(rows),
            "type": kind,
        }
        if normalized:
            accessor["normalized"] = True
        if bounds:
            accessor["min"], accessor["max"] = self.bounds(rows)
        return self.append("accessors", accessor)

    @staticmethod
    def bounds(rows):
        """Per-component min and max of float32 rows, as float32 values."""
        columns = list(zip(*[tuple(f32(v) for v in row) for row in rows]))
        return [num(min(c)) for c in columns], [num(max(c)) for c in columns]

    def add_sparse_accessor(self, count, kind, component_type, base_rows, substitutes, index_type,
                            target=ARRAY_BUFFER, normalized=False, bounds=None):
        """A sparse accessor of `count` elements: its base is `base_rows` in a
        bufferView, or zeros when base_rows is None (no bufferView); then
        `substitutes` ({element: row}) replace elements. Its indices are
        stored as `index_type`, its values tightly packed; `bounds` are the
        rows after substitution, for min/max."""
        elements = sorted(substitutes)
        accessor = {
            "componentType": component_type,
            "count": count,
            "type": kind,
            "sparse": {
                "count": len(elements),
                "indices": {"bufferView": self.add_view(self.pack(elements, index_type)), "componentType": index_type},
                "values": {"bufferView": self.add_view(self.pack([substitutes[e] for e in elements], component_type))},
            },
        }
        if base_rows is not None:
            assert len(base_rows) == count
            accessor["bufferView"] = self.add_view(self.pack(base_rows, component_type), target)
        if normalized:
            accessor["normalized"] = True
        if bounds is not None:
            accessor["min"], accessor["max"] = self.bounds(bounds)
        return self.append("accessors", accessor)

    def add_indices(self, indices):
        component_type = UNSIGNED_SHORT if max(indices) < 65535 else UNSIGNED_INT
        return self.add_accessor(indices, "SCALAR", component_type, ELEMENT_ARRAY_BUFFER)

    # -- meshes

    def primitive(self, mesh, material, colors=None, tangents=None, uv1=None, texcoord0=True):
        """A primitive of `mesh` with `material`; the mesh's accessors are
        written the first time it is used and shared after. TEXCOORD_0 is
        written only for a material with a texture (and `texcoord0`); `colors`
        is a COLOR_0 accessor; `uv1` the rows of a TEXCOORD_1 of its own."""
        key = id(mesh)
        if key not in self.mesh_accessors:
            attributes = {
                "POSITION": self.add_accessor(mesh.positions, "VEC3", bounds=True),
                "NORMAL": self.add_accessor(mesh.normals, "VEC3"),
            }
            self.mesh_accessors[key] = (attributes, self.add_indices(mesh.indices), mesh)  # keeps mesh alive: id stays unique
        attributes, indices, _ = self.mesh_accessors[key]
        m = self.doc["materials"][material]
        textured = any(k in m["pbrMetallicRoughness"] for k in ("baseColorTexture", "metallicRoughnessTexture")) or \
            any(k in m for k in ("occlusionTexture", "emissiveTexture", "normalTexture"))
        if textured and texcoord0 and "TEXCOORD_0" not in attributes:
            attributes["TEXCOORD_0"] = self.add_accessor(mesh.uvs, "VEC2")
        primitive = {"attributes": dict(attributes), "indices": indices, "material": material}
        if not texcoord0:
            primitive["attributes"].pop("TEXCOORD_0", None)
        if uv1 is not None:
            primitive["attributes"]["TEXCOORD_1"] = self.add_accessor(uv1, "VEC2")
        if colors is not None:
            primitive["attributes"]["COLOR_0"] = colors
        if tangents is not None:
            primitive["attributes"]["TANGENT"] = self.add_accessor(tangents, "VEC4")
        return primitive

    def add_mesh(self, name, *primitives):
        return self.append("meshes", {"name": name, "primitives": list(primitives)})

    def add_material(self, name, color, metallic=None, roughness=None, texture=None, double_sided=None, emissive=None,
                     alpha_mode=None, alpha_cutoff=None, metallic_roughness=None, occlusion=None, emissive_texture=None,
                     normal=None, extensions=None):
        """A material; metallic, roughness, doubleSided, alphaMode and
        alphaCutoff left out when None (glTF's defaults: 1, 1, false, OPAQUE, 0.5).
        occlusion: (texture, strength); normal: (texture, scale)."""
        pbr = {"baseColorFactor": nums(color)}
        if metallic is not None:
            pbr["metallicFactor"] = num(metallic)
        if roughness is not None:
            pbr["roughnessFactor"] = num(roughness)
        if texture is not None:
            pbr["baseColorTexture"] = {"index": texture}
        if metallic_roughness is not None:
            pbr["metallicRoughnessTexture"] = {"index": metallic_roughness}
        material = {"name": name, "pbrMetallicRoughness": pbr}
        if occlusion is not None:
            material["occlusionTexture"] = {"index": occlusion[0], "strength": num(occlusion[1])}
        if emissive_texture is not None:
            material["emissiveTexture"] = {"index": emissive_texture}
        if normal is not None:
            material["normalTexture"] = {"index": normal[0], "scale": num(normal[1])}
        if double_sided is not None:
            material["doubleSided"] = double_sided
        if emissive is not None:
            material["emissiveFactor"] = nums(emissive)
        if alpha_mode is not None:
            material["alphaMode"] = alpha_mode
        if alpha_cutoff is not None:
            material["alphaCutoff"] = num(alpha_cutoff)
        if extensions is not None:  # e.g. KHR_materials_transmission, also listed in extensionsUsed
            material["extensions"] = extensions
            used = self.doc.setdefault("extensionsUsed", [])
            used += [name for name in sorted(extensions) if name not in used]
        return self.append("materials", material)

    def read_at(self, material, set_index, *keys):
        """Makes the named texture references of `material` read TEXCOORD_<set_index>."""
        m = self.doc["materials"][material]
        for key in keys:
            (m["pbrMetallicRoughness"] if key in ("baseColorTexture", "metallicRoughnessTexture") else m)[key]["texCoord"] = set_index
        return material

    # -- textures

    def add_texture(self, image, sampler):
        return self.append("textures", {"sampler": sampler, "source": image})

    def add_image(self, name, png_bytes):
        uri = "data:image/png;base64," + base64.b64encode(png_bytes).decode("ascii")
        return self.append("images", {"name": name, "mimeType": "image/png", "uri": uri})

    def add_sampler(self, mag, min_filter, wrap_s, wrap_t):
        return self.append("samplers", {"magFilter": mag, "minFilter": min_filter, "wrapS": wrap_s, "wrapT": wrap_t})

    # -- animations

    def add_animation(self, name, node, path, times, values, interpolation="LINEAR"):
        """One animation of one channel: `node`'s translation, rotation or
        scale at key `times` (seconds), `values` a tuple per key (three per
        key for CUBICSPLINE: in-tangent, value, out-tangent)."""
        kind = "VEC4" if path == "rotation" else "VEC3"
        times_accessor = self.add_accessor([(t,) for t in times], "SCALAR", target=None, bounds=True)
        values_accessor = self.add_accessor(values, kind, target=None)
        self.doc.setdefault("animations", []).append({
            "name": name,
            "samplers": [{"input": times_accessor, "output": values_accessor, "interpolation": interpolation}],
            "channels": [{"sampler": 0, "target": {"node": node, "path": path}}]})

    # -- nodes

    def add_node(self, name, mesh=None, translation=None, rotation=None, scale=None, parent=None, **extra):
        """A node; a root of the scene unless `parent` (a node index) is given."""
        node = {"name": name}
        if mesh is not None:
            node["mesh"] = mesh
        for key, value in (("translation", translation), ("rotation", rotation), ("scale", scale)):
            if value is not None:
                node[key] = nums(value)
        node.update(extra)
        index = self.append("nodes", node)
        if parent is None:
            self.doc["scenes"][0]["nodes"].append(index)
        else:
            self.doc["nodes"][parent].setdefault("children", []).append(index)
        return index

    def add_camera(self, name, eye, target, yfov_deg=45.0, znear=0.1, zfar=100.0):
        """A perspective camera node at `eye` looking at `target`."""
        camera = self.append("cameras", {"name": name, "type": "perspective", "perspective": {
            "yfov": num(math.radians(yfov_deg)), "znear": num(znear), "zfar": num(zfar)}})
        return self.add_node(name, translation=eye, rotation=look_at(eye, target), camera=camera)

    def add_orthographic_camera(self, name, eye, target, xmag, ymag, znear=0.1, zfar=100.0):
        camera = self.append("cameras", {"name": name, "type": "orthographic", "orthographic": {
            "xmag": num(xmag), "ymag": num(ymag), "znear": num(znear), "zfar": num(zfar)}})
        return self.add_node(name, translation=eye, rotation=look_at(eye, target), camera=camera)

    def add_light(self, name, kind, position, target=None, color=(1, 1, 1), intensity=1.0, inner_deg=None, outer_deg=None):
        """A KHR_lights_punctual light and its node: point lights shine from
        `position`, directional and spot lights from `position` towards
        `target`. Point and spot intensities are candela (facet: I / d^2),
        directional ones lux."""
        extension = self.doc.setdefault("extensions", {}).setdefault("KHR_lights_punctual", {"lights": []})
        light = {"name": name, "type": kind, "color": nums(color), "intensity": num(intensity)}
        if kind == "spot":
            light["spot"] = {"innerConeAngle": num(math.radians(inner_deg)), "outerConeAngle": num(math.radians(outer_deg))}
        extension["lights"].append(light)
        used = self.doc.setdefault("extensionsUsed", [])
        if "KHR_lights_punctual" not in used:
            used.append("KHR_lights_punctual")
        rotation = look_at(position, target) if target is not None else None
        return self.add_node(name, translation=position, rotation=rotation,
                             extensions={"KHR_lights_punctual": {"light": len(extension["lights"]) - 1}})

    # -- output

    def write(self, path):
        self.buffer += b"\0" * (-len(self.buffer) % 4)
        self.doc["buffers"] = [{"byteLength": len(self.buffer),
                                "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(self.buffer)).decode("ascii")}]
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w", encoding="ascii", newline="\n") as out:
            out.write(json.dumps(self.doc, indent=1, sort_keys=True) + "\n")
        print("%-45s %7d bytes" % (os.path.relpath(path, ROOT), os.path.getsize(path)))


# Shared materials and set pieces

GREY_GROUND = ((0.5, 0.5, 0.5, 1), 0.0, 0.8)


def add_ground(g, width=8.0, depth=8.0, translation=None, name="ground", color=GREY_GROUND):
    base, metallic, roughness = color
    material = g.add_material(name, base, metallic, roughness)
    return g.add_node(name, g.add_mesh(name, g.primitive(plane(width, depth), material)), translation=translation)


# ---------------------------------------------------------------- A. feature models

def sparse():
    g = Gltf("Two patches on a grey ground. Left: a 5x5-vertex grid, 2 m across, with a bump in its middle "
             "(centre vertex 0.6 m up, its 8 neighbours 0.25 m), smooth normals, an undistorted 4x4 checker "
             "(cream and grey, one square per grid cell) and vertex colours: corners red (back left), green "
             "(back right), blue (front left), yellow (front right), centre magenta, white elsewhere. "
             "Right: a flat 1.6 m blue square of 8 triangles. Everything comes from sparse accessors; "
             "see the accessors' extras for what reading the sparse parts wrongly shows.")
    columns = rows = 5
    flat = grid_positions(columns, rows, 0.5)
    lift = {12: 0.6}
    for v in (6, 7, 8, 11, 13, 16, 17, 18):
        lift[v] = 0.25
    bumped = [add(p, (0, lift.get(v, 0.0), 0)) for v, p in enumerate(flat)]
    indices = grid_indices(columns, rows)
    normals = smooth_normals(bumped, indices)
    uvs = [(c / (columns - 1), r / (rows - 1)) for r in range(rows) for c in range(columns)]
    inner = [v for v in range(columns * rows) if 0 < v % columns < columns - 1 and 0 < v // columns < rows - 1]

    position = g.add_sparse_accessor(
        len(flat), "VEC3", FLOAT, flat, {v: bumped[v] for v in lift}, UNSIGNED_BYTE, bounds=bumped)
    normal = g.add_sparse_accessor(
        len(flat), "VEC3", FLOAT, None, dict(enumerate(normals)), UNSIGNED_SHORT)
    texcoord = g.add_sparse_accessor(
        len(flat), "VEC2", FLOAT, [(0.0, 0.0) if v in inner else uv for v, uv in enumerate(uvs)],
        {v: uvs[v] for v in inner}, UNSIGNED_INT)
    color = g.add_sparse_accessor(
        len(flat), "VEC4", UNSIGNED_BYTE, [(255, 255, 255, 255)] * len(flat),
        {0: (255, 0, 0, 255), 4: (0, 255, 0, 255), 12: (255, 0, 255, 255), 20: (0, 0, 255, 255), 24: (255, 255, 0, 255)},
        UNSIGNED_BYTE, normalized=True)
    g.doc["accessors"][position]["extras"] = {"expected": "flat base grid; the sparse values lift the centre vertex 12 by "
                                              "0.6 m and vertices 6 7 8 11 13 16 17 18 by 0.25 m (a bump). Unread: flat."}
    g.doc["accessors"][normal]["extras"] = {"expected": "no bufferView: a base of zeros; the sparse values give all 25 "
                                            "normals. Unread: zero normals."}
    g.doc["accessors"][texcoord]["extras"] = {"expected": "the base holds (0, 0) for the 9 inner vertices; the sparse "
                                              "values put them on the regular grid. Unread: the checker collapses to "
                                              "the top-left corner in the middle."}
    g.doc["accessors"][color]["extras"] = {"expected": "base all white; sparse values colour vertices 0 red, 4 green, "
                                           "12 magenta, 20 blue, 24 yellow. Unread: all white."}

    # The second primitive: a 3x3-vertex square whose index list is sparse.
    patch = grid_positions(3, 3, 0.8)
    patch_indices = grid_indices(3, 3)
    broken = patch_indices[:12] + [0] * 12  # the last 4 triangles degenerate in the base
    patch_position = g.add_accessor([add(p, (2.4, 0, 0)) for p in patch], "VEC3", bounds=True)
    patch_normal = g.add_accessor([(0.0, 1.0, 0.0)] * len(patch), "VEC3")
    patch_index = g.add_sparse_accessor(
        len(broken), "SCALAR", UNSIGNED_BYTE, broken, {i: patch_indices[i] for i in range(12, 24)}, UNSIGNED_BYTE,
        target=ELEMENT_ARRAY_BUFFER)
    g.doc["accessors"][patch_index]["extras"] = {"expected": "the base's last 4 triangles are 0 0 0 (degenerate); the "
                                                 "sparse values replace indices 12..23 with the right ones. Unread: "
                                                 "only the back half of the square is drawn."}

    checker_image = g.add_image("checker 16x16", png(16, 16, checker(16, 4, (150, 150, 150), (245, 235, 210))))
    textured = g.add_material("white, checker", (1, 1, 1, 1), 0.0, 0.7,
                              texture=g.add_texture(checker_image, g.add_sampler(NEAREST, NEAREST, REPEAT, REPEAT)))
    blue = g.add_material("blue", (0.15, 0.3, 0.8, 1), 0.0, 0.6)
    mesh = g.add_mesh("sparse patches",
                      {"attributes": {"POSITION": position, "NORMAL": normal, "TEXCOORD_0": texcoord, "COLOR_0": color},
                       "indices": g.add_indices(indices), "material": textured},
                      {"attributes": {"POSITION": patch_position, "NORMAL": patch_normal},
                       "indices": patch_index, "material": blue})
    g.add_node("sparse patches", mesh, translation=(-1.2, 0.05, 0))
    add_ground(g, 8, 6)
    g.add_camera("camera", (-0.2, 2.3, 4.4), (-0.2, 0.1, 0.1))
    g.add_light("key", "spot", (-3.6, 2.2, 1.2), (-0.4, 0, 0), intensity=16, inner_deg=35, outer_deg=50)
    return g


def textured_wraps():
    g = Gltf("Three quads with the same 8x8 texture (a one-texel checker of white and dark blue, texel column 0 "
             "red, row 0 yellow) and texture coordinates from -1 to 2. Left: REPEAT, NEAREST: 3x3 tiles, sharp "
             "texels. Middle: CLAMP_TO_EDGE, LINEAR: one tile in the middle, its edge texels smeared outwards "
             "(red band on the left, yellow band at the top). Right: MIRRORED_REPEAT, LINEAR: 3x3 tiles, every "
             "other one mirrored, so red columns and yellow rows meet in pairs.")
    image = g.add_image("wrap checker 8x8", wrap_texture())
    panel = quad(1.2, 1.2, (-1, -1), (2, 2))
    for i, (name, mag, wrap) in enumerate((("REPEAT, NEAREST", NEAREST, REPEAT),
                                           ("CLAMP_TO_EDGE, LINEAR", LINEAR, CLAMP_TO_EDGE),
                                           ("MIRRORED_REPEAT, LINEAR", LINEAR, MIRRORED_REPEAT))):
        texture = g.add_texture(image, g.add_sampler(mag, mag, wrap, wrap))
        material = g.add_material(name, (1, 1, 1, 1), 0.0, 0.9, texture=texture)
        g.add_node(name, g.add_mesh(name, g.primitive(panel, material)), translation=(1.4 * (i - 1), 0.75, 0))
    add_ground(g, 8, 6)
    g.add_camera("camera", (0, 0.9, 3.6), (0, 0.7, 0))
    g.add_light("sun", "directional", (-1.5, 3.0, 4.0), (0, 0, 0), intensity=1.1)
    return g


def grazing_checker():
    g = Gltf("A 200 m ground with a black and white checker (64x64 texels, 8-texel squares, repeated 100 times: "
             "25 cm squares) seen from 1.5 m up, looking just below the horizon. With mipmaps "
             "(LINEAR_MIPMAP_LINEAR) the squares fade to an even grey towards the horizon; without, they "
             "break into moire.")
    image = g.add_image("checker 64x64", png(64, 64, checker(64, 8, (0, 0, 0), (255, 255, 255))))
    texture = g.add_texture(image, g.add_sampler(LINEAR, LINEAR_MIPMAP_LINEAR, REPEAT, REPEAT))
    material = g.add_material("checker", (1, 1, 1, 1), 0.0, 1.0, texture=texture)
    g.add_node("ground", g.add_mesh("ground", g.primitive(plane(200, 200, 100), material)))
    g.add_camera("camera", (0, 1.5, 0), (0, 1.5 - 0.6, -10), yfov_deg=50, zfar=300)
    g.add_light("sun", "directional", (30, 40, 20), (0, 0, 0), intensity=1.0)
    return g


def texture_transform():
    g = Gltf("KHR_texture_transform on one texture (an F on a grid, 16x16 texels): four panels, left to right: no "
             "transform (one upright F); offset (0.5, 0) (the F shifted by half the panel, wrapping around); rotation "
             "90 degrees (pi/2) about the texture origin; scale (2, 2) with rotation 0.3 and offset (0.25, 0.1) "
             "(four smaller, tilted Fs). REPEAT, bilinear, so every transformed coordinate samples the same image.")
    def pixel(x, y):
        if letter_f(x, y, 5, 4, 1):
            return (200, 40, 30)
        return (230, 230, 220) if (x // 4 + y // 4) % 2 else (120, 150, 200)
    image = g.add_image("F 16x16", png(16, 16, pixel))
    sampler = g.add_sampler(LINEAR, LINEAR, REPEAT, REPEAT)
    panel = quad(1.0, 1.0)
    for i, (name, transform) in enumerate((("no transform", None), ("offset (0.5, 0)", {"offset": [0.5, 0]}),
                                           ("rotation pi/2", {"rotation": num(math.pi / 2)}),
                                           ("scale 2, rotation 0.3, offset", {"scale": [2, 2], "rotation": 0.3, "offset": [0.25, 0.1]}))):
        texture = g.add_texture(image, sampler)
        material = g.add_material(name, (1, 1, 1, 1), 0.0, 0.9, texture=texture)
        if transform is not None:
            g.doc["materials"][material]["pbrMetallicRoughness"]["baseColorTexture"]["extensions"] = {"KHR_texture_transform": transform}
        g.add_node(name, g.add_mesh(name, g.primitive(panel, material)), translation=(1.15 * (i - 1.5), 0.7, 0))
    add_ground(g, 7, 4)
    g.add_camera("camera", (0, 0.9, 3.4), (0, 0.65, 0))
    g.add_light("sun", "directional", (-1.0, 3.0, 4.0), (0, 0, 0), intensity=1.1)
    g.doc["extensionsUsed"] = sorted(set(g.doc.get("extensionsUsed", [])) | {"KHR_texture_transform"})
    return g


def mipmap_modes():
    g = Gltf("Four 2 m wide, 80 m long strips of the checker of grazing_checker.gltf (8-texel squares, 25 cm), "
             "seen from 1.2 m up, one per mipmap min filter, left to right: NEAREST_MIPMAP_NEAREST (bands where "
             "the level changes, sharp texels), LINEAR_MIPMAP_NEAREST (bands, smooth texels), "
             "NEAREST_MIPMAP_LINEAR (no bands, sharp texels), LINEAR_MIPMAP_LINEAR (trilinear: no bands, smooth). "
             "All four fade to grey towards the far end.")
    image = g.add_image("checker 64x64", png(64, 64, checker(64, 8, (0, 0, 0), (255, 255, 255))))
    width, length = 2.0, 80.0
    w, d = width / 2, length / 2
    strip = Mesh([(-w, 0, d), (w, 0, d), (w, 0, -d), (-w, 0, -d)], [(0, 1, 0)] * 4, quad_indices(0, 1, 2, 3),
                 [(0, length / 2), (width / 2, length / 2), (width / 2, 0), (0, 0)])
    for i, (name, min_filter) in enumerate((("NEAREST_MIPMAP_NEAREST", NEAREST_MIPMAP_NEAREST),
                                            ("LINEAR_MIPMAP_NEAREST", LINEAR_MIPMAP_NEAREST),
                                            ("NEAREST_MIPMAP_LINEAR", NEAREST_MIPMAP_LINEAR),
                                            ("LINEAR_MIPMAP_LINEAR", LINEAR_MIPMAP_LINEAR))):
        texture = g.add_texture(image, g.add_sampler(LINEAR, min_filter, REPEAT, REPEAT))
        material = g.add_material(name, (1, 1, 1, 1), 0.0, 1.0, texture=texture)
        g.add_node(name, g.add_mesh(name, g.primitive(strip, material)), translation=(2.1 * (i - 1.5), 0, -d + 1))
    g.add_camera("camera", (0, 1.2, 2.5), (0, 0.2, -8), yfov_deg=50, zfar=200)
    g.add_light("sun", "directional", (30, 40, 20), (0, 0, 0), intensity=1.0)
    return g


def leaf_texture(size=64):
    """A green leaf on a transparent ground: alpha 255 inside an ellipse with
    a midrib and veins cut out as slits, falling off linearly over the outer
    fifth, so the cutoff decides how much of the rim stays."""
    def pixel(x, y):
        u, v = (x + 0.5) / size * 2 - 1, (y + 0.5) / size * 2 - 1
        r = math.sqrt((u / 0.6) ** 2 + (v / 0.95) ** 2)
        a = max(0.0, min(1.0, (1.0 - r) / 0.2))
        if abs(u) < 0.04 or (abs(u) > 0.1 and abs((v - abs(u) * 0.8) * 6 % 1 - 0.5) < 0.06):
            a *= 0.25  # veins: a quarter alpha, cut away by cutoffs above it
        green = int(90 + 100 * (1 - r) if r < 1 else 60)
        return (40, min(green, 220), 30, int(round(255 * a)))
    return png(size, size, pixel, alpha=True)


def lines_points():
    g = Gltf("POINTS, LINES, LINE_LOOP and LINE_STRIP, unlit (base colour times COLOR_0) and depth-tested "
             "against the triangles: a wireframe cube (LINES) whose edges run between its corners' colours "
             "(red along x, green along y, blue along z) around a solid grey box, which hides the far edges' "
             "middles; a yellow LINE_LOOP circle on the ground around it; a LINE_STRIP helix rising from "
             "blue to white on the right; a cloud of 400 white POINTS on a sphere on the left, its back half "
             "hidden by a solid sphere inside it.")
    POINTS, LINES, LINE_LOOP, LINE_STRIP = 0, 1, 2, 3

    def raw(mode, positions, material, colors=None, indices=None):
        attributes = {"POSITION": g.add_accessor(positions, "VEC3", bounds=True)}
        if colors is not None:
            attributes["COLOR_0"] = g.add_accessor(colors, "VEC3")
        primitive = {"attributes": attributes, "mode": mode, "material": material}
        if indices is not None:
            primitive["indices"] = g.add_indices(indices)
        return primitive

    white = g.add_material("unlit white", (1, 1, 1, 1), 0.0, 1.0)
    corners = [(x, y, z) for x in (-0.6, 0.6) for y in (-0.6, 0.6) for z in (-0.6, 0.6)]
    colors = [(0.1 + (x > 0) * 0.9, 0.1 + (y > 0) * 0.9, 0.1 + (z > 0) * 0.9) for x, y, z in corners]
    edges = [a for i in range(8) for j in range(i + 1, 8) if bin(i ^ j).count("1") == 1 for a in (i, j)]
    g.add_node("wire cube", g.add_mesh("wire cube", raw(LINES, corners, white, colors, edges)), translation=(0, 0.8, 0))
    box = g.add_material("box", (0.55, 0.55, 0.6, 1), 0.0, 0.7)
    g.add_node("box", g.add_mesh("box", g.primitive(cube(0.7), box)), translation=(0, 0.8, 0))
    yellow = g.add_material("yellow", (1.0, 0.85, 0.1, 1), 0.0, 1.0)
    circle = [(1.3 * math.cos(2 * math.pi * k / 48), 0.02, 1.3 * math.sin(2 * math.pi * k / 48)) for k in range(48)]
    g.add_node("circle", g.add_mesh("circle", raw(LINE_LOOP, circle, yellow)))
    helix = [(0.35 * math.cos(0.35 * k), 0.05 + 0.025 * k, 0.35 * math.sin(0.35 * k)) for k in range(64)]
    ramp = [(0.2 + 0.8 * k / 63, 0.3 + 0.7 * k / 63, 1.0) for k in range(64)]
    g.add_node("helix", g.add_mesh("helix", raw(LINE_STRIP, helix, white, ramp)), translation=(1.9, 0, 0))
    golden = math.pi * (3 - math.sqrt(5))
    cloud = []
    for k in range(400):
        y = 1 - 2 * (k + 0.5) / 400
        r = math.sqrt(1 - y * y)
        cloud.append((0.6 * r * math.cos(golden * k), 0.6 * y, 0.6 * r * math.sin(golden * k)))
    g.add_node("cloud", g.add_mesh("cloud", raw(POINTS, cloud, white)), translation=(-1.9, 0.8, 0))
    ball = g.add_material("ball", (0.2, 0.35, 0.7, 1), 0.0, 0.5)
    g.add_node("ball", g.add_mesh("ball", g.primitive(uv_sphere(0.5, 32, 16), ball)), translation=(-1.9, 0.8, 0))
    add_ground(g, 7, 5)
    g.add_camera("camera", (0, 2.2, 4.6), (0, 0.6, 0))
    g.add_light("key", "point", (2.0, 4.0, 3.0), intensity=20)
    return g


def alpha_mask():
    g = Gltf("alphaMode MASK: three double-sided panels in front of a wall, each cut by its alpha. Left: a leaf "
             "texture (alpha falling off at the rim, veins at a quarter alpha) with alphaCutoff 0.5: the leaf with its "
             "veins cut out. Middle: the same leaf with alphaCutoff 0.9: a thinner leaf. Right: an untextured panel "
             "whose COLOR_0 alpha runs from 0 at the left to 1 at the right, cutoff 0.5: its right half stays. "
             "Through every cut the wall behind is visible; nothing cut away hides what is behind it.")
    image = g.add_image("leaf 64x64 RGBA", leaf_texture())
    texture = g.add_texture(image, g.add_sampler(LINEAR, LINEAR_MIPMAP_LINEAR, CLAMP_TO_EDGE, CLAMP_TO_EDGE))
    panel = quad(1.2, 1.6)
    for i, cutoff in enumerate((0.5, 0.9)):
        material = g.add_material("leaf, cutoff %g" % cutoff, (1, 1, 1, 1), 0.0, 0.6, texture=texture, double_sided=True,
                                  alpha_mode="MASK", alpha_cutoff=cutoff)
        g.add_node("leaf, cutoff %g" % cutoff, g.add_mesh("leaf %d" % i, g.primitive(panel, material)),
                   translation=(1.4 * (i - 1), 1.0, 0))
    ramp = quad(1.2, 1.6)
    colors = g.add_accessor([(0.8, 0.25, 0.05, 0.0), (0.8, 0.25, 0.05, 1.0), (0.8, 0.25, 0.05, 1.0), (0.8, 0.25, 0.05, 0.0)], "VEC4")
    material = g.add_material("alpha ramp, cutoff 0.5", (1, 1, 1, 1), 0.0, 0.6, double_sided=True, alpha_mode="MASK")
    g.add_node("alpha ramp", g.add_mesh("alpha ramp", g.primitive(ramp, material, colors=colors)), translation=(1.4, 1.0, 0))
    wall = g.add_material("wall", (0.75, 0.75, 0.8, 1), 0.0, 0.9)
    g.add_node("wall", g.add_mesh("wall", g.primitive(quad(6, 3), wall)), translation=(0, 1.2, -1.0))
    add_ground(g, 8, 6)
    g.add_camera("camera", (0, 1.2, 3.4), (0, 1.0, 0))
    g.add_light("key", "point", (1.5, 3.0, 3.0), intensity=16)
    return g


def cube_direction(face, s, t):
    """The direction that OpenGL's cube-map table sends to (s, t) of `face`
    (+x -x +y -y +z -z; t = 0 at the face's top row): renderer/PIPELINE.md,
 "Textures", run backwards."""
    a, b = 2 * s - 1, 2 * t - 1
    return [(1, -b, -a), (-1, -b, a), (a, 1, b), (a, -1, -b), (a, -b, 1), (-a, -b, -1)][face]


def sky_cube(n=64):
    """A cube strip (6n x n) of an outdoor scene: a sky from pale at the
    horizon to deep blue overhead, a sun towards (+x, +y, +z), and below the
    horizon a grey-green ground of 1 m tiles seen from 1.5 m up, so a
    reflection shows which way is up and where the sun is."""
    sun = [c / math.sqrt(3 * 0.8) for c in (0.6, 1.2, 0.6)]
    def colour(d):
        length = math.sqrt(sum(c * c for c in d))
        x, y, z = (c / length for c in d)
        if y > 0:
            k = y ** 0.5
            r, g, b = 200 - 150 * k, 220 - 120 * k, 245 - 45 * k
            if x * sun[0] + y * sun[1] + z * sun[2] > 0.995:
                r, g, b = 255, 245, 210
        else:
            distance = 1.5 / max(-y, 1e-3)
            gx, gz = x * distance, z * distance
            tile = (math.floor(gx) + math.floor(gz)) % 2
            fade = min(1.0, distance / 40.0)
            base = (90, 110, 80) if tile else (130, 140, 115)
            r, g, b = (c * (1 - fade) + 150 * fade for c in base)
        return tuple(int(round(max(0, min(255, c)))) for c in (r, g, b))
    def pixel(x, y):
        face, fx = divmod(x, n)
        return colour(cube_direction(face, (fx + 0.5) / n, (y + 0.5) / n))
    return png(6 * n, n, pixel)


def environment():
    g = Gltf("Environment mapping, with --set environment.map=assets/environment/sky_cube.png: a chrome sphere (metal, "
             "white), a gold sphere (metal: the reflection takes its colour) and a red plastic torus (dielectric: a "
             "faint untinted reflection over its own colour), all reflecting the sky above and the tiled ground below "
             "the horizon, which the background also shows.")
    ball = uv_sphere(0.5, 48, 24)
    ring = torus(0.45, 0.16, 48, 24)
    chrome = g.add_material("chrome", (0.95, 0.95, 0.95, 1), 1.0, 0.15)
    gold = g.add_material("gold", (1.0, 0.76, 0.33, 1), 1.0, 0.25)
    plastic = g.add_material("red plastic", (0.8, 0.08, 0.06, 1), 0.0, 0.3)
    g.add_node("chrome sphere", g.add_mesh("chrome sphere", g.primitive(ball, chrome)), translation=(-1.15, 0.5, 0))
    g.add_node("gold sphere", g.add_mesh("gold sphere", g.primitive(ball, gold)), translation=(0.0, 0.5, 0))
    g.add_node("red torus", g.add_mesh("red torus", g.primitive(ring, plastic)), translation=(1.2, 0.5, 0),
               rotation=axis_angle((1, 0, 0), 60))
    g.add_camera("camera", (0, 1.1, 3.6), (0, 0.5, 0))
    g.add_light("sun", "directional", (3, 6, 3), (0, 0, 0), intensity=1.2)
    return g


def materials():
    g = Gltf("glTF's metallic-roughness materials, for --set shading=pbr (best with --set "
             "environment.map=assets/environment/sky_cube.png): two rows of spheres, roughness 0 to 1 from left to "
             "right; the back row gold metal (its reflection takes the gold, sharp at the left, a blur at the right), "
             "the front row red plastic (red diffuse under a white reflection that fades and spreads with roughness).")
    ball = uv_sphere(0.32, 48, 24)
    for row, (name, colour, metallic, z) in enumerate((("gold", (1.0, 0.76, 0.33, 1), 1.0, -0.45),
                                                      ("red plastic", (0.7, 0.05, 0.04, 1), 0.0, 0.45))):
        for k in range(5):
            roughness = k / 4
            material = g.add_material("%s, roughness %.2f" % (name, roughness), colour, metallic, roughness)
            label = "%s %d" % (name, k)
            g.add_node(label, g.add_mesh(label, g.primitive(ball, material)), translation=(-1.6 + 0.8 * k, 0.34, z))
    add_ground(g, 6, 4)
    g.add_camera("camera", (0, 2.7, 3.0), (0, 0.15, -0.1))
    g.add_light("sun", "directional", (-2, 5, 3), (0, 0, 0), intensity=2.5)
    return g


def pbr_maps():
    g = Gltf("shading=pbr's material maps, each read at TEXCOORD_0: a sphere whose metallic-roughness texture "
             "makes one half gold metal and the other gold-coloured plastic, smooth at the poles and rough "
             "at the equator; a cube whose occlusion texture (strength 1) darkens the ambient light toward its edges "
             "and in a cross; a panel whose emissive texture lights a green grid on black.")
    sampler = g.add_sampler(LINEAR, LINEAR_MIPMAP_LINEAR, REPEAT, REPEAT)
    def mr(x, y):  # G roughness: 0 at the poles, 1 at the equator; B metallic: 1 on the left half (u < 0.5)
        v = (y + 0.5) / 64
        rough = int(round(255 * (1 - abs(2 * v - 1))))
        return (0, rough, 255 if x < 32 else 0)
    mr_texture = g.add_texture(g.add_image("metallic-roughness 64x64", png(64, 64, mr)), sampler)
    def ao(x, y):
        u, v = (x + 0.5) / 64, (y + 0.5) / 64
        edge = min(u, 1 - u, v, 1 - v)
        level = min(1.0, 0.25 + 4 * edge)
        if abs(u - 0.5) < 0.06 or abs(v - 0.5) < 0.06:
            level *= 0.3
        return (int(round(255 * level)),) * 3
    ao_texture = g.add_texture(g.add_image("occlusion 64x64", png(64, 64, ao)), sampler)
    def glow(x, y):
        on = x % 16 < 3 or y % 16 < 3
        return (20, 255, 60) if on else (0, 0, 0)
    glow_texture = g.add_texture(g.add_image("emissive grid 64x64", png(64, 64, glow)), sampler)
    gold = g.add_material("gold, maps for metal and roughness", (1.0, 0.76, 0.33, 1), 1.0, 1.0, metallic_roughness=mr_texture)
    clay = g.add_material("clay, occlusion map", (0.8, 0.8, 0.75, 1), 0.0, 0.7, occlusion=(ao_texture, 1.0))
    panel = g.add_material("dark panel, emissive grid", (0.05, 0.05, 0.05, 1), 0.0, 0.5, emissive=(1, 1, 1),
                           emissive_texture=glow_texture)
    g.add_node("sphere", g.add_mesh("sphere", g.primitive(uv_sphere(0.5, 64, 32), gold)), translation=(-1.2, 0.5, 0))
    g.add_node("cube", g.add_mesh("cube", g.primitive(cube(0.8), clay)), translation=(0.1, 0.4, 0), rotation=axis_angle((0, 1, 0), 30))
    g.add_node("panel", g.add_mesh("panel", g.primitive(quad(0.9, 0.9), panel)), translation=(1.3, 0.55, -0.1),
               rotation=axis_angle((0, 1, 0), -20))
    add_ground(g, 5, 3)
    g.add_camera("camera", (0, 1.4, 3.2), (0, 0.45, 0))
    g.add_light("sun", "directional", (-2, 4, 3), (0, 0, 0), intensity=2.0)
    return g


def texcoord_sets():
    g = Gltf("Texture references reading TEXCOORD_0 and TEXCOORD_1 (glTF's texCoord). Left: a cube whose base "
             "colour brick texture repeats 3 times per face on TEXCOORD_0, while its occlusion texture (dark edges "
             "and a dark cross), its emissive texture (a green frame) and its normal texture (4 by 4 dimples) read "
             "TEXCOORD_1, once per face; the course's shading shows all but the occlusion, shading=pbr all four. Middle: a leaf cut by alphaMode MASK whose texture reads TEXCOORD_1, the "
             "primitive's TEXCOORD_0 all zero (read by mistake, it would keep or cut the whole panel); its shadow "
             "on the wall is leaf-shaped. Right: a panel with only TEXCOORD_1, a checker read from it; below it, a "
             "panel whose texture asks for TEXCOORD_1, which it lacks: its factor alone (orange), with a warning.")
    sampler = g.add_sampler(LINEAR, LINEAR_MIPMAP_LINEAR, REPEAT, REPEAT)
    bricks = g.add_texture(g.add_image("bricks 64x64", brick_texture()), sampler)
    def ao(x, y):
        u, v = (x + 0.5) / 64, (y + 0.5) / 64
        level = min(1.0, 0.3 + 5 * min(u, 1 - u, v, 1 - v))
        return (int(round(255 * (level * 0.35 if abs(u - 0.5) < 0.05 or abs(v - 0.5) < 0.05 else level))),) * 3
    occlusion = g.add_texture(g.add_image("occlusion 64x64", png(64, 64, ao)), sampler)
    def frame(x, y):
        return (30, 255, 80) if min(x, 63 - x, y, 63 - y) in (4, 5, 6) else (0, 0, 0)
    glow = g.add_texture(g.add_image("emissive frame 64x64", png(64, 64, frame)), sampler)
    dimples = g.add_texture(g.add_image("dimples normal map 64x64", dimples_normal_map()), sampler)
    box = g.add_material("bricks on TEXCOORD_0; occlusion, emissive and normal on TEXCOORD_1", (1, 1, 1, 1), 0.0, 0.6,
                         texture=bricks, occlusion=(occlusion, 1.0), emissive=(1, 1, 1), emissive_texture=glow, normal=(dimples, 1.0))
    g.read_at(box, 1, "occlusionTexture", "emissiveTexture", "normalTexture")
    block = cube(0.9)
    tiled = Mesh(block.positions, block.normals, block.indices, [(3 * u, 3 * v) for u, v in block.uvs])
    g.add_node("cube", g.add_mesh("cube", g.primitive(tiled, box, uv1=block.uvs)), translation=(-1.05, 0.45, 0),
               rotation=axis_angle((0, 1, 0), 35))
    leaf_texture_index = g.add_texture(g.add_image("leaf 64x64 RGBA", leaf_texture()),
                                       g.add_sampler(LINEAR, LINEAR_MIPMAP_LINEAR, CLAMP_TO_EDGE, CLAMP_TO_EDGE))
    leaf = g.read_at(g.add_material("leaf on TEXCOORD_1, cutoff 0.5", (1, 1, 1, 1), 0.0, 0.6, texture=leaf_texture_index,
                                    double_sided=True, alpha_mode="MASK"), 1, "baseColorTexture")
    panel = quad(1.0, 1.4)
    zeros = Mesh(panel.positions, panel.normals, panel.indices, [(0, 0)] * 4)
    g.add_node("leaf", g.add_mesh("leaf", g.primitive(zeros, leaf, uv1=panel.uvs)), translation=(0.1, 1.0, 0.2))
    checker_texture = g.add_texture(g.add_image("checker 32x32", png(32, 32, checker(32, 8, (40, 40, 160), (230, 230, 230)))),
                                    g.add_sampler(NEAREST, NEAREST, REPEAT, REPEAT))
    only1 = g.read_at(g.add_material("checker on TEXCOORD_1, the only set", (1, 1, 1, 1), 0.0, 0.6, texture=checker_texture),
                      1, "baseColorTexture")
    small = quad(0.8, 0.8)
    g.add_node("TEXCOORD_1 only", g.add_mesh("TEXCOORD_1 only", g.primitive(small, only1, uv1=small.uvs, texcoord0=False)),
               translation=(1.15, 1.35, 0))
    missing = g.read_at(g.add_material("checker on TEXCOORD_1, which the panel lacks", (0.9, 0.45, 0.1, 1), 0.0, 0.6,
                                       texture=checker_texture), 1, "baseColorTexture")
    g.add_node("no TEXCOORD_1", g.add_mesh("no TEXCOORD_1", g.primitive(small, missing)), translation=(1.15, 0.45, 0))
    wall = g.add_material("wall", (0.75, 0.75, 0.8, 1), 0.0, 0.9)
    g.add_node("wall", g.add_mesh("wall", g.primitive(quad(6, 3), wall)), translation=(0, 1.2, -1.0))
    add_ground(g, 6, 4)
    g.add_camera("camera", (0.0, 1.7, 4.4), (0.0, 0.75, 0))
    g.add_light("key", "point", (-0.6, 2.6, 2.6), intensity=12)
    return g


def dimples_normal_map(size=64, cells=4):
    """A tangent-space normal texture of a grid of round dimples, (n + 1)/2 in
    bytes with n = normalize(-dh/du, -dh/dv, 1); the top row of the PNG is t = 0."""
    def height(u, v):
        cu, cv = (u * cells) % 1 - 0.5, (v * cells) % 1 - 0.5
        r2 = (cu * cu + cv * cv) / 0.16
        return -(1 - r2) ** 2 if r2 < 1 else 0.0
    def pixel(x, y):
        u, v, e = (x + 0.5) / size, (y + 0.5) / size, 0.5 / size
        du = (height(u + e, v) - height(u - e, v)) / (2 * e) * 0.05
        dv = (height(u, v + e) - height(u, v - e)) / (2 * e) * 0.05
        # v grows down the image while the tangent frame's t axis grows up the texture: dh/dt = -dh/dv.
        n = normalize((-du, dv, 1.0))
        return tuple(int(round(255 * (c + 1) / 2)) for c in n)
    return png(size, size, pixel)


def normal_map():
    g = Gltf("A glTF normal texture of round dimples, 4 by 4 per face: on a sphere (tangents computed by facet), "
             "on a square panel (tangents from the file's TANGENT) and on a cube at scale 2. The dimples catch the "
             "light on the side facing it and shade on the other, with Phong and pbr shading; flat and Gouraud "
             "shading light per triangle or vertex and show none.")
    sampler = g.add_sampler(LINEAR, LINEAR_MIPMAP_LINEAR, REPEAT, REPEAT)
    dimples = g.add_texture(g.add_image("dimples normal map 64x64", dimples_normal_map()), sampler)
    blue = g.add_material("blue, dimpled", (0.25, 0.4, 0.85, 1), 0.0, 0.35, normal=(dimples, 1.0))
    sand = g.add_material("sand, dimpled", (0.85, 0.72, 0.5, 1), 0.0, 0.5, normal=(dimples, 1.0))
    clay = g.add_material("clay, dimpled at scale 2", (0.8, 0.35, 0.3, 1), 0.0, 0.5, normal=(dimples, 2.0))
    g.add_node("sphere", g.add_mesh("sphere", g.primitive(uv_sphere(0.5, 64, 32), blue)), translation=(-1.2, 0.5, 0))
    panel = quad(0.9, 0.9)
    g.add_node("panel", g.add_mesh("panel", g.primitive(panel, sand, tangents=[(1, 0, 0, 1)] * len(panel.positions))),
               translation=(0.05, 0.55, -0.1))
    g.add_node("cube", g.add_mesh("cube", g.primitive(cube(0.7), clay)), translation=(1.25, 0.35, 0), rotation=axis_angle((0, 1, 0), 35))
    add_ground(g, 5, 3)
    g.add_camera("camera", (0, 1.3, 3.2), (0, 0.45, 0))
    g.add_light("key", "point", (-1.5, 2.5, 2.5), intensity=14.0)
    return g


def height_map(size=128):
    """A greyscale height map: a round hill in the middle, a ring of ripples
    around it and a low border, h from 0 (black) to 1 (white)."""
    def pixel(x, y):
        u, v = (x + 0.5) / size - 0.5, (y + 0.5) / size - 0.5
        r = math.sqrt(u * u + v * v)
        hill = math.exp(-(r / 0.12) ** 2)
        ripples = 0.35 * (0.5 + 0.5 * math.cos(r * 2 * math.pi * 6)) * max(0.0, 1 - r / 0.5)
        h = min(1.0, hill + ripples)
        g = int(round(255 * h))
        return (g, g, g)
    return png(size, size, pixel)


def displacement():
    g = Gltf("Displacement mapping, with --set material.displacementMap=assets/displacement/height.png (and "
             "material.displacementScale, material.displacementSubdivisions): a square of sand and a blue sphere over "
             "a grey ground, both subdivided and moved along their normals by the map (white is high): a hill in the "
             "middle ringed by ripples, on the square and on the side of the sphere that faces the camera; shadows "
             "follow the displaced shapes. The ground has no texture coordinates and stays flat. Without the setting "
             "the square and the sphere are flat and smooth.")
    # A white texture: TEXCOORD_0 is what the height map is read at; the colour stays the factor's.
    white = g.add_texture(g.add_image("white 4x4", png(4, 4, lambda x, y: (255, 255, 255))),
                          g.add_sampler(LINEAR, LINEAR_MIPMAP_LINEAR, REPEAT, REPEAT))
    sand = g.add_material("sand", (0.85, 0.72, 0.5, 1), 0.0, 0.8, texture=white)
    blue = g.add_material("blue", (0.25, 0.4, 0.85, 1), 0.0, 0.4, texture=white)
    n = 17
    positions = grid_positions(n, n, 2.4 / (n - 1))
    uvs = [(c / (n - 1), r / (n - 1)) for r in range(n) for c in range(n)]
    terrain = Mesh(positions, [(0, 1, 0)] * len(positions), grid_indices(n, n), uvs)
    g.add_node("terrain", g.add_mesh("terrain", g.primitive(terrain, sand)), translation=(-0.9, 0.01, 0))
    g.add_node("sphere", g.add_mesh("sphere", g.primitive(uv_sphere(0.45, 48, 24), blue)), translation=(1.2, 0.7, 0))
    add_ground(g, 6, 5)
    g.add_camera("camera", (0.2, 2.0, 3.2), (0.1, 0.2, 0))
    g.add_light("key", "directional", (-2, 4, 2.5), (0, 0, 0), intensity=1.2)
    return g


def bump():
    g = Gltf("Bump mapping, with --set material.bumpMap=assets/displacement/height.png (and material.bumpScale): "
             "the course's N' = N + B_u (N x P_t) - B_v (N x P_s) per pixel with Phong or pbr shading, on a flat square "
             "and a sphere: the hill and ripples of the height map appear in the shading under a low light, while the "
             "silhouettes and shadows stay those of the flat square and the smooth sphere (the geometry does not move, "
             "unlike displacement mapping).")
    white = g.add_texture(g.add_image("white 4x4", png(4, 4, lambda x, y: (255, 255, 255))),
                          g.add_sampler(LINEAR, LINEAR_MIPMAP_LINEAR, REPEAT, REPEAT))
    sand = g.add_material("sand", (0.85, 0.72, 0.5, 1), 0.0, 0.6, texture=white)
    blue = g.add_material("blue", (0.25, 0.4, 0.85, 1), 0.0, 0.4, texture=white)
    g.add_node("square", g.add_mesh("square", g.primitive(plane(2.4, 2.4), sand)), translation=(-0.9, 0.01, 0))
    g.add_node("sphere", g.add_mesh("sphere", g.primitive(uv_sphere(0.55, 64, 32), blue)), translation=(1.2, 0.6, 0))
    add_ground(g, 6, 5)
    g.add_camera("camera", (0.2, 2.0, 3.2), (0.1, 0.2, 0))
    g.add_light("low sun", "directional", (-4, 1.5, 1.0), (0, 0, 0), intensity=1.4)
    return g


def fog():
    g = Gltf("Fog, the course's atmospheric attenuation (with --set fog.mode=linear, exponential or exponential2, "
             "and fog.color set to the background): an avenue of columns and spheres receding 40 m into the "
             "distance on a long ground; the far ones fade into the fog colour, the near ones keep theirs.")
    column = cylinder(0.25, 2.0, 24)
    ball = uv_sphere(0.35, 32, 16)
    stone = g.add_material("stone", (0.75, 0.7, 0.62, 1), 0.0, 0.7)
    red = g.add_material("red", (0.8, 0.1, 0.08, 1), 0.0, 0.4)
    blue = g.add_material("blue", (0.12, 0.25, 0.8, 1), 0.0, 0.4)
    for k in range(10):
        z = 1.0 - 4.2 * k
        for side in (-1, 1):
            g.add_node("column %d %+d" % (k, side), g.add_mesh("column %d %+d" % (k, side), g.primitive(column, stone)),
                       translation=(1.8 * side, 0.0, z))
        g.add_node("sphere %d" % k, g.add_mesh("sphere %d" % k, g.primitive(ball, red if k % 2 else blue)), translation=(0, 0.35, z - 2.1))
    add_ground(g, 8, 48, translation=(0, 0, -18), color=((0.32, 0.36, 0.3, 1), 0.0, 0.9))
    g.add_camera("camera", (0.4, 1.6, 5.0), (0, 0.9, -10), zfar=120)
    g.add_light("sun", "directional", (-3, 6, 4), (0, 0, 0), intensity=1.6)
    return g


def painter():
    g = Gltf("The painter's algorithm and where it fails (with --set hsr=painter; the z-buffer draws it right): "
             "left, three sloping bars in a cycle, each lying over the next at one end and under the one before at "
             "the other, so no back-to-front order of the three exists; right, two upright panels that pass through "
             "each other, each in front over half of their overlap; at the back, three cards stacked one behind "
             "the other, which depth order paints right.")
    colors = [("red bar", (0.85, 0.15, 0.1, 1)), ("green bar", (0.15, 0.7, 0.2, 1)), ("blue bar", (0.15, 0.3, 0.9, 1))]
    # The corners of a triangle of lines; bar k runs along corner k -> corner k+1, rising from 0.2 m to 0.4 m
    # there, so that at each corner the bar that ends high lies over the one that starts low.
    corners = [(-1.6 + 0.8 * math.cos(math.radians(a)), 0.8 * math.sin(math.radians(a))) for a in (90, 210, 330)]
    for k, (name, color) in enumerate(colors):
        (ax, az), (bx, bz) = corners[k], corners[(k + 1) % 3]
        length = math.hypot(bx - ax, bz - az)
        ux, uz = (bx - ax) / length, (bz - az) / length  # along the bar
        px, pz = -uz, ux                                 # across it
        half, extra, low, high = 0.15, 0.45, 0.2, 0.4
        def at(s, side):
            h = low + (high - low) * s / length
            return (ax + ux * s + px * side * half, h, az + uz * s + pz * side * half)
        positions = [at(-extra, -1), at(-extra, 1), at(length + extra, 1), at(length + extra, -1)]
        normal = normalize(cross(sub(positions[2], positions[0]), sub(positions[1], positions[0])))
        if normal[1] < 0:
            normal = mul(normal, -1)
        indices = quad_indices(0, 3, 2, 1) if dot(cross(sub(positions[3], positions[0]), sub(positions[2], positions[0])), normal) > 0 \
            else quad_indices(0, 1, 2, 3)
        bar = Mesh(positions, [normal] * 4, indices)
        g.add_node(name, g.add_mesh(name, g.primitive(bar, g.add_material(name, color, 0.0, 0.5, double_sided=True))))
    for name, color, turn in (("cream panel", (0.9, 0.85, 0.7, 1), 35), ("violet panel", (0.55, 0.3, 0.8, 1), -35)):
        g.add_node(name, g.add_mesh(name, g.primitive(quad(1.3, 1.0), g.add_material(name, color, 0.0, 0.6, double_sided=True))),
                   translation=(1.5, 0.55, 0.1), rotation=axis_angle((0, 1, 0), turn))
    for k, (name, color) in enumerate((("near card", (0.9, 0.75, 0.1, 1)), ("middle card", (0.1, 0.7, 0.8, 1)),
                                       ("far card", (0.8, 0.35, 0.6, 1)))):
        g.add_node(name, g.add_mesh(name, g.primitive(quad(0.8, 0.6), g.add_material(name, color, 0.0, 0.6))),
                   translation=(-0.1 + 0.3 * k, 0.45 + 0.12 * k, -1.3 - 0.35 * k))
    add_ground(g, 8, 6)
    g.add_camera("camera", (0.1, 2.6, 3.6), (0.0, 0.3, -0.2))
    g.add_light("sun", "directional", (-2, 6, 3), (0, 0, 0), intensity=1.1)
    return g


def glass_texture(size=64):
    """Frosted glass with a clear window: alpha 0.85 at the rim falling to
    0.15 in a round window at the middle, and opaque white lead lines
    (alpha 1) on a 4 x 4 grid, so the base colour texture's alpha varies
    from nearly clear to opaque across one pane."""
    def pixel(x, y):
        u, v = (x + 0.5) / size * 2 - 1, (y + 0.5) / size * 2 - 1
        r = math.sqrt(u * u + v * v)
        a = 0.15 + 0.7 * max(0.0, min(1.0, (r - 0.35) / 0.4))
        lead = max(abs((u + 1) * 2 % 1 - 0.5), abs((v + 1) * 2 % 1 - 0.5)) > 0.45
        if lead:
            return (235, 235, 230, 255)
        return (200, 225, 255, int(round(255 * a)))
    return png(size, size, pixel, alpha=True)


def transparency():
    g = Gltf("Transparency (alphaMode BLEND): blended surfaces are drawn after the opaque ones, back to front, "
             "depth-tested without depth writes. Left: three tinted panes (red, green, blue, alpha 0.5) one behind "
             "the other, overlapping, so each overlap shows two or three of them mixed. Middle: a glass ball "
             "(alpha 0.3, double-sided) around an opaque gold cube: its back faces blend behind the cube, its front "
             "faces over it; with transparency.sort=object a double-sided ball's own faces come in file order, with "
             "triangle they come back to front. Right: a frosted pane whose texture alpha runs from 0.85 at the rim to 0.15 in "
             "its window, with opaque leading; in front, a ramp whose COLOR_0 alpha runs from 0 to 1. At the back, "
             "two crossing panes (amber, violet) pass through each other: no back-to-front order of the two exists, "
             "so one half of their crossing blends in the wrong order, the painter's algorithm's failure. "
             "Blended fragments cast shadows where alpha >= transparency.shadowCutoff (0.5): the tinted panes and "
             "the leading do, the ball and the window do not.")
    for k, (name, color) in enumerate((("red pane", (0.9, 0.1, 0.1, 0.5)), ("green pane", (0.1, 0.8, 0.2, 0.5)),
                                       ("blue pane", (0.15, 0.3, 0.95, 0.5)))):
        material = g.add_material(name, color, 0.0, 0.4, double_sided=True, alpha_mode="BLEND")
        g.add_node(name, g.add_mesh(name, g.primitive(quad(0.9, 1.1), material)),
                   translation=(-2.0 + 0.35 * k, 0.6 + 0.1 * k, 0.5 - 0.45 * k), rotation=axis_angle((0, 1, 0), 20))
    gold = g.add_material("gold cube", (1.0, 0.75, 0.3, 1), 1.0, 0.35)
    g.add_node("gold cube", g.add_mesh("gold cube", g.primitive(cube(0.5), gold)), translation=(-0.3, 0.25, 0.8),
               rotation=axis_angle((0, 1, 0), 30))
    glass = g.add_material("glass ball", (0.75, 0.9, 1.0, 0.3), 0.0, 0.05, double_sided=True, alpha_mode="BLEND")
    g.add_node("glass ball", g.add_mesh("glass ball", g.primitive(uv_sphere(0.6, 32, 16), glass)), translation=(-0.3, 0.6, 0.8))
    image = g.add_image("frosted glass 64x64 RGBA", glass_texture())
    texture = g.add_texture(image, g.add_sampler(LINEAR, LINEAR_MIPMAP_LINEAR, CLAMP_TO_EDGE, CLAMP_TO_EDGE))
    frosted = g.add_material("frosted pane", (1, 1, 1, 1), 0.0, 0.3, texture=texture, double_sided=True, alpha_mode="BLEND")
    g.add_node("frosted pane", g.add_mesh("frosted pane", g.primitive(quad(1.1, 1.1), frosted)), translation=(1.9, 0.75, -0.1),
               rotation=axis_angle((0, 1, 0), -20))
    ramp = quad(1.2, 0.35)
    colors = g.add_accessor([(0.95, 0.5, 0.1, 0.0), (0.95, 0.5, 0.1, 1.0), (0.95, 0.5, 0.1, 1.0), (0.95, 0.5, 0.1, 0.0)], "VEC4")
    material = g.add_material("alpha ramp", (1, 1, 1, 1), 0.0, 0.6, double_sided=True, alpha_mode="BLEND")
    g.add_node("alpha ramp", g.add_mesh("alpha ramp", g.primitive(ramp, material, colors=colors)), translation=(1.5, 0.2, 0.9))
    for name, color, turn in (("amber pane", (0.95, 0.6, 0.1, 0.6), 35), ("violet pane", (0.55, 0.25, 0.85, 0.6), -35)):
        material = g.add_material(name, color, 0.0, 0.5, double_sided=True, alpha_mode="BLEND")
        g.add_node(name, g.add_mesh(name, g.primitive(quad(1.3, 0.9), material)), translation=(0.7, 0.9, -1.4),
                   rotation=axis_angle((0, 1, 0), turn))
    wall = g.add_material("wall", (0.75, 0.72, 0.68, 1), 0.0, 0.9)
    g.add_node("wall", g.add_mesh("wall", g.primitive(quad(7, 3), wall)), translation=(0, 1.5, -2.6))
    add_ground(g, 8, 7)
    g.add_camera("camera", (0.2, 2.6, 6.4), (0.0, 0.6, -0.4))
    g.add_light("key", "point", (2.0, 4.0, 3.5), intensity=20)
    return g


def antialiasing():
    g = Gltf("Anti-aliasing (with --set antialiasing.samples=4, 9 or 16, and antialiasing.pattern=jittered): "
             "geometry finer than a pixel, which mipmaps cannot smooth. A floor of 1 m tiles in two colours "
             "receding to the horizon, whose far rows break into moire with one sample per pixel; a wheel of 40 "
             "spokes that thin to a point at its hub; five wires at shallow slopes, whose edges step; each edge "
             "averaged in linear light where samples resolve it.")
    light_tiles, dark_tiles = [], []
    for row in range(40):
        for col in range(-8, 8):
            (light_tiles if (row + col) % 2 == 0 else dark_tiles).append((col, -row))
    for name, tiles, color in (("light tiles", light_tiles, (0.85, 0.85, 0.8, 1)), ("dark tiles", dark_tiles, (0.08, 0.08, 0.1, 1))):
        positions, normals, indices = [], [], []
        for x, z in tiles:
            n = len(positions)
            positions += [(x, 0, z), (x + 1, 0, z), (x + 1, 0, z - 1), (x, 0, z - 1)]
            normals += [(0, 1, 0)] * 4
            indices += quad_indices(n, n + 1, n + 2, n + 3)
        g.add_node(name, g.add_mesh(name, g.primitive(Mesh(positions, normals, indices), g.add_material(name, color, 0.0, 0.8))),
                   translation=(0, 0, 2))
    positions, normals, indices = [], [], []
    for k in range(40):
        a0, a1 = 2 * math.pi * k / 40, 2 * math.pi * (k + 0.35) / 40  # each spoke a thin wedge, 35 % of its sector
        n = len(positions)
        positions += [(0, 0, 0), (math.cos(a0), math.sin(a0), 0), (math.cos(a1), math.sin(a1), 0)]
        normals += [(0, 0, 1)] * 3
        indices += [n, n + 1, n + 2]
    g.add_node("wheel", g.add_mesh("wheel", g.primitive(Mesh(positions, normals, indices),
                                                       g.add_material("wheel", (0.9, 0.3, 0.1, 1), 0.0, 0.5, double_sided=True))),
               translation=(-1.6, 1.5, -2.0), scale=(1.2, 1.2, 1.2))
    for k in range(5):
        wire = cube(1.0)
        g.add_node("wire %d" % k, g.add_mesh("wire %d" % k, g.primitive(wire, g.add_material("wire %d" % k, (0.2, 0.5, 0.95, 1), 0.0, 0.4))),
                   translation=(1.6, 0.8 + 0.35 * k, -2.0), rotation=axis_angle((0, 0, 1), 3 + 4 * k), scale=(2.6, 0.03, 0.03))
    g.add_camera("camera", (0.0, 1.6, 4.0), (0.0, 0.9, -4.0))
    g.add_light("sun", "directional", (-2, 6, 4), (0, 0, 0), intensity=1.2)
    return g


def write_png(path, png_bytes):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "wb") as out:
        out.write(png_bytes)
    print("%-45s %7d bytes" % (os.path.relpath(path, ROOT), os.path.getsize(path)))


# ---------------------------------------------------------------- B. the course tour

def transformations():
    g = Gltf("Model transformations compose: a parent node T * R * S (translated 0.5 m up, turned 30 degrees about "
             "y, scaled 1.5) carries a grey hub and its own axes (x red, y green, z blue, each 1 m long locally); "
             "its children are translated in its frame: a yellow cube at the end of its x axis with a white "
             "sphere on top (a grandchild, scaled 0.5), and a cyan cube at the end of its z axis, turned 45 "
             "degrees about its own x. Everything the parent does, its children follow.")
    box, ball = cube(), uv_sphere(0.5, 24, 12)
    mat = {name: g.add_material(name, color, 0.0, roughness) for name, color, roughness in (
        ("grey", (0.55, 0.55, 0.6, 1), 0.5), ("red", (0.85, 0.1, 0.1, 1), 0.5), ("green", (0.1, 0.7, 0.15, 1), 0.5),
        ("blue", (0.1, 0.25, 0.9, 1), 0.5), ("yellow", (0.9, 0.75, 0.1, 1), 0.4), ("cyan", (0.1, 0.7, 0.8, 1), 0.4),
        ("white", (0.9, 0.9, 0.9, 1), 0.3))}
    meshes = {name: g.add_mesh(name + " cube", g.primitive(box, mat[name])) for name in mat if name != "white"}
    parent = g.add_node("parent: T * R * S", translation=(0, 0.5, 0), rotation=axis_angle((0, 1, 0), 30),
                        scale=(1.5, 1.5, 1.5))
    g.add_node("hub", meshes["grey"], scale=(0.25, 0.25, 0.25), parent=parent)
    thin = 0.06
    for name, axis, size in (("red", (0.5, 0, 0), (1, thin, thin)), ("green", (0, 0.5, 0), (thin, 1, thin)),
                             ("blue", (0, 0, 0.5), (thin, thin, 1))):
        g.add_node("parent's axis, " + name, meshes[name], translation=axis, scale=size, parent=parent)
    child_x = g.add_node("child: translated along x", meshes["yellow"], translation=(1.2, 0, 0),
                         scale=(0.4, 0.4, 0.4), parent=parent)
    g.add_node("grandchild: translated up, scaled 0.5", g.add_mesh("white sphere", g.primitive(ball, mat["white"])),
               translation=(0, 1.0, 0), scale=(0.5, 0.5, 0.5), parent=child_x)
    g.add_node("child: translated along z, rotated about x", meshes["cyan"], translation=(0, 0, 1.2),
               rotation=axis_angle((1, 0, 0), 45), scale=(0.4, 0.4, 0.4), parent=parent)
    add_ground(g, 8, 8)
    g.add_camera("camera", (3.2, 3.0, 4.6), (0.4, 0.4, 0.6))
    g.add_light("sun", "directional", (-2, 5, 3), (0, 0, 0), intensity=1.1)
    return g


def projections():
    g = Gltf("Six equal 0.6 m cubes in a row receding along -z, every 1.5 m, alternately orange and teal. "
             "The first camera (perspective, used by default) makes them shrink towards a vanishing point; "
             "the second (orthographic, same place and direction) keeps them equal in size.")
    box = cube(0.6)
    orange = g.add_mesh("orange cube", g.primitive(box, g.add_material("orange", (0.9, 0.45, 0.1, 1), 0.0, 0.5)))
    teal = g.add_mesh("teal cube", g.primitive(box, g.add_material("teal", (0.1, 0.6, 0.6, 1), 0.0, 0.5)))
    for i in range(6):
        g.add_node("cube %d" % (i + 1), orange if i % 2 == 0 else teal, translation=(0, 0.3, 1.5 - 1.5 * i))
    add_ground(g, 6, 14, translation=(0, 0, -2))
    eye, target = (1.8, 1.4, 4.0), (0, 0.3, -2.5)
    g.add_camera("perspective camera", eye, target, yfov_deg=40)
    g.add_orthographic_camera("orthographic camera", eye, target, xmag=3.2, ymag=2.4)
    g.add_light("sun", "directional", (-3, 5, 2), (0, 0, -2), intensity=1.1)
    return g


def culling():
    g = Gltf("Back-face culling: an open box (no top) and a tube (a cylinder without caps), seen from above, "
             "beside a closed sphere. With culling on, only their outer walls that face the camera are drawn: "
             "the ground shows through where the inner walls and the box's floor (all back faces) would be. "
             "With culling off, the insides show. The sphere looks the same either way.")
    open_box = cube(1.0, skip=("+y",))
    tube = cylinder(0.45, 1.0, 24, caps=False)
    g.add_node("open box", g.add_mesh("open box", g.primitive(open_box, g.add_material(
        "orange", (0.9, 0.5, 0.15, 1), 0.0, 0.6))), translation=(-1.3, 0.5, 0))
    g.add_node("tube", g.add_mesh("tube", g.primitive(tube, g.add_material(
        "teal", (0.15, 0.6, 0.65, 1), 0.0, 0.6))), translation=(0.2, 0, 0))
    g.add_node("closed sphere", g.add_mesh("sphere", g.primitive(uv_sphere(0.45, 24, 12), g.add_material(
        "violet", (0.5, 0.3, 0.8, 1), 0.0, 0.4))), translation=(1.5, 0.45, 0.1))
    add_ground(g, 8, 6)
    g.add_camera("camera", (0.4, 3.4, 3.4), (0.1, 0.2, 0))
    g.add_light("key", "point", (-1.5, 4.5, 2.5), intensity=28)
    return g


def hidden_surfaces():
    g = Gltf("Hidden surfaces: two long boxes cross through each other (red along x, blue turned 60 degrees), "
             "so each hides part of the other and their intersection is a crisp line; a green sphere passes "
             "through an upright cream panel, half of it in front, half behind and hidden.")
    box = cube()
    g.add_node("red box", g.add_mesh("red box", g.primitive(box, g.add_material(
        "red", (0.85, 0.15, 0.1, 1), 0.0, 0.5))), translation=(-1.0, 0.35, 0), scale=(2.0, 0.5, 0.5))
    g.add_node("blue box", g.add_mesh("blue box", g.primitive(box, g.add_material(
        "blue", (0.15, 0.3, 0.85, 1), 0.0, 0.5))), translation=(-1.0, 0.4, 0), rotation=axis_angle((0, 1, 0), 60),
        scale=(2.0, 0.4, 0.6))
    g.add_node("panel", g.add_mesh("panel", g.primitive(quad(1.4, 1.4), g.add_material(
        "cream", (0.9, 0.85, 0.7, 1), 0.0, 0.7))), translation=(1.3, 0.7, 0), rotation=axis_angle((0, 1, 0), -20))
    g.add_node("sphere through the panel", g.add_mesh("sphere", g.primitive(uv_sphere(0.45, 32, 16), g.add_material(
        "green", (0.2, 0.75, 0.3, 1), 0.0, 0.35))), translation=(1.25, 0.75, 0.05))
    add_ground(g, 8, 6)
    g.add_camera("camera", (0.6, 2.4, 4.4), (0.1, 0.45, 0))
    g.add_light("key", "point", (-2.0, 4.5, 3.0), intensity=30)
    return g


def lighting():
    g = Gltf("Illumination: two rows of five spheres of one colour, roughness 0.1, 0.3, 0.5, 0.7, 0.9 from left "
             "to right; front row metallic 0 (dielectric: bright diffuse, small white highlights growing wide "
             "and faint), back row metallic 1 (darker diffuse, stronger highlights). Lit by a warm point light "
             "(front left), a blue-white spot light from above aimed at the middle, and a dim directional "
             "light from the right.")
    ball = uv_sphere(0.35, 32, 16)
    for row, (metallic, z) in enumerate(((0.0, 0.6), (1.0, -0.4))):
        for i, roughness in enumerate((0.1, 0.3, 0.5, 0.7, 0.9)):
            name = "metallic %g, roughness %g" % (metallic, roughness)
            material = g.add_material(name, (0.75, 0.45, 0.2, 1), metallic, roughness)
            g.add_node(name, g.add_mesh(name, g.primitive(ball, material)), translation=(0.9 * (i - 2), 0.35, z))
    add_ground(g, 8, 6)
    g.add_camera("camera", (0, 2.0, 4.2), (0, 0.3, 0.1))
    g.add_light("point, warm", "point", (-2.5, 2.5, 2.5), color=(1.0, 0.85, 0.7), intensity=9)
    g.add_light("spot, blue-white", "spot", (0.5, 4.0, 1.0), (0, 0, 0.1), color=(0.75, 0.85, 1.0), intensity=7,
                inner_deg=20, outer_deg=32)
    g.add_light("directional, from the right", "directional", (4, 3, 1), (0, 0, 0), intensity=0.25)
    return g


def shading():
    g = Gltf("Shading models: a low-polygon sphere (12 x 6) and torus (12 x 6) with smooth normals, glossy, "
             "lit by one point light. Flat shading shows every facet; Gouraud smooths the facets but smears "
             "and loses the highlights; Phong keeps round highlights on the same coarse geometry.")
    g.add_node("low-poly sphere", g.add_mesh("low-poly sphere", g.primitive(uv_sphere(0.6, 12, 6), g.add_material(
        "glossy red", (0.8, 0.15, 0.1, 1), 0.0, 0.3))), translation=(-0.9, 0.6, 0))
    g.add_node("low-poly torus", g.add_mesh("low-poly torus", g.primitive(torus(0.5, 0.2, 12, 6), g.add_material(
        "glossy blue", (0.15, 0.3, 0.85, 1), 0.0, 0.3))), translation=(0.9, 0.62, 0), rotation=axis_angle((1, 0, 0), 50))
    add_ground(g, 8, 6)
    g.add_camera("camera", (0, 1.9, 3.6), (0, 0.5, 0))
    g.add_light("key", "point", (-1.5, 3.0, 2.5), intensity=12)
    return g


def shadows():
    g = Gltf("Shadow maps: a golden torus floating 1 m over the ground, tilted, and a small cube under it. A spot "
             "light from the front left and a point light from the right each throw a ring-shaped shadow of the "
             "torus (and one of the cube) on the ground; where the two shadows overlap it is darkest.")
    g.add_node("torus", g.add_mesh("torus", g.primitive(torus(0.6, 0.18, 48, 16), g.add_material(
        "gold", (0.85, 0.6, 0.2, 1), 0.0, 0.4))), translation=(0, 1.0, 0), rotation=axis_angle((1, 0, 0.3), 25))
    g.add_node("cube", g.add_mesh("cube", g.primitive(cube(0.4), g.add_material(
        "grey-blue", (0.4, 0.5, 0.7, 1), 0.0, 0.6))), translation=(0.1, 0.2, 0.1), rotation=axis_angle((0, 1, 0), 20))
    add_ground(g, 8, 8)
    g.add_camera("camera", (0.5, 3.0, 4.2), (0, 0.4, 0))
    g.add_light("spot", "spot", (-1.6, 3.8, 1.6), (0, 0.5, 0), intensity=11, inner_deg=25, outer_deg=40)
    g.add_light("point", "point", (2.4, 3.2, -0.6), intensity=9)
    return g


def texture():
    g = Gltf("Texture mapping: a 64x64 brick texture drawn by the script, with a cream letter F in its top-left "
             "corner, on every face of a cube (upright on the sides, the F readable, not mirrored) and on the "
             "floor, repeated 4 x 4 (F's top towards the back). REPEAT, mipmapped.")
    image = g.add_image("bricks with F", brick_texture())
    bricks = g.add_texture(image, g.add_sampler(LINEAR, LINEAR_MIPMAP_LINEAR, REPEAT, REPEAT))
    material = g.add_material("bricks", (1, 1, 1, 1), 0.0, 0.8, texture=bricks)
    g.add_node("textured cube", g.add_mesh("textured cube", g.primitive(cube(), material)),
               translation=(0, 0.5, 0), rotation=axis_angle((0, 1, 0), 30))
    g.add_node("textured floor", g.add_mesh("textured floor", g.primitive(plane(6, 6, 4), material)))
    g.add_camera("camera", (1.4, 1.8, 3.2), (0, 0.45, 0))
    g.add_light("key", "point", (-1.8, 3.5, 2.8), intensity=22)
    return g


def glass(ior=1.5, transmission=1.0, attenuation=None):
    """The extensions of a transmissive material: KHR_materials_transmission,
    KHR_materials_ior and, given (colour, distance), KHR_materials_volume."""
    extensions = {"KHR_materials_transmission": {"transmissionFactor": num(transmission)},
                  "KHR_materials_ior": {"ior": num(ior)}}
    if attenuation is not None:
        extensions["KHR_materials_volume"] = {"attenuationColor": nums(attenuation[0]), "attenuationDistance": num(attenuation[1]),
                                              "thicknessFactor": num(1.0)}
    return extensions


def checker_floor(g, name="checker floor", size=8.0, repeat=8.0):
    image = g.add_image("checker 64x64", png(64, 64, checker(64, 8, (40, 40, 46), (225, 222, 210))))
    texture = g.add_texture(image, g.add_sampler(LINEAR, LINEAR_MIPMAP_LINEAR, REPEAT, REPEAT))
    material = g.add_material(name, (1, 1, 1, 1), 0.0, 0.9, texture=texture)
    return g.add_node(name, g.add_mesh(name, g.primitive(plane(size, size, repeat), material)))


def reflection():
    g = Gltf("Recursive ray tracing, reflection (with --backend ray): two parallel mirrors, one ahead of the camera "
             "and one behind it, face each other across a checker floor with a red ball, a blue post and a gold "
             "sphere between them. Each mirror shows the other's image of the room again and again, smaller each "
             "time, once more for each level of ray.depth (1: no reflected rays, the mirrors lit as plain "
             "metal; 5, the default: four images deep, then the deepest mirror as plain metal). The polished gold "
             "sphere (metallic, roughness 0.15, so k_r = 0.85 O_d) mirrors the room tinted gold; with --set "
             "ray.gloss=true and ray.samples=64 its reflection spreads over its Phong lobe. The rasterizers draw "
             "the mirrors as plain metal.")
    mirror = g.add_material("mirror", (0.92, 0.94, 0.95, 1), 1.0, 0.0)
    g.add_node("back mirror", g.add_mesh("back mirror", g.primitive(quad(5.0, 2.6), mirror)), translation=(0, 1.3, -2.0))
    g.add_node("front mirror", g.add_mesh("front mirror", g.primitive(quad(5.0, 2.6), mirror)), translation=(0, 1.3, 5.0),
               rotation=axis_angle((0, 1, 0), 180))
    red = g.add_material("red ball", (0.85, 0.1, 0.08, 1), 0.0, 0.4)
    g.add_node("red ball", g.add_mesh("red ball", g.primitive(uv_sphere(0.35, 32, 16), red)), translation=(-0.9, 0.35, 0.2))
    blue = g.add_material("blue post", (0.1, 0.25, 0.8, 1), 0.0, 0.6)
    g.add_node("blue post", g.add_mesh("blue post", g.primitive(cylinder(0.15, 1.4, 24), blue)), translation=(1.0, 0.0, -0.9))
    gold = g.add_material("polished gold", (1.0, 0.76, 0.33, 1), 1.0, 0.15)
    g.add_node("gold sphere", g.add_mesh("gold sphere", g.primitive(uv_sphere(0.45, 48, 24), gold)), translation=(0.1, 0.45, 1.0))
    floor = checker_floor(g, size=5.0, repeat=5.0)
    g.doc["nodes"][floor]["scale"] = nums((1.0, 1.0, 1.4))
    g.doc["nodes"][floor]["translation"] = nums((0.0, 0.0, 1.5))
    g.add_camera("camera", (0.7, 1.35, 4.0), (0.0, 0.8, -2.0), yfov_deg=50)
    g.add_light("key", "point", (0.5, 2.6, 1.8), intensity=9)
    return g


def refraction():
    g = Gltf("Recursive ray tracing, refraction (with --backend ray): light bends by Snell's law at each glass "
             "surface (KHR_materials_transmission 1, KHR_materials_ior). Left: a clear slab (n = 1.5) turned 35 "
             "degrees in front of a striped wall; the stripes seen through it are displaced sideways by "
             "d = h sin(theta1 - theta2)/cos(theta2) and continue parallel, as the slab formula says. Middle: a ball "
             "of tinted glass (KHR_materials_volume: attenuationColor (0.4, 0.8, 0.5) after 0.5 m), darker where the "
             "rays inside it run longer (Beer's law), the floor upside down in it. Right: a diamond-like ball "
             "(n = 2.4) whose rays reflect totally inside it where they meet its surface past the critical angle "
             "(render prints the count of total internal reflections). The rasterizers draw the glass opaque.")
    stripes = g.add_image("stripes 64x8", png(64, 8, lambda x, y: (30, 30, 34) if (x // 8) % 2 else (235, 228, 205)))
    striped = g.add_material("striped wall", (1, 1, 1, 1), 0.0, 0.9,
                             texture=g.add_texture(stripes, g.add_sampler(LINEAR, LINEAR_MIPMAP_LINEAR, REPEAT, REPEAT)))
    wall = quad(6.0, 2.5)
    wall = Mesh(wall.positions, wall.normals, wall.indices, [(0, 1), (6, 1), (6, 0), (0, 0)])
    g.add_node("striped wall", g.add_mesh("striped wall", g.primitive(wall, striped)), translation=(0, 1.25, -1.6))
    clear = g.add_material("clear glass slab", (1, 1, 1, 1), 0.0, 0.0, extensions=glass(1.5))
    g.add_node("glass slab", g.add_mesh("glass slab", g.primitive(cube(1.0), clear)), translation=(-1.5, 0.7, -0.3),
               rotation=axis_angle((0, 1, 0), 35), scale=(1.1, 1.4, 0.25))
    tinted = g.add_material("tinted glass", (1, 1, 1, 1), 0.0, 0.0, extensions=glass(1.5, attenuation=((0.4, 0.8, 0.5), 0.5)))
    g.add_node("tinted ball", g.add_mesh("tinted ball", g.primitive(uv_sphere(0.5, 48, 24), tinted)), translation=(0.1, 0.5, 0.1))
    diamond = g.add_material("diamond", (1, 1, 1, 1), 0.0, 0.0, extensions=glass(2.4))
    g.add_node("diamond ball", g.add_mesh("diamond ball", g.primitive(uv_sphere(0.4, 48, 24), diamond)), translation=(1.5, 0.4, 0.0))
    checker_floor(g, size=6.0, repeat=6.0)
    g.add_camera("camera", (0.0, 1.6, 4.0), (0.0, 0.6, -0.4), yfov_deg=45)
    g.add_light("key", "point", (-1.0, 3.2, 2.5), intensity=14)
    return g


def depth_of_field():
    g = Gltf("Stochastic ray tracing, depth of field (with --backend ray --set camera.aperture=0.08 --set "
             "ray.samples=64): a row of seven coloured posts receding from 2 m to 8 m, on a checker floor. The "
             "thin lens keeps the eye depth camera.focusDistance sharp (0, the default: autofocus on what the image's centre "
             "shows, the fourth post) "
             "and spreads a point at depth z over a circle of radius aperture |z - f| / f; with aperture 0 (the "
             "default) every post is sharp, as the rasterizers draw it.")
    colors = ((0.85, 0.15, 0.1), (0.9, 0.5, 0.1), (0.85, 0.8, 0.15), (0.2, 0.7, 0.25), (0.15, 0.6, 0.8), (0.2, 0.3, 0.85), (0.6, 0.25, 0.8))
    for k, color in enumerate(colors):
        material = g.add_material("post %d" % k, color + (1,), 0.0, 0.5)
        g.add_node("post %d" % k, g.add_mesh("post %d" % k, g.primitive(cylinder(0.12, 1.0, 24), material)),
                   translation=(-0.9 + 0.3 * k, 0.0, 2.0 - 1.0 * k))
    checker_floor(g, size=12.0, repeat=12.0)
    g.add_camera("camera", (0.0, 0.9, 4.0), (0.0, 0.5, -1.0), yfov_deg=40)
    g.add_light("key", "point", (2.0, 4.0, 3.0), intensity=30)
    return g


def motion_blur():
    g = Gltf("Stochastic ray tracing, motion blur (with --backend ray --set camera.shutter=0.25 --set ray.samples=64): glTF "
             "node animations (translation, rotation; LINEAR, STEP and CUBICSPLINE keys) move a red ball across the "
             "floor at 4 m/s, spin a four-bladed propeller once a second, and drop a blue cube in steps while a spline stretches it "
             "(1.75 times as tall half way); --set time=T "
             "places them at T seconds in every backend, and the ray tracer's paths sample the shutter from T to "
             "T + camera.shutter, so the ball streaks over 1 m and the blades over a quarter turn, while the cube, "
             "which jumps between keys, is sharp unless a jump falls inside the shutter.")
    red = g.add_material("red ball", (0.85, 0.1, 0.08, 1), 0.0, 0.4)
    ball = g.add_node("moving ball", g.add_mesh("ball", g.primitive(uv_sphere(0.3, 32, 16), red)), translation=(-2.0, 0.3, 0.6))
    g.add_animation("ball across", ball, "translation", [0.0, 1.0], [(-2.0, 0.3, 0.6), (2.0, 0.3, 0.6)])
    blade_material = g.add_material("blades", (0.9, 0.75, 0.2, 1), 0.0, 0.5)
    hub = g.add_node("propeller", translation=(0.0, 1.5, -0.8))
    for k in range(4):
        g.add_node("blade %d" % k, g.add_mesh("blade %d" % k, g.primitive(cube(1.0), blade_material)), parent=hub,
                   rotation=axis_angle((0, 0, 1), 90 * k), translation=mul((math.cos(math.radians(90 * k)), math.sin(math.radians(90 * k)), 0), 0.45),
                   scale=(0.8, 0.14, 0.05))
    quarter = [tuple(axis_angle((0, 0, 1), -90 * k)) for k in range(5)]
    g.add_animation("propeller turning", hub, "rotation", [0.25 * k for k in range(5)], quarter)
    blue = g.add_material("blue cube", (0.15, 0.3, 0.85, 1), 0.0, 0.5)
    cube_node = g.add_node("stepping cube", g.add_mesh("cube", g.primitive(cube(0.5), blue)), translation=(1.6, 1.25, -0.2))
    g.add_animation("cube dropping", cube_node, "translation", [0.0, 0.3, 0.6, 0.9],
                    [(1.6, 1.25, -0.2), (1.6, 0.85, -0.2), (1.6, 0.5, -0.2), (1.6, 0.25, -0.2)], interpolation="STEP")
    # Hermite: scale y = 1 + 3(s - s^2), 1 at the keys, 1.75 half way.
    g.add_animation("cube stretching", cube_node, "scale", [0.0, 1.0],
                    [(0, 0, 0), (1, 1, 1), (0, 3, 0), (0, -3, 0), (1, 1, 1), (0, 0, 0)], interpolation="CUBICSPLINE")
    checker_floor(g, size=8.0, repeat=8.0)
    g.add_camera("camera", (0.0, 1.6, 4.5), (0.0, 0.8, 0.0), yfov_deg=45)
    g.add_light("key", "point", (1.5, 4.0, 3.0), intensity=25)
    return g


def particles():
    g = Gltf("Particle systems (renderer/PIPELINE.md, \"Particle systems\"; --set time=T, the viewer's play button): three emitters "
             "that glTF nodes place in their extras (facet_particles, with particles.N's keys, in the node's frame). Left: a "
             "fountain in a stone basin, particles born 600 a second at 4.5 m/s in a 10-degree cone, pulled down by gravity, "
             "bouncing off the basin's floor (restitution 0.4, friction 0.2) and fading from white-blue to deep blue. Middle: a "
             "fire whose sprites are blended additively (their light added to what is behind), rising against gravity with "
             "drag toward a wind that leans it right. Right: smoke blown by the same wind, large soft sprites blended over the "
             "scene, its node turned so that its emitter points up and back. Each sprite faces the camera, is tested against the "
             "z-buffer without writing it and blends back to front; both rasterizers draw every time T alike.")
    stone = g.add_material("stone", (0.45, 0.43, 0.4, 1), 0.0, 0.9)
    g.add_node("basin", g.add_mesh("basin", g.primitive(cylinder(0.6, 0.2, 48), stone)), translation=(-1.4, 0.1, 0.0))
    fountain = {"rate": 600, "speed": 4.5, "spread": 10, "lifetime": 2.5, "startSize": 0.06, "endSize": 0.12,
                "groundHeight": 0.2, "startColor": [0.7, 0.85, 1.0], "endColor": [0.05, 0.25, 0.9], "seed": 3}
    g.add_node("fountain emitter", translation=(-1.4, 0.22, 0.0), extras={"facet_particles": fountain})
    logs = g.add_material("logs", (0.3, 0.18, 0.1, 1), 0.0, 0.8)
    for k in range(3):
        g.add_node("log %d" % k, g.add_mesh("log %d" % k, g.primitive(cylinder(0.08, 0.7, 16), logs)), translation=(0.2, 0.08, 0.0),
                   rotation=axis_angle(normalize((math.cos(math.radians(60 * k)), 0, math.sin(math.radians(60 * k)))), 90))
    fire = {"rate": 400, "speed": 0.6, "speedSpread": 0.3, "spread": 25, "lifetime": 1.2, "startSize": 0.25, "endSize": 0.05,
            "gravity": [0, 1.5, 0], "drag": 0.02, "mass": 0.01, "wind": [0.6, 0, 0], "ground": False,
            "startColor": [1.0, 0.55, 0.12], "endColor": [0.6, 0.05, 0.0], "startAlpha": 0.8, "endAlpha": 0.0,
            "blending": "additive", "seed": 5}
    g.add_node("fire emitter", translation=(0.2, 0.15, 0.0), extras={"facet_particles": fire})
    smoke = {"rate": 60, "speed": 0.8, "spread": 15, "lifetime": 4.0, "startSize": 0.2, "endSize": 0.9,
             "gravity": [0, 0.3, 0], "drag": 0.01, "mass": 0.01, "wind": [0.5, 0, -0.2], "ground": False,
             "startColor": [0.35, 0.35, 0.37], "endColor": [0.7, 0.7, 0.72], "startAlpha": 0.5, "endAlpha": 0.0, "seed": 9}
    g.add_node("chimney", g.add_mesh("chimney", g.primitive(cube(1.0), stone)), translation=(1.6, 0.5, -0.4), scale=(0.35, 1.0, 0.35))
    g.add_node("smoke emitter", translation=(1.6, 1.02, -0.4), rotation=axis_angle((1, 0, 0), -20), extras={"facet_particles": smoke})
    checker_floor(g, size=8.0, repeat=8.0)
    g.add_camera("camera", (0.0, 1.8, 5.0), (0.0, 0.9, 0.0), yfov_deg=45)
    g.add_light("key", "point", (-1.5, 4.0, 3.0), intensity=25)
    return g


SCENES = [
    (MATERIALS_DIR, "sparse.gltf", sparse),
    (MATERIALS_DIR, "textured_wraps.gltf", textured_wraps),
    (MATERIALS_DIR, "grazing_checker.gltf", grazing_checker),
    (MATERIALS_DIR, "mipmap_modes.gltf", mipmap_modes),
    (MATERIALS_DIR, "texture_transform.gltf", texture_transform),
    (MATERIALS_DIR, "alpha_mask.gltf", alpha_mask),
    (MATERIALS_DIR, "pbr_maps.gltf", pbr_maps),
    (MATERIALS_DIR, "normal_map.gltf", normal_map),
    (MATERIALS_DIR, "lines_points.gltf", lines_points),
    (MATERIALS_DIR, "texcoord_sets.gltf", texcoord_sets),
    (ASSETS_DIR, "transformations.gltf", transformations),
    (ASSETS_DIR, "projections.gltf", projections),
    (ASSETS_DIR, "culling.gltf", culling),
    (ASSETS_DIR, "hidden_surfaces.gltf", hidden_surfaces),
    (ASSETS_DIR, "lighting.gltf", lighting),
    (ASSETS_DIR, "shading.gltf", shading),
    (ASSETS_DIR, "shadows.gltf", shadows),
    (ASSETS_DIR, "texture.gltf", texture),
    (ASSETS_DIR, "environment.gltf", environment),
    (ASSETS_DIR, "displacement.gltf", displacement),
    (ASSETS_DIR, "materials.gltf", materials),
    (ASSETS_DIR, "bump.gltf", bump),
    (ASSETS_DIR, "fog.gltf", fog),
    (ASSETS_DIR, "painter.gltf", painter),
    (ASSETS_DIR, "transparency.gltf", transparency),
    (ASSETS_DIR, "antialiasing.gltf", antialiasing),
    (ASSETS_DIR, "reflection.gltf", reflection),
    (ASSETS_DIR, "refraction.gltf", refraction),
    (ASSETS_DIR, "depth_of_field.gltf", depth_of_field),
    (ASSETS_DIR, "motion_blur.gltf", motion_blur),
    (ASSETS_DIR, "particles.gltf", particles),
]


def main():
    for folder, name, build in SCENES:
        build().write(os.path.join(folder, name))
    write_png(os.path.join(ASSETS_DIR, "environment", "sky_cube.png"), sky_cube())
    write_png(os.path.join(ASSETS_DIR, "displacement", "height.png"), height_map())


if __name__ == "__main__":
    main()
