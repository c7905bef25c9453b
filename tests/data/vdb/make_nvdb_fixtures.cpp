// Writes the .nvdb fixtures of tests/data/vdb/ (README.md there) with NanoVDB's own writer
// (tools::build::Grid, tools::createNanoGrid, io::writeGrid(s), GridHandle::write) and, for
// tiles.nvdb, an OpenVDB tree converted by NanoVDB. Not built with candela: see the README.
#include <nanovdb/tools/GridBuilder.h>
#include <nanovdb/tools/CreateNanoGrid.h>
#include <nanovdb/io/IO.h>
#include <nanovdb/GridHandle.h>
#include <openvdb/openvdb.h>
#include <openvdb/math/Transform.h>
#include <cstdio>
#include <string>
#include <vector>

using namespace nanovdb;

static GridHandle<HostBuffer> density_8x6x5() {
    tools::build::Grid<float> g(0.0f, "density", GridClass::FogVolume);
    auto acc = g.getAccessor();
    for (int k = -1; k < 4; ++k)
        for (int j = 2; j < 8; ++j)
            for (int i = -3; i < 5; ++i) {
                if (i == 0 && j == 4 && k == 1) continue;  // one inactive voxel inside the bbox
                acc.setValue(Coord(i, j, k), float(1 + (i + 3) + 8 * (j - 2) + 48 * (k + 1)));
            }
    return tools::createNanoGrid(g);
}

int main(int argc, char** argv) {
    const std::string dir = argc > 1 ? argv[1] : ".";
    io::writeGrid(dir + "/density_8x6x5.nvdb", density_8x6x5());
    io::writeGrid(dir + "/density_8x6x5_zip.nvdb", density_8x6x5(), io::Codec::ZIP);
    density_8x6x5().write(dir + "/density_8x6x5_raw.nvdb");  // a raw grid buffer, no segment header
    {
        tools::build::Grid<float> g(0.0f, "density", GridClass::FogVolume);
        g.setTransform(0.5, Vec3d(1.0, -2.0, 3.0));
        auto acc = g.getAccessor();
        for (int k = 0; k < 2; ++k)
            for (int j = 0; j < 2; ++j)
                for (int i = 0; i < 3; ++i) acc.setValue(Coord(i, j, k), 2.0f + float(i) + 10.0f * float(j) + 100.0f * float(k));
        io::writeGrid(dir + "/scaled_translated.nvdb", tools::createNanoGrid(g));
    }
    std::vector<GridHandle<HostBuffer>> two;
    {
        tools::build::Grid<float> d(0.0f, "density", GridClass::FogVolume);
        auto a = d.getAccessor();
        for (int k = 0; k < 2; ++k)
            for (int j = 0; j < 2; ++j)
                for (int i = 0; i < 2; ++i) a.setValue(Coord(i, j, k), 0.5f);
        tools::build::Grid<float> t(1.5f, "temperature", GridClass::FogVolume);
        auto b = t.getAccessor();
        for (int k = 5; k < 8; ++k) b.setValue(Coord(5, 5, k), 1000.0f + float(k));
        two.push_back(tools::createNanoGrid(d));
        two.push_back(tools::createNanoGrid(t));
    }
    io::writeGrids(dir + "/two_grids.nvdb", two);  // two segments, one grid each
    {
        const GridHandle<HostBuffer>* handles[2] = {&two[0], &two[1]};
        io::writeGrid(dir + "/two_grids_one_segment.nvdb", mergeGrids(handles, 2));  // one segment, two grids
    }
    {
        tools::build::Grid<double> g(0.0, "density", GridClass::FogVolume);
        g.getAccessor().setValue(Coord(1, 2, 3), 4.0);
        io::writeGrid(dir + "/double.nvdb", tools::createNanoGrid(g));
    }
    {
        openvdb::initialize();
        auto g = openvdb::FloatGrid::create(0.0f);
        g->setName("density");
        g->setGridClass(openvdb::GRID_FOG_VOLUME);
        openvdb::math::Mat4d m = openvdb::math::Mat4d::identity();
        m.preScale(openvdb::Vec3d(0.25));
        m.postRotate(openvdb::math::Z_AXIS, M_PI / 2);
        m.postTranslate(openvdb::Vec3d(0.1, 0.2, 0.3));
        g->setTransform(openvdb::math::Transform::createLinearTransform(m));
        g->fill(openvdb::CoordBBox(openvdb::Coord(-8, -8, -8), openvdb::Coord(23, 15, 7)), 0.75f, true);
        g->tree().setValue(openvdb::Coord(30, 1, 2), 2.0f);
        std::printf("tiles: active tiles %llu leaves %llu\n", (unsigned long long)g->tree().activeTileCount(), (unsigned long long)g->tree().leafCount());
        std::cout << m << "\n";
        io::writeGrid(dir + "/tiles.nvdb", tools::createNanoGrid(*g));
    }
    return 0;
}
