// Film regions: the per-pixel values that checkpoints, shard parts and MPI messages carry, read
// and written back bit for bit, in row-major order, with the weight sum after the three sums.
#include <gtest/gtest.h>

#include <vector>

#include "candela/film/film.h"

namespace candela {
namespace CANDELA_UNITY_ID {

TEST(FilmRegion, ReadsRowMajorWithWeightsAfterTheSums) {
    Film film(5, 4, true);
    EXPECT_EQ(film.values_per_pixel(), 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 5; ++x) {
            film.sum(x, y) = {double(x), double(y), 1.0 / double(1 + x + y)};
            film.weight(x, y) = double(10 * y + x);
        }
    const PixelBounds region{1, 2, 4, 4};  // 3 x 2 pixels
    std::vector<double> values(size_t(region.width() * region.height() * 4));
    film.read_region(region, values.data());
    EXPECT_EQ(values[0], 1.0);   // (1, 2): r
    EXPECT_EQ(values[1], 2.0);   // g
    EXPECT_EQ(values[3], 21.0);  // its weight sum
    EXPECT_EQ(values[4], 2.0);   // (2, 2): r
    EXPECT_EQ(values[12], 1.0);  // (1, 3): r, the second row
    EXPECT_EQ(values[15], 31.0);

    Film copy(5, 4, true);
    copy.write_region(region, values.data());
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 5; ++x) {
            const bool inside = x >= 1 && x < 4 && y >= 2;
            const PixelSum expected = inside ? film.sum(x, y) : PixelSum{0, 0, 0};
            EXPECT_EQ(copy.sum(x, y), expected) << x << "," << y;
            EXPECT_EQ(copy.weight(x, y), inside ? film.weight(x, y) : 0.0) << x << "," << y;
        }
}

TEST(FilmRegion, AnUnweightedFilmHasThreeValuesPerPixel) {
    Film film(2, 2);
    EXPECT_EQ(film.values_per_pixel(), 3);
    film.sum(1, 1) = {0.1, 0.2, 0.3};
    std::vector<double> values(12);
    film.read_region({0, 0, 2, 2}, values.data());
    EXPECT_EQ(values[9], 0.1);
    EXPECT_EQ(values[11], 0.3);
}

}  // namespace
}  // namespace candela
