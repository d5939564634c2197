#pragma once
// The field table of RenderSettings: one visit function lists every field
// with its key, a label, its unit, its range and a line of help. JSON
// reading and writing, the command line, `facet settings --keys` and the
// viewer's controls are all driven by it, so a new field is added in one
// place.
#include <string_view>

#include "settings/render_settings.h"

namespace facet {

// Color: a vec3 of linear RGB (the viewer shows a colour picker). A string
// field is a file name unless it is Text (a transfer function's points).
enum class FieldKind { Value, Color, Text };

// One field: {key, label, unit, help, min, max, kind}.
//
// The label is what the viewer's panel calls the field, in the course's words
// and symbols ("half-angle of view", "shadow bias minimum b_min"), never the
// camelCase key.
//
// The unit is what the number is measured in ("degrees", "pixels", "texels",
// "world units", "seconds", "kg", "m/s^2"). It is empty where there is none:
// booleans, choices, file names and colours; integer counts and seeds
// (samples, levels, subdivisions); and pure numbers: coefficients, fractions
// and alphas in [0, 1], the light's intensity and attenuation factors, the
// shininess exponent, the index of refraction. A number whose range reaches
// outside [0, 1] has a unit unless it is one of these pure numbers
// (tests/settings/test_settings_table.cpp holds the list).
struct FieldInfo {
  std::string_view key;         // JSON key within its group
  std::string_view label = {};  // the viewer's label, in the course's words
  std::string_view unit = {};   // "degrees", "world units", ...; empty: none (see above)
  std::string_view help = {};   // one line for --help and the viewer's tooltips
  double min = 0, max = 0;      // inclusive range for numbers (min == max: unbounded)
  FieldKind kind = FieldKind::Value;
};

// A nested object of settings: its key and the header the viewer shows.
// A visitor that needs only the key may take a std::string_view.
struct GroupInfo {
  std::string_view key;    // "shadows"
  std::string_view label;  // "shadow maps"
  constexpr operator std::string_view() const { return key; }
};

// Visitor interface (duck-typed): v.field(info, T& value) for float, int,
// bool, glm::vec3, std::optional<float>, std::string (a file path) and enums with a names table
// (v.choice(info, Enum& value, names)); v.group(GroupInfo, fn) for nested objects;
// v.list(info, std::vector<T>&) for a list (the lights, the particle
// emitters), whose elements visitItem describes.

// A list of settings items: its key, its label, what one item is called, the most it may hold.
struct ListInfo {
  std::string_view key;    // "particles"
  std::string_view label;  // "particle emitters"
  std::string_view item;   // "emitter"
  std::size_t max = 0;
  std::string_view help;
};

template <class Visitor>
void visitItem(Visitor& v, Light& l) {
  v.choice({"kind", "light kind", "", "point, directional or spot"}, l.kind, kLightKindNames);
  v.field({"position", "light position", "world units", "world position (point, spot)"}, l.position);
  v.field({"direction", "light direction", "", "world direction the light shines in (directional, spot)"}, l.direction);
  v.field({"color", "light colour", "", "linear RGB, each in [0, 1]", 0, 1, FieldKind::Color}, l.color);
  v.field({"intensity", "intensity I_p", "", "I_p = intensity * color", 0, 1e6}, l.intensity);
  v.field({"attenuation", "attenuation c1, c2, c3", "", "c1, c2, c3 of f_att = min(1, 1/(c1 + c2 d + c3 d^2)), each >= 0", 0, 1e6}, l.attenuation);
  v.field({"spotCutoff", "cut-off angle beta", "degrees", "spot cut-off angle beta in degrees", 0.1, 89.9}, l.spotCutoffDeg);
  v.field({"castsShadow", "casts shadows", "", "render a shadow map for this light"}, l.castsShadow);
  v.field({"radius", "light radius", "world units or degrees",
           "ray: soft shadows from a sphere of this radius (point, spot; world units) or a cone of this half-angle (directional; degrees)", 0, 1e6},
          l.radius);
}

template <class Visitor>
void visitItem(Visitor& v, Emitter& e) {
  v.field({"position", "birth position", "world units", "world position where particles are born"}, e.position);
  v.field({"rate", "birth rate", "particles/s", "particles born per second", 1e-6, 1e9}, e.rate);
  v.field({"startTime", "first birth time", "seconds", "seconds: the first particle is born then", 0, 1e6}, e.startTime);
  v.field({"direction", "initial direction", "", "world direction of the initial velocity (not zero)"}, e.direction);
  v.field({"spread", "spread half-angle", "degrees", "degrees: initial directions fill a cone of this half-angle", 0, 180}, e.spread);
  v.field({"speed", "initial speed", "world units/s", "initial speed, world units per second", 0, 1e6}, e.speed);
  v.field({"speedSpread", "speed spread", "world units/s", "speeds are uniform in speed +- speedSpread", 0, 1e6}, e.speedSpread);
  v.field({"lifetime", "particle lifetime", "seconds", "seconds a particle lives", 1e-3, 1e4}, e.lifetime);
  v.field({"startColor", "colour at birth", "", "linear RGB at birth", 0, 1, FieldKind::Color}, e.startColor);
  v.field({"endColor", "colour at death", "", "linear RGB at death (linear in age between)", 0, 1, FieldKind::Color}, e.endColor);
  v.field({"startAlpha", "alpha at birth", "", "alpha at birth", 0, 1}, e.startAlpha);
  v.field({"endAlpha", "alpha at death", "", "alpha at death", 0, 1}, e.endAlpha);
  v.field({"startSize", "size at birth", "world units", "the sprite's side at birth, world units", 0, 1e6}, e.startSize);
  v.field({"endSize", "size at death", "world units", "the sprite's side at death, world units", 0, 1e6}, e.endSize);
  v.field({"mass", "mass m", "kg", "m in a = F/m, kg", 1e-9, 1e9}, e.mass);
  v.field({"gravity", "gravity g", "m/s^2", "acceleration on every particle, m/s^2"}, e.gravity);
  v.field({"drag", "drag coefficient k", "kg/s", "k of the drag force F = k (wind - v), kg/s", 0, 1e6}, e.drag);
  v.field({"wind", "wind velocity", "m/s", "the air's velocity, m/s"}, e.wind);
  v.field({"ground", "bounce off the ground", "", "particles bounce off the plane y = groundHeight"}, e.ground);
  v.field({"groundHeight", "ground height", "world units", "y of the ground plane", -1e6, 1e6}, e.groundHeight);
  v.field({"restitution", "restitution coefficient", "", "the share of the normal speed kept at a bounce", 0, 1}, e.restitution);
  v.field({"friction", "friction coefficient", "", "the share of the tangential speed lost at a bounce", 0, 1}, e.friction);
  v.field({"sprite", "sprite image", "", "a PNG with alpha drawn on each particle; empty: a soft disc"}, e.sprite);
  v.choice({"blending", "sprite blending", "", "over: the frame's blending equation; additive: C_o = C_b a_b + C_f a_f, adding light"}, e.blending,
           kSpriteBlendingNames);
  v.field({"castsShadow", "casts shadows", "", "the sprites cast shadows where their alpha is at least transparency.shadowCutoff"}, e.castsShadow);
  v.field({"seed", "random seed", "", "the generator's seed: the same seed, the same particles", 0, 16777216}, e.seed);
  v.field({"step", "time step", "seconds", "seconds: the fixed step Newton's laws are integrated with", 1e-5, 1}, e.step);
}

template <class Visitor>
void visitSettings(Visitor& v, RenderSettings& s) {
  v.field({"width", "image width", "pixels", "image width in pixels", 1, kMaxImageSide}, s.width);
  v.field({"height", "image height", "pixels", "image height in pixels", 1, kMaxImageSide}, s.height);
  v.group(GroupInfo{"camera", "camera"}, [&] {
    CameraSettings& c = s.camera;
    v.choice({"source", "camera source", "", "auto: the scene's camera or one fitted to the scene; manual: the values below"}, c.source,
             kSourceNames);
    v.field({"eye", "eye P_eye", "world units", "P_eye, world position of the eye (manual)"}, c.eye);
    v.field({"reference", "reference P_ref", "world units", "P_ref, the point looked at (manual)"}, c.reference);
    v.field({"up", "up vector v_up", "", "v_up, the up vector (manual)"}, c.up);
    v.choice({"projection", "projection type", "", "perspective or parallel"}, c.projection, kProjectionKindNames);
    v.field({"halfAngle", "half-angle of view", "degrees", "theta, horizontal half-angle of view in degrees", 0.5, 89.5}, c.halfAngleDeg);
    v.field({"parallelWidth", "view width W", "world units", "width W of the parallel view box in world units", 1e-6, 1e9}, c.parallelWidth);
    v.field({"near", "near plane N", "world units", "N, near plane distance (> 0)", 1e-6, 1e9}, c.near);
    v.field({"far", "far plane F", "world units", "F, far plane distance (> near)", 1e-6, 1e9}, c.far);
    v.field({"aperture", "aperture radius", "world units", "ray: thin-lens radius in world units (depth of field); 0: a pinhole", 0, 1e6},
            c.aperture);
    v.field({"focusDistance", "focus distance", "world units",
             "ray: the eye depth in focus, world units; 0: autofocus on what the image's centre shows", 0, 1e9},
            c.focusDistance);
    v.field({"shutter", "shutter time", "seconds", "ray: seconds the shutter stays open from `time`: motion blur of what the scene's animation moves",
             0, 1e6},
            c.shutter);
  });
  v.choice({"lightSource", "light source", "", "auto: the scene's lights or one fitted to the scene; manual: the list in lights"}, s.lightSource,
           kSourceNames);
  v.list({"lights", "lights", "light", kMaxLights, "the lights of lightSource = manual"}, s.lights);
  v.field({"ambient", "ambient intensity I_a", "", "I_a, ambient intensity", 0, 1}, s.ambient);
  v.choice({"shading", "shading model", "", "flat, gouraud, phong or pbr (glTF's metallic-roughness BRDF)"}, s.shading, kShadingModeNames);
  v.choice({"specular", "specular model", "", "phong (R.V) or blinn-phong (N.H)"}, s.specular, kSpecularModelNames);
  v.field({"cullBackFaces", "back-face culling", "", "drop triangles with signed window area <= 0; off: two-sided lighting"}, s.cullBackFaces);
  v.choice({"hsr", "hidden-surface removal", "",
            "hidden-surface removal: zbuffer, painter (triangles sorted by farthest eye depth, drawn back to front, no depth buffer) or "
            "scanline (the CPU backend's scanline z-buffer)"},
           s.hsr, kHiddenSurfaceNames);
  v.group(GroupInfo{"material", "material overrides"}, [&] {
    MaterialOverrides& m = s.material;
    v.field({"ka", "ambient coefficient k_a", "", "k_a for every material (null: derived from glTF)", 0, 1}, m.ka);
    v.field({"kd", "diffuse coefficient k_d", "", "k_d for every material (null: derived from glTF)", 0, 1}, m.kd);
    v.field({"ks", "specular coefficient k_s", "", "k_s for every material (null: derived from glTF)", 0, 1}, m.ks);
    v.field({"shininess", "shininess exponent n", "", "n for every material (null: derived from glTF)", 1, 4096}, m.shininess);
    v.field({"opacity", "opacity factor", "", "alpha factor for every material in place of glTF's; below 1 every material is blended (null: glTF's)",
             0, 1},
            m.opacity);
    v.field({"reflectivity", "reflectivity k_r", "",
             "ray: k_r = reflectivity O_s of the reflected ray for every material (null: metallic (1 - roughness))", 0, 1},
            m.reflectivity);
    v.field({"transmission", "transmission k_t", "", "ray: k_t of the transmitted ray for every material (null: KHR_materials_transmission)", 0, 1},
            m.transmission);
    v.field({"ior", "index of refraction n", "", "ray: index of refraction n for every material (null: KHR_materials_ior, 1.5)", 0.1, 10}, m.ior);
    v.choice({"procedural", "procedural pattern", "",
              "none, or a checker or noise pattern of the model-space point in place of every base colour texture"},
             m.procedural, kProceduralNames);
    v.field({"proceduralScale", "pattern scale k", "cells/model unit", "k: the pattern's cells per model unit", 0.01, 1000}, m.proceduralScale);
    v.field({"displacementMap", "displacement map", "", "a greyscale PNG height map h read at TEXCOORD_0: P' = P + (scale h) N; empty: none"},
            m.displacementMap);
    v.field({"displacementScale", "displacement scale", "model units", "model units a vertex moves along N where h = 1", -1000, 1000},
            m.displacementScale);
    v.field({"displacementSubdivisions", "displacement subdivisions k", "", "k: each triangle of a displaced mesh is split into 4^k first", 0,
             kMaxDisplacementSubdivisions},
            m.displacementSubdivisions);
    v.field({"bumpMap", "bump map", "", "a greyscale PNG height map h read at TEXCOORD_0 that bends N per pixel (phong, pbr); empty: none"},
            m.bumpMap);
    v.field({"bumpScale", "bump scale k", "texture-coordinate units", "k of the bump B = k h, in texture-coordinate units", -10, 10}, m.bumpScale);
  });
  v.choice({"blending", "blending equation", "",
            "straight: C_o = (C_f a_f + C_b a_b (1 - a_f)) / a_o; premultiplied: C_o = C_f + C_b (1 - a_f), the colour buffer holding C a"},
           s.blending, kBlendingNames);
  v.group(GroupInfo{"transparency", "transparency"}, [&] {
    TransparencySettings& t = s.transparency;
    v.choice({"sort", "sort order", "", "blended surfaces drawn back to front by object (bounding-box centre) or by triangle (farthest vertex)"},
             t.sort, kTransparencySortNames);
    v.field({"shadowCutoff", "shadow alpha cut-off", "", "a blended fragment casts a shadow where its alpha is at least this", 0, 1}, t.shadowCutoff);
  });
  v.group(GroupInfo{"antialiasing", "anti-aliasing"}, [&] {
    AntialiasingSettings& a = s.antialiasing;
    v.field({"samples", "samples per pixel", "", "supersampling: 1, 4, 9 or 16 samples per pixel (s x s), averaged in linear light", 1,
             kMaxSamplesPerSide * kMaxSamplesPerSide},
            a.samples);
    v.choice({"pattern", "sample pattern", "",
              "grid: the cells' centres; jittered: one seeded random position in each cell; area: exact coverage (CPU only)"},
             a.pattern, kSamplePatternNames);
    v.field({"seed", "random seed", "", "jittered: the generator's seed (the same seed places the same samples)", 0, 16777216}, a.seed);
  });
  v.group(GroupInfo{"shadows", "shadow maps"}, [&] {
    ShadowSettings& sh = s.shadows;
    v.field({"enabled", "shadow maps on", "", "2-pass shadow maps"}, sh.enabled);
    v.field({"mapSize", "shadow map size S", "texels", "S of the S x S shadow map", kMinShadowMapSize, kMaxShadowMapSize}, sh.mapSize);
    v.field({"biasSlope", "shadow bias slope b_slope", "", "b_slope of bias = max(b_slope (1 - N.L), b_min)", 0, 1}, sh.biasSlope);
    v.field({"biasMin", "shadow bias minimum b_min", "", "b_min of bias = max(b_slope (1 - N.L), b_min)", 0, 1}, sh.biasMin);
    v.field({"pcfRadius", "PCF radius r", "texels", "r: PCF over (2r+1)^2 samples, 0 = hard", 0, kMaxPcfRadius}, sh.pcfRadius);
  });
  v.group(GroupInfo{"textures", "textures"}, [&] {
    v.choice({"filter", "texture filter", "", "auto (each texture's sampler), nearest, bilinear or trilinear (mipmapped)"}, s.textures.filter,
             kTextureFilterNames);
  });
  v.group(GroupInfo{"environment", "environment map"}, [&] {
    EnvironmentSettings& e = s.environment;
    v.field({"map", "cube map file", "", "a cube map PNG, six square faces side by side (+x -x +y -y +z -z); empty: none"}, e.map);
    v.field({"reflectivity", "map reflectivity k_r", "", "k_r of the reflection k_r I_r, I_r the map in direction R = 2(N.V)N - V", 0, 1},
            e.reflectivity);
    v.field({"background", "map as background", "", "empty pixels show the map in their view direction"}, e.background);
  });
  v.group(GroupInfo{"fog", "fog"}, [&] {
    FogSettings& f = s.fog;
    v.choice({"mode", "fog mode", "", "the course's fog by eye depth d: none, linear, exponential (e^-density d) or exponential2 (e^-(density d)^2)"},
             f.mode, kFogModeNames);
    v.field({"color", "fog colour C_fog", "", "C_fog, linear RGB, each in [0, 1]", 0, 1, FieldKind::Color}, f.color);
    v.field({"start", "fog start depth", "world units", "linear: the eye depth where fog begins", 0, 1e9}, f.start);
    v.field({"end", "fog end depth", "world units", "linear: the eye depth where fog hides everything (> start)", 0, 1e9}, f.end);
    v.field({"density", "fog density", "per world unit", "exponential and exponential2: density per world unit", 0, 1e3}, f.density);
  });
  v.group(GroupInfo{"ray", "ray tracing"}, [&] {
    RaySettings& r = s.ray;
    v.field({"depth", "ray tree depth", "",
             "levels of the ray tree: 1 casts primary (and shadow) rays only; each more level reflects and refracts once more", 1, kMaxRayDepth},
            r.depth);
    v.field({"minContribution", "minimum ray weight", "",
             "a reflected or transmitted ray whose weight k_r or k_t (product along its path) is below this is not traced", 0, 1},
            r.minContribution);
    v.field({"epsilon", "offset epsilon", "scene radii",
             "a ray leaving a surface starts epsilon R off it (R: the scene's bounding radius), against surface acne", 0, 0.1},
            r.epsilon);
    v.field({"spheres", "exact spheres", "", "trace the builtin sphere as a sphere (the course's quadratic), not as its triangles"}, r.spheres);
    v.field({"samples", "paths per pixel", "",
             "paths per pixel: each samples the pixel, the lens, the lights' areas and the gloss and translucency lobes once", 1, kMaxRaySamples},
            r.samples);
    v.field({"seed", "random seed", "", "the paths' generator seed (the same seed, the same image, whatever the threads)", 0, 16777216}, r.seed);
    v.field({"gloss", "glossy reflection", "", "reflected rays spread over the Phong lobe of the surface's exponent n (glossy reflection)"}, r.gloss);
    v.field({"translucency", "translucent transmission", "", "transmitted rays spread over the same lobe (translucency)"}, r.translucency);
  });
  v.list({"particles", "particle emitters", "emitter", kMaxEmitters, "particle emitters, on top of those the scene's glTF nodes place"}, s.particles);
  v.group(GroupInfo{"volume", "volume rendering"}, [&] {
    VolumeSettings& vs = s.volume;
    v.field({"file", "volume file", "", "a NRRD (.nrrd, .nhdr) or NIfTI-1 (.nii, .nii.gz) volume, or builtin:marschner-lobb; empty: none"}, vs.file);
    v.field({"resolution", "built-in volume resolution", "", "builtin:marschner-lobb: samples along each axis", 2, 512}, vs.resolution);
    v.choice({"mode", "volume rendering mode", "", "raycast (v-buffer ray casting), splat (footprints back to front) or isosurface (marching cubes)"},
             vs.mode, kVolumeModeNames);
    v.field({"transfer", "transfer function", "",
             "the transfer function: a preset (grey, mri, bone, rainbow, iso-surface) or points 'value r g b a, ...', values increasing", 0, 0,
             FieldKind::Text},
            vs.transfer);
    v.field({"center", "box centre", "world units", "world position of the volume box's centre"}, vs.center);
    v.field({"size", "box size", "world units", "world length of the volume box's longest side", 1e-6, 1e9}, vs.size);
    v.field(
        {"rotation", "box rotation", "degrees", "degrees about x, then y, then z, about the box's centre (a scan's z up: [-90, 0, 0])", -360, 360},
        vs.rotation);
    v.field({"step", "ray step", "voxel spacings", "raycast: distance between samples along a ray, in voxel spacings", 0.01, 16}, vs.step);
    v.field({"earlyTermination", "early ray termination", "", "raycast: a ray stops once its opacity reaches this (1: never)", 0, 1},
            vs.earlyTermination);
    v.field({"emptySpaceSkipping", "empty-space skipping", "", "raycast: step over macro cells the transfer function makes transparent"},
            vs.emptySpaceSkipping);
    v.field(
        {"splatRadius", "splat radius", "voxel spacings", "splat: the footprint's radius in voxel spacings (Gaussian, sigma = radius / 3)", 0.5, 8},
        vs.splatRadius);
    v.field({"isoValue", "iso value", "data units", "isosurface: the iso value in the data's units (null: the mean of the data)", -1e30, 1e30},
            vs.isoValue);
    v.field({"isoColor", "isosurface colour", "", "isosurface: the mesh's base colour, linear RGB", 0, 1, FieldKind::Color}, vs.isoColor);
  });
  v.field({"time", "animation time", "seconds", "seconds into the scene's glTF animations: where they place its meshes", 0, 1e6}, s.time);
  v.field({"background", "background colour", "", "linear RGB of empty pixels, each in [0, 1]", 0, 1, FieldKind::Color}, s.background);
  v.field({"backgroundAlpha", "background alpha", "", "alpha of empty pixels in the PNG: 1 opaque, 0 transparent (as F3D's --no-background)", 0, 1},
          s.backgroundAlpha);
}

}  // namespace facet
