#pragma once
// One entry of the scene file's `shapes`: which geometry, which material, and its emission. Its
// index in the scene's shape array is the shape id of hits and the Embree geometry id.
#include <cstdint>

#include "candela/math/rgb.h"

namespace candela {

enum class ShapeKind { kMesh, kSphere, kDisk, kCurves, kQuadric };  // a quad is a mesh; kQuadric: quadric.h

struct Shape {
    ShapeKind kind = ShapeKind::kMesh;
    uint32_t index = 0;     // into the scene's meshes, spheres, disks, curves or quadrics
    uint32_t material = 0;  // into the scene's materials
    Rgb emission;           // black: not a light
    bool two_sided = false; // emission leaves both sides
    // Spectral mode: the emission as a spectrum of the scene's textures, normalized to luminance
    // 1 and scaled; 0xffffffff: the illuminant uplift of `emission`.
    uint32_t emission_spectrum = 0xffffffffu;
    // The media on either side (indices into the scene's media; 0xffffffff: none, vacuum), pbrt-
    // v4's MediumInterface: `interior` is the side the normal points away from. Equal: the shape
    // is no boundary between media, and a ray crossing it stays in the medium it was in.
    uint32_t interior = 0xffffffffu;
    uint32_t exterior = 0xffffffffu;
    bool is_medium_boundary() const { return interior != exterior; }
};

}  // namespace candela
