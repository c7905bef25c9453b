// The `media` section's bounded kinds (docs/SCENE_FORMAT.md, "Media"): pbrt-v4's uniformgrid,
// rgbgrid and cloud (media.cpp: GridMedium::Create, RGBGridMedium::Create, CloudMedium::Create),
// with pbrt-v4's parameters and defaults under candela's key names. Grids are charged to the
// memory budget, from their sizes, before their values are read.
#include <fmt/format.h>

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "candela/formats/json/scene_sections.h"
#include "candela/media/cloud_medium.h"
#include "candela/media/grid_medium.h"
#include "candela/media/rgb_grid_medium.h"
#include "candela/scene/memory_budget.h"

namespace candela {

namespace {

// The box p0..p1 (defaults (0, 0, 0) and (1, 1, 1)), in medium space; the corners may be given in
// any order (pbrt-v4's Bounds3f(p0, p1)), but the box must have volume.
MediumBox read_box(JsonCursor& c, const Transform& to_world) {
    MediumBox box;
    box.medium_from_world = affine_map_3f(to_world.inverse());
    std::optional<JsonCursor> p0 = c.get("p0"), p1 = c.get("p1");
    const Vec3f a = p0 ? p0->vec3f() : Vec3f(0.0f), b = p1 ? p1->vec3f() : Vec3f(1.0f);
    box.bounds = Bounds3f{};
    box.bounds.extend(a);
    box.bounds.extend(b);
    for (int i = 0; i < 3; ++i)
        if (!(box.bounds.hi[i] > box.bounds.lo[i])) {
            const JsonCursor& at = p1 ? *p1 : (p0 ? *p0 : c);
            at.fail(fmt::format("a medium's box p0..p1 must have volume; it is flat in {}", "xyz"[i]));
        }
    return box;
}

// `size`: [nx, ny, nz], each >= 1, and their product (the voxel count).
struct GridSize {
    int nx = 1, ny = 1, nz = 1;
    uint64_t voxels() const { return uint64_t(nx) * uint64_t(ny) * uint64_t(nz); }
};

GridSize read_size(JsonCursor& c) {
    const JsonCursor size = c.require("size");
    const std::vector<JsonCursor> e = size.elements(3, "[nx, ny, nz], three integers >= 1");
    const GridSize s{e[0].integer(Bounds::at_least(1)), e[1].integer(Bounds::at_least(1)), e[2].integer(Bounds::at_least(1))};
    // Beyond 2^48 voxels no machine holds the grid, and 3 numbers per voxel still fit 64 bits.
    if (double(s.nx) * double(s.ny) * double(s.nz) > 0x1p48)
        size.fail(fmt::format("a grid of {} x {} x {} voxels is beyond any memory", s.nx, s.ny, s.nz));
    return s;
}

// Fails unless grid `key` of `c` has `n` elements (`per_voxel` numbers per voxel).
void check_grid_length(const JsonCursor& grid, std::string_view key, const GridSize& size, int per_voxel) {
    const uint64_t expected = size.voxels() * uint64_t(per_voxel);
    const size_t got = grid.array_size();
    if (got != expected)
        grid.fail(fmt::format("\"{}\" has {} numbers; size {} x {} x {} needs {}{}", key, got, size.nx, size.ny,
                              size.nz, expected, per_voxel == 3 ? " (three per voxel: r, g, b)" : ""));
}

LatticeGrid read_float_grid(const JsonCursor& grid, const GridSize& size) {
    LatticeGrid g;
    g.nx = size.nx;
    g.ny = size.ny;
    g.nz = size.nz;
    g.values = grid.float_array(Bounds::at_least(0));
    return g;
}

std::vector<Rgb> read_rgb_grid(const JsonCursor& grid) {
    const std::vector<float> v = grid.float_array(Bounds::at_least(0));
    std::vector<Rgb> out(v.size() / 3);
    for (size_t i = 0; i < out.size(); ++i) out[i] = Rgb(v[3 * i], v[3 * i + 1], v[3 * i + 2]);
    return out;
}

void charge(MemoryBudget& budget, const JsonCursor& at, uint64_t bytes, const GridSize& size, std::string_view kind) {
    if (auto refused = budget.charge(bytes, fmt::format("a {} medium of {} x {} x {} voxels", kind, size.nx, size.ny, size.nz)))
        at.fail(*refused);
}

// pbrt-v4's `uniformgrid`.
GridMedium read_uniform_grid(JsonCursor& c, const Scene& scene, const Transform& to_world, MemoryBudget& budget) {
    GridMedium m;
    m.box = read_box(c, to_world);
    const GridSize size = read_size(c);
    JsonCursor density = c.require("density");
    check_grid_length(density, "density", size, 1);
    std::optional<JsonCursor> temperature = c.get("temperature");
    if (temperature) check_grid_length(*temperature, "temperature", size, 1);
    std::optional<JsonCursor> Le_scale = c.get("Le_scale");
    const bool Le_scale_grid = Le_scale && !Le_scale->is_number();
    if (Le_scale_grid) check_grid_length(*Le_scale, "Le_scale", size, 1);
    const int float_grids = 1 + (temperature ? 1 : 0) + (Le_scale_grid ? 1 : 0);
    charge(budget, density, grid_medium_memory_bytes(size.voxels(), float_grids, 0, temperature.has_value()), size,
           "uniformgrid");

    m.density = cell_centred_field(read_float_grid(density, size), m.box.bounds);
    read_medium_coefficients(c, scene, m.sigma_a, m.sigma_s);
    m.g = read_medium_g(c);

    // Emission: a temperature grid or Le (normalized, times a number Le_scale, by
    // read_medium_emission), times the Le_scale grid: the one given, or pbrt-v4's 1x1x1 default.
    const bool has_Le = c.has("Le");
    if (has_Le && temperature)
        c.document().fail_at_key(c.pointer(), "Le", "give \"Le\" or \"temperature\", not both");
    float number_scale = 1.0f;
    if (temperature) {
        m.temperature = cell_centred_field(read_float_grid(*temperature, size), m.box.bounds);
        read_temperature_mapping(c, m.temperature_offset, m.temperature_scale);
        if (Le_scale && !Le_scale_grid) number_scale = Le_scale->number_f(Bounds::at_least(0));
    } else if (std::optional<MediumSpectrum> Le = read_medium_emission(c, scene)) {
        m.Le = *Le;
    }
    m.Le_scale = Le_scale_grid ? cell_centred_field(read_float_grid(*Le_scale, size), m.box.bounds)
                               : make_le_scale_field(number_scale, m.box.bounds);
    finish_grid_medium(m);
    return m;
}

// pbrt-v4's `rgbgrid`.
RgbGridMedium read_rgb_grid_medium(JsonCursor& c, const Transform& to_world, MemoryBudget& budget) {
    RgbGridMedium m;
    m.box = read_box(c, to_world);
    const GridSize size = read_size(c);
    std::optional<JsonCursor> sigma_a = c.get("sigma_a"), sigma_s = c.get("sigma_s"), Le = c.get("Le");
    if (!sigma_a && !sigma_s) c.fail("an rgbgrid medium needs \"sigma_a\", \"sigma_s\" or both");
    // pbrt-v4 requires sigma_a with Le (RGBGridMedium's constructor checks it).
    if (Le && !sigma_a) c.document().fail_at_key(c.pointer(), "Le", "an rgbgrid's \"Le\" needs \"sigma_a\" too");
    int grids = 0;
    for (auto [key, grid] : {std::pair{"sigma_a", &sigma_a}, std::pair{"sigma_s", &sigma_s}, std::pair{"Le", &Le}})
        if (*grid) {
            check_grid_length(**grid, key, size, 3);
            ++grids;
        }
    charge(budget, sigma_a ? *sigma_a : *sigma_s, grid_medium_memory_bytes(size.voxels(), 0, grids, false), size,
           "rgbgrid");
    if (sigma_a) m.sigma_a = make_rgb_lattice(size.nx, size.ny, size.nz, read_rgb_grid(*sigma_a), false);
    if (sigma_s) m.sigma_s = make_rgb_lattice(size.nx, size.ny, size.nz, read_rgb_grid(*sigma_s), false);
    if (Le) m.Le = make_rgb_lattice(size.nx, size.ny, size.nz, read_rgb_grid(*Le), true);
    if (auto v = c.get("Le_scale")) m.Le_scale = v->number_f(Bounds::at_least(0));
    m.scale = read_medium_scale(c);
    m.g = read_medium_g(c);
    finish_rgb_grid_medium(m);
    return m;
}

// pbrt-v4's `cloud`.
CloudMedium read_cloud(JsonCursor& c, const Scene& scene, const Transform& to_world) {
    CloudMedium m;
    m.box = read_box(c, to_world);
    read_medium_coefficients(c, scene, m.sigma_a, m.sigma_s, /*scalable=*/false);
    if (auto v = c.get("density")) m.density = v->number_f(Bounds::at_least(0));
    if (auto v = c.get("wispiness")) m.wispiness = v->number_f(Bounds::at_least(0));
    if (auto v = c.get("frequency")) m.frequency = v->number_f(Bounds::at_least(0));
    m.g = read_medium_g(c);
    return m;
}

}  // namespace

Medium read_bounded_medium(std::string_view type, JsonCursor& c, const Scene& scene, const Transform& to_world,
                           MemoryBudget& budget) {
    if (type == "uniformgrid") return read_uniform_grid(c, scene, to_world, budget);
    if (type == "rgbgrid") return read_rgb_grid_medium(c, to_world, budget);
    return read_cloud(c, scene, to_world);
}

}  // namespace candela
