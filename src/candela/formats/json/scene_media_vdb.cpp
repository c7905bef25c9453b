// The `media` section's grids from files (docs/SCENE_FORMAT.md, "Media"): pbrt-v4's `nanovdb`
// medium (media.cpp, NanoVDBMedium::Create) for NanoVDB files, and `openvdb` for OpenVDB files
// (Blender's, Houdini's), the same medium. Each becomes a GridMedium (media/grid_medium.h) whose
// grids are the file's voxels placed by the file's index-to-world map (in medium space).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "candela/formats/json/scene_sections.h"
#include "candela/formats/vdb/nanovdb_reader.h"
#include "candela/formats/vdb/openvdb_reader.h"
#include "candela/media/grid_medium.h"
#include "candela/scene/enum_names.h"

namespace candela {

namespace {

// The inverse of a grid's index-to-world affine map (world here is medium space), shifted so that
// the lattice's sample 0 is voxel index_min: lattice = world_to_index(p) - index_min.
std::optional<AffineMap3f> lattice_from_medium(const VolumeGrid& g) {
    const double(&a)[3][4] = g.index_to_world;
    const double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                       a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    if (!(std::abs(det) > 1e-30) || !std::isfinite(det)) return std::nullopt;
    double inv[3][3];
    inv[0][0] = (a[1][1] * a[2][2] - a[1][2] * a[2][1]) / det;
    inv[0][1] = (a[0][2] * a[2][1] - a[0][1] * a[2][2]) / det;
    inv[0][2] = (a[0][1] * a[1][2] - a[0][2] * a[1][1]) / det;
    inv[1][0] = (a[1][2] * a[2][0] - a[1][0] * a[2][2]) / det;
    inv[1][1] = (a[0][0] * a[2][2] - a[0][2] * a[2][0]) / det;
    inv[1][2] = (a[0][2] * a[1][0] - a[0][0] * a[1][2]) / det;
    inv[2][0] = (a[1][0] * a[2][1] - a[1][1] * a[2][0]) / det;
    inv[2][1] = (a[0][1] * a[2][0] - a[0][0] * a[2][1]) / det;
    inv[2][2] = (a[0][0] * a[1][1] - a[0][1] * a[1][0]) / det;
    const double origin[3] = {double(g.index_min.x), double(g.index_min.y), double(g.index_min.z)};
    AffineMap3f m;
    for (int i = 0; i < 3; ++i) {
        double t = 0.0;
        for (int k = 0; k < 3; ++k) {
            m.m[i][k] = float(inv[i][k]);
            t -= inv[i][k] * a[k][3];
        }
        m.m[i][3] = float(t - origin[i]);
    }
    return m;
}

// The grid as a GridField, or fails at `at` when its map cannot be inverted.
GridField field_of(VolumeGrid grid, const JsonCursor& at) {
    std::optional<AffineMap3f> map = lattice_from_medium(grid);
    if (!map) at.fail(fmt::format("grid \"{}\": its index-to-world map is singular", grid.name));
    return placed_field(grid.nx, grid.ny, grid.nz, std::move(grid.values), *map, grid.background);
}

Bounds3f world_bounds(const VolumeGrid& g) {
    return Bounds3f{Vec3f(g.world_min), Vec3f(g.world_max)};
}

}  // namespace

Medium read_vdb_medium(std::string_view type, JsonCursor& c, const Scene& scene, const Transform& to_world,
                       MemoryBudget& budget) {
    const bool nano = type == "nanovdb";
    const JsonCursor file_key = c.require("file");
    const std::filesystem::path file =
        referenced_file(file_key, scene.file.parent_path(), nano ? "NanoVDB" : "OpenVDB");
    const std::string density_name = c.get("grid_name") ? c.get("grid_name")->string() : "density";
    const std::string temperature_name =
        c.get("temperature_name") ? c.get("temperature_name")->string() : "temperature";
    auto read = [&](const std::string& name) {
        return load_referenced(file_key, [&] {
            return nano ? read_nanovdb_grid(file, name, budget) : read_openvdb_grid(file, name, budget);
        });
    };
    // pbrt-v4 reads the temperature grid when the file has one of that name.
    const std::vector<std::string> names =
        load_referenced(file_key, [&] { return nano ? nanovdb_grid_names(file) : openvdb_grid_names(file); });
    const bool hot = std::find(names.begin(), names.end(), temperature_name) != names.end();

    GridMedium m;
    m.box.medium_from_world = affine_map_3f(to_world.inverse());
    VolumeGrid density = read(density_name);
    if (density.voxel_count() == 0) file_key.fail(fmt::format("grid \"{}\" has no active voxels", density_name));
    m.box.bounds = world_bounds(density);
    m.density = field_of(std::move(density), file_key);
    if (hot) {
        VolumeGrid temperature = read(temperature_name);
        if (temperature.voxel_count() > 0) {
            m.box.bounds.extend(world_bounds(temperature));
            m.temperature = field_of(std::move(temperature), file_key);
        }
    }
    for (int i = 0; i < 3; ++i)
        if (!(m.box.bounds.hi[i] > m.box.bounds.lo[i]))
            file_key.fail(fmt::format("grid \"{}\" is flat in {}: it encloses no volume", density_name, "xyz"[i]));
    read_medium_coefficients(c, scene, m.sigma_a, m.sigma_s);
    m.g = read_medium_g(c);
    // pbrt-v4's NanoVDBMedium: Le = Lescale (a number, the same everywhere) times the blackbody of
    // (temperature - offset) x scale; no Le spectrum.
    read_temperature_mapping(c, m.temperature_offset, m.temperature_scale);
    const float Le_scale = c.get("Le_scale") ? c.get("Le_scale")->number_f(Bounds::at_least(0)) : 1.0f;
    m.Le_scale = placed_field(1, 1, 1, {Le_scale}, AffineMap3f{}, Le_scale);
    if (m.temperature.empty()) m.Le_scale = GridField{};
    finish_grid_medium(m, vdb_majorant_resolution(m.density.lattice.nx, m.density.lattice.ny, m.density.lattice.nz));
    return m;
}

}  // namespace candela
