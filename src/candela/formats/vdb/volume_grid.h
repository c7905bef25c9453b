#pragma once
// A scalar volume grid read from a NanoVDB (.nvdb, nanovdb_reader.h) or OpenVDB (.vdb,
// openvdb_reader.h) file, as plain data: the dense block of voxels covering the grid's active
// voxels, the value everywhere else, and the affine map from index space to world space. The
// media code (media/grid_medium.h) turns it into its own lattice; this type knows nothing of it.
//
// Where the values sit: voxel (i,j,k) holds its value at the index-space point (i,j,k) exactly,
// which is where NanoVDB's and OpenVDB's trilinear samplers (SampleFromVoxels<.., 1>, BoxSampler)
// put it, and so pbrt-v4's NanoVDBMedium: a lookup at index point p interpolates the eight voxels
// around it, floor(p) and floor(p) + 1 along each axis. The cell of voxel (i,j,k) as a box is
// [i, i+1] x [j, j+1] x [k, k+1]; the world bounds below are of those boxes.
#include <cstddef>
#include <string>
#include <vector>

#include "candela/math/vec.h"

namespace candela {

struct VolumeGrid {
    std::string name;            // the grid's name in the file ("density", "temperature")
    Vec3<int> index_min{};       // index coordinates of values[0]
    int nx = 0, ny = 0, nz = 0;  // the block's size in voxels; all 0 for a grid with no active voxel
    // nx*ny*nz values, x fastest: voxel index_min + (x,y,z) is values[(z*ny + y)*nx + x]. The block
    // is the bounding box of the active voxels (and active tiles); each voxel in it holds what the
    // file's tree returns for it (NanoVDB's getValue): an inactive voxel or tile keeps the value
    // the file stores for it, which the usual writers set to the background.
    std::vector<float> values;
    float background = 0;  // the value of every voxel outside the block
    // world = index_to_world * (i, j, k, 1): rows of a 3x4 affine matrix, as the file's map says.
    double index_to_world[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};
    // The world-space box of the active voxels' cells, as the file stores it (NanoVDB's world
    // bbox: the map applied to the index box [min, max + 1]); for OpenVDB files, computed so.
    Vec3d world_min{}, world_max{};

    size_t voxel_count() const { return size_t(nx) * size_t(ny) * size_t(nz); }
    // The value of voxel (i,j,k) in index coordinates: from the block, or the background outside it.
    float value_at(int i, int j, int k) const {
        const long long x = (long long)i - index_min.x, y = (long long)j - index_min.y, z = (long long)k - index_min.z;
        if (x < 0 || y < 0 || z < 0 || x >= nx || y >= ny || z >= nz) return background;
        return values[size_t((z * ny + y) * nx + x)];
    }
    // The world-space position of index point (i,j,k) (need not be integer).
    Vec3d index_to_world_point(Vec3d p) const {
        Vec3d w;
        for (int r = 0; r < 3; ++r)
            w[r] = index_to_world[r][0] * p.x + index_to_world[r][1] * p.y + index_to_world[r][2] * p.z +
                   index_to_world[r][3];
        return w;
    }
};

}  // namespace candela
