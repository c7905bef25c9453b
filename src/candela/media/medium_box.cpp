#include "candela/media/medium_box.h"

namespace candela {

AffineMap3f affine_map_3f(const Transform& t) {
    AffineMap3f a;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 4; ++j) a.m[i][j] = float(t.matrix()[size_t(i)][size_t(j)]);
    return a;
}

}  // namespace candela
