// Writes smoke.nvdb for candela's pbrt-v4 media reference (tests/data/pbrt-media/): with the
// NanoVDB headers pbrt-v4 pins (src/ext/openvdb/nanovdb, NanoVDB 32.3), so that pbrt-v4 reads it.
// Two grids, FogVolume class, voxel size 1/16, origin 0: "density" on the index box [0,15] x
// [0,11] x [0,15] (a lumpy blob; 0 outside it, inactive) and "temperature" on the same box.
#include <nanovdb/util/GridBuilder.h>
#include <nanovdb/util/IO.h>

#include <cmath>
#include <vector>

int main(int argc, char** argv) {
    const char* out = argc > 1 ? argv[1] : "smoke.nvdb";
    const nanovdb::CoordBBox box(nanovdb::Coord(0, 0, 0), nanovdb::Coord(15, 11, 15));
    auto centre = [](const nanovdb::Coord& ijk, float& x, float& y, float& z) {
        x = (ijk[0] + 0.5f) / 16.0f;
        y = (ijk[1] + 0.5f) / 16.0f;
        z = (ijk[2] + 0.5f) / 16.0f;
    };
    nanovdb::GridBuilder<float> density(0.0f, nanovdb::GridClass::FogVolume);
    density([&](const nanovdb::Coord& ijk) {
        float x, y, z;
        centre(ijk, x, y, z);
        const float r = std::sqrt((x - 0.5f) * (x - 0.5f) + 1.4f * (y - 0.35f) * (y - 0.35f) + (z - 0.5f) * (z - 0.5f));
        const float lumps = 0.5f + 0.5f * std::sin(19.0f * x) * std::cos(13.0f * z + 5.0f * y);
        const float d = std::max(0.0f, 1.0f - r / 0.45f);
        return d > 0 ? 4.0f * d * (0.6f + 0.4f * lumps) : 0.0f;
    }, box);
    nanovdb::GridBuilder<float> temperature(0.0f, nanovdb::GridClass::FogVolume);
    temperature([&](const nanovdb::Coord& ijk) {
        float x, y, z;
        centre(ijk, x, y, z);
        const float r = std::sqrt((x - 0.5f) * (x - 0.5f) + (y - 0.25f) * (y - 0.25f) + (z - 0.5f) * (z - 0.5f));
        const float t = std::max(0.0f, 1.0f - r / 0.3f);
        return t > 0 ? 1.0f + 2.4f * t : 0.0f;  // in thousands of kelvin: temperaturescale 1000
    }, box);
    std::vector<nanovdb::GridHandle<>> handles;
    handles.push_back(density.getHandle(1.0 / 16.0, nanovdb::Vec3d(0), "density"));
    handles.push_back(temperature.getHandle(1.0 / 16.0, nanovdb::Vec3d(0), "temperature"));
    nanovdb::io::writeGrids(out, handles);
    return 0;
}
