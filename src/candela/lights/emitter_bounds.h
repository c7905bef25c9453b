#pragma once
// The LightBounds (light_bounds.h) of each kind of candela light, as pbrt-v4's Light::Bounds()
// gives them: a diffuse area light bounds its shape with the shape's cone of front normals and
// emits up to pi/2 past them (DiffuseAreaLight); a point light emits all around (PointLight); a
// spot light along its axis, fully within cos_falloff_start and not beyond the falloff's width
// past it (SpotLight). Directional lights and the environment have no bounds (nullopt): they are
// "infinite" lights. phi is pbrt-v4's: the largest RGB component of the emission (pbrt-v4 takes
// the spectrum's maximum) times pi times the area, or 4 pi times the intensity; only ratios
// between lights matter.
#include <optional>
#include <span>

#include "candela/geometry/disk.h"
#include "candela/geometry/quadric.h"
#include "candela/geometry/shape.h"
#include "candela/geometry/sphere.h"
#include "candela/geometry/triangle_mesh.h"
#include "candela/lights/delta_light.h"
#include "candela/lights/light_bounds.h"

namespace candela {

// The bounds of shape `shape` emitting `shape.emission` (area: its emitting area).
LightBounds area_light_bounds(const Shape& shape, std::span<const TriangleMesh> meshes,
                              std::span<const Sphere> spheres, std::span<const Disk> disks,
                              std::span<const Quadric> quadrics, float area);

// The bounds of a point or spot light; nullopt for a directional light.
std::optional<LightBounds> delta_light_bounds(const DeltaLight& light);

}  // namespace candela
