// The transmittance of bench/scenes/media-grids-vs-pbrt/cloud.json's cloud along each pixel's
// rays (16 per pixel, 4000 steps each), from candela's density function: the reference both
// renderers' images are compared with (README.md). Not part of the build.
#include <cstdio>
#include <cmath>
#include "candela/media/cloud_medium.h"
using namespace candela;
int main() {
    CloudMedium c; c.density = 1.3f; c.wispiness = 0.7f; c.frequency = 4.0f;
    const int n = 16, steps = 4000;
    for (int j = 0; j < n; ++j) {           // image row, top first
        for (int i = 0; i < n; ++i) {
            // average over a 4x4 grid of sub-pixel positions
            double T = 0;
            for (int sy = 0; sy < 4; ++sy) for (int sx = 0; sx < 4; ++sx) {
                float x = (i + (sx + 0.5f) / 4) / n, y = 1.0f - (j + (sy + 0.5f) / 4) / n;
                double tau = 0;
                for (int k = 0; k < steps; ++k) { float z = (k + 0.5f) / steps; tau += c.density_at(Vec3f(x, y, z)); }
                T += std::exp(-4.0 * tau / steps);
            }
            printf("%.5f ", T / 16);
        }
        printf("\n");
    }
}
