// Writes density_8x6x5_v32_3.nvdb of tests/data/vdb/ (README.md there) with NanoVDB 32.3.3, the
// version pbrt-v4 pins (magic "NanoVDB0"): GridBuilder<float>, io::writeGrid. Not built with candela.
#include <nanovdb/util/GridBuilder.h>
#include <nanovdb/util/IO.h>
#include <string>
int main(int argc, char** argv) {
    const std::string dir = argc > 1 ? argv[1] : ".";
    nanovdb::GridBuilder<float> builder(0.0f, nanovdb::GridClass::FogVolume);
    auto acc = builder.getAccessor();
    for (int k = -1; k < 4; ++k)
        for (int j = 2; j < 8; ++j)
            for (int i = -3; i < 5; ++i) {
                if (i == 0 && j == 4 && k == 1) continue;
                acc.setValue(nanovdb::Coord(i, j, k), float(1 + (i + 3) + 8 * (j - 2) + 48 * (k + 1)));
            }
    nanovdb::io::writeGrid(dir + "/density_8x6x5_v32_3.nvdb", builder.getHandle<>(0.5, nanovdb::Vec3d(1.0, -2.0, 3.0), "density"));
}
