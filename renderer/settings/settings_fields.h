#pragma once
// The field table of RenderSettings: one visit function lists every field
// with its key, its range and a line of help. JSON reading and writing, the
// command line and the viewer's controls are all driven by it, so a new
// field is added in one place.
#include <string_view>

#include "settings/render_settings.h"

namespace facet {

enum class FieldKind { Value, Color };  // Color: a vec3 of linear RGB (the viewer shows a colour picker)

struct FieldInfo {
  std::string_view key;   // JSON key within its group
  std::string_view help;  // one line for --help and the viewer's tooltips
  double min = 0, max = 0;  // inclusive range for numbers (min == max: unbounded)
  FieldKind kind = FieldKind::Value;
};

// Visitor interface (duck-typed): v.field(info, T& value) for float, int,
// bool, glm::vec3, std::optional<float>, std::string (a file path) and enums with a names table
// (v.choice(info, Enum& value, names)); v.group(key, fn) for nested objects;
// v.list(info, std::vector<T>&) for a list (the lights, the particle
// emitters), whose elements visitItem describes.

// A list of settings items: its key, what one item is called, the most it may hold.
struct ListInfo {
  std::string_view key;   // "lights"
  std::string_view item;  // "light"
  std::size_t max = 0;
  std::string_view help;
};

template <class Visitor>
void visitItem(Visitor& v, Light& l) {
  v.choice({"kind", "point, directional or spot"}, l.kind, kLightKindNames);
  v.field({"position", "world position (point, spot)"}, l.position);
  v.field({"direction", "world direction the light shines in (directional, spot)"}, l.direction);
  v.field({"color", "linear RGB, each in [0, 1]", 0, 1, FieldKind::Color}, l.color);
  v.field({"intensity", "I_p = intensity * color", 0, 1e6}, l.intensity);
  v.field({"attenuation", "c1, c2, c3 of f_att = min(1, 1/(c1 + c2 d + c3 d^2)), each >= 0", 0, 1e6}, l.attenuation);
  v.field({"spotCutoff", "spot cut-off angle beta in degrees", 0.1, 89.9}, l.spotCutoffDeg);
  v.field({"castsShadow", "render a shadow map for this light"}, l.castsShadow);
  v.field({"radius", "ray: soft shadows from a sphere of this radius (point, spot; world units) or a cone of this half-angle (directional; degrees)",
           0, 1e6},
          l.radius);
}

template <class Visitor>
void visitItem(Visitor& v, Emitter& e) {
  v.field({"position", "world position where particles are born"}, e.position);
  v.field({"rate", "particles born per second", 1e-6, 1e9}, e.rate);
  v.field({"startTime", "seconds: the first particle is born then", 0, 1e6}, e.startTime);
  v.field({"direction", "world direction of the initial velocity (not zero)"}, e.direction);
  v.field({"spread", "degrees: initial directions fill a cone of this half-angle", 0, 180}, e.spread);
  v.field({"speed", "initial speed, world units per second", 0, 1e6}, e.speed);
  v.field({"speedSpread", "speeds are uniform in speed +- speedSpread", 0, 1e6}, e.speedSpread);
  v.field({"lifetime", "seconds a particle lives", 1e-3, 1e4}, e.lifetime);
  v.field({"startColor", "linear RGB at birth", 0, 1, FieldKind::Color}, e.startColor);
  v.field({"endColor", "linear RGB at death (linear in age between)", 0, 1, FieldKind::Color}, e.endColor);
  v.field({"startAlpha", "alpha at birth", 0, 1}, e.startAlpha);
  v.field({"endAlpha", "alpha at death", 0, 1}, e.endAlpha);
  v.field({"startSize", "the sprite's side at birth, world units", 0, 1e6}, e.startSize);
  v.field({"endSize", "the sprite's side at death, world units", 0, 1e6}, e.endSize);
  v.field({"mass", "m in a = F/m, kg", 1e-9, 1e9}, e.mass);
  v.field({"gravity", "acceleration on every particle, m/s^2"}, e.gravity);
  v.field({"drag", "k of the drag force F = k (wind - v), kg/s", 0, 1e6}, e.drag);
  v.field({"wind", "the air's velocity, m/s"}, e.wind);
  v.field({"ground", "particles bounce off the plane y = groundHeight"}, e.ground);
  v.field({"groundHeight", "y of the ground plane", -1e6, 1e6}, e.groundHeight);
  v.field({"restitution", "the share of the normal speed kept at a bounce", 0, 1}, e.restitution);
  v.field({"friction", "the share of the tangential speed lost at a bounce", 0, 1}, e.friction);
  v.field({"sprite", "a PNG with alpha drawn on each particle; empty: a soft disc"}, e.sprite);
  v.choice({"blending", "over: the frame's blending equation; additive: C_o = C_b a_b + C_f a_f, adding light"}, e.blending, kSpriteBlendingNames);
  v.field({"castsShadow", "the sprites cast shadows where their alpha is at least transparency.shadowCutoff"}, e.castsShadow);
  v.field({"seed", "the generator's seed: the same seed, the same particles", 0, 16777216}, e.seed);
  v.field({"step", "seconds: the fixed step Newton's laws are integrated with", 1e-5, 1}, e.step);
}

template <class Visitor>
void visitSettings(Visitor& v, RenderSettings& s) {
  v.field({"width", "image width in pixels", 1, kMaxImageSide}, s.width);
  v.field({"height", "image height in pixels", 1, kMaxImageSide}, s.height);
  v.group("camera", [&] {
    CameraSettings& c = s.camera;
    v.choice({"source", "auto: the scene's camera or one fitted to the scene; manual: the values below"}, c.source, kSourceNames);
    v.field({"eye", "P_eye, world position of the eye (manual)"}, c.eye);
    v.field({"reference", "P_ref, the point looked at (manual)"}, c.reference);
    v.field({"up", "v_up, the up vector (manual)"}, c.up);
    v.choice({"projection", "perspective or parallel"}, c.projection, kProjectionKindNames);
    v.field({"halfAngle", "theta, horizontal half-angle of view in degrees", 0.5, 89.5}, c.halfAngleDeg);
    v.field({"parallelWidth", "width W of the parallel view box in world units", 1e-6, 1e9}, c.parallelWidth);
    v.field({"near", "N, near plane distance (> 0)", 1e-6, 1e9}, c.near);
    v.field({"far", "F, far plane distance (> near)", 1e-6, 1e9}, c.far);
    v.field({"aperture", "ray: thin-lens radius in world units (depth of field); 0: a pinhole", 0, 1e6}, c.aperture);
    v.field({"focusDistance", "ray: the eye depth in focus, world units; 0: autofocus on what the image's centre shows", 0, 1e9},
            c.focusDistance);
    v.field({"shutter", "ray: seconds the shutter stays open from `time`: motion blur of what the scene's animation moves", 0, 1e6}, c.shutter);
  });
  v.choice({"lightSource", "auto: the scene's lights or one fitted to the scene; manual: the list in lights"}, s.lightSource, kSourceNames);
  v.list({"lights", "light", kMaxLights, "the lights of lightSource = manual"}, s.lights);
  v.field({"ambient", "I_a, ambient intensity", 0, 1}, s.ambient);
  v.choice({"shading", "flat, gouraud, phong or pbr (glTF's metallic-roughness BRDF)"}, s.shading, kShadingModeNames);
  v.choice({"specular", "phong (R.V) or blinn-phong (N.H)"}, s.specular, kSpecularModelNames);
  v.field({"cullBackFaces", "drop triangles with signed window area <= 0; off: two-sided lighting"}, s.cullBackFaces);
  v.choice({"hsr",
            "hidden-surface removal: zbuffer, painter (triangles sorted by farthest eye depth, drawn back to front, no depth buffer) or "
            "scanline (the CPU backend's scanline z-buffer)"},
           s.hsr, kHiddenSurfaceNames);
  v.group("material", [&] {
    MaterialOverrides& m = s.material;
    v.field({"ka", "k_a for every material (null: derived from glTF)", 0, 1}, m.ka);
    v.field({"kd", "k_d for every material (null: derived from glTF)", 0, 1}, m.kd);
    v.field({"ks", "k_s for every material (null: derived from glTF)", 0, 1}, m.ks);
    v.field({"shininess", "n for every material (null: derived from glTF)", 1, 4096}, m.shininess);
    v.field({"opacity", "alpha factor for every material in place of glTF's; below 1 every material is blended (null: glTF's)", 0, 1}, m.opacity);
    v.field({"reflectivity", "ray: k_r = reflectivity O_s of the reflected ray for every material (null: metallic (1 - roughness))", 0, 1},
            m.reflectivity);
    v.field({"transmission", "ray: k_t of the transmitted ray for every material (null: KHR_materials_transmission)", 0, 1}, m.transmission);
    v.field({"ior", "ray: index of refraction n for every material (null: KHR_materials_ior, 1.5)", 0.1, 10}, m.ior);
    v.choice({"procedural", "none, or a checker or noise pattern of the model-space point in place of every base colour texture"}, m.procedural,
             kProceduralNames);
    v.field({"proceduralScale", "k: the pattern's cells per model unit", 0.01, 1000}, m.proceduralScale);
    v.field({"displacementMap", "a greyscale PNG height map h read at TEXCOORD_0: P' = P + (scale h) N; empty: none"}, m.displacementMap);
    v.field({"displacementScale", "model units a vertex moves along N where h = 1", -1000, 1000}, m.displacementScale);
    v.field({"displacementSubdivisions", "k: each triangle of a displaced mesh is split into 4^k first", 0, kMaxDisplacementSubdivisions},
            m.displacementSubdivisions);
    v.field({"bumpMap", "a greyscale PNG height map h read at TEXCOORD_0 that bends N per pixel (phong, pbr); empty: none"}, m.bumpMap);
    v.field({"bumpScale", "k of the bump B = k h, in texture-coordinate units", -10, 10}, m.bumpScale);
  });
  v.choice({"blending",
            "straight: C_o = (C_f a_f + C_b a_b (1 - a_f)) / a_o; premultiplied: C_o = C_f + C_b (1 - a_f), the colour buffer holding C a"},
           s.blending, kBlendingNames);
  v.group("transparency", [&] {
    TransparencySettings& t = s.transparency;
    v.choice({"sort", "blended surfaces drawn back to front by object (bounding-box centre) or by triangle (farthest vertex)"}, t.sort,
             kTransparencySortNames);
    v.field({"shadowCutoff", "a blended fragment casts a shadow where its alpha is at least this", 0, 1}, t.shadowCutoff);
  });
  v.group("antialiasing", [&] {
    AntialiasingSettings& a = s.antialiasing;
    v.field({"samples", "supersampling: 1, 4, 9 or 16 samples per pixel (s x s), averaged in linear light", 1, kMaxSamplesPerSide * kMaxSamplesPerSide},
            a.samples);
    v.choice({"pattern", "grid: the cells' centres; jittered: one seeded random position in each cell; area: exact coverage (CPU only)"}, a.pattern, kSamplePatternNames);
    v.field({"seed", "jittered: the generator's seed (the same seed places the same samples)", 0, 16777216}, a.seed);
  });
  v.group("shadows", [&] {
    ShadowSettings& sh = s.shadows;
    v.field({"enabled", "2-pass shadow maps"}, sh.enabled);
    v.field({"mapSize", "S of the S x S shadow map", kMinShadowMapSize, kMaxShadowMapSize}, sh.mapSize);
    v.field({"biasSlope", "b_slope of bias = max(b_slope (1 - N.L), b_min)", 0, 1}, sh.biasSlope);
    v.field({"biasMin", "b_min of bias = max(b_slope (1 - N.L), b_min)", 0, 1}, sh.biasMin);
    v.field({"pcfRadius", "r: PCF over (2r+1)^2 samples, 0 = hard", 0, kMaxPcfRadius}, sh.pcfRadius);
  });
  v.group("textures", [&] {
    v.choice({"filter", "auto (each texture's sampler), nearest, bilinear or trilinear (mipmapped)"}, s.textures.filter, kTextureFilterNames);
  });
  v.group("environment", [&] {
    EnvironmentSettings& e = s.environment;
    v.field({"map", "a cube map PNG, six square faces side by side (+x -x +y -y +z -z); empty: none"}, e.map);
    v.field({"reflectivity", "k_r of the reflection k_r I_r, I_r the map in direction R = 2(N.V)N - V", 0, 1}, e.reflectivity);
    v.field({"background", "empty pixels show the map in their view direction"}, e.background);
  });
  v.group("fog", [&] {
    FogSettings& f = s.fog;
    v.choice({"mode", "the course's fog by eye depth d: none, linear, exponential (e^-density d) or exponential2 (e^-(density d)^2)"}, f.mode,
             kFogModeNames);
    v.field({"color", "C_fog, linear RGB, each in [0, 1]", 0, 1, FieldKind::Color}, f.color);
    v.field({"start", "linear: the eye depth where fog begins", 0, 1e9}, f.start);
    v.field({"end", "linear: the eye depth where fog hides everything (> start)", 0, 1e9}, f.end);
    v.field({"density", "exponential and exponential2: density per world unit", 0, 1e3}, f.density);
  });
  v.group("ray", [&] {
    RaySettings& r = s.ray;
    v.field({"depth", "levels of the ray tree: 1 casts primary (and shadow) rays only; each more level reflects and refracts once more", 1,
             kMaxRayDepth},
            r.depth);
    v.field({"minContribution", "a reflected or transmitted ray whose weight k_r or k_t (product along its path) is below this is not traced", 0, 1},
            r.minContribution);
    v.field({"epsilon", "a ray leaving a surface starts epsilon R off it (R: the scene's bounding radius), against surface acne", 0, 0.1},
            r.epsilon);
    v.field({"spheres", "trace the builtin sphere as a sphere (the course's quadratic), not as its triangles"}, r.spheres);
    v.field({"samples", "paths per pixel: each samples the pixel, the lens, the lights' areas and the gloss and translucency lobes once", 1,
             kMaxRaySamples},
            r.samples);
    v.field({"seed", "the paths' generator seed (the same seed, the same image, whatever the threads)", 0, 16777216}, r.seed);
    v.field({"gloss", "reflected rays spread over the Phong lobe of the surface's exponent n (glossy reflection)"}, r.gloss);
    v.field({"translucency", "transmitted rays spread over the same lobe (translucency)"}, r.translucency);
  });
  v.list({"particles", "emitter", kMaxEmitters, "particle emitters, on top of those the scene's glTF nodes place"}, s.particles);
  v.group("volume", [&] {
    VolumeSettings& vs = s.volume;
    v.field({"file", "a NRRD (.nrrd, .nhdr) or NIfTI-1 (.nii, .nii.gz) volume, or builtin:marschner-lobb; empty: none"}, vs.file);
    v.field({"resolution", "builtin:marschner-lobb: samples along each axis", 2, 512}, vs.resolution);
    v.choice({"mode", "raycast (v-buffer ray casting), splat (footprints back to front) or isosurface (marching cubes)"}, vs.mode, kVolumeModeNames);
    v.field({"transfer", "the transfer function: a preset (grey, mri, bone, rainbow, iso-surface) or points 'value r g b a, ...', values increasing"},
            vs.transfer);
    v.field({"center", "world position of the volume box's centre"}, vs.center);
    v.field({"size", "world length of the volume box's longest side", 1e-6, 1e9}, vs.size);
    v.field({"rotation", "degrees about x, then y, then z, about the box's centre (a scan's z up: [-90, 0, 0])", -360, 360}, vs.rotation);
    v.field({"step", "raycast: distance between samples along a ray, in voxel spacings", 0.01, 16}, vs.step);
    v.field({"earlyTermination", "raycast: a ray stops once its opacity reaches this (1: never)", 0, 1}, vs.earlyTermination);
    v.field({"emptySpaceSkipping", "raycast: step over macro cells the transfer function makes transparent"}, vs.emptySpaceSkipping);
    v.field({"splatRadius", "splat: the footprint's radius in voxel spacings (Gaussian, sigma = radius / 3)", 0.5, 8}, vs.splatRadius);
    v.field({"isoValue", "isosurface: the iso value in the data's units (null: the mean of the data)", -1e30, 1e30}, vs.isoValue);
    v.field({"isoColor", "isosurface: the mesh's base colour, linear RGB", 0, 1, FieldKind::Color}, vs.isoColor);
  });
  v.field({"time", "seconds into the scene's glTF animations: where they place its meshes", 0, 1e6}, s.time);
  v.field({"background", "linear RGB of empty pixels, each in [0, 1]", 0, 1, FieldKind::Color}, s.background);
  v.field({"backgroundAlpha", "alpha of empty pixels in the PNG: 1 opaque, 0 transparent (as F3D's --no-background)", 0, 1}, s.backgroundAlpha);
}

}  // namespace facet
