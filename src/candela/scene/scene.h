#pragma once
// A loaded scene: everything the renderer needs, in flat arrays referenced by index. Produced by
// load_scene (scene_loader.h); geometry is already in world space with orientation resolved.
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "candela/camera/camera_settings.h"
#include "candela/film/film_settings.h"
#include "candela/geometry/curves.h"
#include "candela/geometry/disk.h"
#include "candela/geometry/quadric.h"
#include "candela/geometry/instance.h"
#include "candela/geometry/instance_motion.h"
#include "candela/geometry/shape.h"
#include "candela/geometry/sphere.h"
#include "candela/geometry/triangle_mesh.h"
#include "candela/image/image.h"
#include "candela/lights/delta_light.h"
#include "candela/lights/environment_light.h"
#include "candela/materials/material.h"
#include "candela/materials/subsurface.h"
#include "candela/media/medium.h"
#include "candela/math/rgb.h"
#include "candela/math/transform.h"
#include "candela/scene/render_settings.h"
#include "candela/textures/texture_file.h"
#include "candela/textures/texture_set.h"

namespace candela {

// The `environment` light: a radiance map (1x1 for a constant colour), equirectangular or
// equal-area (square); `scale` includes the factor that `illuminance` asks for.
struct EnvironmentSettings {
    Image radiance;
    float scale = 1.0f;
    Transform to_world;  // rotates the light's frame into the world
    EnvironmentSampling sampling = EnvironmentSampling::kImportance;
    EnvironmentMapping mapping = EnvironmentMapping::kEquirectangular;
    EnvironmentFilter filter = EnvironmentFilter::kBilinear;
};

// An image file that textures read, loaded once however many textures name it (the loader
// matches files by canonical path and colorspace).
struct TextureFile {
    std::filesystem::path path;       // the file, relative to the working folder or absolute
    std::filesystem::path canonical;  // what identifies it
    TextureColorspace colorspace = TextureColorspace::kSrgb;  // kLinear for float formats
    float gamma = 1.0f;               // the exponent of TextureColorspace::kGamma
    std::string name;                 // as the scene file writes it, for messages
    std::string pointer;              // the JSON pointer of the first `file` key naming it
};

// A point, spot or directional light. A directional light given by `power` gets its irradiance
// only when the scene's size is known (build_light_set): its `irradiance` holds colour x scale,
// to be multiplied by power / (pi r^2), r the radius of the scene's bounding sphere (pbrt-v4's
// DistantLight, whose power is pi r^2 E).
struct DeltaLightSettings {
    DeltaLight light;
    std::optional<float> directional_power;  // W; only for a directional light
    // Spectral mode: the light's colour as a spectrum of textures (kNoSpectrum: its RGB colour's
    // illuminant uplift), normalized to luminance 1, times spectrum_scale (its scale and power).
    uint32_t spectrum = kNoSpectrum;
    float spectrum_scale = 1.0f;
};

struct Scene {
    std::filesystem::path file;  // the scene file, as given
    std::string output_file;     // film.filename: the default output image ("" for <scene name>.png)
    // For a scene translated from another format (a pbrt-v4 file), or loaded from a document in
    // memory (the Python module): the JSON document it was loaded from, and the hashes of the
    // meshes it held in memory under file names, which the content hash (content_hash.h) reads
    // instead of scene.file and those files.
    std::string translated_json;
    std::map<std::string, uint64_t> inline_file_hashes;

    IntegratorSettings integrator;
    SamplerSettings sampler;
    CameraSettings camera;
    FilmSettings film;

    TextureSet textures;  // what textured material parameters index
    std::vector<std::string> texture_names;  // parallel to textures: the name, "" when inline
    std::vector<TextureFile> texture_files;  // parallel to textures' images
    std::vector<Material> materials;
    std::vector<std::string> material_names;  // parallel to materials
    std::vector<Subsurface> subsurfaces;       // the interiors of `subsurface` materials
    std::vector<TriangleMesh> meshes;
    std::vector<Sphere> spheres;
    std::vector<Disk> disks;
    std::vector<Quadric> quadrics;  // cylinders, partial spheres and partial disks (quadric.h)
    std::vector<CurveSet> curves;
    std::vector<Shape> shapes;  // in the world, except those of objects
    // Instancing (geometry/instance.h): each object a run of `shapes` in object space, without
    // emission; each instance an object placed by a transform. Empty in most scenes.
    std::vector<ObjectShapes> objects;
    std::vector<std::string> object_names;  // parallel to objects
    std::vector<Instance> instances;
    // The placements over the shutter of the moving instances (Instance::motion indexes them), and
    // of the moving shapes, each of which the loader makes a one-shape object and its instance.
    std::vector<InstanceMotion> instance_motions;
    std::optional<EnvironmentSettings> environment;
    std::vector<DeltaLightSettings> delta_lights;
    // Participating media (media/medium.h), named; shapes index them (Shape::interior/exterior).
    std::vector<Medium> media;
    std::vector<std::string> medium_names;  // parallel to media
    uint32_t camera_medium = kNoMedium;     // the medium the camera sits in
    // Problems that do not stop loading (e.g. an environment map that is not 2:1), one line each,
    // already located ("file: message"); the CLI prints them as warnings.
    std::vector<std::string> warnings;
};

// Whether the scene places a participating medium anywhere: the camera in one, or a shape with one
// on either side. Integrators other than volpath and bsdf render such media as vacuum, and the
// scene loader and a render job's --integrator both warn so (pbrt-v4's cpu/render.cpp does too).
inline bool places_media(const Scene& scene) {
    if (scene.camera_medium != kNoMedium) return true;
    for (const Shape& shape : scene.shapes)
        if (shape.interior != kNoMedium || shape.exterior != kNoMedium) return true;
    return false;
}

// Whether some material scatters below its surface by the tabulated BSSRDF, which only volpath
// follows (and bsdf, volpath without light sampling, there); the other integrators see only its
// dielectric boundary, as pbrt-v4's path integrator does, and the scene loader warns so (pbrt-v4's
// cpu/render.cpp does too). The random walk's interior is a medium: places_media covers it.
inline bool has_tabulated_subsurface(const Scene& scene) {
    for (const Subsurface& s : scene.subsurfaces)
        if (s.method == SubsurfaceMethod::kTabulated) return true;
    return false;
}

}  // namespace candela
