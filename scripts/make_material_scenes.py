#!/usr/bin/env python3
"""Writes the material test scenes of assets/scenes (run from anywhere):
red_cube.gltf (glTF's default metallic and roughness), vertex_colors.gltf
(COLOR_0 as float RGB, normalized unsigned byte RGBA and unsigned short
RGBA), double_sided.gltf (two quads seen from behind, one double-sided) and
unlit.gltf (a KHR_materials_unlit cube beside a lit one).
The output is the same bytes on every run."""
import base64
import json
import os
import struct

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "assets", "scenes")

# A unit cube [-0.5, 0.5]^3, four vertices per face, counter-clockwise outside.
FACES = [((1, 0, 0), (0, 0, -1), (0, 1, 0)), ((-1, 0, 0), (0, 0, 1), (0, 1, 0)), ((0, 1, 0), (1, 0, 0), (0, 0, -1)),
         ((0, -1, 0), (1, 0, 0), (0, 0, 1)), ((0, 0, 1), (1, 0, 0), (0, 1, 0)), ((0, 0, -1), (-1, 0, 0), (0, 1, 0))]
FACE_COLORS = [(1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 1, 0), (0, 1, 1), (1, 0, 1)]


def cube():
    positions, normals, indices = [], [], []
    for n, u, v in FACES:
        base = len(positions)
        for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
            positions.append(tuple(0.5 * n[k] + 0.5 * su * u[k] + 0.5 * sv * v[k] for k in range(3)))
            normals.append(n)
        indices += [base, base + 1, base + 2, base, base + 2, base + 3]
    return positions, normals, indices


def quad(size):
    """The square [-size, size]^2 of y = 0, facing +y."""
    s = size
    return [(-s, 0, s), (s, 0, s), (s, 0, -s), (-s, 0, -s)], [(0, 1, 0)] * 4, [0, 1, 2, 0, 2, 3]


class Gltf:
    def __init__(self):
        self.data = bytearray()
        self.doc = {"asset": {"version": "2.0", "generator": "facet scenes"}, "scene": 0, "scenes": [{"nodes": []}],
                    "nodes": [], "meshes": [], "materials": [], "accessors": [], "bufferViews": []}

    def view(self, raw, target):
        while len(self.data) % 4:
            self.data.append(0)
        self.doc["bufferViews"].append({"buffer": 0, "byteOffset": len(self.data), "byteLength": len(raw), "target": target})
        self.data += raw
        return len(self.doc["bufferViews"]) - 1

    def accessor(self, values, kind, component, fmt, normalized=False, target=34962):
        flat = [c for v in values for c in (v if isinstance(v, tuple) else (v,))]
        a = {"bufferView": self.view(struct.pack("<%d%s" % (len(flat), fmt), *flat), target), "componentType": component,
             "count": len(values), "type": kind}
        if normalized:
            a["normalized"] = True
        if kind == "VEC3" and component == 5126 and not normalized:
            a["min"] = [min(v[k] for v in values) for k in range(3)]
            a["max"] = [max(v[k] for v in values) for k in range(3)]
        self.doc["accessors"].append(a)
        return len(self.doc["accessors"]) - 1

    def mesh(self, name, positions, normals, indices, material, colors=None):
        attributes = {"POSITION": self.accessor(positions, "VEC3", 5126, "f"), "NORMAL": self.accessor(normals, "VEC3", 5126, "f")}
        if colors:
            attributes["COLOR_0"] = self.accessor(*colors)
        prim = {"attributes": attributes, "indices": self.accessor(indices, "SCALAR", 5125, "I", target=34963), "material": material}
        self.doc["meshes"].append({"name": name, "primitives": [prim]})
        return len(self.doc["meshes"]) - 1

    def material(self, name, pbr, **extra):
        self.doc["materials"].append(dict({"name": name, "pbrMetallicRoughness": pbr}, **extra))
        return len(self.doc["materials"]) - 1

    def node(self, node):
        self.doc["nodes"].append(node)
        self.doc["scenes"][0]["nodes"].append(len(self.doc["nodes"]) - 1)

    def camera(self, translation, rotation):
        self.doc["cameras"] = [{"type": "perspective", "perspective": {"yfov": 0.7, "znear": 0.1, "zfar": 50}}]
        self.node({"name": "camera", "camera": 0, "translation": translation, "rotation": rotation})

    def light(self, name, light, translation, rotation=None):
        self.doc.setdefault("extensionsUsed", ["KHR_lights_punctual"])
        lights = self.doc.setdefault("extensions", {"KHR_lights_punctual": {"lights": []}})["KHR_lights_punctual"]["lights"]
        lights.append(light)
        node = {"name": name, "translation": translation, "extensions": {"KHR_lights_punctual": {"light": len(lights) - 1}}}
        if rotation:
            node["rotation"] = rotation
        self.node(node)

    def write(self, name):
        doc = dict(self.doc)
        doc["buffers"] = [{"byteLength": len(self.data),
                           "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(self.data)).decode()}]
        with open(os.path.join(OUT, name), "w") as f:
            json.dump(doc, f, indent=1, sort_keys=True)
            f.write("\n")


def look_down(pitch_deg):
    """A rotation quaternion (x, y, z, w) pitching the camera down by pitch_deg about x."""
    import math
    h = -0.5 * pitch_deg * math.pi / 180.0
    return [math.sin(h), 0.0, 0.0, math.cos(h)]


def ground(g):
    m = g.material("ground", {"baseColorFactor": [0.6, 0.6, 0.58, 1], "metallicFactor": 0, "roughnessFactor": 0.8})
    g.node({"name": "ground", "mesh": g.mesh("ground", *quad(3.0), m)})


def red_cube():
    """A plain red cube without metallicFactor/roughnessFactor (glTF's default 1 and 1): it must look red."""
    g = Gltf()
    ground(g)
    red = g.material("red", {"baseColorFactor": [0.8, 0.05, 0.05, 1]})
    g.node({"name": "red cube", "mesh": g.mesh("cube", *cube(), red), "translation": [0, 0.5, 0], "rotation": [0, 0.3826834, 0, 0.9238795]})
    g.light("sun", {"type": "point", "intensity": 14, "color": [1, 0.97, 0.92]}, [-2.5, 4, 3])
    g.camera([0, 1.6, 3.2], look_down(22))
    g.write("red_cube.gltf")


def vertex_colors():
    """Three cubes coloured per face through COLOR_0: float RGB, unsigned byte RGBA, unsigned short RGBA."""
    g = Gltf()
    ground(g)
    white = g.material("white", {"baseColorFactor": [1, 1, 1, 1], "metallicFactor": 0, "roughnessFactor": 0.6})
    per_vertex = [c for c in FACE_COLORS for _ in range(4)]
    encodings = [(per_vertex, "VEC3", 5126, "f"),
                 ([tuple(255 * k for k in c) + (255,) for c in per_vertex], "VEC4", 5121, "B", True),
                 ([tuple(65535 * k for k in c) + (65535,) for c in per_vertex], "VEC4", 5123, "H", True)]
    for i, colors in enumerate(encodings):
        mesh = g.mesh("cube %d" % i, *cube(), white, colors=colors)
        g.node({"name": "cube %d" % i, "mesh": mesh, "translation": [1.4 * (i - 1), 0.5, 0], "rotation": [0.2, 0.35, 0, 0.915]})
    g.light("lamp", {"type": "point", "intensity": 14}, [-1.5, 4, 3])
    g.camera([0, 2.2, 5.2], look_down(22))
    g.write("vertex_colors.gltf")


def double_sided():
    """Two upright quads whose fronts face away from the camera: the left one is
    double-sided (drawn, lit from behind), the right one single-sided (culled)."""
    g = Gltf()
    ground(g)
    both = g.material("double-sided", {"baseColorFactor": [0.2, 0.5, 0.9, 1], "metallicFactor": 0, "roughnessFactor": 0.5}, doubleSided=True)
    one = g.material("single-sided", {"baseColorFactor": [0.9, 0.4, 0.1, 1], "metallicFactor": 0, "roughnessFactor": 0.5})
    # quad() faces +y; rotated -90° about x it faces -z, away from the camera at +z.
    facing_away = [-0.7071068, 0, 0, 0.7071068]
    g.node({"name": "double-sided quad", "mesh": g.mesh("quad a", *quad(0.6), both), "translation": [-0.8, 0.7, 0], "rotation": facing_away})
    g.node({"name": "single-sided quad", "mesh": g.mesh("quad b", *quad(0.6), one), "translation": [0.8, 0.7, 0], "rotation": facing_away})
    g.light("lamp", {"type": "point", "intensity": 8}, [0.5, 3, 3])
    g.camera([0, 1.2, 3.5], look_down(8))
    g.write("double_sided.gltf")


def unlit():
    """red_cube.gltf's lit cube, and behind it on the right a green cube whose material is
    KHR_materials_unlit: its base colour at every pixel, whatever the light and the shading."""
    g = Gltf()
    ground(g)
    red = g.material("red", {"baseColorFactor": [0.8, 0.05, 0.05, 1]})
    green = g.material("unlit green", {"baseColorFactor": [0.1, 0.7, 0.25, 1]}, extensions={"KHR_materials_unlit": {}})
    g.node({"name": "red cube", "mesh": g.mesh("cube", *cube(), red), "translation": [0, 0.5, 0], "rotation": [0, 0.3826834, 0, 0.9238795]})
    g.node({"name": "unlit green cube", "mesh": g.mesh("unlit cube", *cube(), green), "translation": [1.5, 0.5, -2.2], "rotation": [0, 0.258819, 0, 0.9659258]})
    g.light("sun", {"type": "point", "intensity": 14, "color": [1, 0.97, 0.92]}, [-2.5, 4, 3])
    g.camera([0, 1.6, 3.2], look_down(22))
    g.doc["extensionsUsed"].append("KHR_materials_unlit")
    g.write("unlit.gltf")


if __name__ == "__main__":
    red_cube()
    vertex_colors()
    double_sided()
    unlit()
